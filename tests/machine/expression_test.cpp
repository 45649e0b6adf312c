// Expression semantics through the interpreter: FANUC functions, precedence, vacant values.
#include <gtest/gtest.h>

#include <cmath>

#include "support/run_program.hpp"

using namespace ncurve;
using ncurve::test::run;

namespace {
double eval(const std::string& expr, machine::MachineProfile p = machine::default_mill()) {
  auto r = run("#100=" + expr + "\nM30\n", p);
  EXPECT_TRUE(r.result.ok()) << (r.result.alarm ? nc::format(*r.result.alarm) : "");
  return r.var(100);
}
}  // namespace

TEST(Expression, TrigonometryInDegrees) {
  EXPECT_DOUBLE_EQ(eval("SIN[30.]"), std::sin(M_PI / 6));
  EXPECT_EQ(eval("SIN[180.]"), 0.0);
  EXPECT_EQ(eval("COS[90.]"), 0.0);
  EXPECT_NEAR(eval("TAN[45.]"), 1.0, 1e-15);
  EXPECT_NEAR(eval("ACOS[0.5]"), 60.0, 1e-12);
  EXPECT_NEAR(eval("ASIN[-0.5]"), 330.0, 1e-12);  // 270..90 without NAT
  auto nat = machine::default_mill();
  nat.atan_signed = true;
  EXPECT_NEAR(eval("ASIN[-0.5]", nat), -30.0, 1e-12);
}

TEST(Expression, SineAndCosineAreExactOnWholeQuarterTurns) {
  for (int k = -9; k <= 9; ++k) {
    const double sine[4] = {0, 1, 0, -1};
    const int q = ((k % 4) + 4) % 4;
    const std::string angle = std::to_string(90 * k) + ".";
    EXPECT_EQ(eval("SIN[" + angle + "]"), sine[q]) << angle;
    EXPECT_EQ(eval("COS[" + angle + "]"), sine[(q + 1) % 4]) << angle;
  }
  EXPECT_EQ(eval("SIN[36000090.]"), 1.0);
  // near a quarter turn is not on it
  EXPECT_NEAR(eval("COS[90.000001]"), -std::sin(1e-6 * M_PI / 180), 1e-15);
  EXPECT_NE(eval("COS[90.000001]"), 0.0);
  EXPECT_NEAR(eval("SIN[-179.99999]"), -std::sin(1e-5 * M_PI / 180), 1e-15);
}

TEST(Expression, AtanIsQuadrantAware) {
  EXPECT_NEAR(eval("ATAN[1]/[1]"), 45.0, 1e-12);
  EXPECT_NEAR(eval("ATAN[1]/[-1]"), 135.0, 1e-12);
  EXPECT_NEAR(eval("ATAN[-1]/[-1]"), 225.0, 1e-12);
  EXPECT_NEAR(eval("ATAN[-1]/[1]"), 315.0, 1e-12);
  auto nat = machine::default_mill();
  nat.atan_signed = true;
  EXPECT_NEAR(eval("ATAN[-1]/[-1]", nat), -135.0, 1e-12);
  auto r = run("#100=ATAN[1,1]\nM30\n");  // 30i syntax on a 0i profile
  EXPECT_EQ(r.alarm_code(), "PS0114");
  auto thirty = machine::default_mill();
  thirty.control = machine::Control::fanuc_30i;
  EXPECT_NEAR(eval("ATAN[1,-1]", thirty), 135.0, 1e-12);
}

TEST(Expression, RoundingFunctions) {
  EXPECT_EQ(eval("FIX[3.7]"), 3.0);
  EXPECT_EQ(eval("FIX[-3.7]"), -3.0);
  EXPECT_EQ(eval("FUP[3.1]"), 4.0);
  EXPECT_EQ(eval("FUP[-3.1]"), -4.0);
  EXPECT_EQ(eval("ROUND[2.5]"), 3.0);
  EXPECT_EQ(eval("ROUND[-2.5]"), -3.0);
  EXPECT_EQ(eval("ABS[-2.25]"), 2.25);
}

TEST(Expression, OtherFunctions) {
  EXPECT_EQ(eval("SQRT[16.]"), 4.0);
  EXPECT_NEAR(eval("LN[EXP[2.]]"), 2.0, 1e-12);
  EXPECT_EQ(eval("POW[2.,10.]"), 1024.0);
  EXPECT_EQ(eval("BCD[25]"), 37.0);  // 0010 0101
  EXPECT_EQ(eval("BIN[37]"), 25.0);
  EXPECT_EQ(eval("ADP[0.01]"), 10.0);  // IS-B: back to the number as written
  EXPECT_EQ(eval("7 MOD 3"), 1.0);
  EXPECT_EQ(eval("-7 MOD 3"), -1.0);
  EXPECT_EQ(eval("12 AND 10"), 8.0);
  EXPECT_EQ(eval("12 OR 3"), 15.0);
  EXPECT_EQ(eval("12 XOR 10"), 6.0);
}

TEST(Expression, FanucPrecedence) {
  EXPECT_EQ(eval("1+2*3"), 7.0);
  EXPECT_EQ(eval("[1+2]*3"), 9.0);
  EXPECT_EQ(eval("8/4/2"), 1.0);
  EXPECT_EQ(eval("1 OR 2 AND 3"), 3.0);  // AND binds like *, OR like +
  EXPECT_EQ(eval("-2*3"), -6.0);
  EXPECT_EQ(eval("10-2-3"), 5.0);
}

TEST(Expression, VacantRules) {
  auto r = run(
      "#10=#1\n"          // plain copy stays vacant
      "#11=#1+1\n"        // vacant acts as 0 in arithmetic
      "#12=#1*10\n"       // 0, not vacant
      "#13=-#1\n"         // still vacant
      "IF [#1 EQ #0] THEN #14=1\n"
      "IF [#1 EQ 0] THEN #15=1\n"   // vacant is not 0 for EQ
      "IF [#1 GE 0] THEN #16=1\n"   // but is 0 for GE
      "#17=0\n"
      "IF [#17 NE #0] THEN #18=1\n"
      "#100=#10\n#101=#11\n#102=#12\n#103=#13\n#104=#14\n#105=#15\n#106=#16\n#107=#18\nM30\n");
  ASSERT_TRUE(r.result.ok()) << nc::format(*r.result.alarm);
  EXPECT_TRUE(r.vacant(100));
  EXPECT_EQ(r.var(101), 1.0);
  EXPECT_FALSE(r.vacant(102));
  EXPECT_EQ(r.var(102), 0.0);
  EXPECT_TRUE(r.vacant(103));
  EXPECT_EQ(r.var(104), 1.0);
  EXPECT_TRUE(r.vacant(105));
  EXPECT_EQ(r.var(106), 1.0);
  EXPECT_EQ(r.var(107), 1.0);
}

TEST(Expression, IndirectVariables) {
  auto r = run("#1=105\n#[#1]=7.5\n#[#1+1]=#[100+5]*2\nM30\n");
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(r.var(105), 7.5);
  EXPECT_EQ(r.var(106), 15.0);
}

TEST(Expression, ErrorsNameTheAlarmLineAndColumn) {
  auto r = run("#1=0\n#100=5/#1\nM30\n");
  EXPECT_EQ(r.alarm_code(), "PS0112");
  EXPECT_EQ(r.alarm_line(), 2u);
  EXPECT_EQ(r.result.alarm->span.column, 7u);
  EXPECT_EQ(run("#100=SQRT[-1]\n").alarm_code(), "PS0119");
  EXPECT_EQ(run("#100=ACOS[2]\n").alarm_code(), "PS0119");
  EXPECT_EQ(run("#100=EXP[1000]\n").alarm_code(), "PS0111");
  EXPECT_EQ(run("#100=#20000\n").alarm_code(), "PS0115");
  EXPECT_EQ(run("#0=1\n").alarm_code(), "PS0116");
  EXPECT_EQ(run("#5001=1\n").alarm_code(), "PS0116");
  EXPECT_EQ(run("#100=TAN[90]\n").alarm_code(), "PS0111");
}
