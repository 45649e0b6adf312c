#include "helicoid/contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
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

}  // namespace

double helix_angle(double lead, double radius) {
  return lead == 0 ? 0 : std::atan(2 * std::numbers::pi * radius / std::abs(lead)) / kDeg;
}

std::int64_t Lattice::size(double profile_length) const {
  auto na = static_cast<std::int64_t>(std::floor(alpha_max / alpha_step + 1e-9));
  auto ns = static_cast<std::int64_t>(std::floor(profile_length / s_step + 1e-9));
  return (2 * na + 1) * (ns + 1);
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

std::vector<Contact> ContactSearch::run_axial(const std::vector<double>& psis, Method method, const AxialMotion& m) const {
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
  }
  return out;
}

double ContactSearch::plane_distance(double psi) const {
  auto hit = plane_profile_.first_hit(psi, 0);
  if (!hit.found) return std::numeric_limits<double>::quiet_NaN();
  return hit.x + cutter_.outer_radius() - corner_radius_;
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

  // Second differences at c on the lattice of stride `stride`, in units of that stride:
  // {f_ii, f_jj, f_ij}, centred where the rows allow and one-sided at their edges; nullopt where
  // a value is not finite.
  std::optional<std::array<double, 3>> stencil_hessian(Node c, int stride) {
    auto f = [&](int di, int dj) { return value({c.i + di * stride, c.j + dj * stride}); };
    // The three points along an axis, and the pair for the mixed difference, that stay inside.
    auto span = [&](bool along_i) {
      auto ok = [&](int k) { return inside(along_i ? Node{c.i + k * stride, c.j} : Node{c.i, c.j + k * stride}); };
      return ok(-1) && ok(1) ? -1 : (ok(1) && ok(2) ? 0 : -2);
    };
    int a = span(true), b = span(false);
    std::array<double, 3> h{f(a, 0) - 2 * f(a + 1, 0) + f(a + 2, 0), f(0, b) - 2 * f(0, b + 1) + f(0, b + 2), 0};
    int a0 = a == -2 ? -1 : a, b0 = b == -2 ? -1 : b;
    int a1 = a == -1 ? 1 : a0 + 1, b1 = b == -1 ? 1 : b0 + 1;
    h[2] = (f(a1, b1) - f(a1, b0) - f(a0, b1) + f(a0, b0)) / ((a1 - a0) * (b1 - b0));
    if (!std::isfinite(h[0] + h[1] + h[2])) return std::nullopt;
    return h;
  }

  // A distance evaluated off the walk (with its gradient) kept for the walk.
  ContactSearch::Distance eval_node(Node n) {
    auto at = eval(alpha(n), s(n));
    std::int64_t key = (static_cast<std::int64_t>(n.i) << 32) ^ static_cast<std::uint32_t>(n.j);
    cache_.try_emplace(key, at.d);
    return at;
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
    return {a, s, at.d, at};
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

  // Every lattice point, skipping those whose bound is not below the best so far; the row
  // alpha = 0 first, for a good best early.
  Node brute() {
    Node best{0, 0};
    double best_d = kInf;
    auto consider = [&](Node n) {
      if (lower_bound(n) >= best_d) return;
      ++evaluations_;
      double d = cs_.distance(psi_, alpha(n), s(n)).d;
      if (d < best_d) best_d = d, best = n;
    };
    for (int j = 0; j <= cs_.ns_; ++j) consider({0, j});
    for (int i = -cs_.na_; i <= cs_.na_; ++i)
      if (i != 0)
        for (int j = 0; j <= cs_.ns_; ++j) consider({i, j});
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

// The robust search's traces, carried from step to step: per element of the cutter profile
// (corner, each flank) a fine trace of the smallest distance within its rows, and a coarse trace
// of its interior (away from the shoulders it shares with its neighbours), where a separate
// contact can rise while the fine trace sits on a shoulder. A coarse trace close to the best is
// descended to the fine lattice.
class RobustTraces {
public:
  explicit RobustTraces(const ContactSearch& cs)
      : ns_(cs.s_cells()), alpha_step_(cs.lattice().alpha_step), s_step_(cs.lattice().s_step) {
    double start = 0;
    for (const auto& e : cs.cutter().elements()) {
      double end = start + e.length();
      int j_lo = static_cast<int>(std::ceil(start / s_step_ - 1e-9));
      int j_hi = std::min(ns_, static_cast<int>(std::floor(end / s_step_ + 1e-9)));
      if (j_hi >= j_lo) fine_.emplace_back(j_lo, j_hi, Node{0, (j_lo + j_hi) / 2});
      if (j_hi - j_lo > 4 * kCoarse) {
        coarse_.emplace_back(j_lo + kCoarse, j_hi - kCoarse, Node{0, (j_lo + j_hi) / 2});
        fine_.back().guarded = true;
      }
      start = end;
    }
  }

  // The lattice contact of this step.
  Node next(StepSearch& step, int step_index) {
    // The trace that held the contact last time first, then the others that are due.
    std::size_t lead = 0;
    for (std::size_t k = 0; k < fine_.size(); ++k)
      if (fine_[k].gap < fine_[lead].gap) lead = k;
    best_ = kInf;
    value_.assign(fine_.size(), kInf);
    for (std::size_t k = 0; k < fine_.size(); ++k) {
      std::size_t at = (lead + k) % fine_.size();
      if (at != lead && !fine_[at].due()) continue;
      Node n = advance(fine_[at], step, 1);
      offer(at, n, step.value(n));
      if (on_shoulder(fine_[at], n)) {
        if (at == lead)
          for (auto& f : fine_) f.idle = 0;
        else if (fine_[at].guarded)
          fine_[at].idle = kAsleep;
      }
    }
    for (auto& t : coarse_) {  // every step: a new contact can rise faster than any rate seen so far
      const double margin = 2 * t.gap_rate + 0.02;
      if (predicted_clear(t, step, margin, step_index)) continue;
      Node n = advance(t, step, kCoarse);
      t.hessian = step.stencil_hessian(n, kCoarse);
      double v = step.fitted_minimum(n, kCoarse);
      double coarseness = step.value(n) - v;
      if (v <= best_ + margin + coarseness) {
        for (std::size_t k = 0; k < fine_.size(); ++k) {  // the element holding this coarse trace
          auto& f = fine_[k];
          if (f.j_lo > t.j_lo || f.j_hi < t.j_hi) continue;
          step.restrict_rows(f.j_lo, f.j_hi);
          Node m = step.descend(n, kCoarse / 2, kTie);
          if (step.value(m) < value_[k]) f.path = {m}, f.idle = 0;
          offer(k, m, step.value(m));
        }
      }
      t.schedule(v, best_, step_index);
    }
    for (std::size_t k = 0; k < fine_.size(); ++k)
      if (std::isfinite(value_[k]) && fine_[k].idle != kAsleep) fine_[k].schedule(value_[k], best_, step_index);
    return node_;
  }

private:
  static constexpr int kCoarse = 16;  // lattice cells per coarse step
  static constexpr int kAsleep = std::numeric_limits<int>::max();
  // A trace well above the best is left alone for as many steps as its gap could not close at
  // twice the fastest rate the gap has changed lately (the fastest so far, fading by a factor a
  // step: a rate seen at the crest says little about the flank ten steps on).
  static constexpr double kRateFade = 0.7;

  struct Trace {
    Trace(int lo, int hi, Node start) : j_lo(lo), j_hi(hi), first(start) {}
    int j_lo, j_hi;
    Node first;
    std::vector<Node> path;
    bool guarded = false;  // has a coarse trace of its interior
    std::optional<std::array<double, 3>> hessian;  // of the last full walk's stencil (coarse traces)
    double gap = kInf, gap_rate = 0;
    int idle = 0;     // steps left before the next update
    int updated = -1; // step of the last update
    bool due() {
      if (idle > 0) {
        --idle;
        if (!path.empty()) path = {path.back()};  // a stale line no longer predicts
        return false;
      }
      return true;
    }
    void schedule(double value, double best, int step_index) {
      double g = value - best;
      if (updated >= 0 && std::isfinite(gap) && std::isfinite(g)) {
        int steps = step_index - updated;
        gap_rate = std::max(gap_rate * std::pow(kRateFade, steps), std::abs(g - gap) / steps);
      }
      gap = g;
      updated = step_index;
      double rate = std::max(gap_rate, 0.01);
      idle = std::isfinite(g) ? std::max(0, static_cast<int>(g / (2 * rate)) - 1) : 0;
    }
  };

  void offer(std::size_t k, Node n, double v) {
    value_[k] = std::min(value_[k], v);
    if (v < best_) best_ = v, node_ = n;
  }

  Node advance(Trace& t, StepSearch& step, int stride) {
    step.restrict_rows(t.j_lo, t.j_hi);
    Node n = t.path.empty() ? step.descend(t.first, 64, kTie) : step.walk(predicted(t.path, t.first), stride, kTie, true);
    t.path.push_back(n);
    return n;
  }

  // A fine trace resting on a row it shares with a neighbour element is that neighbour's
  // shoulder, not a contact of its own: it sleeps until its coarse trace wakes it.
  bool on_shoulder(const Trace& t, Node n) const {
    return (n.j == t.j_lo && t.j_lo > 0) || (n.j == t.j_hi && t.j_hi < ns_);
  }

  // One evaluation with its gradient and the last stencil's curvature predict a coarse trace's
  // minimum; a prediction clear of the best by twice its own drop needs no walk (the trace moves
  // to the predicted minimum and is rescheduled).
  bool predicted_clear(Trace& t, StepSearch& step, double margin, int step_index) {
    if (!t.hessian || t.path.empty()) return false;
    step.restrict_rows(t.j_lo, t.j_hi);
    Node p = step.clamp(predicted(t.path, t.first));
    auto at = step.eval_node(p);
    const auto& h = *t.hessian;
    double ga = at.d_alpha * alpha_step_ * kCoarse, gs = at.d_s * s_step_ * kCoarse;
    // The quadratic model's minimum within the rows: the full Newton step, or along alpha alone
    // where that step would leave the rows.
    double det = h[0] * h[1] - h[2] * h[2];
    double di = 0, dj = 0;
    bool model = at.hit && h[0] > 0;
    if (model && det > 0) {
      di = -(h[1] * ga - h[2] * gs) / det;
      dj = -(-h[2] * ga + h[0] * gs) / det;
    }
    if (model && (det <= 0 || !step.inside({p.i, p.j + static_cast<int>(std::lround(dj)) * kCoarse}))) {
      model = (p.j == t.j_lo && gs > 0) || (p.j == t.j_hi && gs < 0);  // pinned to the edge
      di = -ga / h[0], dj = 0;
    }
    double drop = -(ga * di + gs * dj) / 2;
    // Where the model curves down, the walk's neighbours could be lower than its minimum.
    for (int ki = -1; ki <= 1; ++ki)
      for (int kj = -1; kj <= 1; ++kj)
        if (step.inside({p.i + ki * kCoarse, p.j + kj * kCoarse}))
          drop = std::max(drop, -(ga * ki + gs * kj + (h[0] * ki * ki + 2 * h[2] * ki * kj + h[1] * kj * kj) / 2));
    if (!model || std::abs(di) > 2 || std::abs(dj) > 2 || at.d - 2 * drop <= best_ + margin) return false;
    t.path.push_back(step.clamp({p.i + static_cast<int>(std::lround(di)) * kCoarse,
                                 p.j + static_cast<int>(std::lround(dj)) * kCoarse}));
    t.schedule(at.d - drop, best_, step_index);
    return true;
  }

  std::vector<Trace> fine_, coarse_;
  int ns_;
  double alpha_step_, s_step_;
  // This step's best so far, its node, and each fine trace's value.
  double best_ = kInf;
  Node node_;
  std::vector<double> value_;
};

}  // namespace

std::vector<Contact> ContactSearch::run(const std::vector<double>& psis, Method method) const {
  std::vector<Contact> out;
  std::vector<Node> path;  // lattice contacts so far
  const Node corner{0, static_cast<int>(std::lround(cutter_.corner_middle() / lattice_.s_step))};
  RobustTraces traces(*this);
  for (std::size_t step_index = 0; step_index < psis.size(); ++step_index) {
    const double psi = psis[step_index];
    StepSearch step(*this, psi);
    Node node;
    switch (method) {
      case Method::brute: node = step.brute(); break;
      case Method::nine_point: node = step.walk(predicted(path, corner), 1, 0.0, false); break;
      case Method::robust: node = traces.next(step, static_cast<int>(step_index)); break;
    }
    path.push_back(node);
    auto refined = step.refine(node);
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
    c.evaluations = step.evaluations();
    c.plane_A = plane_distance(psi);
    out.push_back(c);
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
  for (int i = -(na_ / kStride) * kStride; i <= na_; i += kStride)
    for (int j = 0; j <= ns_; j += kStride) {
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
