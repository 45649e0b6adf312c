// Mill tool compensation memory A, B and C: the system variables and G10 L10..L13 of each, as the
// FANUC 0i-M / 30i-M manuals lay them out, and the H value G43 applies.
#include <gtest/gtest.h>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {
machine::MachineProfile with_memory(machine::OffsetMemory m) {
  auto p = test::zero_offset_mill();
  p.offset_memory = m;
  return p;
}
}  // namespace

TEST(Offsets, MemoryAHoldsOneValueForHAndD) {
  auto r = run("G10 L11 P1 R5.\n#101=#2001\n#102=#10001\n#10002=7.5\n#103=#2002\nM30\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_DOUBLE_EQ(r.var(101), 5.0);
  EXPECT_DOUBLE_EQ(r.var(102), 5.0);
  EXPECT_DOUBLE_EQ(r.var(103), 7.5);
  // #2201 is no offset on memory A
  EXPECT_FALSE(run("#1=#2201\nM30\n").result.ok());
}

TEST(Offsets, MemoryBSeparatesGeometryAndWear) {
  auto r = run("G10 L10 P1 R100.\nG10 L11 P1 R-0.2\n#101=#11001\n#102=#10001\n#103=#2201\n#104=#2001\n"
               "G90 G43 Z0 H1\nM30\n",
               with_memory(machine::OffsetMemory::B));
  ASSERT_TRUE(r.result.ok()) << r.result.alarm->message;
  EXPECT_DOUBLE_EQ(r.var(101), 100.0);
  EXPECT_DOUBLE_EQ(r.var(102), -0.2);
  EXPECT_DOUBLE_EQ(r.var(103), 100.0);
  EXPECT_DOUBLE_EQ(r.var(104), -0.2);
  EXPECT_FALSE(run("#1=#13001\nM30\n", with_memory(machine::OffsetMemory::B)).result.ok());
}

TEST(Offsets, MemoryCSeparatesHAndD) {
  auto r = run("G10 L10 P2 R150.\nG10 L11 P2 R0.1\nG10 L12 P2 R6.\nG10 L13 P2 R-0.05\n"
               "#101=#11002\n#102=#10002\n#103=#13002\n#104=#12002\n#13003=4.\n#105=#13003\nM30\n",
               with_memory(machine::OffsetMemory::C));
  ASSERT_TRUE(r.result.ok()) << r.result.alarm->message;
  EXPECT_DOUBLE_EQ(r.var(101), 150.0);
  EXPECT_DOUBLE_EQ(r.var(102), 0.1);
  EXPECT_DOUBLE_EQ(r.var(103), 6.0);
  EXPECT_DOUBLE_EQ(r.var(104), -0.05);
  EXPECT_DOUBLE_EQ(r.var(105), 4.0);
}

TEST(Offsets, G43AppliesGeometryPlusWear) {
  auto p = with_memory(machine::OffsetMemory::C);
  auto r = run("G10 L10 P1 R100.\nG10 L11 P1 R-0.5\nG10 L12 P1 R5.\nG90 G43 G00 Z10. H1\n#101=#5023\nM30\n", p);
  ASSERT_TRUE(r.result.ok());
  // machine Z = work Z + tool length (geometry + wear), D values not involved
  EXPECT_NEAR(r.var(101) - r.motions().back().end[2], 99.5, 1e-9);
}

// An H word alone in G43/G44 mode puts the new number's value in force (the old one is replaced,
// not added): machine Z = work Z + H value under G43, - H value under G44.
TEST(Offsets, HAloneInG43ModeChangesTheLength) {
  auto r = run("G10 L10 P1 R100.\nG10 L10 P2 R150.\nG90 G43 G00 Z10. H1\n#101=#5023\nZ20. H2\n#102=#5023\n"
               "G44 Z0 H1\n#103=#5023\nH2\nZ5.\n#104=#5023\nG49 Z5.\n#105=#5023\nH1\nZ5.\n#106=#5023\nM30\n");
  ASSERT_TRUE(r.result.ok()) << r.result.alarm->message;
  EXPECT_NEAR(r.var(101), 10.0 + 100.0, 1e-9);
  EXPECT_NEAR(r.var(102), 20.0 + 150.0, 1e-9);
  EXPECT_NEAR(r.var(103), 0.0 - 100.0, 1e-9);
  EXPECT_NEAR(r.var(104), 5.0 - 150.0, 1e-9);
  EXPECT_NEAR(r.var(105), 5.0, 1e-9);
  EXPECT_NEAR(r.var(106), 5.0, 1e-9);  // G49: an H alone applies nothing
}

TEST(Offsets, ProfileTableAndBadKeys) {
  auto p = machine::parse_profile(
      "[machine]\noffset_memory = \"C\"\n[tool_offsets]\n\"1\" = { length = 120.0, radius = 5.0, radius_wear = -0.01 }\n",
      "m.toml");
  ASSERT_EQ(p.offset_memory, machine::OffsetMemory::C);
  EXPECT_DOUBLE_EQ(p.tool_offsets.at(1).geometry, 120.0);
  EXPECT_DOUBLE_EQ(p.tool_offsets.at(1).d_geometry, 5.0);
  EXPECT_DOUBLE_EQ(p.tool_offsets.at(1).d_wear, -0.01);
  EXPECT_THROW(machine::parse_profile("[tool_offsets]\n\"1.5\" = 2.0\n", "m.toml"), std::runtime_error);
  EXPECT_THROW(machine::parse_profile("[tool_offsets]\n\"1\" = { length = 1.0, radius = 2.0 }\n", "m.toml"),
               std::runtime_error);
  EXPECT_THROW(machine::parse_profile("[machine]\noffset_memory = \"D\"\n", "m.toml"), std::runtime_error);
}
