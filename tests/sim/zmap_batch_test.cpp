// ZMap::cut_batch against the same sweeps cut and probed one after another (cut_line, cut_arc,
// probe_line, probe_arc): random lines, ramps, plunges, arcs and helices of every tool shape, the
// map equal to the bit, the cut that last lowered each cell the same, and every report equal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

#include "base/parallel.hpp"
#include "sim/zmap.hpp"

using namespace ncurve::sim;

namespace {

constexpr double kPi = std::numbers::pi;

// 30 x 20 x 10 mm on 0.1 mm cells: 300 x 200
ZMap stock() { return ZMap(Box{{0, 0, -10}, {30, 20, 0}}, 0.1); }

ToolShape random_tool(std::mt19937& rng) {
  std::uniform_real_distribution<double> radius(0.3, 3);
  const double r = radius(rng);
  switch (rng() % 4) {
    case 0: return ToolShape::flat(r);
    case 1: return ToolShape::ball(r);
    case 2: return ToolShape::bull_nose(r, r * std::uniform_real_distribution<double>(0.1, 0.9)(rng));
    default: return ToolShape::cone(r, std::uniform_real_distribution<double>(60, 140)(rng));
  }
}

// Lines (level, ramps, plunges) and arcs (level, helices of up to two turns), some reaching past the
// map; a quarter of them probes. Each is marked with its index.
std::vector<Sweep> random_sweeps(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-2, 32), y(-2, 22), z(-6, 1), unit(0, 1);
  std::vector<Sweep> out;
  for (std::size_t k = 0; k < n; ++k) {
    Sweep s;
    s.tool = random_tool(rng);
    s.probe = rng() % 4 == 0;
    s.a = {x(rng), y(rng), z(rng)};
    const double kind = unit(rng);
    if (kind < 0.3) {  // level
      s.b = {s.a[0] + 8 * (unit(rng) - 0.5), s.a[1] + 8 * (unit(rng) - 0.5), s.a[2]};
    } else if (kind < 0.6) {  // ramp
      s.b = {s.a[0] + 8 * (unit(rng) - 0.5), s.a[1] + 8 * (unit(rng) - 0.5), z(rng)};
    } else if (kind < 0.7) {  // plunge
      s.b = {s.a[0], s.a[1], z(rng)};
    } else {  // arc or helix
      Arc arc;
      arc.cx = s.a[0];
      arc.cy = s.a[1];
      arc.radius = 6 * unit(rng);
      arc.start_angle = 2 * kPi * (unit(rng) - 0.5);
      arc.sweep = 4 * kPi * (unit(rng) - 0.5);
      arc.z_start = z(rng);
      arc.z_end = kind < 0.85 ? arc.z_start : z(rng);
      s.arc = arc;
    }
    s.mark = static_cast<std::uint32_t>(k);
    out.push_back(s);
  }
  return out;
}

// The sweeps one after another, each cut marking its cells with its index, and what each reported.
std::vector<CutReport> one_by_one(ZMap& map, const std::vector<Sweep>& sweeps) {
  map.report_cuts(true);
  std::vector<CutReport> out;
  for (const Sweep& s : sweeps) {
    map.mark_cuts(static_cast<std::uint32_t>(out.size()));
    if (s.probe) {
      out.push_back(s.arc ? map.probe_arc(s.tool, *s.arc) : map.probe_line(s.tool, s.a, s.b));
      continue;
    }
    if (s.arc) map.cut_arc(s.tool, *s.arc);
    else map.cut_line(s.tool, s.a, s.b);
    out.push_back(map.last_cut());
  }
  return out;
}

bool same_heights(const ZMap& a, const ZMap& b) {
  return a.heights().size() == b.heights().size() &&
         std::memcmp(a.heights().data(), b.heights().data(), a.heights().size_bytes()) == 0;
}

}  // namespace

TEST(ZMapBatch, EqualsTheSweepsOneByOne) {
  const std::vector<Sweep> sweeps = random_sweeps(400, 36);
  ZMap ref = stock();
  const std::vector<CutReport> want = one_by_one(ref, sweeps);
  std::size_t removing = 0, probes_meeting = 0;
  for (std::size_t k = 0; k < sweeps.size(); ++k) {
    removing += !sweeps[k].probe && want[k].removed();
    probes_meeting += sweeps[k].probe && want[k].removed();
  }
  ASSERT_GT(removing, 100u);  // the batch is about something
  ASSERT_GT(probes_meeting, 20u);

  // one batch, and batches of uneven sizes
  for (std::size_t size : {sweeps.size(), std::size_t{1}, std::size_t{7}, std::size_t{150}}) {
    ZMap map = stock();
    map.mark_cuts(ZMap::kNoCut);  // each sweep marks the cells it lowers with its own
    std::vector<CutReport> got(sweeps.size());
    for (std::size_t k = 0; k < sweeps.size(); k += size) {
      const std::size_t m = std::min(size, sweeps.size() - k);
      map.cut_batch(std::span(sweeps).subspan(k, m), std::span(got).subspan(k, m));
    }
    EXPECT_TRUE(same_heights(map, ref)) << "batches of " << size;
    EXPECT_TRUE(std::equal(map.cut_by().begin(), map.cut_by().end(), ref.cut_by().begin(), ref.cut_by().end()))
        << "batches of " << size;
    EXPECT_EQ(map.volume_removed(), ref.volume_removed());
    for (std::size_t k = 0; k < sweeps.size(); ++k) {
      SCOPED_TRACE(testing::Message() << "batches of " << size << ", sweep " << k);
      EXPECT_EQ(got[k].volume, want[k].volume);
      EXPECT_EQ(got[k].deepest, want[k].deepest);
      EXPECT_EQ(got[k].i, want[k].i);
      EXPECT_EQ(got[k].j, want[k].j);
      EXPECT_EQ(got[k].from, want[k].from);
    }
  }
}

TEST(ZMapBatch, WithoutReportsTheProbesLeaveTheMap) {
  const std::vector<Sweep> sweeps = random_sweeps(200, 7);
  ZMap ref = stock();
  for (const Sweep& s : sweeps) {
    if (s.probe) continue;
    if (s.arc) ref.cut_arc(s.tool, *s.arc);
    else ref.cut_line(s.tool, s.a, s.b);
  }
  ZMap map = stock();
  map.cut_batch(sweeps);
  EXPECT_TRUE(same_heights(map, ref));
  EXPECT_GT(ref.volume_removed(), 0);
}

// The last cut's report stays readable, as after cut_line.
TEST(ZMapBatch, LastCutIsTheLastCutsReport) {
  std::vector<Sweep> sweeps(2);
  sweeps[0] = {ToolShape::flat(1), {5, 5, -1}, {10, 5, -1}, std::nullopt, false};
  sweeps[1] = {ToolShape::flat(5), {5, 5, -0.5}, {10, 5, -0.5}, std::nullopt, true};  // a probe
  ZMap map = stock();
  std::vector<CutReport> got(2);
  map.cut_batch(sweeps, got);
  // a 1 mm deep slot of width 2 and length 5 with round ends: 1 x (2 x 5 + pi), to the cells
  EXPECT_NEAR(map.last_cut().volume, 10 + kPi, std::sqrt(2.0) * 0.1 * (10 + 2 * kPi));
  EXPECT_EQ(map.last_cut().volume, got[0].volume);
  EXPECT_NEAR(got[0].deepest, 1, 1e-12);
  // the probe 0.5 mm deep meets the stock's top beside the slot, the slot's floor nowhere
  EXPECT_NEAR(got[1].deepest, 0.5, 1e-12);
  EXPECT_EQ(map.height_at(7, 5), -1);
}

// A batch cut while the cores' pool is busy (here: from its own work items, two maps at once) runs
// its bands on its own thread, to the same map.
TEST(ZMapBatch, WithThePoolBusy) {
  const std::vector<Sweep> sweeps = random_sweeps(150, 11);
  ZMap ref = stock();
  one_by_one(ref, sweeps);
  std::vector<ZMap> maps(2, stock());
  ncurve::base::for_each_on_cores(maps.size(), [&](std::size_t k) {
    maps[k].mark_cuts(ZMap::kNoCut);
    std::vector<CutReport> reports(sweeps.size());
    maps[k].cut_batch(sweeps, reports);
  });
  for (const ZMap& map : maps) EXPECT_TRUE(same_heights(map, ref));
}
