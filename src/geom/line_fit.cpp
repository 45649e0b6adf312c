// Line fitting: greedy longest segments within the tolerance (the step scanned on the quintic),
// long curves cut into chunks fit on all cores or fit from both ends at once, and the equal-step
// and equal-chord fits.
#include "geom/approx.hpp"
#include "base/memory.hpp"
#include "base/parallel.hpp"
#include "base/vector_clones.hpp"
#include "geom/fit_internal.hpp"
#include "geom/quintic.hpp"
#include "geom/search.hpp"
#include "geom/segment_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace ncurve::geom {
using namespace fit;

namespace {

// max_distance with the placed curve points at both ends already known.
template <class Dist>
double deviation(const Fit& f, double ta, double tb, const Vec3& at_ta, const Vec3& at_tb, Dist dist) {
  auto at = [&](double t) { return dist(t == ta ? at_ta : t == tb ? at_tb : f.place(f.curve.point(t))); };
  return sampled_maximum(at, ta, tb, kPieceSamples, kPieceResolution * (tb - ta)).value;
}

struct Vertex {
  Vec3 at;           // as emitted (snapped)
  Local curve;       // the placed curve there
  Vec3 aimed;        // before snapping
  Vec3 normal;       // the curve's outward normal there
  double curvature;  // and its curvature
};

// Vertices: exact curve points at both ends of the range, elsewhere the curve point moved outward
// by `offset` (a band of +-tol holds segments about 1.4 times longer than chords), then snapped.
Vertex vertex(const Fit& f, double t, double offset) {
  Vertex v;
  v.curve = local(f, t);
  v.curvature = outward(v.curve, v.normal);
  v.aimed = v.curve.p;
  if (offset > 0 && t > f.curve.t0() && t < f.curve.t1()) v.aimed = add(v.curve.p, scale(v.normal, offset));
  v.at = f.grid.snap(v.aimed);
  return v;
}

double segment_error(const Fit& f, double ta, double tb, const Vertex& a, const Vertex& b, bool radial = false) {
  if (radial)
    return deviation(f, ta, tb, a.curve.p, b.curve.p,
                     [&](const Vec3& p) { return radial_distance(p, a.at, b.at, f.centre, f.plane); });
  const Segment ab(a.at, b.at);
  return deviation(f, ta, tb, a.curve.p, b.curve.p, [&](const Vec3& p) { return ab.distance(p); });
}

// Steps are searched to 0.3 %: closer, the coordinate rounding decides more than the step does.
constexpr double kStepRel = 3e-3;

// The scan's test of kScanBatch steps at once, its loops on vectors: over[j] is whether the hump
// P at hump_at * s[j] on the quintic lies farther than `limit` from the line from A (`start`) to
// B, the end at s[j] moved by `offset` and snapped: |AP x AB|^2 > limit^2 |AB|^2, computed as
// the scan computes one step (the same operations in the same order). False if a coordinate is
// beyond the fast rounding's reach (the scan then tests those steps one at a time).
// With kAxes = 2, z left out: where the quintic, the offset and the start have none, z adds zeros
// (the same figures).
constexpr std::size_t kScanBatch = 8;
template <int kAxes>
[[gnu::always_inline]] inline bool scan_batch_on(const Quintic& q, const Vec3& offset, const Vec3& start,
                                                 const Grid& grid, double hump_at, double limit2, const double* s,
                                                 bool* over) {
  constexpr double kShift = 0x1.8p52;
  double ab[3][kScanBatch] = {}, ap[3][kScanBatch] = {}, steps[kScanBatch];
  bool in_reach = true;
  for (int a = 0; a < kAxes; ++a) {
    const double o = q.origin[a], c0 = q.c[0][a], c1 = q.c[1][a], c2 = q.c[2][a], c3 = q.c[3][a], c4 = q.c[4][a];
    const double moved = offset[a], from = start[a], step = grid.step()[a], per_mm = grid.per_mm()[a];
    for (std::size_t j = 0; j < kScanBatch; ++j) {
      const double sj = s[j], sh = hump_at * sj;
      ab[a][j] = (o + sj * (c0 + sj * (c1 + sj * (c2 + sj * (c3 + sj * c4))))) + moved;
      ap[a][j] = (o + sh * (c0 + sh * (c1 + sh * (c2 + sh * (c3 + sh * c4))))) - from;
    }
    if (step > 0) {
      for (std::size_t j = 0; j < kScanBatch; ++j) {
        steps[j] = ab[a][j] * per_mm;
        ab[a][j] = ((steps[j] + kShift) - kShift) * step - from;
      }
      for (std::size_t j = 0; j < kScanBatch; ++j) in_reach = in_reach && std::fabs(steps[j]) < 0x1p51;
    } else {
      for (std::size_t j = 0; j < kScanBatch; ++j) ab[a][j] -= from;
    }
  }
  for (std::size_t j = 0; j < kScanBatch; ++j) {
    const double cz = ap[0][j] * ab[1][j] - ap[1][j] * ab[0][j];
    if constexpr (kAxes == 2) {
      over[j] = cz * cz > limit2 * (ab[0][j] * ab[0][j] + ab[1][j] * ab[1][j]);
    } else {
      const double cx = ap[1][j] * ab[2][j] - ap[2][j] * ab[1][j];
      const double cy = ap[2][j] * ab[0][j] - ap[0][j] * ab[2][j];
      const double length2 = ab[0][j] * ab[0][j] + ab[1][j] * ab[1][j] + ab[2][j] * ab[2][j];
      over[j] = cx * cx + cy * cy + cz * cz > limit2 * length2;
    }
  }
  return in_reach;
}
NCURVE_VECTOR_CLONES bool scan_batch(const Quintic& q, const Vec3& offset, const Vec3& start, const Grid& grid,
                                     double hump_at, double limit2, const double* s, bool* over) {
  return scan_batch_on<3>(q, offset, start, grid, hump_at, limit2, s, over);
}
NCURVE_VECTOR_CLONES bool scan_batch_xy(const Quintic& q, const Vec3& offset, const Vec3& start, const Grid& grid,
                                        double hump_at, double limit2, const double* s, bool* over) {
  return scan_batch_on<2>(q, offset, start, grid, hump_at, limit2, s, over);
}

double band_offset(const Fit& f, bool band) { return band ? std::max(0.0, f.tol - f.grid.worst_error()) : 0.0; }
// how far a segment's deviation on the quintic and on the curve may differ (see confirmed)
double trust_of(const Fit& f) { return 1e-3 * f.tol; }

// Greedy longest segments from `from` to `to` (vertices there as anywhere else in the curve),
// room made for `expected` of them; ended early at the first vertex at or beyond `stop`. With
// `errors`, each segment's deviation is noted there.
Path lines_greedy(const Fit& f, bool band, bool radial, double from, double to, std::size_t expected = 0,
                  double stop = std::numeric_limits<double>::infinity(), std::vector<double>* errors = nullptr) {
  Path path;
  path.pieces.reserve(expected);
  const double t_end = to;
  const double span = f.curve.t1() - f.curve.t0();
  const double offset = band_offset(f, band);
  const double trust = trust_of(f);
  double ta = from;
  Vertex a = vertex(f, ta, offset);
  double learned = 1;  // the last step over its curvature prediction (the band, the rounding)
  while (ta < t_end && ta < stop) {
    Vertex b{};
    double b_error = 0, b_t = ta;  // the longest segment within the tolerance tried so far
    ModelMaxima b_model{};
    const double predicted = step_guess(f, a.curve, a.curvature, f.tol + offset);
    // a step tried on the quintic; the longest within the tolerance kept in b
    struct Tried {
      double e;
      ModelMaxima m;
      Vertex end;
    };
    auto tried_with = [&](double tb, const Vertex& end, const SegmentQuintic& model) {
      Tried r{0, model.maxima(kLineSamples), end};
      r.e = r.m.best.value;
      if (r.e <= f.tol && tb > b_t) b = r.end, b_error = r.e, b_t = tb, b_model = r.m;
      return r;
    };
    auto tried_on_model = [&](double tb) {
      const Vertex end = vertex(f, tb, offset);
      return tried_with(tb, end, SegmentQuintic(a.curve, end.curve, tb - ta, Segment(a.at, end.at)));
    };
    auto longest = [&](bool on_model) {
      b_t = ta;
      auto error_to = [&](double tb) {
        if (on_model) return tried_on_model(tb).e;
        Vertex end = vertex(f, tb, offset);
        const double e = segment_error(f, ta, tb, a, end, radial);
        if (e <= f.tol && tb > b_t) b = end, b_error = e, b_t = tb;
        return e;
      };
      double tb = longest_within(ta, t_end, std::min(t_end, ta + predicted * learned), f.tol, offset, error_to, span, [&] {
        return fmt::format("{}: no segment from t = {:.6g} stays within {} mm (tolerance below the machine increment?)",
                           f.curve.name(), ta, f.tol);
      }, kStepRel);
      if (tb != b_t) throw std::logic_error("lines_greedy: the step found was not the longest one measured");
      return tb;
    };
    // The step by a scan: the curve's jet at a first step, the guess, gives the quintic over it,
    // from which the error of longer and shorter steps is estimated without the curve: their end
    // vertex aimed and snapped, their hump where the first step's lies in proportion (its
    // distance is stationary there, so the estimate is off by second-order terms; the first
    // step's own error calibrates it). From a little beyond where the estimate without rounding meets the
    // tolerance, down in steps of 0.1 %, each step estimated within goes on trial until one is:
    // the rounding of the end vertex makes some steps a few per cent longer than others around
    // them, and the scan finds them. NaN where that does not settle it (no hump inside, three
    // trials over).
    auto scanned = [&]() {
      constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
      constexpr double kAbove = 0.02, kBelow = 0.04, kStep = 0.001;
      constexpr int kTrials = 3;
      b_t = ta;
      const double h0 = std::min(t_end, ta + predicted * learned) - ta, t0 = ta + h0;
      const Vertex first = vertex(f, t0, offset);
      // its hump by Newton's method from the middle; the first step goes on trial when the scan
      // comes down to it (or at once, where that finds no hump above both ends or the step ends
      // the curve)
      const SegmentQuintic first_model(a.curve, first.curve, h0, Segment(a.at, first.at));
      Maximum hump = first_model.middle_hump();
      bool first_tried = false;
      if (t0 == t_end || !(hump.value * hump.value > std::max(first_model.at(0), first_model.at(1)))) {
        const Tried r = tried_with(t0, first, first_model);
        first_tried = true;
        if (t0 == t_end && r.e <= f.tol) return t_end;
        hump = {-1, 0};
        for (const Maximum& m : {r.m.best, r.m.second})
          if (m.at > 0 && m.at < 1 && m.value > hump.value) hump = m;
        if (!(hump.value >= 0)) return kNaN;
      }
      const Quintic q = Quintic::through(a.curve.p, a.curve.d1, a.curve.d2, first.curve.p, first.curve.d1,
                                         first.curve.d2, h0);
      const Vec3 offset_vector = offset > 0 ? scale(first.normal, offset) : Vec3{0, 0, 0};
      const bool in_xy = q.c[0][2] == 0 && q.c[1][2] == 0 && q.c[2][2] == 0 && q.c[3][2] == 0 && q.c[4][2] == 0 &&
                         offset_vector[2] == 0 && q.origin[2] == a.at[2] && !(f.grid.step()[2] > 0);
      // |AP x AB|^2 and |AB|^2 (the hump's distance from the line squared is their ratio) for the
      // step h, from a to the end aimed at (snapped, or both ends as aimed)
      auto across = [&](double h, bool snapped, double& length2) {
        const double s = h / h0;
        const Vec3& start = snapped ? a.at : a.aimed;
        const Vec3 aimed = add(q.at(s), offset_vector);
        const Vec3 ab = sub(snapped ? f.grid.snap(aimed) : aimed, start);
        const Vec3 c = cross(sub(q.at(hump.at * s), start), ab);
        length2 = dot(ab, ab);
        return dot(c, c);
      };
      auto estimate = [&](double h, bool snapped) {
        double length2 = 0;
        const double c2 = across(h, snapped, length2);
        return std::sqrt(c2 / length2);
      };
      const double calibration = hump.value - estimate(h0, true);
      const double smooth = estimate(h0, false) + calibration;
      if (!(smooth + offset > 0)) return kNaN;
      const double h_tol = h0 * std::sqrt((f.tol + offset) / (smooth + offset));
      const double limit = f.tol - calibration;  // on the estimate
      if (!(limit > 0)) return kNaN;
      // the steps' tests, a batch at a time as the scan comes to them
      std::array<double, kScanBatch> batch_s{};
      std::array<bool, kScanBatch> batch_over{};
      std::size_t batch_first = 0, batch_end = 0;  // the steps tested: [batch_first, batch_end)
      double batch_rel = 1 + kAbove;                // the rel of step batch_end, as the scan steps it
      bool batches = true;
      auto over_limit = [&](std::size_t i, double h) {
        if (batches && i >= batch_end) {
          for (; batch_end < i; ++batch_end) batch_rel -= kStep;
          batch_first = batch_end;
          for (std::size_t j = 0; j < kScanBatch; ++j, ++batch_end, batch_rel -= kStep)
            batch_s[j] = std::min(h_tol * batch_rel, t_end - ta) / h0;  // as the scan's h (past its end too)
          batches = (in_xy ? scan_batch_xy : scan_batch)(q, offset_vector, a.at, f.grid, hump.at, limit * limit,
                                                         batch_s.data(), batch_over.data());
        }
        if (batches) return batch_over[i - batch_first];
        double length2 = 0;
        return across(h, true, length2) > limit * limit * length2;
      };
      int trials = 0;
      double h_before = 0;
      std::size_t i = 0;
      for (double rel = 1 + kAbove; rel >= 1 - kBelow && trials < kTrials; rel -= kStep, ++i) {
        const double h = std::min(h_tol * rel, t_end - ta);
        if (!first_tried && h <= h0) {
          first_tried = true;
          if (tried_with(t0, first, first_model).e <= f.tol) return b_t;
        }
        if (ta + h <= b_t) return b_t;  // the first trial was longer
        if (h == h_before || over_limit(i, h)) continue;
        h_before = h;
        ++trials;
        if (tried_on_model(ta + h).e <= f.tol) return b_t;
      }
      if (!first_tried) tried_with(t0, first, first_model);
      return b_t > ta ? b_t : kNaN;
    };
    const bool on_model = f.model_steps && !radial;
    double tb = on_model ? scanned() : std::numeric_limits<double>::quiet_NaN();
    if (std::isnan(tb)) tb = longest(on_model);
    if (on_model) {
      const Segment ab(a.at, b.at);
      auto on_curve = [&](const Maximum& m) { return confirmed(f.curve, f.place, ab, ta, tb - ta, m, trust); };
      double e = confirmed(on_curve, b_model, trust).value;
      if (e <= f.tol) b_error = e;
      else tb = longest(false);  // the quintic misleads here: every trial on the curve
    }
    if (tb < t_end) learned = std::clamp((tb - ta) / predicted, 0.25, 4.0);
    path.max_deviation = std::max(path.max_deviation, b_error);
    if (f.budget) f.budget->add();
    path.pieces.push_back(Piece{false, a.at, b.at, {}, false, ta, tb});
    if (errors) errors->push_back(b_error);
    ta = tb;
    a = b;
  }
  return path;
}

// The segments predicted from the curvature (a sag of the tolerance, with the band) from the
// start of the curve up to each of kSamples equal steps in its parameter.
struct Prediction {
  static constexpr std::size_t kSamples = Survey::kSteps;
  std::vector<double> ts, segments;
  double total() const { return segments.back(); }
  // where `count` segments are predicted (0 < count < total())
  double where(double count) const {
    std::size_t i = 1;
    while (segments[i] < count) ++i;
    const double f_in = (count - segments[i - 1]) / (segments[i] - segments[i - 1]);
    return ts[i - 1] + f_in * (ts[i] - ts[i - 1]);
  }
};
// 1 / step_guess at n points from their first and second derivatives (d[0..2][i], d[3..5][i]),
// on vectors: the same operations as outward() and step_guess().
NCURVE_VECTOR_CLONES void step_densities(std::size_t n, const double* const* d, double h, double range, double* out) {
  for (std::size_t i = 0; i < n; ++i) {
    const double ax = d[0][i], ay = d[1][i], az = d[2][i], bx = d[3][i], by = d[4][i], bz = d[5][i];
    const double s2 = ax * ax + ay * ay + az * az;
    const double along = (bx * ax + by * ay + bz * az) / s2;
    const double px = bx - ax * along, py = by - ay * along, pz = bz - az * along;
    const double k = std::sqrt(px * px + py * py + pz * pz) / s2;
    const double speed = std::sqrt(s2);
    const double guess = std::sqrt(8 * h / k) / speed;  // in every lane, then chosen: no branch
    out[i] = 1 / ((k > 1e-12) & (speed > 0) & (guess < range) ? guess : range);
  }
}

Prediction predicted_segments(const Fit& f, bool band) {
  constexpr std::size_t kPoints = Prediction::kSamples + 1;
  const double t0 = f.curve.t0(), t1 = f.curve.t1(), h = f.tol + band_offset(f, band);
  Prediction p;
  p.ts.resize(kPoints);
  p.segments.assign(kPoints, 0.0);
  for (std::size_t i = 0; i < kPoints; ++i) p.ts[i] = t0 + (t1 - t0) * static_cast<double>(i) / Prediction::kSamples;
  std::optional<Survey> own;
  const Survey& survey = f.survey ? *f.survey : own.emplace(f.curve.survey());
  // placed (Placement::component)
  const std::vector<double> none(kPoints, 0.0);
  const double* d[6];
  for (std::size_t a = 0; a < 3; ++a) {
    d[a] = f.place.component(a, survey.d1(0), Survey::kPoints, none.data());
    d[3 + a] = f.place.component(a, survey.d2(0), Survey::kPoints, none.data());
  }
  std::vector<double> density(kPoints);
  step_densities(kPoints, d, h, t1 - t0, density.data());
  for (std::size_t i = 1; i < kPoints; ++i)
    p.segments[i] = p.segments[i - 1] + 0.5 * (density[i] + density[i - 1]) * (p.ts[i] - p.ts[i - 1]);
  return p;
}

// Where a long curve is cut to be fit on several threads at once: about every
// Fit::chunk_segments predicted segments.
struct Chunks {
  std::vector<double> cuts;
  double segments = 0;  // predicted in each
};
Chunks chunk_cuts(const Fit& f, const Prediction& p) {
  const double t0 = f.curve.t0(), t1 = f.curve.t1(), total = p.total();
  if (!(f.chunk_segments > 0) || !std::isfinite(total)) return {{t0, t1}, total};
  const int chunks = std::max(1, static_cast<int>(std::min(total / f.chunk_segments, 64.0)));
  std::vector<double> cuts{t0};
  for (int k = 1; k < chunks; ++k) cuts.push_back(p.where(total * k / chunks));
  cuts.push_back(t1);
  return {cuts, total / chunks};
}

// Fewer predicted segments than this are fit from the start alone.
constexpr double kBothWaysSegments = 16;

// A join is not searched on the curve where its deviation on the quintic through its ends is over
// this many tolerances. On a segment within the tolerance the quintic is off by about a thousandth
// of one, and by the sixth power of the length on a longer one: a join twice as long, 0.07.
constexpr double kJoinHopeless = 1.5;

// The greedy fit from both ends at once (on two cores where there are two), each going to its
// first vertex past `middle`: forwards F0 = t0 .. FK, backwards B0 = t1 .. BJ. Where the longest
// step from a point reaches no less from a later point, k plus the fewest backward steps that reach
// back to Fk is the fewest segments for every k; so F0 .. F(K-1), one segment to the first Bj at or
// before FK, then on to B0, is the fewest. Neither greedy fit is exact (the rounding of vertices
// breaks the rule, steps are searched to a fraction of a per cent), so the joins of one segment
// fewer are tried first; a join is taken where it is within the tolerance, else the forward fit
// goes on to the end. The result depends on the curve alone, not on the threads.
Path lines_both_ways(const Fit& f, bool band, bool radial, double middle, std::size_t expected) {
  const Curve back_curve = f.curve.reversed();
  const Fit back{back_curve, f.place, f.grid,      f.plane,        f.tol,          f.centre,
                 f.arcs_with_r, f.r_step, f.arc_radius_limit, f.model_steps, f.chunk_segments, f.both_ways,
                 nullptr,     f.budget};
  const double t0 = f.curve.t0(), t1 = f.curve.t1();
  Path ahead, behind;
  std::vector<double> ahead_errors, behind_errors;
  bool behind_failed = false;  // its error would name t traced backwards: the forward fit names it
  base::for_each_on_cores(2, [&](std::size_t k) {
    if (k == 0) {
      ahead = lines_greedy(f, band, radial, t0, t1, expected, middle, &ahead_errors);
      return;
    }
    try {
      behind = lines_greedy(back, band, radial, -t1, -t0, expected, -middle, &behind_errors);
    } catch (const std::runtime_error&) {
      behind_failed = true;
    }
  });
  const std::size_t K = ahead.pieces.size();
  const double reached = ahead.pieces.back().t1;
  auto ahead_to_the_end = [&] {
    if (reached < t1) {
      Path rest = lines_greedy(f, band, radial, reached, t1);
      ahead.max_deviation = std::max(ahead.max_deviation, rest.max_deviation);
      ahead.pieces.insert(ahead.pieces.end(), rest.pieces.begin(), rest.pieces.end());
    }
    return ahead;
  };
  if (behind_failed || reached >= t1) return ahead_to_the_end();
  // the vertices: F[k] = ahead's k-th, B[j] = behind's j-th (B[0] = t1), each with its point
  std::vector<double> F{t0}, B{t1};
  for (const Piece& p : ahead.pieces) F.push_back(p.t1);
  for (const Piece& p : behind.pieces) B.push_back(-p.t1);
  auto forward_point = [&](std::size_t k) { return k == 0 ? ahead.pieces[0].start : ahead.pieces[k - 1].end; };
  auto backward_point = [&](std::size_t j) { return j == 0 ? behind.pieces[0].start : behind.pieces[j - 1].end; };
  // the first backward vertex at or before FK, and the last forward vertex before that
  std::size_t j = 1;
  while (B[j] > reached) ++j;
  std::size_t k = K - 1;
  while (k > 0 && F[k] >= B[j]) --k;
  // the joins of one segment fewer, shortest first, then the join the rule gives
  struct Join {
    std::size_t k, j;
  };
  std::vector<Join> joins;
  for (std::size_t dk = 0; dk <= 2; ++dk)  // (k - 1, j), (k, j - 1), (k + 1, j - 2)
    if (k + dk >= 1 && k + dk <= K + 1 && j >= dk && F[k + dk - 1] < B[j - dk]) joins.push_back({k + dk - 1, j - dk});
  std::sort(joins.begin(), joins.end(), [&](const Join& a, const Join& b) { return B[a.j] - F[a.k] < B[b.j] - F[b.k]; });
  if (F[k] < B[j]) joins.push_back({k, j});
  const double offset = band_offset(f, band);
  for (const Join& join : joins) {
    const double ta = F[join.k], tb = B[join.j];
    const Vertex a = vertex(f, ta, offset), b = vertex(f, tb, offset);
    double error;
    if (radial) {
      error = segment_error(f, ta, tb, a, b, true);
    } else {
      const Segment segment(a.at, b.at);
      const ModelMaxima model = on_quintic(a.curve, b.curve, tb - ta, segment, kLineSamples);
      if (model.best.value > kJoinHopeless * f.tol) continue;
      error = segment_maximum(f.curve, f.place, ta, tb, a.curve, segment, trust_of(f), [&](double) { return model; })
                  .distance;
    }
    if (!(error <= f.tol)) continue;
    Path path;
    path.pieces.reserve(join.k + 1 + join.j);
    path.pieces.assign(ahead.pieces.begin(), ahead.pieces.begin() + static_cast<std::ptrdiff_t>(join.k));
    path.pieces.push_back(Piece{false, forward_point(join.k), backward_point(join.j), {}, false, ta, tb});
    for (std::size_t i = join.j; i-- > 0;) {
      const Piece& p = behind.pieces[i];
      path.pieces.push_back(Piece{false, p.end, p.start, {}, false, -p.t1, -p.t0});
    }
    path.max_deviation = error;
    for (std::size_t i = 0; i < join.k; ++i) path.max_deviation = std::max(path.max_deviation, ahead_errors[i]);
    for (std::size_t i = 0; i < join.j; ++i) path.max_deviation = std::max(path.max_deviation, behind_errors[i]);
    return path;
  }
  return ahead_to_the_end();
}

Path lines_in_chunks(const Fit& f, bool band, bool radial = false) {
  const Prediction prediction = predicted_segments(f, band);
  const Chunks c = chunk_cuts(f, prediction);
  const std::vector<double>& cuts = c.cuts;
  const std::size_t chunks = cuts.size() - 1;
  // room for twice the prediction: pages never written cost nothing
  const auto expected = std::isfinite(c.segments) ? static_cast<std::size_t>(2 * c.segments) + 16 : 0;
  if (chunks == 1) {
    if (f.both_ways && prediction.total() >= kBothWaysSegments && std::isfinite(prediction.total()))
      return lines_both_ways(f, band, radial, prediction.where(prediction.total() / 2), expected / 2 + 8);
    return lines_greedy(f, band, radial, cuts[0], cuts[1]);
  }
  std::vector<Path> parts(chunks);
  base::for_each_on_cores(chunks, [&](std::size_t k) {
    parts[k] = lines_greedy(f, band, radial, cuts[k], cuts[k + 1], expected);
  });
  Path path;
  std::size_t pieces = 0;
  for (const Path& part : parts) pieces += part.pieces.size();
  base::reserve_large(path.pieces, pieces);
  for (std::size_t k = 0; k < chunks; ++k) {
    path.max_deviation = std::max(path.max_deviation, parts[k].max_deviation);
    path.pieces.insert(path.pieces.end(), parts[k].pieces.begin(), parts[k].pieces.end());
  }
  return path;
}

// All chords for the given parameters (vertices on the curve); the largest error.
double chords_error(const Fit& f, const std::vector<double>& ts, Path* out) {
  double worst = 0;
  Vertex a = vertex(f, ts[0], 0);
  for (std::size_t i = 1; i < ts.size(); ++i) {
    Vertex b = vertex(f, ts[i], 0);
    double e = segment_error(f, ts[i - 1], ts[i], a, b);
    worst = std::max(worst, e);
    if (out && f.budget) f.budget->add();
    if (out) out->pieces.push_back(Piece{false, a.at, b.at, {}, false, ts[i - 1], ts[i]});
    a = b;
  }
  return worst;
}

std::vector<double> equal_steps(const Fit& f, long n) {
  std::vector<double> ts;
  for (long i = 0; i <= n; ++i) ts.push_back(f.curve.t0() + (f.curve.t1() - f.curve.t0()) * i / n);
  return ts;
}

std::vector<double> equal_chords(const Fit& f, double length) {
  std::vector<double> ts{f.curve.t0()};
  const double t_end = f.curve.t1(), span = t_end - f.curve.t0();
  while (ts.back() < t_end) {
    double ta = ts.back();
    Vec3 pa = f.place(f.curve.point(ta));
    auto shorter = [&](double t) { return norm(sub(f.place(f.curve.point(t)), pa)) <= length; };
    if (shorter(t_end)) {
      ts.push_back(t_end);
      break;
    }
    double speed = norm(local(f, ta).d1);
    double hi = std::min(t_end, ta + 1.5 * length / std::max(speed, 1e-12));
    while (shorter(hi) && hi < t_end) hi = std::min(t_end, ta + 2 * (hi - ta));
    ts.push_back(largest_ok(ta, hi, shorter, span));
    if (ts.size() > 50'000'000) throw std::runtime_error("too many segments");
    if (f.budget && ts.size() > f.budget->most + 1) throw PieceBudget::TooManyPieces(f.budget->most);
  }
  return ts;
}

template <class Make>
long smallest_passing(long lo_fail, long hi, Make passes) {  // passes(hi) is true, passes(lo_fail) false
  while (hi - lo_fail > 1) {
    long mid = lo_fail + (hi - lo_fail) / 2;
    if (passes(mid)) hi = mid; else lo_fail = mid;
  }
  return hi;
}

}  // namespace

Path fit_lines(const Fit& f, LineMethod method) {
  if (f.tol <= f.grid.worst_error())
    throw std::runtime_error(fmt::format("tolerance {} mm is not above the coordinate rounding ({:.6f} mm)", f.tol,
                                         f.grid.worst_error()));
  switch (method) {
    case LineMethod::equal_error: return lines_in_chunks(f, true);
    case LineMethod::equal_error_on_curve: return lines_in_chunks(f, false);
    case LineMethod::radial_error: return lines_in_chunks(f, false, true);
    case LineMethod::equal_step: {
      auto passes = [&](long n) { return chords_error(f, equal_steps(f, n), nullptr) <= f.tol; };
      long n = 1;
      while (!passes(n)) {
        n *= 2;
        if (n > (1L << 24)) throw std::runtime_error("no equal step meets the tolerance");
        if (f.budget && n / 2 >= static_cast<long>(f.budget->most)) throw PieceBudget::TooManyPieces(f.budget->most);
      }
      n = smallest_passing(n / 2, n, passes);
      Path p;
      p.max_deviation = chords_error(f, equal_steps(f, n), &p);
      return p;
    }
    case LineMethod::equal_chord: {
      // the longest chord length for which every chord is within the tolerance (bisection on length)
      Vec3 a = f.place(f.curve.point(f.curve.t0()));
      double total = 0;
      constexpr int kRough = 256;
      for (int i = 1; i <= kRough; ++i) {
        double t = f.curve.t0() + (f.curve.t1() - f.curve.t0()) * i / kRough;
        Vec3 q = f.place(f.curve.point(t));
        total += norm(sub(q, a));
        a = q;
      }
      auto passes = [&](double len) { return chords_error(f, equal_chords(f, len), nullptr) <= f.tol; };
      double lo = 0, hi = total;
      double len = total;
      while (!passes(len)) {
        hi = len;
        len /= 2;
        if (len < 1e-9) throw std::runtime_error("no chord length meets the tolerance");
      }
      lo = len;
      for (int i = 0; i < 30 && hi - lo > 1e-6 * lo; ++i) {
        double mid = 0.5 * (lo + hi);
        if (passes(mid)) lo = mid; else hi = mid;
      }
      Path p;
      p.max_deviation = chords_error(f, equal_chords(f, lo), &p);
      return p;
    }
  }
  return {};
}

}  // namespace ncurve::geom
