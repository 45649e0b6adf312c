// What the workbench colours the backplot by (docs/serve.md): the feed the planner reaches over
// each move (POST /api/analyze with "moves": true), and a generated program's curve as a polyline
// with each move's deviation from it (POST /api/gen).
#pragma once
#include <fmt/format.h>

#include <cstdint>
#include <deque>
#include <vector>

#include "gen/generate.hpp"
#include "machine/move.hpp"
#include "motion/planner.hpp"

namespace ncurve::serve {

// The feeds of each move of a run, indexed as /api/run's moves (events and moves the planner does
// not time, of no length, are 0). Give it every move (made) before the planner, and the planner's
// blocks (planned) as they are timed.
class FeedColumns {
public:
  explicit FeedColumns(std::size_t limit) : limit_(limit) {}
  void made(const machine::Move& m);
  void planned(const motion::BlockTime& b);
  // {"count", "complete", "message"?, "feed_programmed", "feed_peak", "feed_end"}
  void write_json(fmt::memory_buffer& b) const;

private:
  std::size_t limit_;
  std::uint64_t seen_ = 0;
  std::deque<std::uint64_t> waiting_;  // the moves made that the planner has yet to time, in order
  std::vector<float> programmed_, peak_, end_;
};

// The curve the program was measured against (the cutter centre's with a tool radius), placed as
// the program cuts it (the last depth pass), sampled until each chord is within `within` mm of the
// curve (checked at the quarters of each piece) or `most` points are reached.
struct CurvePolyline {
  std::vector<geom::Vec3> points;  // work coordinates, mm; lathe X as a radius
  double within = 0;               // the largest distance of the curve from a chord found at the checks
};
CurvePolyline curve_polyline(const geom::Curve& curve, const geom::Placement& placement, double within,
                             std::size_t most);

// ,"reference":{...},"move_deviation":{...} of /api/gen's answer (lathe X as a diameter where
// the profile programs diameters, as /api/run).
void write_gen_geometry(fmt::memory_buffer& b, const CurvePolyline& curve, const gen::Stats& stats,
                        const machine::MachineProfile& profile);

}  // namespace ncurve::serve
