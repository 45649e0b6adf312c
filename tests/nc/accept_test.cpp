// What controls accept in the text: ':' program numbers, the closing '%', comments that end at
// their first ')'.
#include <gtest/gtest.h>

#include "nc/program.hpp"

using namespace ncurve::nc;

namespace {
ParseResult parse_text(const std::string& text) { return parse(std::make_shared<SourceFile>("t.nc", text)); }
}  // namespace

TEST(Accept, ColonIsTheIsoProgramNumber) {
  // ISO code writes the program number with ':' where EIA writes O; several programs per file
  auto r = parse_text("%\n:1234 (MAIN)\nG00 X1.\nM30\n:9010\nM99\nO9011\nM99\n%\n");
  ASSERT_TRUE(r.diagnostics.empty()) << format(r.diagnostics[0]);
  ASSERT_EQ(r.programs.size(), 3u);
  EXPECT_EQ(r.programs[0]->number, 1234);
  EXPECT_EQ(r.programs[0]->name, "MAIN");
  EXPECT_EQ(r.programs[0]->blocks.size(), 2u);
  EXPECT_EQ(r.programs[1]->number, 9010);
  EXPECT_EQ(r.programs[2]->number, 9011);
  // the program number may share its line with a block, as O may
  auto s = parse_text(":55 G00 X1.\n");
  ASSERT_EQ(s.programs.size(), 1u);
  EXPECT_EQ(s.programs[0]->number, 55);
  EXPECT_EQ(s.programs[0]->blocks.size(), 1u);
}

// ':' or O starting a block without a number: the number is missing (a ':' typed for '(', a
// placeholder left in a template), not an address out of place
TEST(Accept, ProgramNumberAddressWithoutANumber) {
  for (const char* text : {"G00 X1.\n:(SOLVE FOR B)\n", "G00 X1.\nO[YOUR NUMBER]\n"}) {
    auto r = parse_text(text);
    ASSERT_EQ(r.diagnostics.size(), 1u) << text;
    EXPECT_EQ(r.diagnostics[0].code, "PS0005") << text;
    EXPECT_EQ(r.diagnostics[0].span.line, 2u);
    EXPECT_EQ(r.diagnostics[0].span.column, 1u);
    EXPECT_NE(r.diagnostics[0].message.find("no program number after"), std::string::npos) << r.diagnostics[0].message;
  }
}

TEST(Accept, ColonElsewhereSaysWhatItIs) {
  auto r = parse_text("G00 X1. :12\n");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "PS0009");
  EXPECT_EQ(r.diagnostics[0].span.column, 9u);
  EXPECT_NE(r.diagnostics[0].message.find("program number address"), std::string::npos) << r.diagnostics[0].message;
  auto a = parse_text("#1=#1-#11:\n");  // a line ended with ':' instead of ';'
  ASSERT_EQ(a.diagnostics.size(), 1u);
  EXPECT_EQ(a.diagnostics[0].code, "PS0114");
  EXPECT_EQ(a.diagnostics[0].span.column, 10u);
  EXPECT_NE(a.diagnostics[0].message.find("':' after the expression"), std::string::npos);
}

TEST(Accept, TextAfterTheClosingPercentIsNotRead) {
  // line 5 closes the file; O2000 (line 6) and :3000 (line 9) are never read, nor is the bad block
  auto r = parse_text("%\nO1000\nM98 P2000\nM30\n%\nO2000\nX1..\nM99\n  :3000\nM99\n");
  ASSERT_TRUE(r.diagnostics.empty());
  ASSERT_EQ(r.programs.size(), 1u);
  ASSERT_EQ(r.after_end.size(), 2u);
  EXPECT_EQ(r.after_end[0].number, 2000);
  EXPECT_EQ(r.after_end[0].line, 6u);
  EXPECT_EQ(r.after_end[0].end_line, 5u);
  EXPECT_EQ(r.after_end[1].number, 3000);
  EXPECT_EQ(r.after_end[1].line, 9u);
  // a leading '%' does not close anything; without a closing one nothing is left unread
  EXPECT_TRUE(parse_text("%\nO1\nM30\n").after_end.empty());
}

TEST(Accept, CommentEndsAtItsFirstCloseParenthesis) {
  // "(TOOL (6MM) ENDMILL)": the comment is "(TOOL (6MM)", columns 1..11; " ENDMILL)" is read as
  // words, and ENDMILL (column 13) starts with END, a macro word wanting a loop number at column 16
  auto r = parse_text("G00 X1.\n(TOOL (6MM) ENDMILL)\nM30\n");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  const Diagnostic& d = r.diagnostics[0];
  EXPECT_EQ(d.span.line, 2u);
  EXPECT_EQ(d.span.column, 16u);
  EXPECT_NE(d.message.find("the comment opened at column 1 closed early at column 11"), std::string::npos)
      << d.message;
  // the comment kept for #3000 messages is the text up to the first ')'
  EXPECT_EQ(r.programs[0]->comments.at(0), "TOOL (6MM");
  // words after the early end: here ')' alone, after a call in the comment
  auto s = parse_text("G00 X1. ( CALL (O9100) )\n");
  ASSERT_EQ(s.diagnostics.size(), 1u);
  EXPECT_EQ(s.diagnostics[0].span.column, 24u);
  EXPECT_NE(s.diagnostics[0].message.find("')' is not an address"), std::string::npos);
  EXPECT_NE(s.diagnostics[0].message.find("opened at column 9 closed early at column 22"), std::string::npos)
      << s.diagnostics[0].message;
  // a '(' inside a comment that the line's last ')' closes is no problem, and a stray ')' after a
  // plain comment gets no note about nesting
  EXPECT_TRUE(parse_text("G00 X1. (A (B\n").diagnostics.size() == 1u);  // not closed at all: its own alarm
  EXPECT_TRUE(parse_text("G00 X1. (A B) (C (D)\n").diagnostics.empty());
  auto t = parse_text("G00 X1. (A) )\n");
  ASSERT_EQ(t.diagnostics.size(), 1u);
  EXPECT_EQ(t.diagnostics[0].message.find("closed early"), std::string::npos);
}
