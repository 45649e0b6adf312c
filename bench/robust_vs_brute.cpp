// The robust search against brute force on seed 004's rotor, on any lattice and phase step:
//   ./build/bench/robust_vs_brute [included_angle=35] [psi_step=1] [lattice_step=0.05]
// prints every phase where the two centre distances differ by more than 1e-9 mm and the mean
// evaluations per step of each. Brute force on the default lattice takes about 0.6 s a step.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "helicoid/contact.hpp"

using namespace ncurve::helicoid;

int main(int argc, char** argv) {
  const double angle = argc > 1 ? std::atof(argv[1]) : 35, step = argc > 2 ? std::atof(argv[2]) : 1;
  const double cell = argc > 3 ? std::atof(argv[3]) : 0.05;
  if (!(angle > 0 && angle < 180) || !(step > 0) || !(cell > 0)) {
    std::fprintf(stderr, "usage: robust_vs_brute [included_angle] [psi_step] [lattice_step]\n");
    return 2;
  }
  Workpiece work{EndProfile::seed004_rotor(), 860, 1, 5};
  ContactSearch cs(work, DiscCutter::v_insert(252, 1.2, angle, 18), Setting{helix_angle(860, 43), 177.7},
                   Lattice{cell, cell, 30});
  std::vector<double> psis;
  for (int i = 0; i * step <= 72 + 1e-9; ++i) psis.push_back(i * step);
  auto robust = cs.run(psis, Method::robust);
  auto brute = cs.run(psis, Method::brute);
  int differ = 0;
  double robust_evaluations = 0, brute_evaluations = 0;
  for (std::size_t i = 0; i < psis.size(); ++i) {
    robust_evaluations += static_cast<double>(robust[i].evaluations);
    brute_evaluations += static_cast<double>(brute[i].evaluations);
    if (std::abs(robust[i].A - brute[i].A) <= 1e-9) continue;
    ++differ;
    std::printf("psi %g: robust A %.9f (%s), brute A %.9f (%s)\n", psis[i], robust[i].A, robust[i].region.c_str(),
                brute[i].A, brute[i].region.c_str());
  }
  const double n = static_cast<double>(psis.size());
  std::printf("%g deg insert, psi step %g, lattice %g: %zu steps, %d differ; evaluations per step: robust %.1f, "
              "brute %.0f\n", angle, step, cell, psis.size(), differ, robust_evaluations / n, brute_evaluations / n);
  return differ == 0 ? 0 : 1;
}
