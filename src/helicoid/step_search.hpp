// One phase of the contact search on the cutter's lattice (private to src/helicoid): cached
// directed distances, the nine-point walk, refinement off the lattice, brute force; and the
// units the contact files share.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <unordered_map>
#include <utility>
#include <vector>

#include "helicoid/contact.hpp"

namespace ncurve::helicoid {

inline constexpr double kDeg = std::numbers::pi / 180;
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kSettled = 1e-7;  // of a lattice cell: a shorter Newton step is not taken
inline constexpr int kRefineSteps = 12;   // Newton steps of the refinement at most (it usually takes 2 or 3)

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

}  // namespace ncurve::helicoid
