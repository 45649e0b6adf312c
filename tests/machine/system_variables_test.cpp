// The system variables' ranges as the FANUC manuals number them: what a program may read, what it
// may write, and the alarm for the rest (PS0115 no such variable, PS0116 read-only).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "support/run_program.hpp"

namespace ncurve {
namespace {

using test::run;

TEST(SystemVariables, ReadOnlyRangesRefuseAWrite) {
  for (int n : {1000, 1035, 3002, 3011, 3012, 4001, 4022, 4101, 4130, 5001, 5021, 5106}) {
    auto r = run(fmt::format("#{}=1\nM30\n", n));
    EXPECT_EQ(r.alarm_code(), "PS0116") << "#" << n;
  }
}

TEST(SystemVariables, NumbersTheControlLacksAreNoVariable) {
  for (int n : {1036, 1099, 1136, 3100, 4200, 5107, 5200, 5327, 6000, 7961}) {
    EXPECT_EQ(run(fmt::format("#1=#{}\nM30\n", n)).alarm_code(), "PS0115") << "read #" << n;
    EXPECT_EQ(run(fmt::format("#{}=1\nM30\n", n)).alarm_code(), "PS0115") << "write #" << n;
  }
}

TEST(SystemVariables, WritableRangesKeepWhatIsWritten) {
  // output signals, the switches #3003..#3005, parts counts, a work offset (G55 X) and G54.1 P1 Y
  auto r = run("#1100=1\n#3003=2\n#3901=7\n#3902=9\n#5221=12.5\n#7002=-3.\nM30\n");
  ASSERT_TRUE(r.result.ok()) << (r.result.alarm ? r.result.alarm->message : "");
  EXPECT_EQ(r.var(1100), 1);
  EXPECT_EQ(r.var(3003), 2);
  EXPECT_EQ(r.var(3901), 8);  // M30 counts the part made
  EXPECT_EQ(r.var(3902), 9);
  EXPECT_EQ(r.var(5221), 12.5);
  EXPECT_EQ(r.var(7002), -3);
  EXPECT_EQ(r.var(1000), 0);  // input signals: no PMC attached, all 0
}

}  // namespace
}  // namespace ncurve
