// The cut part against a design (src/sim/design_check*): a 40 x 40 x 10 block with a channel 10
// wide and 5 deep along X, cut by a 6 mm end mill in two passes; the amounts worked by hand from
// the walls and the 0.04 mm cells (centres at odd multiples of 0.02: the walls at Y+-5 fall
// between 4.98 and 5.02).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <random>

#include "sim/design_check.hpp"
#include "sim/mesh_top.hpp"
#include "support/meshes.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

const char* const kSetup = R"(
[stock]
shape = "box"
min = [-20, -20, -10]
max = [20, 20, 0]

[tools.1]
kind = "flat"
diameter = 6
flute_length = 20
)";

// The design as three boxes side by side (the check reads only its top): Z0 beside the channel,
// Z-5 in it.
sim::Mesh design() {
  sim::Mesh m;
  for (const sim::Mesh& b : {test::box_mesh(-20, 20, -20, -5, -10, 0), test::box_mesh(-20, 20, -5, 5, -10, -5),
                             test::box_mesh(-20, 20, 5, 20, -10, 0)}) {
    const auto n = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (auto t : b.triangles) m.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  }
  return m;
}

// The channel in two passes along X at Y-y and Y+y, depth z (the first on line 5, the second on
// line 9, M30 on line 11).
std::string channel(double y, double z = -5) {
  return fmt::format(
      "T1 M06\nM03 S1000\nG90 G00 X-25. Y{0:.3f} Z5.\nG01 Z{1:.3f} F300.\nX25.\nG00 Z5.\nY{2:.3f}\nG01 Z{1:.3f}\nX-25.\n"
      "G00 Z5.\nM30\n",
      -y, z, y);
}

struct Checked {
  sim::DesignResult result;
  std::vector<const sim::Finding*> of(const std::string& code) const {
    std::vector<const sim::Finding*> out;
    for (const auto& f : result.findings)
      if (f.diagnostic.code == code) out.push_back(&f);
    return out;
  }
};

Checked check(const std::string& program, double tol = 0.01) {
  const auto profile = test::calculator_mill();
  const test::Ran ran = test::run(program, profile);
  EXPECT_TRUE(ran.result.ok());
  const sim::SetupFile setup = sim::parse_setup(kSetup, "s.toml");
  sim::MillTools tools(setup.tools, profile);
  sim::VerifyOptions o;
  o.cell = 0.04;
  o.mark_cells = true;
  sim::Verifier v(*setup.stock, tools, setup.tool_in_spindle, o);
  for (const auto& m : ran.moves) v.on_move(m);
  EXPECT_TRUE(v.findings().empty());
  const std::vector<double> top = sim::mesh_top(design(), v.map());
  Checked c;
  c.result = sim::check_design({&v.map(), top, v.map().cut_by(), v.cut_blocks(), v.last_block(), "part.stl", tol});
  return c;
}

}  // namespace

TEST(DesignCheck, TheChannelCutExactlyHasNoFinding) {
  const Checked c = check(channel(2));  // the 6 mm tool at Y+-2 reaches Y+-5
  EXPECT_TRUE(c.result.findings.empty()) << c.result.findings[0].diagnostic.message;
  EXPECT_EQ(c.result.gouge.cells, 0u);
  EXPECT_EQ(c.result.stock_left.cells, 0u);
}

TEST(DesignCheck, OversizeIsAGougeAtTheBlockThatCutIt) {
  // walls at Y+-5.05: the rows at +-5.02 cut 5 deep, 0.04 from the nearest centre of the channel's
  // floor (4.98); the true 0.05 within a cell
  const Checked c = check(channel(2.05));
  const auto found = c.of("NC2087");
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0]->diagnostic.span.line, 5u);  // Y-2.05: the -Y wall
  EXPECT_EQ(found[1]->diagnostic.span.line, 9u);  // Y+2.05: the +Y wall
  for (const sim::Finding* f : found) {
    EXPECT_NEAR(f->amount, 0.05, 0.04);
    EXPECT_NEAR(f->amount, 0.04, 1e-9);
    EXPECT_NEAR(std::abs(f->at[1]), 5.02, 1e-9);
    EXPECT_NEAR(f->at[2], -5, 1e-9);
    EXPECT_NE(f->diagnostic.message.find("0.040 mm into the design part.stl"), std::string::npos)
        << f->diagnostic.message;
  }
  EXPECT_LT(found[0]->at[1], 0);
  EXPECT_EQ(c.result.gouge.cells, 2u * 1000);  // two rows the stock's length
  EXPECT_TRUE(c.of("NC2088").empty());
}

TEST(DesignCheck, UndersizeIsStockLeftSaidAtTheEnd) {
  // walls at Y+-4.95: the rows at +-4.98 stand 5 above the floor, 0.04 from the wall's first centre
  const Checked c = check(channel(1.95));
  const auto found = c.of("NC2088");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0]->diagnostic.span.line, 11u);  // M30
  EXPECT_NEAR(found[0]->amount, 0.04, 1e-9);
  EXPECT_NEAR(std::abs(found[0]->at[1]), 4.98, 1e-9);
  EXPECT_EQ(c.result.stock_left.cells, 2u * 1000);
  EXPECT_TRUE(c.of("NC2087").empty());
}

TEST(DesignCheck, TooDeepIsMeasuredVertically) {
  // 0.5 below the channel's floor: no cell of the design is that low, the vertical 0.5 stands
  const Checked c = check(channel(2, -5.5));
  const auto found = c.of("NC2087");
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0]->amount, 0.5, 1e-9);
  EXPECT_NEAR(c.result.gouge.amount, 0.5, 1e-9);
}

TEST(DesignCheck, AWallWithinTheToleranceIsNoFalseAlarm) {
  // 0.03 oversize: the rows at +-5.02 are cut 5 mm below the design's top, yet 0.04 from its
  // floor: within --tol 0.05 nothing is found (a height alone would say 5 mm)
  EXPECT_TRUE(check(channel(2.03), 0.05).result.findings.empty());
  // with --tol 0.01 the same rows are found, by the cell (0.04), not by their 5 mm
  const Checked tight = check(channel(2.03));
  ASSERT_EQ(tight.of("NC2087").size(), 2u);
  EXPECT_NEAR(tight.result.gouge.amount, 0.04, 1e-9);
}

TEST(DesignCheck, RandomPartsAgainstEveryCellSearched) {
  // an independent reference: every cell of the map searched (no rings), the rule as stated:
  // within ceil(min(vertical / cell, tol / cell + 2)) cells, the nearest centre on the other side
  std::mt19937 random(2087);
  std::uniform_int_distribution<int> level(0, 8);
  const double cell = 0.5, tol = 0.3;
  for (int round = 0; round < 20; ++round) {
    sim::ZMap map(sim::Box{{0, 0, -10}, {15, 15, 0}}, cell);  // 30 x 30
    const int nx = map.nx(), ny = map.ny();
    std::vector<double> design(static_cast<std::size_t>(nx) * ny);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        map.start_cell(i, j, -0.25 * level(random));  // plateaus, so that equal heights occur
        design[static_cast<std::size_t>(j) * nx + i] = level(random) == 8 ? -INFINITY : -0.25 * level(random);
      }
    const std::vector<std::uint32_t> by(design.size(), 0);
    const sim::BlockAt block{nullptr, 1};
    const sim::DesignResult r = sim::check_design({&map, design, by, {&block, 1}, {nullptr, 2}, "d.stl", tol});
    sim::DesignExtreme gouge, left;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double h = map.height(i, j), d = design[static_cast<std::size_t>(j) * nx + i];
        const bool cuts = h < d - tol;
        const double floor = std::max(d, -10.0), vertical = cuts ? d - h : h - floor;
        if (!cuts && !(h > floor + tol)) continue;
        const double reach = std::ceil(std::min(vertical / cell, tol / cell + 2));
        double amount = vertical;
        for (int jj = 0; jj < ny; ++jj)
          for (int ii = 0; ii < nx; ++ii) {
            const double far = std::hypot(ii - i, jj - j), t = design[static_cast<std::size_t>(jj) * nx + ii];
            if (far <= reach && (cuts ? t <= h + 1e-9 : t >= h - 1e-9)) amount = std::min(amount, far * cell);
          }
        if (!(amount > tol)) continue;
        sim::DesignExtreme& e = cuts ? gouge : left;
        ++e.cells;
        e.amount = std::max(e.amount, amount);
      }
    EXPECT_EQ(r.gouge.cells, gouge.cells) << round;
    EXPECT_EQ(r.stock_left.cells, left.cells) << round;
    EXPECT_NEAR(r.gouge.amount, gouge.amount, 1e-12) << round;
    EXPECT_NEAR(r.stock_left.amount, left.amount, 1e-12) << round;
    EXPECT_GT(gouge.cells + left.cells, 0u);
  }
}
