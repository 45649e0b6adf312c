// #4001..#4022: the G code in force in each modal group, read after each code of the group, on the
// machining center and on the lathe's G code systems A, B and C. The groups are those of the 0i-F /
// 30i-B G code tables; the lathe's differ from the mill's (G96/G97 group 02, plane 16, G22/G23 09,
// drilling cycles 10, return level 11 on systems B and C, inch/metric G70/G71 on system C).
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {

machine::MachineProfile lathe(char system) {
  auto p = machine::default_lathe();
  p.gcode_system = system;
  return p;
}

// Runs `setup` and reads `variable` after each block of `codes` into #100, #101, ...; checks them.
void expect_reads(const machine::MachineProfile& profile, const std::string& setup, int variable,
                  const std::vector<std::pair<std::string, double>>& codes) {
  std::string text = setup;
  for (std::size_t i = 0; i < codes.size(); ++i)
    text += codes[i].first + "\n#" + std::to_string(100 + i) + "=#" + std::to_string(variable) + "\n";
  text += "M30\n";
  auto r = run(text, profile);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm) << "\n" << text;
  for (std::size_t i = 0; i < codes.size(); ++i)
    EXPECT_DOUBLE_EQ(r.var(100 + static_cast<int>(i)), codes[i].second)
        << "#" << variable << " after " << codes[i].first;
}

}  // namespace

TEST(ModalVariables, MillGroups) {
  const auto mill = machine::default_mill();
  expect_reads(mill, "", 4001, {{"G00 X1.", 0}, {"G01 X2. F100.", 1}, {"G02 X4. R1.", 2}, {"G03 X6. R1.", 3}});
  expect_reads(mill, "", 4002, {{"", 17}, {"G18", 18}, {"G19", 19}, {"G17", 17}});
  expect_reads(mill, "", 4003, {{"G91", 91}, {"G90", 90}});
  expect_reads(mill, "", 4004, {{"G23", 23}, {"G22", 22}, {"G23", 23}});
  expect_reads(mill, "", 4005, {{"G95", 95}, {"G94", 94}});
  expect_reads(mill, "", 4006, {{"G20", 20}, {"G21", 21}});
  expect_reads(mill, "G10 L11 P1 R3.\nG00 X-10. Y-10.\n", 4007,
               {{"", 40}, {"G41 D1 G01 X10. Y0 F100.", 41}, {"Y10.", 41}, {"G40 G00 X20.", 40},
                {"G42 D1 G01 X10. Y0 F100.", 42}, {"G40 G00 X-10. Y-10.", 40}});
  expect_reads(mill, "", 4008, {{"", 49}});
  expect_reads(mill, "G00 Z10.\n", 4009, {{"G81 Z-3. R1. F100.", 81}, {"G80", 80}});
  expect_reads(mill, "", 4010, {{"G99", 99}, {"G98", 98}});
  expect_reads(mill, "", 4013, {{"", 97}, {"G96 S100", 96}, {"G97 S100", 97}});
  expect_reads(mill, "", 4014, {{"G55", 55}, {"G59", 59}, {"G54", 54}});
  expect_reads(mill, "", 4015, {{"G61", 61}, {"G62", 62}, {"G63", 63}, {"G64", 64}});
}

TEST(ModalVariables, LatheSystemA) {
  const auto a = lathe('A');
  expect_reads(a, "", 4001, {{"G00 X10. Z1.", 0}, {"G01 Z0 F0.1", 1}, {"G90 X8. Z-5. F0.1", 90}});
  expect_reads(a, "", 4002, {{"", 97}, {"G50 S2000", 97}, {"G96 S100", 96}, {"G97 S500", 97}});
  expect_reads(a, "", 4004, {{"", 69}});
  expect_reads(a, "", 4005, {{"G98", 98}, {"G99", 99}});
  expect_reads(a, "", 4006, {{"G20", 20}, {"G21", 21}});
  expect_reads(a, "G00 X40. Z5.\n", 4007,
               {{"", 40}, {"G42 G01 Z0 F0.1", 42}, {"G40 G00 X50. Z5.", 40}, {"G41 G01 Z0 F0.1", 41},
                {"G40 G00 X50. Z5.", 40}});
  expect_reads(a, "", 4008, {{"", 25}});
  expect_reads(a, "", 4009, {{"G23", 23}, {"G22", 22}});
  expect_reads(a, "G00 X0 Z5.\n", 4010, {{"", 80}, {"G83 Z-10. R2. Q2000 F0.1", 83}, {"G80", 80}});
  expect_reads(a, "", 4016, {{"", 18}});
  expect_reads(a, "", 4011, {{"", 0}, {"G50 X100. Z50.", 0}});
}

TEST(ModalVariables, LatheSystemsBAndC) {
  const auto b = lathe('B');
  expect_reads(b, "", 4001, {{"G00 X10. Z1.", 0}, {"G77 X8. Z-5. F0.1", 77}});
  expect_reads(b, "", 4002, {{"G96 S100", 96}, {"G97 S500", 97}});
  expect_reads(b, "", 4003, {{"G91", 91}, {"G90", 90}});
  expect_reads(b, "", 4005, {{"G94", 94}, {"G95", 95}});
  expect_reads(b, "", 4006, {{"G20", 20}, {"G21", 21}});
  expect_reads(b, "", 4011, {{"G99", 99}, {"G98", 98}});
  expect_reads(b, "", 4016, {{"", 18}});
  const auto c = lathe('C');
  expect_reads(c, "", 4006, {{"G70", 70}, {"G71", 71}});
  expect_reads(c, "", 4002, {{"G96 S100", 96}, {"G97 S500", 97}});
}
