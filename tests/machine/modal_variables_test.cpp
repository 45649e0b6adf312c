// #4001..#4022: the G code in force in each modal group, read after each code of the group, on the
// machining center and on the lathe's G code systems A, B and C. The groups are those of the 0i-F /
// 30i-B G code tables; the lathe's differ from the mill's (G96/G97 group 02, plane 16, G22/G23 09,
// drilling cycles 10, return level 11 on systems B and C, inch/metric G70/G71 on system C).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <string>
#include <utility>
#include <vector>

#include "machine/g_codes.hpp"
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

namespace {

// Each group's variable read after each of its codes, as the 0i-F / 30i-B G code tables list them
// (machining center; lathe systems A and B), with the words a block needs to be accepted.
struct Read {
  int variable;
  std::string block;
  double value;
};

const std::vector<Read> kMillReads = {
    {4001, "G00 X1.", 0}, {4001, "G01 X2. F100.", 1}, {4001, "G02 X4. R1.", 2}, {4001, "G03 X6. R1.", 3},
    {4001, "S500 M03\nG33 Z-1. F1.", 33}, {4001, "G00 Z0", 0},
    {4002, "G18", 18}, {4002, "G19", 19}, {4002, "G17", 17},
    {4003, "G91", 91}, {4003, "G90", 90},
    {4004, "G23", 23}, {4004, "G22", 22},
    {4005, "G95", 95}, {4005, "G94", 94},
    {4006, "G20", 20}, {4006, "G21", 21},
    {4007, "G41 D1 G01 X10. Y0 F100.", 41}, {4007, "G40 G00 X20.", 40}, {4007, "G42 D1 G01 X10. Y0 F100.", 42},
    {4007, "G40 G00 X-10. Y-10.", 40},
    {4008, "G43 H1", 43}, {4008, "G44 H1", 44}, {4008, "G49", 49},
    {4010, "G99", 99}, {4010, "G98", 98},
    {4009, "G00 Z10.\nG81 Z-3. R1. F100.", 81}, {4009, "G82 Z-3. R1. P100", 82}, {4009, "G83 Z-3. R1. Q1.", 83},
    {4009, "G73 Z-3. R1. Q1.", 73}, {4009, "G85 Z-3. R1.", 85}, {4009, "G86 Z-3. R1.", 86},
    {4009, "G89 Z-3. R1. P100", 89}, {4009, "G76 Z-3. R1. Q0.1", 76}, {4009, "G88 Z-3. R1.", 88},
    {4009, "G98 G87 Z-3. R-5. Q0.1", 87}, {4009, "G99 G84 Z-3. R1.", 84}, {4009, "M04\nG74 Z-3. R1.", 74},
    {4009, "G80", 80},
    {4011, "G51 X0 Y0 P2.", 51}, {4011, "G50", 50},
    {4012, "G66 P9001", 66}, {4012, "G67", 67},
    {4013, "G96 S100", 96}, {4013, "G97 S100", 97},
    {4014, "G55", 55}, {4014, "G56", 56}, {4014, "G57", 57}, {4014, "G58", 58}, {4014, "G59", 59},
    {4014, "G54.1 P1", 54.1}, {4014, "G54", 54},
    {4015, "G61", 61}, {4015, "G62", 62}, {4015, "G63", 63}, {4015, "G64", 64},
    {4016, "G68 X0 Y0 R30.", 68}, {4016, "G69", 69},
    {4017, "G16", 16}, {4017, "G15", 15},
    {4022, "G51.1 X0", 51.1}, {4022, "G50.1 X0", 50.1},
    {4021, "G12.1", 12.1}, {4021, "G13.1", 13.1},
};

const std::vector<Read> kLatheAReads = {
    {4001, "G00 X10. Z1.", 0}, {4001, "G01 Z0 F0.1", 1}, {4001, "G02 X12. Z-1. R1.", 2},
    {4001, "G03 X14. Z-2. R1.", 3}, {4001, "G32 Z-10. F1.", 32}, {4001, "G00 X20. Z1.", 0},
    {4001, "G90 X18. Z-5. F0.1", 90}, {4001, "G92 X18. Z-5. F1.", 92}, {4001, "G94 X10. Z-1. F0.1", 94},
    {4001, "G00 X20. Z1.", 0},
    {4002, "G96 S100", 96}, {4002, "G97 S500", 97},
    {4005, "G99", 99}, {4005, "G98", 98},
    {4006, "G20", 20}, {4006, "G21", 21},
    {4007, "G42 G01 Z0 F0.1", 42}, {4007, "G40 G00 X50. Z5.", 40}, {4007, "G41 G01 Z0 F0.1", 41},
    {4007, "G40 G00 X50. Z5.", 40},
    {4008, "G26", 26}, {4008, "G25", 25},
    {4009, "G23", 23}, {4009, "G22", 22},
    {4010, "G00 X0 Z5.\nG83 Z-10. R2. Q2000 F0.1", 83}, {4010, "G85 Z-10. R2.", 85}, {4010, "G80", 80},
    {4010, "G00 X20. Z5.\nG84 Z-10. R2. F1.", 84}, {4010, "G80", 80},
    {4010, "G00 X20. Z5. C0\nG87 X5. R2. F0.1", 87}, {4010, "G88 X5. R2. F1.", 88}, {4010, "G89 X5. R2. F0.1", 89},
    {4010, "G80", 80},
    {4012, "G66 P9001", 66}, {4012, "G67", 67},
    {4014, "G55", 55}, {4014, "G56", 56}, {4014, "G57", 57}, {4014, "G58", 58}, {4014, "G59", 59},
    {4014, "G54.1 P1", 54.1}, {4014, "G54", 54},
    {4015, "G61", 61}, {4015, "G62", 62}, {4015, "G63", 63}, {4015, "G64", 64},
    {4016, "G17", 17}, {4016, "G19", 19}, {4016, "G18", 18},
    {4004, "G69", 69},
    {4021, "G18\nG12.1", 12.1}, {4021, "G13.1", 13.1},
};

const std::vector<Read> kLatheBReads = {
    {4001, "G00 X10. Z1.", 0}, {4001, "G01 Z0 F0.1", 1}, {4001, "G02 X12. Z-1. R1.", 2},
    {4001, "G03 X14. Z-2. R1.", 3}, {4001, "G33 Z-10. F1.", 33}, {4001, "G00 X20. Z1.", 0},
    {4001, "G77 X18. Z-5. F0.1", 77}, {4001, "G78 X18. Z-5. F1.", 78}, {4001, "G79 X10. Z-1. F0.1", 79},
    {4001, "G00 X20. Z1.", 0},
    {4002, "G96 S100", 96}, {4002, "G97 S500", 97},
    {4003, "G91", 91}, {4003, "G90", 90},
    {4005, "G95", 95}, {4005, "G94", 94},
    {4006, "G20", 20}, {4006, "G21", 21},
    {4007, "G42 G01 Z0 F0.1", 42}, {4007, "G40 G00 X50. Z5.", 40}, {4007, "G41 G01 Z0 F0.1", 41},
    {4007, "G40 G00 X50. Z5.", 40},
    {4008, "G26", 26}, {4008, "G25", 25},
    {4009, "G23", 23}, {4009, "G22", 22},
    {4010, "G00 X0 Z5.\nG83 Z-10. R2. Q2000 F0.1", 83}, {4010, "G85 Z-10. R2.", 85}, {4010, "G80", 80},
    {4010, "G00 X20. Z5.\nG84 Z-10. R2. F1.", 84}, {4010, "G80", 80},
    {4010, "G00 X20. Z5. C0\nG87 X5. R2. F0.1", 87}, {4010, "G88 X5. R2. F1.", 88}, {4010, "G89 X5. R2. F0.1", 89},
    {4010, "G80", 80},
    {4011, "G99", 99}, {4011, "G98", 98},
    {4012, "G66 P9001", 66}, {4012, "G67", 67},
    {4014, "G55", 55}, {4014, "G56", 56}, {4014, "G57", 57}, {4014, "G58", 58}, {4014, "G59", 59},
    {4014, "G54.1 P1", 54.1}, {4014, "G54", 54},
    {4015, "G61", 61}, {4015, "G62", 62}, {4015, "G63", 63}, {4015, "G64", 64},
    {4016, "G17", 17}, {4016, "G19", 19}, {4016, "G18", 18},
    {4004, "G69", 69},
    {4021, "G18\nG12.1", 12.1}, {4021, "G13.1", 13.1},
};

// Runs the reads in order, each into #100, #101, ...; every group's variable is checked after each.
void expect_all(const machine::MachineProfile& profile, const std::string& setup, const std::vector<Read>& reads) {
  std::string text = setup;
  for (std::size_t i = 0; i < reads.size(); ++i)
    text += reads[i].block + "\n#" + std::to_string(100 + i) + "=#" + std::to_string(reads[i].variable) + "\n";
  text += "M30\nO9001\nM99\n";
  auto r = run(text, profile);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm) << "\n" << text;
  for (std::size_t i = 0; i < reads.size(); ++i)
    EXPECT_DOUBLE_EQ(r.var(100 + static_cast<int>(i)), reads[i].value)
        << "#" << reads[i].variable << " after " << reads[i].block;
}

// Every simulated code of a modal group in the table is one of the manual's reads above, in the
// group the manual gives it: a row whose group is wrong, or a code added without a read, fails.
void expect_table_covered(machine::GMachine m, const std::vector<Read>& reads) {
  for (int g = 0; g < 2600; ++g) {
    const machine::GCode* row = machine::g_code(g, m);
    if (!row || row->status != machine::GStatus::simulated || row->group == 0 || row->group > 22) continue;
    if (g == 611 || g == 1120 || g == 1130 || g == 661) continue;  // G61.1 needs a profile; G112/G113: G12.1/G13.1
    const bool read = std::ranges::any_of(reads, [&](const Read& r) {
      return r.variable == 4000 + row->group && std::lround(r.value * 10) == g;
    });
    EXPECT_TRUE(read) << machine::g_name(g) << " (group " << int(row->group) << ") is not read by the test";
  }
}

}  // namespace

machine::MachineProfile with_c(machine::MachineProfile p) {
  p.axes += "C";
  p.polar_linear_axis = 1;  // No.5460: X
  p.polar_rotary_axis = static_cast<int>(p.axes.size());  // No.5461: C
  p.rotary[5].rotary = true;                                // No.1006#0 ROT of C
  return p;
}

TEST(ModalVariables, EveryCodeOfEveryGroupOnTheMill) {
  expect_all(with_c(machine::default_mill()), "G10 L11 P1 R3.\nG10 L10 P1 R50.\nG00 X-10. Y-10.\n", kMillReads);
  expect_table_covered(machine::kMill, kMillReads);
}

TEST(ModalVariables, EveryCodeOfEveryGroupOnLatheSystemA) {
  expect_all(with_c(lathe('A')), "G00 X40. Z5.\n", kLatheAReads);
  expect_table_covered(machine::kLatheA, kLatheAReads);
}

TEST(ModalVariables, EveryCodeOfEveryGroupOnLatheSystemB) {
  expect_all(with_c(lathe('B')), "G00 X40. Z5.\n", kLatheBReads);
  expect_table_covered(machine::kLatheB, kLatheBReads);
}

// #4107..#4130: the words in force (the 30i-B table of modal information other than G codes):
// D, F, H, the last M, the last sequence number N, the program number O, S, T, and P of G54.1.
TEST(ModalVariables, WordsInForceOnTheMill) {
  auto r = run("O1234\nN10 G90 G54.1 P3 G00 X0 Y0 S1200 M03 T5\nN20 G43 H2 D4 G01 X1. F250.\nN30 M08\n"
               "#100=#4107\n#101=#4109\n#102=#4111\n#103=#4113\n#104=#4114\n#105=#4115\n#106=#4119\n"
               "#107=#4120\n#108=#4130\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  const double want[] = {4, 250, 2, 8, 30, 1234, 1200, 5, 3};
  for (int i = 0; i < 9; ++i) EXPECT_EQ(r.var(100 + i), want[i]) << "#" << 100 + i;
}

// On a system A lathe F is per revolution under G99 and a T code names tool and offset (T0202).
TEST(ModalVariables, WordsInForceOnALathe) {
  machine::MachineProfile p = machine::default_lathe();
  p.gcode_system = 'A';
  auto r = run("G99 G00 X40. Z5. S500 M03 T0202\nG01 Z-10. F0.2\n#100=#4109\n#101=#4119\n#102=#4120\n"
               "#103=#4130\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_DOUBLE_EQ(r.var(100), 0.2);
  EXPECT_EQ(r.var(101), 500);
  EXPECT_EQ(r.var(102), 202);
  EXPECT_TRUE(r.vacant(103));  // no G54.1 P in force
}
