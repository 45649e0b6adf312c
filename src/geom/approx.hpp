// Tool paths of lines and arcs within a shape tolerance of a curve, and the deviation measure
// that proves it (maximum distance, found by optimisation on each piece).
#pragma once
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "geom/curve.hpp"

namespace ncurve::geom {

// Where a curve point lands on the machine: axis a = curve[from[a]] + offset[a], or the offset
// alone where from[a] < 0 (a lathe profile drawn in x, y goes to Z, X; internal units: lathe X
// as a radius). The identity by default.
struct Placement {
  std::array<int, 3> from{0, 1, 2};
  Vec3 offset{0, 0, 0};
  Vec3 operator()(const Vec3& c) const {
    Vec3 out = direction(c);
    for (int a = 0; a < 3; ++a) out[a] += offset[a];
    return out;
  }
  // a derivative of the curve as it lies on the machine
  Vec3 direction(const Vec3& d) const {
    Vec3 out;
    for (int a = 0; a < 3; ++a) out[a] = from[a] >= 0 ? d[from[a]] : 0.0;
    return out;
  }
  // The same for many points held coordinate by coordinate (coordinate c's values at first + c *
  // stride): where the machine's axis a reads them, or `none` (zeros) where the curve has none.
  const double* component(std::size_t a, const double* first, std::size_t stride, const double* none) const {
    return from[a] >= 0 ? first + static_cast<std::size_t>(from[a]) * stride : none;
  }
};

// Where emitted coordinates land: each axis rounds to its least increment (in internal units:
// a lathe's diameter X rounds to half the increment as a radius).
class Grid {
public:
  Grid() : Grid(Vec3{0.001, 0.001, 0.001}) {}
  explicit Grid(const Vec3& step);  // a step of 0: the axis is not rounded
  const Vec3& step() const { return step_; }
  const Vec3& per_mm() const { return per_mm_; }
  Vec3 snap(const Vec3& p) const;
  double worst_error() const;  // largest distance snap() moves a point

private:
  Vec3 step_, per_mm_;  // per_mm_: 1 / step (a product is faster than a quotient)
};

// The plane of arcs: u = p[u_axis], v = p[v_axis], counter-clockwise in (u, v) is G03.
struct Plane {
  int u_axis = 0, v_axis = 1;
};

struct Piece {
  bool arc = false;
  Vec3 start{}, end{}, centre{};  // machine coordinates as emitted (snapped)
  bool ccw = false;
  double t0 = 0, t1 = 0;  // curve parameters the piece stands for
  double r = 0;           // arcs with R words: the R written (negative beyond 180 degrees)
};

// The most pieces a fit may make, counted over all its threads: the one beyond throws
// TooManyPieces (a fit of both ways may count part of the path twice).
struct PieceBudget {
  std::size_t most = 0;
  std::atomic<std::size_t> made{0};
  void add() {
    if (made.fetch_add(1, std::memory_order_relaxed) >= most) throw TooManyPieces(most);
  }
  struct TooManyPieces : std::runtime_error {
    explicit TooManyPieces(std::size_t most)
        : std::runtime_error("more than " + std::to_string(most) + " lines or arcs") {}
  };
};

struct Path {
  std::vector<Piece> pieces;
  double max_deviation = 0;  // as measured while building (exact, before the round trip)
};

// radial_error: seed 000's placement, vertices on the curve, the error measured along the ray from
// Fit::centre (the spiral's centre) to the curve point, to where it meets the chord.
enum class LineMethod { equal_step, equal_chord, equal_error, equal_error_on_curve, radial_error };

struct Fit {
  const Curve& curve;
  Placement place;
  Grid grid;
  Plane plane;
  double tol;
  Vec3 centre{0, 0, 0};  // radial_error: machine coordinates of the centre
  // arcs as the control will check and draw them
  bool arcs_with_r = false;        // R words: the control finds the centre from R and the ends
  double r_step = 0.001;           // increment of an R word
  double arc_radius_limit = 1e300;  // No.3410: start and end radius may differ by this much
  // Equal error: each step scanned on the quintic through the jets at its ends (a trial, one
  // curve evaluation, then steps estimated from that quintic and the few estimated within tried),
  // its deviation confirmed on the curve; off: every trial on the curve.
  bool model_steps = true;
  // Equal error on a long curve: cut where about this many segments are predicted, the pieces fit
  // on all cores (cuts depend on the curve alone; each join may cost a segment). 0: never cut.
  double chunk_segments = 4096;
  // Equal error on a curve not cut: fit from both ends at once (on two cores where there are),
  // joined where the two meet (see lines_both_ways: as few segments as the fit from the start,
  // give or take one); the same result on any machine. Off: from the start alone.
  bool both_ways = true;
  // The curve's survey, from its validate(): spares the prediction of equal-error steps its jets.
  const Survey* survey = nullptr;
  PieceBudget* budget = nullptr;  // none: no bound
};

Path fit_lines(const Fit& fit, LineMethod method);
Path fit_arcs(const Fit& fit);  // biarcs, tangent-continuous, split at inflections

// Largest distance from the curve over [ta, tb] to the geometry dist() measures, and where.
struct Worst {
  double distance = 0;
  double t = 0;
};
Worst max_distance(const Curve& curve, const Placement& place, double ta, double tb,
                   const std::function<double(const Vec3&)>& dist);

// Placed point, first and second derivative (placements are affine).
struct PlacedJet {
  Vec3 p, d1, d2;
};
PlacedJet placed_jet(const Curve& curve, const Placement& place, double t);
PlacedJet placed_jet(const Curve::Jet& j, const Placement& place);

// max_distance with the placed jets at ta and tb known: the maximum is placed on the quintic
// through them and its value taken on the curve, where it must be a local maximum (the curve no
// higher a little to either side) and agree with the quintic within `trust`; otherwise (a step
// too long for the quintic) the search on the curve alone. `samples` steps on the quintic before
// Brent's method: 4 for a segment (humps at the ends and in the middle), 6 for an arc.
Worst max_distance(const Curve& curve, const Placement& place, double ta, double tb, const PlacedJet& a,
                   const PlacedJet& b, const std::function<double(const Vec3&)>& dist, double trust,
                   int samples = 6);

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b);
class Segment;
// max_distance to a segment: its humps on the quintic found by Newton's method on the distance
// across the segment, a polynomial (no search through a distance function).
Worst max_distance(const Curve& curve, const Placement& place, double ta, double tb, const PlacedJet& a,
                   const PlacedJet& b, const Segment& segment, double trust);
// The same for many points against one segment (its direction and length worked out once).
class Segment {
public:
  Segment() : Segment(Vec3{0, 0, 0}, Vec3{0, 0, 0}) {}
  Segment(const Vec3& a, const Vec3& b) : a_(a), ab_{b[0] - a[0], b[1] - a[1], b[2] - a[2]} {
    const double len2 = ab_[0] * ab_[0] + ab_[1] * ab_[1] + ab_[2] * ab_[2];
    inv_len2_ = len2 > 0 ? 1 / len2 : 0;
  }
  const Vec3& start() const { return a_; }
  const Vec3& vector() const { return ab_; }  // start to end
  double distance(const Vec3& p) const {
    const double ax = p[0] - a_[0], ay = p[1] - a_[1], az = p[2] - a_[2];
    double s = (ax * ab_[0] + ay * ab_[1] + az * ab_[2]) * inv_len2_;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    const double dx = ax - s * ab_[0], dy = ay - s * ab_[1], dz = az - s * ab_[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  }

private:
  Vec3 a_, ab_;
  double inv_len2_;
};
// max_distance to a segment for many pieces at once: the curve jets that confirm their humps are
// evaluated together (Curve::jets), which may differ from one-point jets in the last bits.
struct SegmentPiece {
  double ta = 0, tb = 0;
  PlacedJet a{}, b{};  // at ta and tb
  Segment segment;
};
void max_distances(const Curve& curve, const Placement& place, std::span<const SegmentPiece> pieces, double trust,
                   std::span<Worst> out);

// Distance from p to where the ray from centre through p meets the line ab, in the plane (u, v).
double radial_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& centre, const Plane& plane);
// Distance to an arc in the plane from start to end about centre (radius varying linearly from
// the start radius to the end radius, as a control interpolates a slightly unequal arc), with
// the out-of-plane coordinate interpolated linearly (helix).
double point_arc_distance(const Vec3& p, const Piece& arc, const Plane& plane);

// Parameters where the curve's turning direction in the plane changes sign.
std::vector<double> inflections(const Curve& curve, const Placement& place, const Plane& plane);

}  // namespace ncurve::geom
