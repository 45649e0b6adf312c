#include "helicoid/contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "geom/search.hpp"

namespace ncurve::helicoid {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSettled = 1e-7;  // of a lattice cell: a shorter Newton step is not taken
constexpr int kRefineSteps = 12;   // Newton steps of the refinement at most (it usually takes 2 or 3)

EndProfile offset_profile(const EndProfile& base, double distance) {
  auto eval = [base, distance](double u, Vec2& p, Vec2& d) {
    auto at = [&](double v) {
      Vec2 q = base.point(v), n = base.outward_normal(v);
      return Vec2{q.x + distance * n.x, q.y + distance * n.y};
    };
    p = at(u);
    constexpr double h = 1e-5;
    Vec2 a = at(u - h), b = at(u + h);
    d = {(b.x - a.x) / (2 * h), (b.y - a.y) / (2 * h)};
  };
  return EndProfile(base.name() + " offset", eval, base.u0(), base.period(), false);
}

// The lattice rows of each element of the cutter profile (a row on a joint is in both; an element
// shorter than a row may have none: j_hi < j_lo).
std::vector<std::pair<int, int>> element_rows(const DiscCutter& cutter, double s_step, int ns) {
  std::vector<std::pair<int, int>> rows;
  double start = 0;
  for (const auto& e : cutter.elements()) {
    double end = start + e.length();
    rows.emplace_back(static_cast<int>(std::ceil(start / s_step - 1e-9)),
                      std::min(ns, static_cast<int>(std::floor(end / s_step + 1e-9))));
    start = end;
  }
  return rows;
}

}  // namespace

double helix_angle(double lead, double radius) {
  return lead == 0 ? 0 : std::atan(2 * std::numbers::pi * radius / std::abs(lead)) / kDeg;
}

std::int64_t Lattice::size(double profile_length) const {
  // in doubles, held below 2^62: a tiny step must not overflow the conversion
  const double na = std::floor(alpha_max / alpha_step + 1e-9), ns = std::floor(profile_length / s_step + 1e-9);
  const double n = (2 * na + 1) * (ns + 1);
  return n < 4e18 ? static_cast<std::int64_t>(n) : std::int64_t{4'000'000'000'000'000'000};
}

Method method_from_name(const std::string& name) {
  if (name == "brute") return Method::brute;
  if (name == "nine-point") return Method::nine_point;
  if (name == "robust") return Method::robust;
  throw std::runtime_error(fmt::format("unknown method '{}' (brute, nine-point or robust)", name));
}

const char* method_name(Method m) {
  switch (m) {
    case Method::brute: return "brute";
    case Method::nine_point: return "nine-point";
    case Method::robust: return "robust";
  }
  return "?";
}

ContactSearch::ContactSearch(Workpiece work, DiscCutter cutter, Setting setting, Lattice lattice)
    : work_(std::move(work)), cutter_(std::move(cutter)), setting_(setting), lattice_(lattice),
      plane_profile_(work_.profile) {
  if (!(lattice_.alpha_step > 0) || !(lattice_.s_step > 0) || !(lattice_.alpha_max > 0) || lattice_.alpha_max >= 90)
    throw std::runtime_error("lattice: steps > 0 and 0 < alpha range < 90 degrees");
  if (lattice_.size(cutter_.length()) > kMostLatticePoints)
    throw std::runtime_error(fmt::format("lattice: {} points, more than {}: a larger step", lattice_.size(cutter_.length()),
                                         kMostLatticePoints));
  double b = setting_.swing * kDeg, h = work_.hand;
  axis_ = {0, -h * std::cos(b), std::sin(b)};
  e2_ = {0, std::sin(b), h * std::cos(b)};
  na_ = static_cast<int>(std::floor(lattice_.alpha_max / lattice_.alpha_step + 1e-9));
  ns_ = static_cast<int>(std::floor(cutter_.length() / lattice_.s_step + 1e-9));
  if (setting_.start_distance <= 0) setting_.start_distance = work_.profile.r_max() + cutter_.outer_radius() + 1;
  for (const auto& e : cutter_.elements())
    if (e.kind == ProfileElement::Kind::arc && e.region == "corner") corner_radius_ = e.radius;
  plane_profile_ = corner_radius_ > 0 ? offset_profile(work_.profile, corner_radius_) : work_.profile;
}

ContactSearch::Distance ContactSearch::distance(double psi, double alpha, double s) const {
  Distance out;
  auto cp = cutter_.at(s);
  double rho = cp.p.x, w = cp.p.y;
  double ca = std::cos(alpha * kDeg), sa = std::sin(alpha * kDeg);
  double A0 = setting_.start_distance;
  Vec3 radial{-ca, sa * e2_[1], sa * e2_[2]};  // unit, from the cutter axis towards the point
  out.q = {A0 + rho * radial[0] + w * axis_[0], rho * radial[1] + w * axis_[1], rho * radial[2] + w * axis_[2]};
  out.n_cutter = {cp.normal.x * radial[0] + cp.normal.y * axis_[0], cp.normal.x * radial[1] + cp.normal.y * axis_[1],
                  cp.normal.x * radial[2] + cp.normal.y * axis_[2]};
  double twist = work_.twist();
  double phi = psi + twist * out.q[2];
  auto hit = work_.profile.first_hit(phi, out.q[1]);
  if (!hit.found) {
    out.d = kInf;
    return out;
  }
  out.hit = true;
  out.x_hit = hit.x;
  out.u = hit.u;
  out.d = out.q[0] - hit.x;
  // Workpiece normal: dS/du x dS/dz of S(u, z) = (R(phi(z)) p(u), z).
  Vec2 t = work_.profile.d1(hit.u);
  double c = std::cos(phi * kDeg), sn = std::sin(phi * kDeg);
  Vec2 tw{c * t.x - sn * t.y, sn * t.x + c * t.y};
  double k = twist * kDeg;
  Vec3 n{tw.y, -tw.x, k * (tw.x * hit.x + tw.y * out.q[1])};
  if (n[0] * hit.x + n[1] * out.q[1] < 0) n = {-n[0], -n[1], -n[2]};
  double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  out.n_work = {n[0] / len, n[1] / len, n[2] / len};
  // Gradient: x_hit moves by -(n_y dQy + n_z dQz) / n_x when the line moves.
  Vec3 dq_alpha{rho * sa * kDeg, rho * ca * e2_[1] * kDeg, rho * ca * e2_[2] * kDeg};
  Vec3 dradial_rho{radial[0] * cp.tangent.x, radial[1] * cp.tangent.x, radial[2] * cp.tangent.x};
  Vec3 dq_s{dradial_rho[0] + cp.tangent.y * axis_[0], dradial_rho[1] + cp.tangent.y * axis_[1],
            dradial_rho[2] + cp.tangent.y * axis_[2]};
  auto dx_hit = [&](const Vec3& dq) { return -(n[1] * dq[1] + n[2] * dq[2]) / n[0]; };
  out.d_alpha = dq_alpha[0] - dx_hit(dq_alpha);
  out.d_s = dq_s[0] - dx_hit(dq_s);
  return out;
}

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

double ContactSearch::plane_distance(double psi) const {
  auto hit = plane_profile_.first_hit(psi, 0);
  if (!hit.found) return std::numeric_limits<double>::quiet_NaN();
  return hit.x + cutter_.outer_radius() - corner_radius_;
}

double ContactSearch::edge_normal_angle(const DiscCutter::Vertex& v, double alpha, const Vec3& n_work) const {
  // The workpiece's inward normal in the frame of the cutter's meridian at alpha: radial, axial
  // (the plane of the profile) and the rest (along the circle).
  const double ca = std::cos(alpha * kDeg), sa = std::sin(alpha * kDeg);
  const Vec3 radial{-ca, sa * e2_[1], sa * e2_[2]}, p{-n_work[0], -n_work[1], -n_work[2]};
  const Vec2 q{p[0] * radial[0] + p[1] * radial[1] + p[2] * radial[2], p[0] * axis_[0] + p[1] * axis_[1] + p[2] * axis_[2]};
  auto turn = [](Vec2 a, Vec2 b) { return std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y); };
  // The nearest normal of the fan from `before` to `after` (turning left): q's own direction
  // within it, else the nearer end.
  Vec2 u = v.before;
  const double sweep = turn(v.before, v.after), at = turn(v.before, q);
  if (std::hypot(q.x, q.y) > 0 && at >= 0 && at <= sweep) {
    const double len = std::hypot(q.x, q.y);
    u = {q.x / len, q.y / len};
  } else if (q.x * v.after.x + q.y * v.after.y > q.x * v.before.x + q.y * v.before.y) {
    u = v.after;
  }
  const double dot = p[0] * (u.x * radial[0] + u.y * axis_[0]) + p[1] * (u.x * radial[1] + u.y * axis_[1]) +
                     p[2] * (u.x * radial[2] + u.y * axis_[2]);
  return std::acos(std::clamp(dot, -1.0, 1.0)) / kDeg;
}

// One phase's search on the lattice: cached evaluations, the nine-point walk, refinement.
class StepSearch {
public:
  StepSearch(const ContactSearch& cs, double psi) : cs_(cs), psi_(psi) {}

  struct Node {
    int i = 0, j = 0;
  };
  // The walk stays within rows j_lo..j_hi (one element of the cutter profile, or all of it).
  void restrict_rows(int j_lo, int j_hi) { j_lo_ = j_lo, j_hi_ = j_hi; }
  bool inside(Node n) const { return n.i >= -cs_.na_ && n.i <= cs_.na_ && n.j >= j_lo_ && n.j <= j_hi_; }
  Node clamp(Node n) const { return {std::clamp(n.i, -cs_.na_, cs_.na_), std::clamp(n.j, j_lo_, j_hi_)}; }
  double alpha(Node n) const { return n.i * cs_.lattice_.alpha_step; }
  double s(Node n) const { return n.j * cs_.lattice_.s_step; }

  double value(Node n) {
    std::int64_t key = (static_cast<std::int64_t>(n.i) << 32) ^ static_cast<std::uint32_t>(n.j);
    auto [it, fresh] = cache_.try_emplace(key, 0.0);
    if (fresh) {
      ++evaluations_;
      it->second = cs_.distance(psi_, alpha(n), s(n)).d;
    }
    return it->second;
  }

  // Seed 004's nine-point search from `start` with lattice stride `stride`: move the 3x3 stencil
  // to its smallest value until the centre is smallest. Equal values (within `tie`) move to the
  // mean of their rows and columns. With `protect`, a centre seen before ends the walk.
  Node walk(Node start, int stride, double tie, bool protect, int max_moves = 100000) {
    Node c = clamp(start);
    std::vector<std::int64_t> seen;
    for (int move = 0; move < max_moves; ++move) {
      double best = kInf;
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          Node n{c.i + di * stride, c.j + dj * stride};
          if (inside(n)) best = std::min(best, value(n));
        }
      if (!std::isfinite(best)) return c;
      double centre = value(c);
      if (centre <= best + tie) return c;
      int rows = 0, cols = 0, count = 0;
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          Node n{c.i + di * stride, c.j + dj * stride};
          if (inside(n) && value(n) <= best + tie) rows += di + 1, cols += dj + 1, ++count;
        }
      auto pick = [count](int sum) { return sum > count ? 1 : (sum == count ? 0 : -1); };  // mean >1, =1, <1
      Node next{c.i + pick(rows) * stride, c.j + pick(cols) * stride};
      if (next.i == c.i && next.j == c.j) return c;
      if (protect) {
        std::int64_t key = (static_cast<std::int64_t>(next.i) << 32) ^ static_cast<std::uint32_t>(next.j);
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) return c;
        seen.push_back(key);
      }
      c = next;
    }
    return c;
  }

  // Coarse to fine: the walk at strides 2^k .. 1.
  Node descend(Node start, int top_stride, double tie) {
    Node c = start;
    for (int stride = top_stride; stride >= 1; stride /= 2) c = walk(c, stride, tie, true);
    return c;
  }

  // The smallest value of the quadratic through the stencil of stride `stride` centred on c
  // (each axis separately): what the lattice minimum underestimates by coarseness.
  double fitted_minimum(Node c, int stride) {
    double f0 = value(c), drop = 0;
    for (int axis = 0; axis < 2; ++axis) {
      Node a = axis ? Node{c.i, c.j - stride} : Node{c.i - stride, c.j};
      Node b = axis ? Node{c.i, c.j + stride} : Node{c.i + stride, c.j};
      if (!inside(a) || !inside(b)) continue;
      double fa = value(a), fb = value(b), curv = fa - 2 * f0 + fb;
      if (curv > 0 && std::isfinite(curv)) drop += (fb - fa) * (fb - fa) / (8 * curv);
    }
    return f0 - drop;
  }

  // The lattice minimum refined off the lattice: Newton on the exact gradient, each step kept only
  // if the distance falls. The model's Hessian starts as the 3x3 stencil's and is corrected after
  // every step by the secant (BFGS) update from the exact gradients at the step's ends. The
  // stencil is a cell wide: where it straddles the joint of two elements of the cutter profile
  // (the corner and a flank meet tangent, but with different curvatures) it averages their
  // curvatures, and Newton with it alone only creeps towards a contact near the joint (by a
  // factor 0.63 a step at seed 004's 70 deg insert, psi = 20 deg, still 1e-4 off after 12
  // steps: a normal angle of 0.002 deg). The secant update learns the curvature where the
  // contact is, and Newton converges in a few steps.
  struct Refined {
    double alpha, s, d;
    ContactSearch::Distance at;
  };
  Refined refine(Node c) {
    restrict_rows(0, cs_.ns_);
    const double ha = cs_.lattice_.alpha_step, hs = cs_.lattice_.s_step;
    auto v = [&](int di, int dj) {
      Node n = clamp({c.i + di, c.j + dj});
      return value(n);
    };
    double f0 = v(0, 0);
    double haa = (v(1, 0) - 2 * f0 + v(-1, 0)) / (ha * ha);
    double hss = (v(0, 1) - 2 * f0 + v(0, -1)) / (hs * hs);
    double has = (v(1, 1) - v(1, -1) - v(-1, 1) + v(-1, -1)) / (4 * ha * hs);
    double a = alpha(c), s = this->s(c);
    auto at = eval(a, s);
    double det = haa * hss - has * has;
    bool newton = std::isfinite(det) && det > 0 && haa > 0;
    if (!newton && std::isfinite(det)) {  // a saddle or a ridge in the stencil (a shoulder): BFGS from its diagonal
      const double floor = 1e-3 * std::max({std::abs(haa) * ha * ha, std::abs(hss) * hs * hs, 1e-12});
      haa = std::max(std::abs(haa), floor / (ha * ha)), hss = std::max(std::abs(hss), floor / (hs * hs)), has = 0;
      det = haa * hss;
      newton = true;
    }
    for (int it = 0; it < kRefineSteps && at.hit; ++it) {
      double da, ds;
      if (newton) {
        da = -(hss * at.d_alpha - has * at.d_s) / det;
        ds = -(-has * at.d_alpha + haa * at.d_s) / det;
      } else {  // steepest descent scaled to a cell
        double g = std::hypot(at.d_alpha * ha, at.d_s * hs);
        if (g == 0) break;
        da = -at.d_alpha * ha * ha / g;
        ds = -at.d_s * hs * hs / g;
      }
      da = std::clamp(da, -2 * ha, 2 * ha);
      ds = std::clamp(ds, -2 * hs, 2 * hs);
      // Settled: a Newton step this short moves the contact by less than the noise of d shows.
      if (newton && std::abs(da) < kSettled * ha && std::abs(ds) < kSettled * hs) break;
      bool improved = false;
      const std::array<double, 3> h_prev{haa, hss, has};
      for (int half = 0; half < 6; ++half) {
        double na = std::clamp(a + da, -cs_.na_ * ha, cs_.na_ * ha);
        double ns = std::clamp(s + ds, 0.0, cs_.cutter_.length());
        auto trial = eval(na, ns);
        if (trial.d <= at.d) {
          improved = std::abs(na - a) > 1e-11 || std::abs(ns - s) > 1e-11;
          if (newton && trial.hit) {  // BFGS: the model takes the curvature the step met
            const double sa = na - a, ss = ns - s, ya = trial.d_alpha - at.d_alpha, ys = trial.d_s - at.d_s;
            const double ba = haa * sa + has * ss, bs = has * sa + hss * ss;
            const double sy = sa * ya + ss * ys, sbs = sa * ba + ss * bs;
            if (sy > 0 && sbs > 0 && std::isfinite(sy + sbs)) {
              haa += ya * ya / sy - ba * ba / sbs;
              hss += ys * ys / sy - bs * bs / sbs;
              has += ya * ys / sy - ba * bs / sbs;
              const double next_det = haa * hss - has * has;
              if (next_det > 0 && haa > 0 && std::isfinite(next_det)) det = next_det;
              else haa = h_prev[0], hss = h_prev[1], has = h_prev[2];  // rounding: keep the last model
            }
          }
          a = na, s = ns, at = trial;
          break;
        }
        da /= 2, ds /= 2;
      }
      if (!improved || (std::abs(da) < 1e-9 * ha && std::abs(ds) < 1e-9 * hs)) break;
    }
    // On an edge of the cutter (a convex joint without a common tangent) the distance has a kink
    // across the joint, over which Newton only hops from side to side: near one, the smallest
    // distance along the edge itself is taken where it is lower.
    for (const auto& v : cs_.cutter_.vertices()) {
      if (std::abs(s - v.s) > 2 * hs && std::abs(this->s(c) - v.s) > 2 * hs) continue;
      auto edge = edge_minimum(v.s, a);
      if (edge.at.hit && edge.d <= at.d) a = edge.alpha, s = edge.s, at = edge.at;
    }
    return {a, s, at.d, at};
  }

  // The smallest distance along the circle of the cutter at arc length sv: Newton on the exact
  // d_alpha from a0, its curvature from secants, each step kept only if the distance falls.
  Refined edge_minimum(double sv, double a0) {
    const double ha = cs_.lattice_.alpha_step, limit = cs_.na_ * ha;
    double a = std::clamp(a0, -limit, limit), curvature = 0;
    auto at = eval(a, sv);
    for (int it = 0; it < 2 * kRefineSteps && at.hit; ++it) {
      if (!(curvature > 0)) {
        const double b = a + ha <= limit ? a + ha : a - ha;
        auto there = eval(b, sv);
        curvature = there.hit ? (there.d_alpha - at.d_alpha) / (b - a) : 0;
        if (!(curvature > 0 && std::isfinite(curvature))) break;
        if (there.d < at.d) a = b, at = there;
      }
      double delta = std::clamp(-at.d_alpha / curvature, -2 * ha, 2 * ha);
      if (std::abs(delta) < kSettled * ha) break;
      bool fell = false;
      for (int half = 0; half < 6 && !fell; ++half, delta /= 2) {
        const double next = std::clamp(a + delta, -limit, limit);
        if (next == a) break;
        auto there = eval(next, sv);
        if (!there.hit || there.d > at.d) continue;
        const double c = (there.d_alpha - at.d_alpha) / (next - a);
        if (c > 0 && std::isfinite(c)) curvature = c;
        a = next, at = there, fell = true;
      }
      if (!fell) break;
    }
    return {a, sv, at.d, at};
  }

  ContactSearch::Distance eval(double a, double s) {
    ++evaluations_;
    return cs_.distance(psi_, a, s);
  }

  // A distance no point of the lattice node can be below: the hit lies within the profile's
  // largest radius, so x_hit <= sqrt(r_max^2 - y^2). +inf where the line misses that circle.
  double lower_bound(Node n) const {
    const double rmax = cs_.work_.profile.r_max();
    const double a = alpha(n) * kDeg;
    auto cp = cs_.cutter_.at(s(n));
    double qx = cs_.setting_.start_distance - cp.p.x * std::cos(a);
    double qy = cp.p.x * std::sin(a) * cs_.e2_[1] + cp.p.y * cs_.axis_[1];
    if (std::abs(qy) >= rmax) return kInf;
    return qx - std::sqrt(rmax * rmax - qy * qy);
  }

  // Every lattice point, skipping those whose bound is not below the best so far by `reach`; the
  // row alpha = 0 first, for a good best early. Returns the lowest point of each element's rows
  // (`rows`, as RobustTraces has them) that is within `reach` of the best (else {0, -1}), its
  // value cached: where two elements touch almost at once, each is refined (ContactSearch::run).
  std::vector<Node> brute(const std::vector<std::pair<int, int>>& rows, double reach) {
    std::vector<Node> best(rows.size(), Node{0, -1});
    std::vector<double> best_d(rows.size(), kInf);
    double lowest = kInf;
    auto consider = [&](Node n) {
      if (lower_bound(n) >= lowest + reach) return;
      ++evaluations_;
      double d = cs_.distance(psi_, alpha(n), s(n)).d;
      lowest = std::min(lowest, d);
      for (std::size_t k = 0; k < rows.size(); ++k)
        if (n.j >= rows[k].first && n.j <= rows[k].second) {
          if (d < best_d[k]) best_d[k] = d, best[k] = n;
          break;
        }
    };
    for (int j = 0; j <= cs_.ns_; ++j) consider({0, j});
    for (int i = -cs_.na_; i <= cs_.na_; ++i)
      if (i != 0)
        for (int j = 0; j <= cs_.ns_; ++j) consider({i, j});
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (!(best_d[k] <= lowest + reach)) {
        best[k] = {0, -1};
        continue;
      }
      std::int64_t key = (static_cast<std::int64_t>(best[k].i) << 32) ^ static_cast<std::uint32_t>(best[k].j);
      cache_.try_emplace(key, best_d[k]);
    }
    return best;
  }

  std::int64_t evaluations() const { return evaluations_; }

private:
  const ContactSearch& cs_;
  double psi_;
  int j_lo_ = 0, j_hi_ = cs_.ns_;
  std::unordered_map<std::int64_t, double> cache_;
  std::int64_t evaluations_ = 0;
};

namespace {

using Node = StepSearch::Node;

// Tracing prediction: the line through the two previous contacts.
Node predicted(const std::vector<Node>& path, Node first) {
  if (path.empty()) return first;
  if (path.size() == 1) return path.back();
  const auto& a = path[path.size() - 2];
  const auto& b = path.back();
  return {2 * b.i - a.i, 2 * b.j - a.j};
}

constexpr double kTie = 1e-9;  // mm: well above the evaluation noise (~1e-12), far below any real step
constexpr double kNearTie = 0.05;  // mm: brute force keeps each element's lowest point this close to the best

// The robust search's traces, carried from step to step.
//
// Per element of the cutter profile (corner, each flank) a fine trace of the smallest distance
// within its rows, walked from the tracing prediction.
//
// And a watch of the whole profile, for contacts that rise apart from the traced ones: rows
// about kWatchSpacing apart and the rows at the joints of the elements, each with its smallest
// distance over alpha, m(s), and the slope of that along the profile, m'(s) = d_s there. A
// contact is a basin of m; a new one is born where the slope, rising away from the contact,
// flattens to 0 beyond a ridge (seed 004's rotor with a 70 deg insert: 3 mm up a flank at
// psi = 13 deg, the contact two degrees later), or rises at a joint (the corner's, when the
// contact comes back from a flank). A basin close to the best is descended to the fine lattice
// and given to the element holding it.
//
// A trace or watched row well above the best is left alone for as long as its gap to the best
// could not close at twice the fastest rate the gap has changed lately, per degree of psi (the
// fastest so far, fading by a factor a degree: a rate seen at the crest says little about the
// flank ten degrees on). A watched row also allows for the fastest rate of any row and of the
// best rising, lately: a row asleep for long has no rate of its own to go by.
class RobustTraces {
public:
  explicit RobustTraces(const ContactSearch& cs)
      : ns_(cs.s_cells()), na_(cs.alpha_cells()), alpha_step_(cs.lattice().alpha_step), s_step_(cs.lattice().s_step) {
    std::vector<int> rows;
    for (const auto& [j_lo, j_hi] : element_rows(cs.cutter(), s_step_, ns_))
      if (j_hi >= j_lo) {
        fine_.emplace_back(j_lo, j_hi, Node{0, (j_lo + j_hi) / 2});
        rows.push_back(j_lo), rows.push_back(j_hi);
      }
    window_ = std::max(1, static_cast<int>(std::lround(kWatchSpacing / s_step_)));
    for (int j = 0; j < ns_; j += window_) rows.push_back(j);
    rows.push_back(ns_);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (int j : rows) watch_.push_back(Watch{j});
    for (auto& f : fine_)  // a trace resting on its shoulder sleeps while the watch sees inside its rows
      for (const auto& w : watch_) f.guarded = f.guarded || (w.j > f.j_lo && w.j < f.j_hi);
  }

  // The lattice contact of this step, at phase psi.
  Node next(StepSearch& step, int step_index, double psi) {
    step_ = travel_ > 0 || step_index > 0 ? std::abs(psi - psi_) : 0;
    travel_ += step_;
    psi_ = psi;
    step_index_ = step_index;
    // The trace that held the contact last time first, then the others that are due.
    std::size_t lead = 0;
    for (std::size_t k = 0; k < fine_.size(); ++k)
      if (fine_[k].gap < fine_[lead].gap) lead = k;
    best_ = kInf;
    value_.assign(fine_.size(), kInf);
    node_of_.assign(fine_.size(), Node{0, -1});
    for (std::size_t k = 0; k < fine_.size(); ++k) {
      std::size_t at = (lead + k) % fine_.size();
      if (at != lead && !fine_[at].due(travel_)) continue;
      Node n = advance(fine_[at], step);
      offer(at, n, step.value(n));
      if (on_shoulder(fine_[at], n)) {
        if (at == lead)
          for (auto& f : fine_) f.asleep = false, f.wake = 0;
        else if (fine_[at].guarded)
          fine_[at].asleep = true;
      }
    }
    for (std::size_t k = 0; k < fine_.size(); ++k)  // the element holding the best
      if (node_of_[k].j == node_.j && node_of_[k].i == node_.i && value_[k] == best_) lead_ = k;
    watch(step);
    for (std::size_t k = 0; k < fine_.size(); ++k)
      if (std::isfinite(value_[k]) && !fine_[k].asleep) fine_[k].schedule(value_[k], best_, travel_, step_, 0);
    // The fastest rate lately of a watched row's gap, or of the best rising.
    const double fade = std::pow(kRateFade, step_);
    double fastest = watch_rate_ * fade;
    if (std::isfinite(last_best_) && step_ > 0) fastest = std::max(fastest, (best_ - last_best_) / step_);
    for (auto& w : watch_)
      if (w.measured == step_index) fastest = std::max(fastest, w.schedule(w.m, best_, travel_, step_, watch_rate_ * fade));
    watch_rate_ = fastest;
    last_best_ = best_;
    return node_;
  }

  // This step's lowest lattice point of each element searched (else {0, -1}).
  const std::vector<Node>& element_minima() const { return node_of_; }

private:
  static constexpr double kWatchSpacing = 1.2;  // mm between watched rows
  static constexpr double kRateFade = 0.7;      // per degree of psi
  static constexpr double kRateFloor = 0.01;    // mm per degree
  // A basin of the watch this close above the best is descended: the parabola's error, and
  // the lattice's (the best is a lattice value, the watch's off the lattice below it).
  static constexpr double kWatchMargin = 0.02;
  static constexpr double kAlphaReach = 2;  // deg: the longest Newton step on a watched row
  static constexpr double kRowAccuracy = 1e-2;  // of a watched row's gap: its smallest distance's accuracy

  struct Schedule {
    double gap = kInf, gap_rate = 0;  // mm, mm per degree of psi
    double updated = -1;              // travel of psi at the last update (< 0: none)
    double wake = 0;                  // travel from which it is due
    bool asleep = false;              // until woken
    // Returns the rate the gap changed at since the last update (0 without one).
    double schedule(double value, double best, double travel, double step, double floor_rate) {
      const double g = value - best;
      const bool known = updated >= 0 && std::isfinite(gap) && std::isfinite(g);  // a rate needs two updates
      double seen = 0;
      if (known && travel > updated) {
        const double span = travel - updated;
        seen = std::abs(g - gap) / span;
        gap_rate = std::max(gap_rate * std::pow(kRateFade, span), seen);
      }
      gap = g;
      updated = travel;
      const double rate = std::max({gap_rate, floor_rate, kRateFloor});
      // Checked at the first step from `wake`: a step early, so never later than the gap could close.
      wake = known ? travel + g / (2 * rate) - step : travel;
      return seen;
    }
    bool due(double travel) const { return !asleep && travel >= wake; }
  };

  struct Trace : Schedule {
    Trace(int lo, int hi, Node start) : j_lo(lo), j_hi(hi), first(start) {}
    int j_lo, j_hi;
    Node first;
    std::vector<Node> path;
    bool guarded = false;  // the watch sees rows inside it
    bool due(double travel) {
      if (Schedule::due(travel)) return true;
      if (!path.empty()) path = {path.back()};  // a stale line no longer predicts
      return false;
    }
  };

  // A watched row: its smallest distance over alpha (off the lattice), and the slope along s.
  struct Watch : Schedule {
    explicit Watch(int row) : j(row) {}
    int j;
    double alpha = 0, alpha_before = 0;  // the minimum's alpha at the last two measurements
    double at = -1, at_before = -1;      // their travel of psi
    int measured = -1;                   // step of the last measurement
    double curvature = 0;                // d2 d / d alpha2 at the minimum, per deg^2 (0: unknown)
    double m = kInf, slope = 0;
  };

  void offer(std::size_t k, Node n, double v) {
    if (v < value_[k]) value_[k] = v, node_of_[k] = n;
    if (v < best_) best_ = v, node_ = n;
  }

  Node advance(Trace& t, StepSearch& step) {
    step.restrict_rows(t.j_lo, t.j_hi);
    Node n = t.path.empty() ? step.descend(t.first, 64, kTie) : step.walk(predicted(t.path, t.first), 1, kTie, true);
    t.path.push_back(n);
    return n;
  }

  // A fine trace resting on a row it shares with a neighbour element is that neighbour's
  // shoulder, not a contact of its own: it sleeps until the watch wakes it.
  bool on_shoulder(const Trace& t, Node n) const {
    return (n.j == t.j_lo && t.j_lo > 0) || (n.j == t.j_hi && t.j_hi < ns_);
  }

  // The smallest distance on a watched row, off the lattice: Newton on the exact d_alpha from the
  // alpha its last two measurements predict (or, the first time, its neighbour's), with the
  // curvature the secants give, each step kept only if the distance falls; it stops when the
  // next step would lower the distance by less than the row needs (a row far above the best
  // needs less). Where Newton fails the row's lattice walk starts it again.
  void measure(Watch& w, StepSearch& step, double guess, double guess_curvature) {
    const double ha = alpha_step_, limit = na_ * ha, s = w.j * s_step_;
    auto clamp = [&](double a) { return std::clamp(a, -limit, limit); };
    double a = guess;
    if (w.measured >= 0) {
      a = w.alpha;
      if (w.at_before >= 0 && w.at > w.at_before) {  // moved on as between the last two, as far at most
        const double span = w.at - w.at_before;
        a += (w.alpha - w.alpha_before) * std::min(travel_ - w.at, span) / span;
      }
    } else {
      w.curvature = guess_curvature;
    }
    double enough = kTie;
    auto newton = [&](ContactSearch::Distance& at) {  // false: no way down found
      // the gap known, else as it looks from here
      const double gap = std::isfinite(w.gap) ? w.gap : at.d - best_;
      enough = std::isfinite(gap) ? std::max(kTie, kRowAccuracy * gap) : kTie;
      for (int it = 0; it < 8; ++it) {
        if (!(w.curvature > 0)) {  // a secant over a cell
          double b = a + ha <= limit ? a + ha : a - ha;
          auto there = step.eval(b, s);
          double c = there.hit ? (there.d_alpha - at.d_alpha) / (b - a) : 0;
          if (!(c > 0 && std::isfinite(c))) return false;
          w.curvature = c;
          if (there.d < at.d) a = b, at = there;
        }
        double delta = -at.d_alpha / w.curvature;
        if (w.curvature * delta * delta / 2 < enough) return true;
        delta = std::clamp(delta, -kAlphaReach, kAlphaReach);
        bool fell = false;
        for (int half = 0; half < 4 && !fell; ++half, delta /= 2) {
          double next = clamp(a + delta);
          if (next == a) return true;  // at the end of the range
          auto there = step.eval(next, s);
          if (!there.hit || there.d > at.d) continue;
          double c = (there.d_alpha - at.d_alpha) / (next - a);
          if (c > 0 && std::isfinite(c)) w.curvature = c;
          a = next, at = there, fell = true;
        }
        if (!fell) return false;
      }
      return true;
    };
    a = clamp(a);
    auto at = step.eval(a, s);
    if (!at.hit || !newton(at)) {
      step.restrict_rows(w.j, w.j);
      Node n = step.descend({static_cast<int>(std::lround(a / ha)), w.j}, 16, kTie);
      w.curvature = 0;
      a = step.alpha(n);
      at = step.eval(a, s);
      if (at.hit) newton(at);
    }
    w.alpha_before = w.alpha, w.at_before = w.at;
    w.alpha = a, w.at = travel_, w.measured = step_index_;
    w.m = at.hit ? at.d : kInf;
    w.slope = at.hit ? at.d_s : 0;
  }

  // Rows near the contact within its element are its trace's own basin (its joints aside: a
  // neighbour's basin can lie just across one). A contact on a shoulder is the neighbour's
  // basin, and its element may hold a basin of its own nearby.
  bool near_lead(int j, int pad) const {
    const auto& f = fine_[lead_];
    return !on_shoulder(f, node_) && std::abs(j - node_.j) <= pad && j > f.j_lo && j < f.j_hi;
  }

  void watch(StepSearch& step) {
    // Rows due, measured outwards from the contact (the first time each starts from its
    // inner neighbour's alpha).
    std::size_t centre = 0;
    for (std::size_t k = 0; k < watch_.size(); ++k)
      if (std::abs(watch_[k].j - node_.j) < std::abs(watch_[centre].j - node_.j)) centre = k;
    auto visit = [&](std::size_t k, const Watch& inner) {
      Watch& w = watch_[k];
      if (w.measured >= 0 && near_lead(w.j, window_ - 1)) {
        w.wake = 0;  // due once the contact moves on
      } else if (w.measured < 0 || w.due(travel_)) {
        measure(w, step, inner.alpha, inner.curvature);
      }
      return std::cref(w);
    };
    Watch start{node_.j};
    start.alpha = step.alpha(node_);
    auto inner = visit(centre, start);
    for (std::size_t k = centre + 1; k < watch_.size(); ++k) inner = visit(k, inner);
    inner = std::cref(watch_[centre]);
    for (std::size_t k = centre; k-- > 0;) inner = visit(k, inner);
    // Basins of m: a slope changing sign from - to + between two rows, or an end of the profile
    // the slope rises from; their lowest value by the parabola of the two slopes. The basin
    // around the contact is its trace's; another close to the best has its rows measured again
    // if they are stale, and if it still is, it is descended.
    struct Basin {
      double low = kInf;
      std::size_t from = 0, lo = 0, hi = 0;  // the lower row, and the rows either side
    };
    auto basin = [&](std::size_t k) {
      Basin out;
      const Watch& w = watch_[k];
      if (!std::isfinite(w.m)) return out;
      if (k + 1 < watch_.size() && w.slope < 0 && watch_[k + 1].slope >= 0 && std::isfinite(watch_[k + 1].m)) {
        const Watch& v = watch_[k + 1];
        double h = (v.j - w.j) * s_step_, curv = (v.slope - w.slope) / h;
        out = {std::min(w.m - w.slope * w.slope / (2 * curv), v.m - v.slope * v.slope / (2 * curv)),
               v.m < w.m ? k + 1 : k, k, k + 1};
      } else if (k == 0 && w.slope >= 0) {
        out = {w.m, k, k, std::min(k + 1, watch_.size() - 1)};
      } else if (k + 1 == watch_.size() && w.slope <= 0) {
        out = {w.m, k, k == 0 ? k : k - 1, k};
      }
      return out;
    };
    for (std::size_t k = 0; k < watch_.size(); ++k) {
      Basin b = basin(k);
      if (!(b.low <= best_ + kWatchMargin)) continue;
      if (near_lead(watch_[b.from].j, window_) &&
          (near_lead(watch_[b.lo].j, window_) || near_lead(watch_[b.hi].j, window_) ||
           (node_.j >= watch_[b.lo].j && node_.j <= watch_[b.hi].j)))
        continue;
      bool stale = false;
      for (std::size_t r = b.lo; r <= b.hi; ++r)
        if (watch_[r].measured != step_index_) {
          measure(watch_[r], step, watch_[r].alpha, watch_[r].curvature);
          stale = true;
        }
      if (stale) b = basin(k);
      if (!(b.low <= best_ + kWatchMargin)) continue;
      // Descended over the whole profile (the basin may lie across a joint), then given to the
      // element holding its lowest point.
      const Watch& from = watch_[b.from];
      step.restrict_rows(0, ns_);
      Node m = step.descend({static_cast<int>(std::lround(from.alpha / alpha_step_)), from.j},
                            std::max(1, window_ / 2), kTie);
      for (std::size_t e = 0; e < fine_.size(); ++e) {
        auto& f = fine_[e];
        if (m.j < f.j_lo || m.j > f.j_hi) continue;
        if (step.value(m) < value_[e]) f.path = {m}, f.asleep = false, f.wake = 0;
        offer(e, m, step.value(m));
        break;
      }
    }
  }

  int ns_, na_;
  double alpha_step_, s_step_;
  std::vector<Trace> fine_;
  std::vector<Watch> watch_;
  int window_ = 1;  // rows in kWatchSpacing
  // Travel of psi so far (degrees, either way), this step's, its phase and index.
  double travel_ = 0, step_ = 0, psi_ = 0;
  int step_index_ = 0;
  double watch_rate_ = 0, last_best_ = kInf;
  // This step's best so far, its node, the trace that led, and each fine trace's value and node.
  double best_ = kInf;
  Node node_;
  std::size_t lead_ = 0;
  std::vector<double> value_;
  std::vector<Node> node_of_;
};

}  // namespace

std::vector<Contact> ContactSearch::run(const std::vector<double>& psis, Method method, const StepDone& done) const {
  std::vector<Contact> out;
  std::vector<Node> path;  // lattice contacts so far
  const Node corner{0, static_cast<int>(std::lround(cutter_.corner_middle() / lattice_.s_step))};
  RobustTraces traces(*this);
  const auto rows = element_rows(cutter_, lattice_.s_step, ns_);
  for (std::size_t step_index = 0; step_index < psis.size(); ++step_index) {
    const double psi = psis[step_index];
    StepSearch step(*this, psi);
    Node node;
    std::vector<Node> minima;  // each element's lowest lattice point (j < 0: none)
    switch (method) {
      case Method::brute:
        minima = step.brute(rows, kNearTie);
        node = minima.front();
        for (const auto& m : minima)
          if (m.j >= 0 && (node.j < 0 || step.value(m) < step.value(node))) node = m;
        break;
      case Method::nine_point: node = step.walk(predicted(path, corner), 1, 0.0, false); break;
      case Method::robust:
        node = traces.next(step, static_cast<int>(step_index), psi);
        minima = traces.element_minima();
        break;
    }
    path.push_back(node);
    auto refined = step.refine(node);
    // Where the contact jumps between elements, two of them touch almost at once, and the lattice
    // can rank them otherwise than they are: each whose lattice value, less twice the lattice's
    // coarseness there, is below the refined contact is refined too, and the lower one is it.
    for (const auto& m : minima) {
      if (m.j < 0 || (m.i == node.i && m.j == node.j)) continue;
      step.restrict_rows(0, ns_);
      const double v = step.value(m), low = v - 2 * (v - step.fitted_minimum(m, 1)) - 1e-9;
      if (!(low < refined.d)) continue;
      auto other = step.refine(m);
      if (other.d < refined.d) refined = other;
    }
    const auto& at = refined.at;
    Contact c;
    c.psi = psi;
    c.phase = psi;
    c.A = setting_.start_distance - refined.d;
    c.alpha = refined.alpha;
    c.s = refined.s;
    c.region = cutter_.region(refined.s);
    c.cutter_point = {at.q[0] - refined.d, at.q[1], at.q[2]};
    c.work_point = {at.x_hit, at.q[1], at.q[2]};
    c.u = at.u;
    c.r = std::hypot(at.x_hit, at.q[1]);
    double dot = -(at.n_cutter[0] * at.n_work[0] + at.n_cutter[1] * at.n_work[1] + at.n_cutter[2] * at.n_work[2]);
    c.normal_angle = std::acos(std::clamp(dot, -1.0, 1.0)) / kDeg;
    for (const auto& v : cutter_.vertices())
      if (refined.s == v.s) {  // on an edge: named by the elements meeting there
        c.normal_angle = edge_normal_angle(v, refined.alpha, at.n_work);
        c.region = cutter_.elements()[v.element - 1].region + "/" + cutter_.elements()[v.element].region;
      }
    c.evaluations = step.evaluations();
    c.plane_A = plane_distance(psi);
    out.push_back(c);
    if (done) done(out.size());
  }
  return out;
}

double ContactSearch::stock(const Contact& pass, double u) const {
  const Vec2 p = work_.profile.point(u);
  const double twist = work_.twist();
  // Smallest over the helix of the distance to the cutter surface: the largest of its negative.
  auto closeness = [&](double z) {
    double phi = (pass.phase + twist * z) * kDeg;
    double c = std::cos(phi), s = std::sin(phi);
    Vec3 rel{c * p.x - s * p.y - pass.A, s * p.x + c * p.y, z};
    double w = rel[0] * axis_[0] + rel[1] * axis_[1] + rel[2] * axis_[2];
    double rho = std::sqrt(std::max(0.0, rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2] - w * w));
    return -cutter_.signed_distance({rho, w});
  };
  // The helix passes the disc within its radius of the contact's height; 64 samples there, then
  // to 1e-5 mm in z (the distance is flat at its minimum: the error is far below 1e-9 mm).
  const double reach = cutter_.outer_radius(), z0 = pass.work_point[2] - pass.z;
  return -geom::sampled_maximum(closeness, z0 - reach, z0 + reach, 64, 1e-5).value;
}

ContactSearch::Cusp ContactSearch::cusp(const Contact& a, const Contact& b) const {
  const double du = std::remainder(b.u - a.u, work_.profile.period());
  if (std::abs(du) < 1e-9) return {std::max(0.0, std::min(stock(a, a.u), stock(b, a.u))), a.u};
  auto left = [&](double t) {
    double u = a.u + t * du;
    return std::min(stock(a, u), stock(b, u));
  };
  auto top = geom::sampled_maximum(left, 0.0, 1.0, 8);
  return {top.value, a.u + top.at * du};
}

ContactSearch::PassPlan ContactSearch::fewest_passes(const std::vector<Contact>& contacts, double tol) const {
  PassPlan plan;
  if (contacts.empty()) return plan;
  if (!(tol > 0)) throw std::runtime_error("pass tolerance must be > 0 mm");
  std::size_t at = 0;
  plan.passes.push_back(0);
  while (at + 1 < contacts.size()) {
    Cusp reach = cusp(contacts[at], contacts[at + 1]);
    if (reach.height > tol)
      throw std::runtime_error(fmt::format(
          "psi = {:g} and {:g} deg: neighbouring passes leave a cusp of {:.6f} mm (at u = {:.3f} deg), above the "
          "tolerance {:g} mm: make the psi step smaller", contacts[at].psi, contacts[at + 1].psi, reach.height, reach.u, tol));
    std::size_t next = at + 1;
    while (next + 1 < contacts.size()) {
      Cusp c = cusp(contacts[at], contacts[next + 1]);
      if (c.height > tol) break;
      reach = c, ++next;
    }
    plan.passes.push_back(next);
    plan.cusps.push_back(reach);
    at = next;
  }
  return plan;
}

double ContactSearch::deepest_penetration(double psi, double A, std::int64_t* evaluations) const {
  // Scan every 8th lattice point (skipping those the largest-radius bound clears), then descend
  // from the lowest few, apart from each other, to the continuous minimum.
  constexpr int kStride = 8;
  const double contact = setting_.start_distance - A;
  StepSearch step(*this, psi);
  struct Low {
    StepSearch::Node n;
    double d;
  };
  std::vector<Low> low;
  // every 8th row, and the rows either side of each edge (there the distance rises steeply both
  // ways: 8 rows off, a sharp tip is farther than any start is looked for)
  std::vector<int> rows;
  for (int j = 0; j <= ns_; j += kStride) rows.push_back(j);
  for (const auto& v : cutter_.vertices())
    for (double j : {std::floor(v.s / lattice_.s_step), std::ceil(v.s / lattice_.s_step)})
      rows.push_back(std::clamp(static_cast<int>(j), 0, ns_));
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  for (int i = -(na_ / kStride) * kStride; i <= na_; i += kStride)
    for (int j : rows) {
      StepSearch::Node n{i, j};
      if (step.lower_bound(n) >= contact + 0.05) continue;
      double d = step.value(n);
      if (d < contact + 0.05) low.push_back({n, d});
    }
  std::sort(low.begin(), low.end(), [](const Low& a, const Low& b) { return a.d < b.d; });
  std::vector<StepSearch::Node> starts;
  for (const auto& l : low) {
    bool near = false;
    for (const auto& s : starts) near = near || (std::abs(s.i - l.n.i) <= 2 * kStride && std::abs(s.j - l.n.j) <= 2 * kStride);
    if (!near) starts.push_back(l.n);
    if (starts.size() == 8) break;
  }
  double deepest = -kInf;
  for (const auto& s : starts) {
    auto r = step.refine(step.descend(s, kStride / 2, 1e-9));
    deepest = std::max(deepest, contact - r.d);
  }
  if (evaluations) *evaluations = step.evaluations();
  return deepest;
}

}  // namespace ncurve::helicoid
