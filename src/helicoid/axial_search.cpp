// The contact search along Z: a table of the X search's centre distance over one lobe, the
// phase where it first reaches the centre distance along the travel, refined by Illinois.
#include "helicoid/contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace ncurve::helicoid {

std::vector<Contact> ContactSearch::run_axial(const std::vector<double>& psis, Method method, const AxialMotion& m,
                                              const StepDone& done) const {
  const double twist = work_.twist();
  if (twist == 0) throw std::runtime_error("a straight workpiece (lead 0) is the same at every Z: the final motion must be X");
  if (m.direction != 1 && m.direction != -1) throw std::runtime_error("axial motion: direction is -1 or +1");
  // A over one lobe, traced: where along the travel A first reaches the centre distance.
  const double period = 360.0 / work_.lobes;
  constexpr int kCells = 144;
  std::vector<double> grid;
  for (int k = 0; k <= kCells; ++k) grid.push_back(period * k / kCells);
  auto table = run(grid, method);
  double a_max = 0;
  for (const auto& c : table) a_max = std::max(a_max, c.A);
  const double target = m.centre_distance;
  if (!(target <= a_max))
    throw std::runtime_error(fmt::format("at centre distance {:g} mm the cutter never reaches the workpiece (A is at "
                                         "most {:.6f} mm)", target, a_max));
  const double sense = twist * m.direction > 0 ? 1 : -1;  // the way the equivalent phase turns
  auto cell_of = [&](double phase) { return static_cast<long>(std::floor(phase / period * kCells)); };
  auto table_phase = [&](long k) { return period * static_cast<double>(k) / kCells; };
  auto table_A = [&](long k) { return table[static_cast<std::size_t>(((k % kCells) + kCells) % kCells)].A; };
  std::vector<Contact> out;
  for (double psi : psis) {
    std::int64_t evaluations = 0;
    // The exact contact at a phase, traced from the two table nodes behind it.
    auto exact = [&](double phase) {
      long k = cell_of(phase) - (sense > 0 ? 0 : -1);
      auto r = run({table_phase(k - static_cast<long>(sense)), table_phase(k), phase}, method);
      for (const auto& c : r) evaluations += c.evaluations;
      return r.back();
    };
    const double start_z = m.start_z.value_or(0);
    const double phase0 = psi + twist * start_z;
    // The next table node from a phase along the travel (or against it).
    auto next_node = [&](double phase, double way) {
      long k = way > 0 ? cell_of(phase) + 1 : cell_of(phase);
      if (way < 0 && table_phase(k) >= phase) --k;
      return k;
    };
    double clear = phase0;
    Contact lo = exact(phase0);
    if (lo.A >= target && m.start_z)
      throw std::runtime_error(fmt::format("psi = {:g} deg: the cutter at centre distance {:g} mm and Z = {:g} mm is not "
                                           "clear of the workpiece (it touches at A = {:.6f} mm): choose another "
                                           "--start-z", psi, target, start_z, lo.A));
    for (long k = next_node(phase0, -sense), n = 0; lo.A >= target; k -= static_cast<long>(sense), ++n) {
      if (n > kCells) throw std::runtime_error(fmt::format("psi = {:g} deg: the cutter is never clear", psi));
      if (table_A(k) < target) clear = table_phase(k), lo = exact(clear);
    }
    // March the table along the travel to the first node at or past the centre distance.
    double a = clear, fa = lo.A - target, b = clear, fb = fa;
    Contact at_b = lo;
    long k = next_node(clear, sense);
    for (int n = 0; n <= kCells + 1 && fb < 0; ++n, k += static_cast<long>(sense)) {
      a = b, fa = fb;
      b = table_phase(k), fb = table_A(k) - target;
    }
    if (fb < 0) throw std::runtime_error(fmt::format("psi = {:g} deg: no touch within a lobe of travel", psi));
    at_b = exact(b);
    fb = at_b.A - target;
    // Illinois on [a, b]: f(a) < 0 <= f(b).
    Contact best = at_b;
    for (int it = 0; it < 60 && std::abs(b - a) > 1e-10 && std::abs(fb) > 1e-10; ++it) {
      double c = b - fb * (b - a) / (fb - fa);
      Contact at_c = exact(c);
      double fc = at_c.A - target;
      if ((fc < 0) == (fb < 0)) {
        fa /= 2;
      } else {
        a = b, fa = fb;
      }
      b = c, fb = fc, best = at_c;
    }
    const double z = start_z + (best.phase - phase0) / twist;
    Contact c = best;
    c.psi = psi;
    c.z = z;
    c.work_point[2] += z;
    c.cutter_point[2] += z;
    c.evaluations = evaluations;
    out.push_back(c);
    if (done) done(out.size());
  }
  return out;
}

}  // namespace ncurve::helicoid
