// The round trip's measurement: a contour's moves against the curve, in runs on all cores
// (Measurer). Included by generate.cpp alone.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "base/parallel.hpp"
#include "base/vector_clones.hpp"
#include "gen/generate.hpp"
#include "geom/search.hpp"

namespace ncurve::gen::detail {

using geom::Vec3;

// Where each move ends on the curve and how far the curve strays from it.
struct Measured {
  double t1;            // the curve parameter nearest the move's end
  double end_distance;  // of the move's end from the curve
  geom::Worst worst;    // the curve's largest distance from the move
};

// A curve parameter and the placed jet there.
struct Place {
  double t = 0;
  geom::PlacedJet jet{};
};

// Measures a contour in runs of kRun moves (fewer in a short one): where each run starts is
// searched in order over the curve that the run before spans, then each run is measured on its
// own (on all cores, or while the program still runs: see Ahead), each end projected from the
// one before. A run's chain must arrive where the next run starts, else the next run is measured
// again from where it did (as one chain in order would).
class Measurer {
public:
  static constexpr std::size_t kRun = 512, kShortRun = 32;

  Measurer(const geom::Curve& curve, const Options& o, bool require_end)
      : curve_(curve), o_(o), map_(axis_map(curve, o)), plane_(plane_of(o.profile)), require_end_(require_end) {}

  const AxisMap& map() const { return map_; }

  // Where run k starts (run 0: the first move's start; after it: where run k-1 ends, by Newton's
  // method from as far along the curve as run k-1 is long, taken if it lies as near as the
  // tolerance allows; else searched over three times that length from where run k-1 starts).
  // Reads moves up to k * run.
  Place run_start(const std::vector<ContourMove>& contour, std::size_t k, const Place& before,
                  std::size_t run = kRun) const {
    double t;
    if (k == 0) {
      t = project(contour[0].start, curve_.t0(), 1e-3 + 10 * o_.tol);
    } else {
      double length = 0;
      for (std::size_t i = (k - 1) * run; i < k * run; ++i) length += contour[i].length;
      const Vec3& p = contour[k * run - 1].end;
      const double near = 10 * o_.tol + 1e-3;
      Place found;
      if (const double step = step_along(before.jet, length); !std::isnan(step)) {
        found.t = project_newton(p, before.t, std::min(curve_.t1(), before.t + step), found.jet);
        if (!std::isnan(found.t) && distance(p, found.jet.p) <= near) return found;
      }
      t = project(p, before.t, 3 * length + near, 64);
    }
    return {t, geom::placed_jet(curve_, map_, t)};
  }

  // Run k from `from` on; `moves` is the contour's length (the last move must reach the end of
  // the curve) or more while it is not known. Writes measured[i] of its moves. The moves go in
  // groups of Tape::kLanes: their ends projected on the curve together (see project_group), then
  // each taken in order where it lies ahead of the one before and near enough (else projected
  // alone, from there), then the lines measured together (geom::max_distances).
  Place measure_run(const std::vector<ContourMove>& contour, std::size_t k, Place from, std::size_t moves,
                    std::vector<Measured>& measured, std::size_t run = kRun) const {
    constexpr std::size_t kGroup = geom::Tape::kLanes;
    const double t_last = curve_.t1();
    const Vec3 curve_end = map_(curve_.point(t_last));
    const std::size_t stop = std::min(moves, (k + 1) * run);
    double t_per_mm = 0;
    std::array<Place, kGroup> to;
    std::array<bool, kGroup> projected;
    std::vector<geom::SegmentPiece> lines;
    std::vector<std::size_t> line_move;
    std::vector<geom::Worst> worst;
    lines.reserve(kGroup);
    line_move.reserve(kGroup);
    for (std::size_t first = k * run; first < stop; first += kGroup) {
      const std::size_t n = std::min(kGroup, stop - first);
      if (!(t_per_mm > 0)) t_per_mm = t_per_mm_at(from.jet, contour[first].length);
      project_group(contour, first, n, from, t_per_mm, to, projected);
      lines.clear();
      line_move.clear();
      for (std::size_t g = 0; g < n; ++g) {
        const std::size_t i = first + g;
        const ContourMove& m = contour[i];
        const geom::Piece piece = piece_of(m);
        Place& end = to[g];
        if (i + 1 == moves && require_end_) {  // the contour must reach the end of the curve
          if (distance(piece.end, curve_end) > o_.tol)
            throw std::runtime_error(fmt::format("the contour ends {:.4f} mm from the end of the curve (t = {:.6g})",
                                                 distance(piece.end, curve_end), t_last));
          end = {t_last, geom::placed_jet(curve_, map_, t_last)};
        } else if (!(projected[g] && end.t > from.t && end.t <= reach(from, m))) {
          end.t = project_newton(piece.end, from.t, std::min(t_last, from.t + m.length * t_per_mm), end.jet);
          if (std::isnan(end.t)) {
            end.t = project(piece.end, from.t, search_reach(m));
            end.jet = geom::placed_jet(curve_, map_, end.t);
          }
        }
        t_per_mm = m.length > 0 ? (end.t - from.t) / m.length : 0;
        measured[i].t1 = end.t;
        measured[i].end_distance = distance(piece.end, end.jet.p);
        if (piece.arc) {
          auto d = [&](const Vec3& p) { return geom::point_arc_distance(p, piece, plane_); };
          measured[i].worst = geom::max_distance(curve_, map_, from.t, end.t, from.jet, end.jet, d, trust(), 6);
        } else {
          lines.push_back({from.t, end.t, from.jet, end.jet, geom::Segment(piece.start, piece.end)});
          line_move.push_back(i);
        }
        from = end;
      }
      worst.resize(lines.size());
      geom::max_distances(curve_, map_, lines, trust(), worst);
      for (std::size_t j = 0; j < lines.size(); ++j) measured[line_move[j]].worst = worst[j];
    }
    return from;
  }

  // The moves of a run: a short contour in four runs (at least kShortRun long), so that it too is
  // measured on all cores (the runs depend on its length alone, so that the figures do not depend
  // on the machine).
  static std::size_t run_of(std::size_t moves) {
    return moves <= kRun ? std::clamp((moves + 3) / 4, kShortRun, kRun) : kRun;
  }

  // The whole contour: runs that `ahead` measured from the start found here are taken as they are.
  // With starts_known, ahead_start are where every run starts (found for these moves already).
  Stats measure(const std::vector<ContourMove>& contour, std::vector<Measured> measured = {},
                const std::vector<Place>& ahead_start = {}, const std::vector<Place>& ahead_end = {},
                bool starts_known = false) const {
    if (contour.empty()) throw std::runtime_error("no contour to measure");
    const std::size_t moves = contour.size();
    const std::size_t run = run_of(moves);
    const std::size_t runs = (moves + run - 1) / run;
    measured.resize(moves);
    std::vector<Place> start(runs), end(runs);
    if (starts_known) start = ahead_start;
    else
      for (std::size_t k = 0; k < runs; ++k) start[k] = run_start(contour, k, k > 0 ? start[k - 1] : Place{}, run);
    auto ahead = [&](std::size_t k) { return k < ahead_end.size() && ahead_start[k].t == start[k].t; };
    std::vector<std::size_t> left;
    for (std::size_t k = 0; k < runs; ++k) {
      if (ahead(k)) end[k] = ahead_end[k];
      else left.push_back(k);
    }
    base::for_each_on_cores(left.size(), [&](std::size_t i) {
      end[left[i]] = measure_run(contour, left[i], start[left[i]], moves, measured, run);
    });
    for (std::size_t k = 1; k < runs; ++k) {
      const double step = end[k - 1].t - start[k - 1].t;
      if (std::fabs(end[k - 1].t - start[k].t) <= 1e-6 * std::fabs(step)) continue;
      start[k] = end[k - 1];
      end[k] = measure_run(contour, k, start[k], moves, measured, run);
    }
    return stats(contour, measured, start[0], run);
  }

private:
  static double distance(const Vec3& a, const Vec3& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  }
  double trust() const { return 1e-3 * o_.tol; }  // the quintic between jets must agree with the curve this well
  static geom::Piece piece_of(const ContourMove& m) {
    geom::Piece piece;
    piece.start = m.start;
    piece.end = m.end;
    piece.arc = m.arc;
    piece.centre = m.centre;
    piece.ccw = m.sweep > 0;
    return piece;
  }

  // nearest curve parameter to p, searching forward from t_from over about `reach` mm of curve
  // (a window scaled by the local speed: the contour follows the curve in order, so a nearby turn
  // of a spiral is never taken for this one)
  double project(const Vec3& p, double t_from, double reach, int samples = 16) const {
    const geom::Curve::Jet j = curve_.jet(t_from);
    const double hi = std::min(curve_.t1(), t_from + step_at_speed({j.p, j.d1, j.d2}, reach));
    auto closeness = [&](double t) {
      const Vec3 q = map_(curve_.point(t));
      return -((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    };
    return geom::sampled_maximum(closeness, t_from, hi, samples).at;
  }

  // The same by Newton's method on (C(t) - p).C'(t) = 0 from a guess past t_from, with the jet
  // there; NaN if it does not settle on a nearest point ahead of t_from.
  double project_newton(const Vec3& p, double t_from, double guess, geom::PlacedJet& j) const {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    // a last step this small moves the jet by its Taylor terms (the next step would be ~1e-8)
    const double settled = 1e-4 * (guess - t_from);
    double t = guess;
    for (int i = 0; i < kNewtonSteps; ++i) {
      j = geom::placed_jet(curve_, map_, t);
      switch (newton_step(p, t_from, settled, t, j)) {
        case Step::settled: return t;
        case Step::failed: return kNaN;
        case Step::going: break;
      }
    }
    return kNaN;
  }

  // One step of it at t with the jet j there: t moved (and where it settles, j moved with it).
  static constexpr int kNewtonSteps = 8;
  enum class Step { going, settled, failed };
  Step newton_step(const Vec3& p, double t_from, double settled, double& t, geom::PlacedJet& j) const {
    const Vec3 r{j.p[0] - p[0], j.p[1] - p[1], j.p[2] - p[2]};
    const double slope = r[0] * j.d1[0] + r[1] * j.d1[1] + r[2] * j.d1[2];
    const double bend =
        j.d1[0] * j.d1[0] + j.d1[1] * j.d1[1] + j.d1[2] * j.d1[2] + r[0] * j.d2[0] + r[1] * j.d2[1] + r[2] * j.d2[2];
    if (!(bend > 0)) return Step::failed;  // not a nearest point
    const double dt = -slope / bend;
    if (!(t + dt > t_from && t + dt <= curve_.t1())) return Step::failed;
    t += dt;
    if (std::fabs(dt) > settled) return Step::going;
    for (int a = 0; a < 3; ++a) {
      j.p[a] += dt * (j.d1[a] + 0.5 * dt * j.d2[a]);
      j.d1[a] += dt * j.d2[a];
    }
    return Step::settled;
  }

  // newton_step on every lane of a batch, on vectors (the same operations, so the same figures):
  // p, d1[a], d2[a] the placed jet's lanes (p: 3 x kLanes), target the points projected; next the
  // moved parameter, moved the jet moved with it (p, then d1: where it settles), state a Step.
  NCURVE_VECTOR_CLONES static void newton_lanes(const double* __restrict p, const double* const* d1,
                                                const double* const* d2, const double* __restrict target,
                                                const double* __restrict t, const double* __restrict settled,
                                                double t_from, double t_end, double* __restrict next,
                                                double* __restrict moved, std::int64_t* __restrict state) {
    constexpr std::size_t n = geom::Tape::kLanes;
    const double *d1x = d1[0], *d1y = d1[1], *d1z = d1[2], *d2x = d2[0], *d2y = d2[1], *d2z = d2[2];
    for (std::size_t j = 0; j < n; ++j) {
      const double px = p[j], py = p[n + j], pz = p[2 * n + j];
      const double rx = px - target[j], ry = py - target[n + j], rz = pz - target[2 * n + j];
      const double ax = d1x[j], ay = d1y[j], az = d1z[j], bx = d2x[j], by = d2y[j], bz = d2z[j];
      const double slope = rx * ax + ry * ay + rz * az;
      const double bend = ax * ax + ay * ay + az * az + rx * bx + ry * by + rz * bz;
      const double dt = -slope / bend;
      const double moved_t = t[j] + dt;
      const bool ahead = (bend > 0) & (moved_t > t_from) & (moved_t <= t_end);
      const bool still = std::fabs(dt) > settled[j];
      next[j] = moved_t;
      state[j] = !ahead ? static_cast<std::int64_t>(Step::failed)
                 : still ? static_cast<std::int64_t>(Step::going)
                         : static_cast<std::int64_t>(Step::settled);
      moved[j] = px + dt * (ax + 0.5 * dt * bx);
      moved[n + j] = py + dt * (ay + 0.5 * dt * by);
      moved[2 * n + j] = pz + dt * (az + 0.5 * dt * bz);
      moved[3 * n + j] = ax + dt * bx;
      moved[4 * n + j] = ay + dt * by;
      moved[5 * n + j] = az + dt * bz;
    }
  }

  // The ends of moves first .. first + n - 1 projected by Newton's method together, each lane from
  // where the moves' lengths up to it reach along the curve from `from` (its speed changing as it
  // does there; else at t_per_mm), the jets of a step evaluated in one batch and its steps taken
  // on vectors (newton_lanes): projected[g] where lane g settled ahead of from.t.
  void project_group(const std::vector<ContourMove>& contour, std::size_t first, std::size_t n, const Place& from,
                     double t_per_mm, std::array<Place, geom::Tape::kLanes>& to,
                     std::array<bool, geom::Tape::kLanes>& projected) const {
    constexpr std::size_t kGroup = geom::Tape::kLanes;
    alignas(64) std::array<double, kGroup> settled{}, ts, next;
    alignas(64) std::array<double, 3 * kGroup> target, placed_p;
    alignas(64) std::array<double, 9 * kGroup> jets;
    alignas(64) std::array<double, 6 * kGroup> moved;
    alignas(64) std::array<std::int64_t, kGroup> state;
    std::array<std::size_t, kGroup> lane;  // the lanes still going
    std::size_t going = 0;
    const double t_from = from.t;
    double along = t_from, length = 0;
    for (std::size_t g = 0; g < n; ++g) {
      const double before = along;
      length += contour[first + g].length;
      const double step = step_along(from.jet, length);
      along = std::min(curve_.t1(), t_from + (std::isnan(step) ? length * t_per_mm : step));
      settled[g] = 1e-4 * (along - before);
      to[g].t = along;
      projected[g] = false;
      if (settled[g] > 0) lane[going++] = g;
      for (std::size_t a = 0; a < 3; ++a) target[a * kGroup + g] = contour[first + g].end[a];
    }
    for (std::size_t g = n; g < kGroup; ++g) {  // lanes without a move: evaluated in vain
      for (std::size_t a = 0; a < 3; ++a) target[a * kGroup + g] = target[a * kGroup + n - 1];
    }
    // placed as map_ places a jet (Placement::component, then the offset)
    static constexpr std::array<double, kGroup> kNone{};
    const double* d1[3];
    const double* d2[3];
    for (int step = 0; step < kNewtonSteps && going > 0; ++step) {
      for (std::size_t g = 0; g < kGroup; ++g) ts[g] = to[std::min(g, n - 1)].t;
      curve_.jet_lanes(ts.data(), jets.data());
      for (std::size_t a = 0; a < 3; ++a) {
        const double* p = map_.component(a, jets.data(), kGroup, kNone.data());
        for (std::size_t g = 0; g < kGroup; ++g) placed_p[a * kGroup + g] = p[g] + map_.offset[a];
        d1[a] = map_.component(a, jets.data() + 3 * kGroup, kGroup, kNone.data());
        d2[a] = map_.component(a, jets.data() + 6 * kGroup, kGroup, kNone.data());
      }
      newton_lanes(placed_p.data(), d1, d2, target.data(), ts.data(), settled.data(), t_from, curve_.t1(),
                   next.data(), moved.data(), state.data());
      std::size_t still = 0;
      for (std::size_t l = 0; l < going; ++l) {
        const std::size_t g = lane[l];
        switch (static_cast<Step>(state[g])) {
          case Step::settled:
            to[g].t = next[g];
            for (std::size_t a = 0; a < 3; ++a) {
              to[g].jet.p[a] = moved[a * kGroup + g];
              to[g].jet.d1[a] = moved[(3 + a) * kGroup + g];
              to[g].jet.d2[a] = d2[a][g];
            }
            projected[g] = true;
            break;
          case Step::failed: break;
          case Step::going:
            to[g].t = next[g];
            lane[still++] = g;
            break;
        }
      }
      going = still;
    }
  }

  // how far along the curve the end of m may lie, from `from` (as project searches)
  double reach(const Place& from, const ContourMove& m) const {
    return from.t + step_at_speed(from.jet, search_reach(m));
  }
  // the length of curve searched for the end of m when Newton's method does not settle
  double search_reach(const ContourMove& m) const { return 3 * m.length + 10 * o_.tol + 1e-3; }
  // The parameter step that covers `length` from j, the speed changing as it does there
  // (speed dt + half_gain dt^2 = length; at rest, where the curve stops at an end of its range,
  // the gain is all of the second derivative); NaN where that has no root.
  static double step_along(const geom::PlacedJet& j, double length) {
    const Vec3 &d1 = j.d1, &d2 = j.d2;
    const double speed = norm(d1);
    const double half_gain = speed > 0 ? 0.5 * (d1[0] * d2[0] + d1[1] * d2[1] + d1[2] * d2[2]) / speed : 0.5 * norm(d2);
    const double reach = speed * speed + 4 * half_gain * length;
    return (speed > 0 && reach >= 0) || (speed == 0 && reach > 0) ? 2 * length / (speed + std::sqrt(reach))
                                                                  : std::numeric_limits<double>::quiet_NaN();
  }
  // The parameter step per mm at j, for a move of `length` from there (see step_at_speed).
  static double t_per_mm_at(const geom::PlacedJet& j, double length) {
    const double speed = norm(j.d1);
    if (length > 0 && speed * speed < 1e-6 * length * norm(j.d2)) return step_at_speed(j, length) / length;
    return 1 / std::max(speed, 1e-12);
  }
  // The parameter step that covers `length` at the speed of j; where the curve is at rest (it
  // stops at an end of its range: the speed gained over the step dwarfs it) from the second
  // derivative, s = |C''| dt^2 / 2.
  static double step_at_speed(const geom::PlacedJet& j, double length) {
    const double speed = norm(j.d1), bend = norm(j.d2);
    if (speed * speed < 1e-6 * length * bend) return std::sqrt(2 * length / bend);
    return length / std::max(speed, 1e-12);
  }
  static double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

  // The worst point, the deviation along the contour, the path drawn: in parts of `run` moves (on
  // all cores where the contour is longer than a run: a short one's parts take less time than
  // handing them over), each part's points placed after those of the parts before it, the parts'
  // worst points and lengths taken in order (the same figures as one pass in order).
  Stats stats(const std::vector<ContourMove>& contour, const std::vector<Measured>& measured,
              const Place& start, std::size_t run) const {
    constexpr int kArcSamples = 16;
    const std::size_t moves = contour.size(), parts = (moves + run - 1) / run;
    std::vector<std::size_t> first_point(parts + 1, 1);  // the path's points before each part
    for (std::size_t k = 0; k < parts; ++k) {
      std::size_t points = 0;
      for (std::size_t i = k * run; i < std::min(moves, (k + 1) * run); ++i) points += contour[i].arc ? kArcSamples : 1;
      first_point[k + 1] = first_point[k] + points;
    }
    struct Farthest {  // the largest distance noted so far and where
      double distance = 0, t = 0;
      void note(double d, double at) {
        if (d > distance) distance = d, t = at;
      }
    };
    std::vector<Farthest> worst(parts);
    std::vector<double> length(parts, 0.0);
    Stats s;
    s.points = moves + 1;
    s.start_t = start.t;
    s.deviation.resize(moves);
    s.move_deviation.resize(moves);
    s.path.resize(first_point.back());
    s.path_block.resize(first_point.back() - 1);
    s.path[0] = contour[0].start;
    auto part = [&](std::size_t k) {
      std::size_t point = first_point[k];
      for (std::size_t i = k * run; i < std::min(moves, (k + 1) * run); ++i) {
        const ContourMove& m = contour[i];
        const Measured& at = measured[i];
        length[k] += m.length;
        worst[k].note(at.end_distance, at.t1);
        worst[k].note(at.worst.distance, at.worst.t);
        s.deviation[i] = {at.t1, at.worst.distance};
        const double from_curve = i > 0 ? measured[i - 1].end_distance : distance(contour[0].start, start.jet.p);
        s.move_deviation[i] = std::max({at.worst.distance, at.end_distance, from_curve});
        if (m.arc) {
          const Vec3& from = m.start;
          const double u0 = from[plane_.u_axis] - m.centre[plane_.u_axis];
          const double v0 = from[plane_.v_axis] - m.centre[plane_.v_axis];
          for (int j = 1; j < kArcSamples; ++j) {
            const double a = m.sweep * j / kArcSamples;
            Vec3 q = from;
            q[plane_.u_axis] = m.centre[plane_.u_axis] + u0 * std::cos(a) - v0 * std::sin(a);
            q[plane_.v_axis] = m.centre[plane_.v_axis] + u0 * std::sin(a) + v0 * std::cos(a);
            s.path_block[point - 1] = i;
            s.path[point++] = q;
          }
        }
        s.path_block[point - 1] = i;
        s.path[point++] = m.end;
      }
    };
    if (moves <= kRun)
      for (std::size_t k = 0; k < parts; ++k) part(k);
    else
      base::for_each_on_cores(parts, part);
    Farthest all;
    all.note(distance(contour[0].start, start.jet.p), start.t);
    for (std::size_t k = 0; k < parts; ++k) {
      s.path_length += length[k];
      all.note(worst[k].distance, worst[k].t);
    }
    s.max_deviation = all.distance;
    s.worst_t = all.t;
    if (all.distance > 0) s.worst_point = map_(curve_.point(all.t));
    return s;
  }

  const geom::Curve& curve_;
  Options o_;
  AxisMap map_;
  geom::Plane plane_;
  bool require_end_;
};

}  // namespace ncurve::gen::detail
