// Inputs the fuzzers found, kept as tests (test.sh --sanitize runs them under AddressSanitizer and
// UndefinedBehaviorSanitizer, where the undefined behaviour they once had halts the test).
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "report/writers.hpp"

namespace ncurve {
namespace {

machine::RunResult run(const std::string& program, machine::MoveSink& sink,
                       const machine::MachineProfile& p = machine::default_mill()) {
  machine::ProgramLibrary lib;
  lib.add_text("f.nc", program, true);
  machine::Interpreter in(p, lib);
  return in.run(sink);
}

// #3000 = a value beyond int: the alarm number was 3000 + (int) value, a signed overflow. Which
// alarm a value beyond the control's range raises is not the point here: that it stops, cleanly.
TEST(FuzzFound, HugeUserAlarmNumbersStopWithAnAlarm) {
  for (const char* value : {"[21474830*100]", "-2147483647", "[99999999*99999999]", "2147480000"}) {
    machine::NullSink sink;
    const auto r = run(std::string("#3000=") + value + " (STOP)\nM30\n", sink);
    ASSERT_TRUE(r.alarm) << value;  // MC..., or a number's own alarm (too many digits)
    EXPECT_FALSE(r.alarm->code.empty()) << value;
  }
}

// An arc of a large radius at a tiny chord tolerance: at most 100,000 CSV rows, not millions.
TEST(FuzzFound, AnArcIsWrittenAsAtMostATenthOfAMillionPoints) {
  for (double tol : {1e-9, 1e-300}) {
    std::ostringstream out;
    const auto p = machine::default_mill();
    report::CsvWriter csv(out, p, tol);
    const auto r = run("G00 X99999. Y0\nG03 I-99999. J0 F1000.\nM30\n", csv, p);
    EXPECT_TRUE(r.ok());
    const std::string text = out.str();
    const auto rows = std::count(text.begin(), text.end(), '\n');
    EXPECT_GT(rows, 90000) << tol;  // the cap, not a coarse arc
    EXPECT_LE(rows, 100000 + 3) << tol;  // header, rapid, the arc's points
  }
}

}  // namespace
}  // namespace ncurve
