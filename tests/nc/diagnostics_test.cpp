// Diagnostics a user can trust: program text printed with its control characters escaped, and the
// text problems of a file bounded (the first 100 kept and the rest counted), however much junk.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>

#include "nc/program.hpp"
#include "report/summary.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

bool has_raw_control(const std::string& s) {
  for (unsigned char c : s)
    if ((c < 0x20 && c != '\n') || c == 0x7F) return true;
  return false;
}

nc::ParseResult parse_text(const std::string& text) {
  return nc::parse(std::make_shared<const nc::SourceFile>("junk.nc", text));
}

std::string repeat(const std::string& line, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += line;
  return out;
}

}  // namespace

TEST(Diagnostics, ControlCharactersAreEscaped) {
  EXPECT_EQ(nc::escape_controls("A\x1b[2JB\x07" "C\rD\bE\x7f" "F"), "A\\x1b[2JB\\x07C\\x0dD\\x08E\\x7fF");
  EXPECT_EQ(nc::escape_controls("TAB\tKEPT"), "TAB\tKEPT");
  EXPECT_EQ(nc::escape_controls("caf\xc3\xa9"), "caf\xc3\xa9");               // UTF-8 text passes
  EXPECT_EQ(nc::escape_controls("CSI\xc2\x9b" "2J"), "CSI\\xc2\\x9b2J");     // C1 control as UTF-8
  EXPECT_EQ(nc::escape_controls(std::string("NUL\0X", 5)), "NUL\\x00X");
}

// The message, the file name and the quoted block: no raw control byte reaches the terminal, and
// the caret stays under the column it marks (the escape is 4 columns wide).
TEST(Diagnostics, FormatEscapesMessageNameAndBlock) {
  auto file = std::make_shared<const nc::SourceFile>("a\x1b]0;title\x07.nc", "X1.\x1bY2.\n");
  nc::Diagnostic d{nc::Severity::error, "MC3001", "STOP\x1b[2J\x07 NOW", nc::Span{file.get(), 1, 5, 1}};
  const std::string text = nc::format(d);
  EXPECT_FALSE(has_raw_control(text)) << text;
  EXPECT_NE(text.find("a\\x1b]0;title\\x07.nc:1:5:"), std::string::npos) << text;
  EXPECT_NE(text.find("MC3001 STOP\\x1b[2J\\x07 NOW"), std::string::npos) << text;
  EXPECT_NE(text.find("    1 | X1.\\x1bY2."), std::string::npos) << text;
  // the caret line: "       | " and 7 spaces (X 1 . \ x 1 b) before the Y
  const std::size_t caret_line = text.rfind('\n') + 1;
  EXPECT_EQ(text.substr(caret_line), "       |        ^");
}

TEST(Diagnostics, MessagesOfARunAreEscapedInTextAndJson) {
  auto r = test::run("#3006=1(LOOK\x1b[2J)\n#3000=1(BELL\x07 CR\x0b)\nM30\n");
  ASSERT_TRUE(r.result.alarm);
  EXPECT_EQ(r.result.alarm->message, "BELL\x07 CR\x0b");  // kept as written
  report::RunReport rep;
  rep.source = "prog\x1b.nc";
  const machine::MachineProfile p = machine::default_mill();
  rep.profile = &p;
  rep.result = &r.result;
  const std::string text = report::summary_text(rep);
  EXPECT_FALSE(has_raw_control(text)) << text;
  EXPECT_NE(text.find("BELL\\x07 CR\\x0b"), std::string::npos);
  EXPECT_NE(text.find("LOOK\\x1b[2J"), std::string::npos);
  EXPECT_NE(text.find("prog\\x1b.nc"), std::string::npos);
  const std::string json = report::summary_json(rep);
  EXPECT_FALSE(has_raw_control(json));
  EXPECT_EQ(nlohmann::json::parse(json)["alarm"]["message"], "BELL\x07 CR\x0b");  // JSON escapes, \u0007
}

// 1000 lines, each a problem carrying N (so each can be a jump target and is parsed): the first
// 100 kept in line order, 900 counted.
TEST(Diagnostics, TheFirstHundredProblemsAreKeptAndTheRestCounted) {
  std::string text;
  for (int i = 1; i <= 1000; ++i) text += "N" + std::to_string(i) + (i % 2 ? " X[[\n" : " G01 X1.2.3\n");
  const nc::ParseResult r = parse_text(text);
  ASSERT_EQ(r.diagnostics.size(), nc::kMaxDiagnostics);
  EXPECT_EQ(r.more_diagnostics, 900u);
  EXPECT_EQ(r.unchecked_lines, 0u);
  for (std::size_t i = 0; i < r.diagnostics.size(); ++i) EXPECT_EQ(r.diagnostics[i].span.line, i + 1);
  // loop problems merge in line order with the syntax ones
  const nc::ParseResult loops = parse_text("END1\n" + repeat("X[[\n", 150) + "DO2\n");
  ASSERT_EQ(loops.diagnostics.size(), nc::kMaxDiagnostics);
  EXPECT_EQ(loops.diagnostics[0].code, "PS0124");
  EXPECT_EQ(loops.diagnostics[0].span.line, 1u);
}

// Lines of junk after a block that alarms, with no N, DO, WHILE, END or O: no jump can reach them,
// so past the first 100 problems they are counted as not checked; blocks that can be reached run.
TEST(Diagnostics, JunkNoJumpCanReachIsCountedNotKept) {
  const nc::ParseResult r = parse_text(repeat("X[[\n", 100000));
  EXPECT_EQ(r.diagnostics.size(), nc::kMaxDiagnostics);
  EXPECT_EQ(r.more_diagnostics + r.unchecked_lines + r.diagnostics.size(), 100000u);
  ASSERT_EQ(r.programs.size(), 1u);
  EXPECT_EQ(r.programs[0]->blocks.size(), 1u);  // the first alarms; none after it can run
  EXPECT_EQ(r.programs[0]->errors.size(), 1u);

  auto ran = test::run("#1=0\nGOTO 10\n" + repeat("X[[\n", 150) + repeat("G01 X#1+1\n", 50) +
                       "N10 WHILE [#1 LT 3] DO1\n#1=#1+1\nEND1\n" + repeat("Y[\n", 120) + "N20 #2=7\nM30\n");
  EXPECT_EQ(ran.alarm_code(), "PS0114");  // falls into the Y[ junk after the loop
  EXPECT_EQ(ran.var(1), 3.0);
  // a second block with the same N is no target (GOTO finds the first): not kept either
  const nc::ParseResult same_n = parse_text(repeat("N7 X[[\n", 1000));
  EXPECT_EQ(same_n.programs[0]->blocks.size(), 1u);
  EXPECT_EQ(same_n.more_diagnostics + same_n.unchecked_lines, 900u);
  auto to_first = test::run("GOTO 7\n#1=1\n" + repeat("N7 X[[\n", 200) + "M30\n");
  EXPECT_EQ(to_first.alarm_code(), "PS0114");
  EXPECT_EQ(to_first.alarm_line(), 3u);
  auto jumped = test::run("GOTO 20\n" + repeat("X[[\n", 150) + "N20 #2=7\nM30\n");
  ASSERT_TRUE(jumped.result.ok());
  EXPECT_EQ(jumped.var(2), 7.0);
  // a block skipped by '/' is transparent: the block after it is kept
  auto p = machine::default_mill();
  p.block_skip = true;
  auto skipped = test::run("/X[[\n#2=5\nM30\n", p);
  ASSERT_TRUE(skipped.result.ok());
  EXPECT_EQ(skipped.var(2), 5.0);
}

// The run's summary prints the first hundred and the counts, in text and in JSON.
TEST(Diagnostics, TheSummaryShowsTheFirstHundredAndTheCounts) {
  const std::string dir = ::testing::TempDir();
  const std::string path = dir + "/junk_summary.nc";
  {
    std::ofstream out(path);
    out << "M30\n";
    for (int i = 1; i <= 300; ++i) out << "N" << i << " X[[\n";  // each N new: a target, parsed
    out << repeat("X[[\n", 100) << repeat("N1 X[[\n", 100);      // none can run: not parsed
  }
  machine::ProgramLibrary lib;
  const auto problems = lib.add_file(path, true);
  EXPECT_EQ(problems.size(), nc::kMaxDiagnostics);
  EXPECT_EQ(lib.problems_left_out(), 200u);
  EXPECT_EQ(lib.unchecked_lines(), 200u);
  const machine::MachineProfile profile = machine::default_mill();
  machine::Interpreter interp(profile, lib);
  machine::NullSink sink;
  machine::RunResult result = interp.run(sink);
  ASSERT_TRUE(result.ok());
  report::RunReport rep;
  rep.source = path;
  rep.profile = &profile;
  rep.result = &result;
  rep.text_problems = problems;
  rep.text_problems_left_out = lib.problems_left_out();
  rep.unchecked_lines = lib.unchecked_lines();
  const std::string text = report::summary_text(rep);
  // 300 problems on lines with a new N (each parsed), the 200 lines of junk after them not checked
  EXPECT_NE(text.find("text problems  300 more"), std::string::npos) << text.substr(0, 800);
  EXPECT_NE(text.find("the first 100 shown"), std::string::npos);
  EXPECT_NE(text.find("... and 200 more text problems not shown"), std::string::npos);
  EXPECT_NE(text.find("... and 200 lines after them not checked"), std::string::npos);
  std::size_t quoted = 0;
  for (std::size_t at = text.find("PS0114"); at != std::string::npos; at = text.find("PS0114", at + 1)) ++quoted;
  EXPECT_EQ(quoted, nc::kMaxDiagnostics);
  const auto json = nlohmann::json::parse(report::summary_json(rep));
  EXPECT_EQ(json["text_problems"].size(), nc::kMaxDiagnostics);
  EXPECT_EQ(json["text_problems_left_out"].get<std::size_t>() + json["unchecked_lines"].get<std::size_t>(), 400u);
}
