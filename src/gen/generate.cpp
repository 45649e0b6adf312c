#include "gen/generate.hpp"
#include "base/memory.hpp"
#include "base/parallel.hpp"
#include "base/vector_clones.hpp"
#include "geom/search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "report/summary.hpp"
#include "gen/forms.hpp"

namespace ncurve::gen {
namespace {

using geom::Sym;
using geom::SymOp;
using geom::Vec3;
using namespace detail;

}  // namespace

const char* to_string(Form f) {
  switch (f) {
    case Form::expanded: return "expanded";
    case Form::arcs: return "arcs";
    case Form::macro: return "macro";
    case Form::adaptive_macro: return "adaptive-macro";
    case Form::cycle: return "cycle";
  }
  return "";
}

bool parse_form(const std::string& text, Form& out) {
  for (Form f : {Form::expanded, Form::arcs, Form::macro, Form::adaptive_macro, Form::cycle}) {
    if (text == to_string(f)) {
      out = f;
      return true;
    }
  }
  return false;
}

AxisMap axis_map(const geom::Curve& curve, const Options& o) {
  AxisMap m;
  const bool uses_z = !curve.planar_z();
  const bool uses_y = curve.uses_y();
  if (is_lathe(o)) {
    if (uses_y && uses_z) throw std::runtime_error("a lathe cuts plane profiles: the curve uses y and z");
    if (uses_y) m.from = {1, -1, 0};  // profile drawn in x, y: Z along x, X (radius) along y
    else m.from = {0, -1, 2};
    // The imaginary tool tip sits a nose radius from the nose centre along X and Z.
    static constexpr int kTipX[10] = {0, -1, -1, 1, 1, 0, -1, 0, 1, 0};
    static constexpr int kTipZ[10] = {0, 1, -1, -1, 1, 1, 0, -1, 0, 0};
    if (o.tip < 0 || o.tip > 9) throw std::runtime_error("the imaginary tool nose direction is 0..9");
    if (o.tool_radius > 0) m.offset = {kTipX[o.tip] * o.tool_radius, 0, kTipZ[o.tip] * o.tool_radius};
    return m;
  }
  if (!uses_z) {
    m.from = {0, 1, -1};
    m.offset = {0, 0, -o.depth};
  }
  return m;
}

geom::Plane plane_of(const machine::MachineProfile& p) {
  if (p.lathe()) return geom::Plane{2, 0};  // G18: Z, X
  return geom::Plane{0, 1};
}

namespace {

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

// Measures a pass's runs while the program still runs, on a thread beside the interpreter: run k
// once a move after it has come (the last run is left to Measurer::measure, which knows where the
// contour ends). stop() before the pass outgrows its reserve (its moves would move) and before
// measuring; runs not done then are measured there.
class Ahead {
public:
  Ahead(const Measurer& m, const std::vector<ContourMove>& moves)
      : measurer_(m), moves_(moves), measured_(room(moves.capacity())), arrived_(moves.size()), worker_([this] { work(); }) {}
  Ahead(const Ahead&) = delete;
  Ahead& operator=(const Ahead&) = delete;
  ~Ahead() { stop(); }

  void arrived(std::size_t moves) {  // the pass has this many moves now
    if (moves % Measurer::kRun != 1) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      arrived_ = moves;
    }
    wake_.notify_one();
  }
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopped_ = true;
    }
    wake_.notify_one();
    if (worker_.joinable()) worker_.join();
  }
  // after stop()
  std::vector<Measured>& measured() { return measured_; }
  const std::vector<Place>& starts() const { return starts_; }
  const std::vector<Place>& ends() const { return ends_; }

private:
  static std::vector<Measured> room(std::size_t moves) {
    std::vector<Measured> measured;
    base::reserve_large(measured, moves);
    measured.resize(moves);
    return measured;
  }
  void work() {
    try {
      for (std::size_t k = 0;; ++k) {
        {
          std::unique_lock<std::mutex> lock(mutex_);
          wake_.wait(lock, [&] { return stopped_ || arrived_ > (k + 1) * Measurer::kRun; });
          if (stopped_) return;
        }
        const Place start = measurer_.run_start(moves_, k, k > 0 ? starts_.back() : Place{});
        const Place end = measurer_.measure_run(moves_, k, start, std::numeric_limits<std::size_t>::max(), measured_);
        starts_.push_back(start);
        ends_.push_back(end);
      }
    } catch (...) {  // Measurer::measure measures the run again and reports what went wrong
    }
  }

  const Measurer& measurer_;
  const std::vector<ContourMove>& moves_;
  std::vector<Measured> measured_;
  std::vector<Place> starts_, ends_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::size_t arrived_ = 0;
  bool stopped_ = false;
  std::thread worker_;
};

bool bitwise_equal(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(Vec3)) == 0; }

}  // namespace

namespace detail {

// The fit's path measured while its program is emitted, read and run: each coordinate as the
// control will read the number written for it (machine::round_to_increment), lengths as the
// interpreter takes them. Its runs are measured by the pool's workers meanwhile and, once the
// moves have come, by all cores. The round trip takes them where the interpreter's moves are these
// bit for bit (the same moves in the same runs give the same figures); else it measures its moves
// itself.
class Speculation {
public:
  Speculation(const geom::Curve& curve, const Options& o, const std::vector<geom::Piece>& pieces)
      : measurer_(curve, o, true), moves_(as_read(pieces, machine::increments_per_mm(o.profile))),
        run_(Measurer::run_of(moves_.size())) {
    const std::size_t runs = (moves_.size() + run_ - 1) / run_;
    starts_.resize(runs);
    ends_.resize(runs);
    measured_.resize(moves_.size());
    beside_.emplace(runs, work_);
  }

  // The figures of `moves` if they are the ones measured.
  std::optional<Stats> take(const std::vector<ContourMove>& moves) {
    try {
      beside_->wait();
    } catch (const std::exception&) {
      return std::nullopt;  // the round trip measures the moves again and reports it
    }
    if (moves.size() != moves_.size()) return std::nullopt;
    for (std::size_t i = 0; i < moves.size(); ++i) {
      const ContourMove &m = moves[i], &s = moves_[i];
      if (m.arc || !bitwise_equal(m.start, s.start) || !bitwise_equal(m.end, s.end) ||
          std::memcmp(&m.length, &s.length, sizeof(double)) != 0)
        return std::nullopt;
    }
    Stats s = measurer_.measure(moves, std::move(measured_), starts_, ends_, true);  // the same moves, the same starts
    s.measured_beside = true;
    return s;
  }

private:
  static std::vector<ContourMove> as_read(const std::vector<geom::Piece>& pieces, double per_unit) {
    auto read = [&](const Vec3& p) {
      return Vec3{machine::round_to_increment(p[0], per_unit), machine::round_to_increment(p[1], per_unit),
                  machine::round_to_increment(p[2], per_unit)};
    };
    std::vector<ContourMove> moves(pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      ContourMove& m = moves[i];
      const bool joined = i > 0 && bitwise_equal(pieces[i].start, pieces[i - 1].end);  // read once
      m.start = joined ? moves[i - 1].end : read(pieces[i].start);
      m.end = read(pieces[i].end);
      m.length = machine::line_length(m.start.data(), m.end.data());
    }
    return moves;
  }

  // run k; run 0 first finds where every run starts (in order), which the others wait for
  void measure_run(std::size_t k) {
    if (k == 0) {
      struct Found {  // also where finding them throws: the others then measure from nowhere, in vain
        std::atomic<bool>& flag;
        ~Found() { flag.store(true, std::memory_order_release); }
      } found{starts_found_};
      for (std::size_t r = 0; r < starts_.size(); ++r)
        starts_[r] = measurer_.run_start(moves_, r, r > 0 ? starts_[r - 1] : Place{}, run_);
    } else {
      while (!starts_found_.load(std::memory_order_acquire)) std::this_thread::yield();
    }
    ends_[k] = measurer_.measure_run(moves_, k, starts_[k], moves_.size(), measured_, run_);
  }

  Measurer measurer_;
  std::vector<ContourMove> moves_;
  std::size_t run_;
  std::vector<Place> starts_, ends_;
  std::atomic<bool> starts_found_{false};
  std::vector<Measured> measured_;
  std::function<void(std::size_t)> work_ = [this](std::size_t k) { measure_run(k); };
  std::optional<base::Beside> beside_;  // last: waited for before the rest goes
};

// The round trip, taking the measurement of a speculation (may be null) where it fits.
Stats round_trip(const std::string& text, const geom::Curve& curve, const Options& o, std::uint32_t first_line,
                 std::uint32_t last_line, Speculation* speculation);

}  // namespace detail

Stats round_trip(const std::string& text, const geom::Curve& curve, const Options& o, std::uint32_t first_line,
                 std::uint32_t last_line) {
  return detail::round_trip(text, curve, o, first_line, last_line, nullptr);
}

Stats detail::round_trip(const std::string& text, const geom::Curve& curve, const Options& o,
                         std::uint32_t first_line, std::uint32_t last_line, Speculation* speculation) {
  machine::ProgramLibrary lib(o.profile.parse_options());
  lib.add_text("<generated>", text, true);
  // The contour's moves, one group per pass: a feed move outside the contour (the plunge) ends one.
  // Each pass is measured against the curve at the pass's own depth, as far as it can be while
  // the program runs (with a core to spare).
  struct Pass {
    std::vector<ContourMove> moves;
    std::unique_ptr<Measurer> measurer;
    std::unique_ptr<Ahead> ahead;
  };
  struct Keep final : machine::MoveSink {
    const geom::Curve& curve;
    const Options& o;
    std::uint32_t first, last;
    bool spare_core = base::cores() > 1;
    std::vector<Pass> passes;
    bool between = true;
    Keep(const geom::Curve& c, const Options& options, std::uint32_t first_line, std::uint32_t last_line)
        : curve(c), o(options), first(first_line), last(last_line) {}
    void on_move(const machine::Move& m) override {
      if (m.kind != machine::MoveKind::line && m.kind != machine::MoveKind::arc) return;
      if (m.line < first || m.line > last) {
        between = true;
        return;
      }
      if (between) {
        if (!passes.empty() && passes.back().ahead) passes.back().ahead->stop();
        Pass& pass = passes.emplace_back();
        base::reserve_large(pass.moves, last - first + 1);  // an expanded contour: a move a line
        Options at_depth = o;
        if (detail::depth_passes(o)) at_depth.depth = -m.start[2];
        pass.measurer = std::make_unique<Measurer>(curve, at_depth, true);
      }
      between = false;
      Pass& pass = passes.back();
      if (pass.ahead && pass.moves.size() == pass.moves.capacity()) pass.ahead->stop();  // the moves will move
      pass.moves.push_back(ContourMove::of(m));
      // a long contour (a run done, room for more): measure while the program runs
      if (spare_core && pass.moves.size() == Measurer::kRun + 1 && pass.moves.capacity() > 2 * Measurer::kRun)
        pass.ahead = std::make_unique<Ahead>(*pass.measurer, pass.moves);
      else if (pass.ahead)
        pass.ahead->arrived(pass.moves.size());
    }
  } keep(curve, o, first_line, last_line);
  machine::Interpreter interp(o.profile, lib);
  machine::RunResult r = interp.run(keep);
  for (Pass& pass : keep.passes)
    if (pass.ahead) pass.ahead->stop();
  if (!r.ok()) throw std::runtime_error("the generated program does not run: " + nc::format(*r.alarm));

  if (keep.passes.empty()) throw std::runtime_error("the generated program cuts no contour");
  if (keep.passes.size() > 1 && !detail::depth_passes(o))
    throw std::runtime_error("the generated program cuts its contour more than once");
  // the last pass is the finished contour
  std::vector<Stats> measured;
  std::optional<Stats> speculated;
  if (speculation && keep.passes.size() == 1 && !keep.passes[0].ahead) speculated = speculation->take(keep.passes[0].moves);
  for (Pass& pass : keep.passes) {
    if (speculated)
      measured.push_back(std::move(*speculated));
    else if (pass.ahead)
      measured.push_back(pass.measurer->measure(pass.moves, std::move(pass.ahead->measured()), pass.ahead->starts(),
                                                pass.ahead->ends()));
    else
      measured.push_back(pass.measurer->measure(pass.moves));
  }
  Stats s = measured.back();
  for (const auto& m : measured)
    if (m.max_deviation > s.max_deviation) s.max_deviation = m.max_deviation, s.worst_t = m.worst_t, s.worst_point = m.worst_point;
  s.passes = keep.passes.size();
  report::SourceStats source = report::source_stats(lib, lib.main()->file.get());  // as `ncurve run` counts
  s.words = source.words;
  s.bytes = source.bytes;
  s.blocks = source.blocks;
  return s;
}

ContourMove ContourMove::of(const machine::Move& m) {
  return {{m.start[0], m.start[1], m.start[2]}, {m.end[0], m.end[1], m.end[2]}, m.center, m.sweep, m.length,
          m.kind == machine::MoveKind::arc};
}

Stats measure(const std::vector<machine::Move>& contour, const geom::Curve& curve, const Options& o, bool require_end) {
  std::vector<ContourMove> moves;
  moves.reserve(contour.size());
  for (const machine::Move& m : contour) moves.push_back(ContourMove::of(m));
  return measure(moves, curve, o, require_end);
}

Stats measure(const std::vector<ContourMove>& contour, const geom::Curve& curve, const Options& o, bool require_end) {
  return Measurer(curve, o, require_end).measure(contour);
}

namespace {

Emitted expanded_or_arcs(const Context& c) {
  const Options& o = c.o;
  geom::Path path;
  std::shared_ptr<Speculation> speculation;
  std::string method;
  if (o.form == Form::arcs) {
    if (c.with_z) throw std::runtime_error("arcs need a plane curve; this one rises in Z (use expanded or macro)");
    path = geom::fit_arcs(c.fit);
    method = "biarcs";
  } else {
    path = geom::fit_lines(c.fit, o.lines);
    // (an inch program's moves are read in inches and converted: never the fit's bit for bit)
    if (!is_lathe(o) && !depth_passes(o) && !o.inch && path.pieces.size() <= Measurer::kRun && base::cores() > 1)
      speculation = std::make_shared<Speculation>(c.curve, o, path.pieces);
    method = o.lines == geom::LineMethod::equal_step    ? "equal parameter step"
             : o.lines == geom::LineMethod::equal_chord ? "equal chord"
             : o.lines == geom::LineMethod::equal_error ? "equal error, tolerance band"
             : o.lines == geom::LineMethod::radial_error ? "equal radial shape error"
                                                         : "equal error, points on the curve";
  }
  Writer w;
  w.text.reserve(1024 + 24 * path.pieces.size());  // "X-123.456 Y78.901" a piece, arcs longer
  w.block("%");
  w.lines(header(c.curve, o, method));
  begin_setup(w, o, c.dec);
  begin_passes(w, o, c.dec);
  modes_block(w, o);
  Frame fr = frame(o, c.words, c.start, c.end, c.dec, c.feed);
  w.lines(fr.before_start);
  w.lines(fr.to_depth);
  Emitted e;
  e.first = w.line + 1;
  // The contour's blocks, in parts on all cores: a block's G code depends only on the piece before.
  const std::vector<geom::Piece>& pieces = path.pieces;
  constexpr std::size_t kPart = 4096;
  std::vector<std::string> parts((pieces.size() + kPart - 1) / kPart);
  auto g_code = [](const geom::Piece& p) { return p.arc ? (p.ccw ? 3 : 2) : 1; };
  base::for_each_on_cores(parts.size(), [&](std::size_t k) {
    std::string& text = parts[k];
    const std::size_t first = k * kPart, last = std::min(pieces.size(), first + kPart);
    text.reserve(32 * (last - first));
    int motion = first == 0 ? 1 : g_code(pieces[first - 1]);
    for (std::size_t i = first; i < last; ++i) {
      const geom::Piece& p = pieces[i];
      const int g = g_code(p);
      if (g != motion) text += fmt::format("G0{} ", g);
      c.words.append(text, p.end);
      if (p.arc) text += ' ' + arc_words(c, p);
      text += '\n';
      motion = g;
    }
  });
  for (const std::string& part : parts) w.text += part;
  w.line += static_cast<std::uint32_t>(pieces.size());
  e.last = w.line;
  end_program(w, c);
  e.text = std::move(w.text);
  e.speculation = std::move(speculation);
  return e;
}

Emitted equal_step_macro(const Context& c) {
  const Options& o = c.o;
  geom::Path steps = geom::fit_lines(c.fit, geom::LineMethod::equal_step);
  const std::size_t n = steps.pieces.size();
  Writer w;
  macro_preamble(w, c, "equal parameter step");
  w.block(fmt::format("#112={} (SEGMENTS)", n));
  w.block("#113=[#111-#110]/#112 (T STEP)");
  w.block("#114=0 (SEGMENT COUNTER)");
  modes_block(w, o);
  w.block("#100=#110");
  int next = kFirstTemp;
  MacroWords mp = macro_words(point_axes(c.curve, c.map, o, c.with_z), next);
  approach(w, c, mp);
  w.block("WHILE [#114 LT #112] DO1");
  w.block("#114=#114+1");
  w.block("#100=#110+#114*#113");
  return close_loop(w, c, mp);
}

}  // namespace

namespace detail {

void end_program(Writer& w, const Context& c) {
  w.lines(frame(c.o, c.words, c.start, c.end, c.dec, c.feed).retract);
  end_passes(w, c.o);
  end_setup(w, c.o);
  w.block("M30");
  w.block("%");
}

Emitted close_loop(Writer& w, const Context& c, const MacroWords& move) {
  for (const auto& a : move.assignments) w.block(a);
  Emitted e;
  e.first = w.line + 1;
  w.block(fmt::format("G01 {}", move.words));
  e.last = w.line;
  w.block("END1");
  end_program(w, c);
  e.text = std::move(w.text);
  return e;
}

std::string arc_words(const Context& c, const geom::Piece& p) {
  if (c.o.profile.arcs_with_r) return fmt::format("R{}", number(p.r, c.dec));
  if (is_lathe(c.o))
    return fmt::format("I{} K{}", number(p.centre[0] - p.start[0], c.dec), number(p.centre[2] - p.start[2], c.dec));
  return fmt::format("I{} J{}", number(p.centre[0] - p.start[0], c.dec), number(p.centre[1] - p.start[1], c.dec));
}

void parameter_blocks(Writer& w, const geom::Curve& curve) {
  for (const auto& p : curve.params())
    w.block(fmt::format("#{}={} ({}: {})", p.var, number(p.value, 12), comment_text(p.name), comment_text(p.doc)));
}

void macro_preamble(Writer& w, const Context& c, const std::string& method, const std::string& more_variables,
                    int t_start) {
  w.block("%");
  w.lines(header(c.curve, c.o, method));
  begin_setup(w, c.o, c.dec);
  begin_passes(w, c.o, c.dec);
  w.block(fmt::format("(#100 = T OF THE {}{})", comment_text(c.curve.name()), more_variables));
  parameter_blocks(w, c.curve);
  w.block(fmt::format("#{}={} (T START)", t_start, number(c.curve.t0(), 12)));
  w.block(fmt::format("#111={} (T END)", number(c.curve.t1(), 12)));
}

void approach(Writer& w, const Context& c, const MacroWords& start) {
  const Options& o = c.o;
  if (is_lathe(o)) {
    w.block(fmt::format("G00 X{} Z{}", number(2 * (c.start[0] + o.clearance), c.dec),
                        number(c.start[2] + o.clearance, c.dec)));
    for (const auto& a : start.assignments) w.block(a);
    w.block(fmt::format("G01 {} F{}", start.words, feed_number(o, c.feed)));
    return;
  }
  w.block(fmt::format("G00 Z{}", number(o.clearance, c.dec)));
  for (const auto& a : start.assignments) w.block(a);
  w.block(fmt::format("G00 {}", start.words));
  if (!c.with_z) w.block(fmt::format("G01 {} F{}", plunge_z(o, -o.depth, c.dec), feed_number(o, c.feed)));
  else w.block(fmt::format("G01 F{}", feed_number(o, c.feed)));
}

}  // namespace detail

void check_options(const Options& o) {
  auto finite = [](double v, const char* what) {
    if (!std::isfinite(v)) throw std::runtime_error(fmt::format("{} must be a finite number, not {}", what, v));
  };
  finite(o.tol, "the tolerance");
  finite(o.feed, "the feed");
  finite(o.depth, "the depth");
  finite(o.clearance, "the clearance");
  finite(o.step_down, "the depth per pass");
  finite(o.tool_radius, "the tool radius");
  if (!(o.tol > 0)) throw std::runtime_error(fmt::format("the tolerance must be above 0 mm, not {}", o.tol));
  if (o.feed < 0) throw std::runtime_error(fmt::format("the feed must not be negative, not {}", o.feed));
  // the set-up
  const bool lathe = is_lathe(o);
  if (o.tool < 0 || o.tool > (lathe ? 64 : 9999))
    throw std::runtime_error(fmt::format("the tool must be 1..{}{}, not {}", lathe ? 64 : 9999,
                                         lathe ? " on a lathe (T with the offset of the same number)" : "", o.tool));
  if (o.spindle < 0 || o.css < 0 || o.max_rpm < 0)
    throw std::runtime_error("spindle speeds must not be negative");
  if (o.css > 0 && !lathe) throw std::runtime_error("a constant surface speed (G96) is for the lathe; give the spindle speed");
  if (o.css > 0 && o.spindle > 0)
    throw std::runtime_error("give the spindle speed or a constant surface speed (G96), not both");
  if (o.max_rpm > 0 && o.css == 0) throw std::runtime_error("the spindle clamp is for a constant surface speed (G96)");
  if (o.spindle_ccw && o.spindle == 0 && o.css == 0) throw std::runtime_error("the spindle's direction needs its speed");
  if (o.inch && o.form == Form::cycle)
    throw std::runtime_error(
        "the cycles' macros (O9010..O9019) are written in mm: for an inch program use --form adaptive-macro (the "
        "same loop, in the program)");
}

Result generate(const geom::Curve& contour, const Options& o) {
  check_options(o);
  geom::Survey survey = contour.validate();
  std::optional<geom::Curve> cutter_centre;
  if (o.tool_radius > 0) {
    const AxisMap placed = axis_map(contour, o);
    geom::Plane plane = plane_of(o.profile);
    cutter_centre.emplace(contour.offset(o.tool_radius, o.side == Side::left, placed.from[plane.u_axis],
                                         placed.from[plane.v_axis]));
    survey = cutter_centre->validate();
  } else if (o.tool_radius < 0) {
    throw std::runtime_error("the tool radius must not be negative");
  }
  const geom::Curve& measured = cutter_centre ? *cutter_centre : contour;
  const bool with_z = !is_lathe(o) && !measured.planar_z();
  if (o.step_down < 0) throw std::runtime_error("the depth per pass must not be negative");
  if (o.step_down > 0 && is_lathe(o)) throw std::runtime_error("depth passes are for the mill");
  if (o.step_down > 0 && with_z) throw std::runtime_error("depth passes need a plane curve; this one rises in Z");
  if (o.step_down > 0 && !(o.depth > 0)) throw std::runtime_error("depth passes need a depth > 0");
  // An inch program: the curve and the options in inches, every form written as in mm; the round
  // trip runs it and measures in mm.
  std::optional<geom::Curve> inches;
  const Options inch_o = o.inch ? in_inches(o) : Options{};
  if (o.inch) {
    inches.emplace(measured.scaled(kMmPerInch));
    survey = inches->survey();
  }
  const geom::Curve& curve = o.inch ? *inches : measured;
  const Options& u = o.inch ? inch_o : o;  // in the program's units
  const int dec = decimals_of(u.profile.increment);
  geom::Vec3 increment{u.profile.increment, u.profile.increment, u.profile.increment};
  if (is_lathe(u) && u.profile.diameter_x) increment[0] = u.profile.increment / 2;
  if (is_lathe(u)) increment[1] = 0;
  if (!is_lathe(u) && !with_z) increment[2] = 0;  // a plane contour's Z is a constant
  const geom::Grid grid(increment);
  // (in mm: the fit's own messages would give inches)
  if (o.inch && !(u.tol * 0.999 > (o.form == Form::arcs ? 2 : 1) * grid.worst_error()))
    throw std::runtime_error(fmt::format(
        "tolerance {} mm is too close to the coordinate rounding of an inch program ({:.6f} mm: steps of {} in){}",
        o.tol, grid.worst_error() * kMmPerInch, u.profile.increment,
        o.form == Form::arcs ? "; arcs need twice that" : ""));
  // measured at the depth the program cuts at: an inch program's is rounded to its increment
  Options measured_o = o;
  if (o.inch && !is_lathe(o) && !with_z)
    measured_o.depth = kMmPerInch * machine::round_to_increment(u.depth, std::round(1 / u.profile.increment));
  const AxisMap map = axis_map(curve, u);
  // the fit aims a little inside the tolerance: the round trip measures the control's own path
  Context c{curve,
            u,
            map,
            with_z,
            dec,
            feed_of(u),
            AxisWords{u, dec, with_z},
            geom::Fit{curve, map, grid, plane_of(u.profile), u.tol * 0.999},
            grid.snap(map(curve.point(curve.t0()))),
            grid.snap(map(curve.point(curve.t1()))),
            measured,
            measured_o};
  c.fit.survey = &survey;
  c.fit.arcs_with_r = u.profile.arcs_with_r;
  c.fit.r_step = u.profile.increment;
  c.fit.arc_radius_limit = u.profile.arc_radius_tolerance * 0.999;
  for (const auto& p : curve.params()) {  // the spiral's centre; other curves: their origin
    if (p.name == "cx") c.fit.centre[0] = in_program_units(u, p.value);
    if (p.name == "cy") c.fit.centre[1] = in_program_units(u, p.value);
  }
  c.fit.centre = map(c.fit.centre);
  Emitted e;
  switch (o.form) {
    case Form::expanded:
    case Form::arcs: e = expanded_or_arcs(c); break;
    case Form::macro: e = equal_step_macro(c); break;
    case Form::adaptive_macro: e = adaptive_macro(c); break;
    case Form::cycle: e = cycle(c); break;
  }
  Result r;
  r.text = std::move(e.text);
  r.parameters = e.parameters;
  r.macro = std::move(e.macro);
  Options on_control = measured_o;
  for (const auto& [key, value] : r.parameters) machine::set_parameter(on_control.profile, key, value);
  r.stats = detail::round_trip(r.text, measured, on_control, e.first, e.last, e.speculation.get());
  r.cutter_centre = std::move(cutter_centre);
  r.within_tolerance = r.stats.max_deviation <= o.tol;
  return r;
}

}  // namespace ncurve::gen
