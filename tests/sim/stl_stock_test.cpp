// An STL stock and STL fixtures on the mill's Z-map (src/sim/mesh_top*, the Verifier): a box as an
// STL is the box stock cell for cell, a stepped STL's cells start at its top and the cells it does
// not cover hold no material, an STL wedge of a clamp is hit where its slope stands and passed over
// where a box round it would have been hit.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "sim/verifier.hpp"
#include "support/meshes.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

const char* const kTools = R"(
[tools.1]
kind = "flat"
diameter = 10
flute_length = 20
)";

struct Cut {
  sim::SetupFile setup;
  std::unique_ptr<sim::MillTools> tools;
  std::unique_ptr<sim::Verifier> verifier;
  std::vector<const sim::Finding*> of(const std::string& code) const {
    std::vector<const sim::Finding*> out;
    for (const auto& f : verifier->findings())
      if (f.diagnostic.code == code) out.push_back(&f);
    return out;
  }
};

Cut cut(const std::string& program, const std::string& setup_text) {
  Cut c;
  const auto profile = test::calculator_mill();
  const test::Ran ran = test::run(program, profile);
  EXPECT_TRUE(ran.result.ok());
  c.setup = sim::parse_setup(setup_text + kTools, ::testing::TempDir() + "s.toml");
  c.tools = std::make_unique<sim::MillTools>(c.setup.tools, profile);
  sim::VerifyOptions o;
  o.cell = 0.1;
  c.verifier = std::make_unique<sim::Verifier>(*c.setup.stock, *c.tools, c.setup.tool_in_spindle, o, c.setup.fixtures);
  for (const auto& m : ran.moves) c.verifier->on_move(m);
  return c;
}

const char* const kSlot = "T1 M06\nM03 S1000\nG90 G00 X-30. Y0.05 Z5.\nG01 Z-3. F200.\nX30.\nG00 Z5.\nM30\n";

}  // namespace

TEST(StlStock, ABoxAsAnStlIsTheBoxStock) {
  test::stl_file("box.stl", test::box_mesh(-20, 20, -15, 15, -10, 0));
  const Cut box = cut(kSlot, "[stock]\nshape = \"box\"\nmin = [-20, -15, -10]\nmax = [20, 15, 0]\n");
  const Cut stl = cut(kSlot, "[stock]\nshape = \"stl\"\nfile = \"box.stl\"\n");
  const sim::ZMap &a = box.verifier->map(), &b = stl.verifier->map();
  ASSERT_EQ(a.nx(), b.nx());
  ASSERT_EQ(a.ny(), b.ny());
  EXPECT_EQ(a.cell(), b.cell());
  for (int j = 0; j < a.ny(); ++j)
    for (int i = 0; i < a.nx(); ++i) ASSERT_EQ(a.height(i, j), b.height(i, j)) << i << " " << j;
  // the slot, 40 long (the stock's length) x 10 wide x 3 deep, to the cells
  EXPECT_NEAR(b.volume_removed(), 40 * 10 * 3, 40 * 0.2 * 3);
  EXPECT_DOUBLE_EQ(a.volume_removed(), b.volume_removed());
}

TEST(StlStock, CellsStartAtTheMeshTopAndOutsideItHoldNothing) {
  // an L: X-20..0 up to Z0 over Y-15..15, X0..20 up to Z-4 over Y-15..0 only (nothing at X > 0, Y > 0)
  sim::Mesh l = test::box_mesh(-20, 0, -15, 15, -10, 0);
  const sim::Mesh low = test::box_mesh(0, 20, -15, 0, -10, -4);
  for (const auto& t : low.triangles) {
    const auto n = static_cast<std::uint32_t>(l.vertices.size());
    for (auto v : t) l.vertices.push_back(low.vertices[v]);
    l.triangles.push_back({n, n + 1, n + 2});
  }
  test::stl_file("l.stl", l);
  const Cut c = cut("T1 M06\nM03 S1000\nG90 G00 X-30. Y0 Z5.\nM30\n", "[stock]\nshape = \"stl\"\nfile = \"l.stl\"\n");
  const sim::ZMap& m = c.verifier->map();
  EXPECT_EQ(m.stock().max[2], 0);
  EXPECT_EQ(m.stock().min[0], -20);
  EXPECT_EQ(m.height_at(-10.05, 10.05), 0);
  EXPECT_EQ(m.height_at(10.05, -10.05), -4);
  EXPECT_EQ(m.height_at(10.05, 10.05), -10);  // not covered: at the bottom
  EXPECT_NEAR(m.volume_removed(), 0, 1e-6);    // nothing is cut, nothing counted
  // a slot along Y at X10 through both: removes only what the L has (Y-15..0 from Z-4 to Z-6)
  const Cut slot = cut("T1 M06\nM03 S1000\nG90 G00 X10. Y-30. Z5.\nG01 Z-6. F200.\nY30.\nG00 Z5.\nM30\n",
                       "[stock]\nshape = \"stl\"\nfile = \"l.stl\"\n");
  EXPECT_NEAR(slot.verifier->map().volume_removed(), 15 * 10 * 2, 15 * 0.2 * 2 + 10 * 0.1 * 2);
  // in inches: the box of a 1 x 1 x 0.5 inch file is 25.4 x 25.4 x 12.7 mm
  test::stl_file("inch_box.stl", test::box_mesh(0, 1, 0, 1, -0.5, 0));
  const Cut inch = cut("M30\n", "inch = true\n[stock]\nshape = \"stl\"\nfile = \"inch_box.stl\"\n");
  EXPECT_DOUBLE_EQ(inch.verifier->map().stock().max[0], 25.4);
  EXPECT_DOUBLE_EQ(inch.verifier->map().stock().min[2], -12.7);
}

TEST(StlFixture, AWedgeIsHitWhereItStandsAndPassedWhereItSlopesAway) {
  // a clamp X30..40 Y-10..10 whose top falls from Z5 at X30 to Z0 at X40 (5 - (x - 30) / 2)
  test::stl_file("wedge.stl", test::prism(30, 40, -10, 10, -20, 5, 0));
  const std::string setup = "[stock]\nshape = \"box\"\nmin = [-50, -50, -20]\nmax = [50, 50, 0]\n"
                            "[[fixtures]]\nname = \"wedge\"\nshape = \"stl\"\nfile = \"wedge.stl\"\n";
  // at Z4 to X28: the edge reaches X33, where the top is 3.5; deepest at the cell by X30, 5 - 0.025 - 4
  const Cut hit = cut("T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z4.\nG01 X28. F300.\nG00 Z20.\nM30\n", setup);
  const auto found = hit.of("NC2086");
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0]->diagnostic.span.line, 4u);
  EXPECT_NEAR(found[0]->amount, 1.0, 0.03);  // the first cell's centre half a cell in, its top 0.025 lower
  EXPECT_NE(found[0]->diagnostic.message.find("'wedge'"), std::string::npos);
  // from +X at Z4 to X42: the edge at X37, where the top is 1.5: clear (the wedge's box, top Z5, would be hit)
  const Cut clear = cut("T1 M06\nM03 S1000\nG90 G00 Z20.\nX60. Y0\nZ4.\nG01 X42. F300.\nG00 Z20.\nM30\n", setup);
  EXPECT_TRUE(clear.of("NC2086").empty());
  const auto checked = clear.verifier->fixtures_checked();
  ASSERT_EQ(checked.size(), 1u);
  EXPECT_EQ(checked[0], "wedge: checked");
}

TEST(StlStock, AMissingOrBadFileIsAnErrorNamingIt) {
  const std::string setup = "[stock]\nshape = \"stl\"\nfile = \"missing.stl\"\n";
  EXPECT_THROW(
      {
        try {
          (void)cut("M30\n", setup);
        } catch (const std::runtime_error& e) {
          EXPECT_NE(std::string(e.what()).find("missing.stl: error: cannot read the STL file"), std::string::npos)
              << e.what();
          throw;
        }
      },
      std::runtime_error);
}
