// External output commands (POPEN, DPRNT, BPRNT, PCLOS), programmable parameter input (G10 L52 ..
// G11) and a machining center's G33 thread cutting. Expected bytes and values are worked out by hand
// from the FANUC operator's manuals (custom macro: external output commands; programmable parameter
// input; equal lead thread cutting) and the parameter manual (No.6001#1 PRT, No.0100#2 CRF, #3 NCR).
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <string>

#include "machine/macro_output.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {

std::string hex(const std::string& bytes) {
  std::string s;
  for (unsigned char c : bytes) s += fmt::format("{:02X} ", c);
  return s;
}

bool warned(const test::Ran& r, const std::string& code) {
  for (const auto& w : r.result.warnings)
    if (w.code == code) return true;
  return false;
}

}  // namespace

// The manual's DPRNT example: #2=128.47398 [53], #5=-91.2 [53], #30=123.456 [20].
// PRT = 0: a space for the + sign and for each leading zero of the 5 integer digits:
//   X, ' ', "  128", ".474" (128.47398 rounded to 3 decimals)
//   Y, '-', "   91", ".200"
//   T, ' ', "23"       123.456 -> 123; only the 2 integer digits asked for are sent
// then the end of block LF CR CR (No.0100#3 NCR = 0, #2 CRF = 0); POPEN sent DC2 (0x12) first.
TEST(MacroOutput, DprntManualExampleWithSpaces) {
  auto r = run("#2=128.47398\n#5=-91.2\n#30=123.456\nPOPEN\nDPRNT[X#2[53]Y#5[53]T#30[20]]\nPCLOS\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(r.result.output.bytes, std::string("\x12X   128.474Y-   91.200T 23\n\r\r\x14"));
  ASSERT_EQ(r.result.output.lines.size(), 1u);
  EXPECT_EQ(r.result.output.lines[0], "X   128.474Y-   91.200T 23");
  EXPECT_FALSE(warned(r, "NC2060"));
}

// PRT = 1: neither the leading zeros nor the + sign send anything.
TEST(MacroOutput, DprntManualExampleWithoutSpaces) {
  auto p = machine::default_mill();
  machine::set_parameter(p, "6001#1", 1);
  auto r = run("#2=128.47398\n#5=-91.2\n#30=123.456\nPOPEN\nDPRNT[X#2[53]Y#5[53]T#30[20]]\nPCLOS\nM30\n", p);
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(r.result.output.bytes, std::string("\x12X128.474Y-91.200T23\n\r\r\x14"));
}

// '*' is sent as a space; spaces in the program are not read; the end-of-block code follows
// No.0100: CRF = 1 gives CR LF, NCR = 1 (CRF = 0) LF alone.
TEST(MacroOutput, TextAndEndOfBlock) {
  auto p = machine::default_mill();
  machine::set_parameter(p, "0100#2", 1);
  auto r = run("POPEN\nDPRNT[ MEASURED*DIA ]\nDPRNT[]\nPCLOS\nM30\n", p);
  EXPECT_EQ(r.result.output.bytes, std::string("\x12MEASURED DIA\r\n\r\n\x14"));
  p = machine::default_mill();
  machine::set_parameter(p, "0100#3", 1);
  r = run("POPEN\nDPRNT[P1/2+3-4?@&_]\nPCLOS\nM30\n", p);
  EXPECT_EQ(r.result.output.bytes, std::string("\x12P1/2+3-4?@&_\n\x14"));
}

// A vacant variable is output as 0: [22] gives ' ' (sign), ' ' (leading zero), '0', ".00".
// -0.0004 [13] rounds to 0.000: no minus sign for a value that prints as zero.
// 0.0005 [03] rounds half away from zero: .001 (no integer digits asked for).
TEST(MacroOutput, DprntVacantRoundingAndNoIntegerDigits) {
  auto p = machine::default_mill();
  machine::set_parameter(p, "0100#3", 1);
  auto r = run("#2=-0.0004\n#3=0.0005\nPOPEN\nDPRNT[A#1[22]B#2[13]C#3[03]D#[1+1][40]]\nPCLOS\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  // D#[1+1][40]: #2 = -0.0004 rounds to 0 -> ' ', "   0"
  EXPECT_EQ(r.result.output.lines.at(0), "A  0.00B 0.000C .001D    0");
}

TEST(MacroOutput, DprntNumberRules) {
  EXPECT_EQ(machine::dprnt_number(-1.5, 3, 0, false), "-  2");     // rounds half away from zero
  EXPECT_EQ(machine::dprnt_number(12345.6, 3, 1, true), "345.6");  // digits above the integer ones dropped
  EXPECT_EQ(machine::dprnt_number(-7.25, 1, 1, true), "-7.3");
  EXPECT_EQ(machine::dprnt_number(0, 4, 4, false), "    0.0000");
}

// The manual's BPRNT example: BPRNT[C**X#100[3]Y#101[3]M#10[0]], #100=0.40956, #101=-1638.4, #10=12.34
//   C, space, space, X, 0.40956*1000 = 409.56 -> 410 = 0000019A, Y, -1638.4*1000 = -1638400 =
//   FFE70000 (two's complement), M, 12.34 -> 12 = 0000000C, end of block.
TEST(MacroOutput, BprntManualExample) {
  auto p = machine::default_mill();
  machine::set_parameter(p, "0100#3", 1);
  auto r = run("#100=0.40956\n#101=-1638.4\n#10=12.34\nPOPEN\nBPRNT[C**X#100[3]Y#101[3]M#10[0]]\nPCLOS\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_EQ(hex(r.result.output.bytes),
            "12 43 20 20 58 00 00 01 9A 59 FF E7 00 00 4D 00 00 00 0C 0A 14 ");
  EXPECT_EQ(r.result.output.lines.at(0), "C  X<0000019A>Y<FFE70000>M<0000000C>");
}

// The NCT 2000M manual's BPRNT table (FANUC-compatible), characters with ISO code's even parity bit:
// BPRNT[C*/X#110[3]Y#120[3]M#112[0]], #110=318.49362, #120=0.723415, #112=23.9:
//   C 43 -> C3 (three 1 bits), '*' = space 20 -> A0, '/' 2F -> AF, X 58 -> D8,
//   318493.62 -> 318494 = 0004DC1E, Y 59 (four 1 bits), 723.415 -> 723 = 000002D3,
//   M 4D, 23.9 -> 24 = 00000018, LF 0A. Binary values carry no parity.
TEST(MacroOutput, BprntWithParity) {
  auto p = machine::default_mill();
  p.output_parity = true;
  machine::set_parameter(p, "0100#3", 1);
  auto r = run("#110=318.49362\n#120=0.723415\n#112=23.9\nPOPEN\nBPRNT[C*/X#110[3]Y#120[3]M#112[0]]\nM30\n", p);
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(hex(r.result.output.bytes),
            "12 C3 A0 AF D8 00 04 DC 1E 59 00 00 02 D3 4D 00 00 00 18 0A ");
}

TEST(MacroOutput, BprntVacantAndRange) {
  auto p = machine::default_mill();
  machine::set_parameter(p, "0100#3", 1);
  auto r = run("POPEN\nBPRNT[#1[3]]\nM30\n", p);  // vacant: 00000000
  EXPECT_EQ(hex(r.result.output.bytes), "12 00 00 00 00 0A ");
  r = run("#1=2048*1048576\nPOPEN\nBPRNT[#1[0]]\nM30\n", p);  // 2^31: beyond 32 bits
  EXPECT_EQ(r.alarm_code(), "PS0003");
  r = run("#1=-2048*1048576\nPOPEN\nBPRNT[#1[0]]\nM30\n", p);  // -2^31 fits
  EXPECT_EQ(hex(r.result.output.bytes), "12 80 00 00 00 0A ");
}

TEST(MacroOutput, WithoutPopenWarns) {
  auto r = run("#1=1\nDPRNT[#1[10]]\nDPRNT[#1[10]]\nM30\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_TRUE(warned(r, "NC2060"));
  EXPECT_EQ(r.result.output.bytes, std::string(" 1\n\r\r 1\n\r\r"));  // sent all the same, no DC2
}

TEST(MacroOutput, BadFormatsAlarm) {
  for (const char* text : {"DPRNT[#1[5]]\n", "DPRNT[#1[54]]\n", "DPRNT[#1[00]]\n", "DPRNT[#1]\n", "DPRNT[X=1]\n",
                           "DPRNT[X#1[53]\n", "DPRNTX\n", "BPRNT[#1[12]]\n", "POPEN X1\n", "DPRNT[#1[53]]X1\n"}) {
    SCOPED_TRACE(text);
    auto r = run(std::string(text) + "M30\n");
    EXPECT_EQ(r.alarm_code(), "PS0114");
  }
}

// ---- G10 L52 programmable parameter input ----

// No.3401#0 DPI (bit 0) set by program: X10 is 0.010 mm before, 10 mm after (calculator-type input).
// No.6001 R00000010 sets bit 1 (PRT): the DPRNT after it sends no spaces.
TEST(ParameterInput, BitParametersTakeEffect) {
  auto r = run("G01 X10 F100\nG10 L52\nN3401 R00000001\nN6001 R10\nG11\nX10\n#1=5\nDPRNT[#1[20]]\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto m = r.motions();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[0].end[0], 0.010, 1e-9);
  EXPECT_NEAR(m[1].end[0], 10.0, 1e-9);
  EXPECT_EQ(r.result.output.lines.at(0), "5");
}

// No.6050 = 100: G100 calls O9010 from then on.
TEST(ParameterInput, WholeNumberParameter) {
  auto r = run("G10 L52\nN6050 R100\nG11\nG100 A1.\nM30\n", machine::default_mill(), {},
               {{"O9010.nc", "O9010\n#100=#1+1\nM99\n"}});
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_DOUBLE_EQ(r.var(100), 2.0);
}

TEST(ParameterInput, UnmodelledAndPowerOff) {
  auto p = machine::default_mill();
  p.axes = "XYZA";
  auto r = run("G10 L52\nN1234 R5\nN3405 R10000000\nN1008 P4 R1\nG11\nM30\n", p);
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_TRUE(warned(r, "NC2061"));  // No.1234, and bit 3405#7 (not modelled)
  EXPECT_TRUE(warned(r, "NC2062"));  // No.1008 waits for power off: A does not roll over in this run
}

TEST(ParameterInput, BadBlocksAlarm) {
  for (const char* text : {"G10 L52\nG01 X1\n", "G10 L52\nN3401 R2\n", "G10 L52\nR1\n", "G10 L52\nN3401\n",
                           "G10 L52\nN1008 R1\n", "G10 L52\nN3401 P1 R1\n", "G10 L52\nN5410 R400000\n",
                           "G10 L52\nN11 R1 G11\n", "G10 L52 X1\n", "G10 L52\nN3401 R1.\n"}) {
    SCOPED_TRACE(text);
    auto r = run(std::string(text) + "G11\nM30\n");
    EXPECT_EQ(r.alarm_code(), "PS0231");
  }
  auto r = run("G10 L50\nN3401 R1\nG11\nM30\n");
  EXPECT_EQ(r.alarm_code(), "NC9001");
}

// ---- G33 on a machining center ----

// From Z5, G33 Z-20. F1.5 at S500: one thread cut of 25 mm fed 1.5 mm per revolution:
// 25 / (1.5 * 500) min = 1/30 min = 2 s. The second cut starts 180 degrees (Q180000) after the
// one-rotation signal; G33 and F are modal.
TEST(MillThreading, G33IsAThreadCut) {
  auto r = run("G90 G00 X0 Y0 Z5.\nS500 M03\nG33 Z-20. F1.5\nG00 Z5.\nG33 Z-20. Q180000\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  auto m = r.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_FALSE(m[0].threading);
  EXPECT_TRUE(m[1].threading);
  EXPECT_NEAR(m[1].end[2], -20, 1e-9);
  EXPECT_NEAR(m[1].feed, 1.5, 1e-12);
  EXPECT_EQ(m[1].thread_start, 0);
  EXPECT_NEAR(m[1].seconds, 2.0, 1e-9);
  EXPECT_FALSE(m[2].threading);
  EXPECT_TRUE(m[3].threading);
  EXPECT_EQ(m[3].thread_start, 180000);
  EXPECT_NEAR(m[3].seconds, 2.0, 1e-9);
}

TEST(MillThreading, Alarms) {
  EXPECT_EQ(run("S500 M03\nG33 Z-20.\nM30\n").alarm_code(), "PS0011");  // no lead
  EXPECT_EQ(run("S500 M03\nG41 D1 G01 X10. F100\nG33 Z-20. F1.\nM30\n").alarm_code(), "NC9001");
}
