#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "nc/program.hpp"

using namespace ncurve::nc;

namespace {
ParseResult parse_text(const std::string& text) { return parse(std::make_shared<SourceFile>("t.nc", text)); }

const Diagnostic* first_error(const ParseResult& r) { return r.diagnostics.empty() ? nullptr : &r.diagnostics[0]; }

// The alarm code of the first problem in the text, or "" when there is none.
std::string first_code(const std::string& text) {
  auto r = parse_text(text);
  return r.diagnostics.empty() ? "" : r.diagnostics[0].code;
}
}  // namespace

TEST(Parser, ProgramsCommentsSequenceNumbersAndSkip) {
  auto r = parse_text("%\nO1234 (MAIN PART)\nN10 g01 x1. (comment) y 2 . 5;\n/N20 G00 X0\nM30\nO2000\nM99\n%\nG00 X99\n");
  ASSERT_EQ(r.diagnostics.size(), 0u) << format(r.diagnostics[0]);
  ASSERT_EQ(r.programs.size(), 2u);
  const Program& p = *r.programs[0];
  EXPECT_EQ(p.number, 1234);
  EXPECT_EQ(p.name, "MAIN PART");
  ASSERT_EQ(p.blocks.size(), 3u);
  const Block& b = p.blocks[0];
  EXPECT_EQ(b.sequence, 10);
  EXPECT_EQ(b.kind, Statement::nc);
  ASSERT_EQ(b.words_end - b.words_begin, 3u);
  EXPECT_EQ(p.words[b.words_begin].letter, 'G');
  const Word& y = p.words[b.words_begin + 2];
  EXPECT_EQ(y.letter, 'Y');
  EXPECT_DOUBLE_EQ(y.value, 2.5);  // spaces are ignored anywhere, even inside numbers
  EXPECT_TRUE(y.decimal_point);
  EXPECT_TRUE(p.blocks[1].block_skip);
  EXPECT_EQ(p.sequence_index.at(20), 1);
  EXPECT_EQ(r.programs[1]->number, 2000);
  EXPECT_EQ(r.programs[1]->blocks.size(), 1u);  // text after the closing % is not read
}

TEST(Parser, DecimalPointIsRecorded) {
  auto r = parse_text("X10 Y10. Z.5\n");
  const Program& p = *r.programs[0];
  EXPECT_FALSE(p.words[0].decimal_point);
  EXPECT_TRUE(p.words[1].decimal_point);
  EXPECT_TRUE(p.words[2].decimal_point);
  EXPECT_DOUBLE_EQ(p.words[2].value, 0.5);
}

TEST(Parser, ArithmeticOutsideBracketsIsPS0004WithColumn) {
  auto r = parse_text("G55 X#106+50. Z#109+50.\n");
  const Diagnostic* d = first_error(r);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->code, "PS0004");
  EXPECT_EQ(d->span.line, 1u);
  EXPECT_EQ(d->span.column, 10u);
  std::string text = format(*d);
  EXPECT_NE(text.find("t.nc:1:10"), std::string::npos);
  EXPECT_NE(text.find("G55 X#106+50."), std::string::npos);  // the block is quoted
  EXPECT_NE(text.find('^'), std::string::npos);
}

TEST(Parser, BracketNestingLimitIsFive) {
  EXPECT_TRUE(parse_text("#1=[[[[[1]]]]]\n").diagnostics.empty());
  auto r = parse_text("#1=[[[[[[1]]]]]]\n");
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].code, "PS0118");
  std::string deep = "#1=" + std::string(1000, '[') + "1" + std::string(1000, ']') + "\n";
  auto d = parse_text(deep);
  ASSERT_FALSE(d.diagnostics.empty());
  EXPECT_EQ(d.diagnostics[0].code, "PS0118");
  // ten thousand brackets and a megabyte line: an alarm, not a stack overflow or a huge allocation
  std::string huge = "#1=" + std::string(10000, '[') + "1" + std::string(10000, ']') + std::string(1 << 20, '1') + "\n";
  EXPECT_FALSE(parse_text(huge).diagnostics.empty());
}

TEST(Parser, AbbreviationsCompileLikeFullWords) {
  auto full = parse_text("WHILE [#1 LT ROUND[2.5]] DO1\nEND1\n");
  auto abbr = parse_text("WH [#1 LT RO[2.5]] DO1\nEN1\n");
  ASSERT_TRUE(full.diagnostics.empty());
  ASSERT_TRUE(abbr.diagnostics.empty());
  ASSERT_EQ(full.programs[0]->code.size(), abbr.programs[0]->code.size());
  for (std::size_t i = 0; i < full.programs[0]->code.size(); ++i)
    EXPECT_EQ(full.programs[0]->code[i].op, abbr.programs[0]->code[i].op);
  EXPECT_EQ(abbr.programs[0]->blocks[0].kind, Statement::while_do);
  EXPECT_EQ(abbr.programs[0]->blocks[1].kind, Statement::end_loop);
}

TEST(Parser, LoopPairingErrors) {
  auto missing_end = parse_text("WHILE [1 EQ 1] DO1\nG00 X1\n");
  ASSERT_FALSE(missing_end.diagnostics.empty());
  EXPECT_EQ(missing_end.diagnostics[0].code, "PS0124");
  EXPECT_EQ(missing_end.diagnostics[0].span.line, 1u);
  EXPECT_EQ(first_code("DO1\nDO2\nEND1\nEND2\n"), "PS0124");  // overlapping loops
  EXPECT_EQ(first_code("DO4\nEND4\n"), "PS0126");
  EXPECT_EQ(first_code("DO1\nDO2\nDO3\nDO1\nEND1\nEND3\nEND2\nEND1\n"), "PS0126");  // four deep
}

TEST(Parser, MacroAndNcStatementInOneBlockIsPS0127) {
  EXPECT_EQ(first_code("G01 X1. GOTO 10\n"), "PS0127");
  EXPECT_EQ(first_code("#1=5 X1.\n"), "PS0127");
}

TEST(Parser, ComparisonsOnlyInConditions) {
  EXPECT_EQ(first_code("#1=#2 GT 3\n"), "PS0114");
  EXPECT_TRUE(parse_text("IF [[#1 GT 3] AND [#2 LT 1]] THEN #3=1\n").diagnostics.empty());
}

TEST(Parser, JunkNeverCrashes) {
  std::string junk;
  for (int i = 0; i < 4096; ++i) junk += static_cast<char>((i * 7919) % 256);
  auto r = parse_text(junk);
  EXPECT_FALSE(r.diagnostics.empty());
  auto unterminated = parse_text("G01 X1. (no end\n");
  ASSERT_FALSE(unterminated.diagnostics.empty());
  EXPECT_EQ(unterminated.diagnostics[0].span.column, 9u);
}

TEST(Parser, StandaloneExpression) {
  EXPECT_NO_THROW(compile_expression("SIN[#1]*2+ATAN[1]/[2]"));
  EXPECT_THROW(compile_expression("SIN[#1"), Alarm);
}

TEST(Parser, TwoArgumentFunctions) {
  EXPECT_NO_THROW(compile_expression("POW[2,3]"));
  EXPECT_NO_THROW(compile_expression("ATAN[1,2]+ATAN[1]/[2]+ATAN[1]"));
  EXPECT_THROW(compile_expression("POW[2]"), Alarm);
  EXPECT_THROW(compile_expression("POW[2,3"), Alarm);
  EXPECT_THROW(compile_expression("POW 2"), Alarm);
}

// Plain NC lines take a fast path; a comment at the end of the line forces the general scanner.
// Both must compile every line to the same words and report the same problems at the same columns.
TEST(Parser, PlainLinesCompileAsTheGeneralScannerDoes) {
  const char* lines[] = {
      "G01 X1.234 Y-5. F100.",  "x 1 . 5 y-2 z+3",       "G90G01X10Y20",       "X.5 Y-.25",
      "X123456789012345.",      "X1234567890123456.",    "X1.2.3",             "X.",
      "X",                      "X1-2",                  "XY1",                "G01 X1 N10",
      "M30 O12",                "\tG00\tX0\r",           "X0.000000000000000001", "G4X-0", "X0.00555555555555556",
      "X-.0000000000000000000000001234", "X 1 2 . 3 4 0", "X-0.", "Y+.0", "G01X1.Y2.Z3.F4.",
      "N10 G01 X1.", "N0010X1", "N 10 X1", "N123456789 X1", "N12345678 X1", "N10", "N10 ", "N10.5 X1",
      "N X1", "G01 N10 X1", "n7 g1 x2", "N10 N20 X1", "N10 O5",
  };
  std::vector<std::string> all(std::begin(lines), std::end(lines));
  std::mt19937 rng(7);  // and lines of random plain-looking characters
  const std::string alphabet = "XYZGFON 0123456789.-+\t";
  for (int i = 0; i < 3000; ++i) {
    std::string line;
    for (int n = static_cast<int>(rng() % 20); n > 0; --n) line += alphabet[rng() % alphabet.size()];
    if (line.find_first_not_of(" \t") != std::string::npos) all.push_back(line);  // a comment alone is a block
  }
  for (const std::string& line : all) {
    auto plain = parse_text(std::string("O1\n") + line + "\n");
    auto general = parse_text(std::string("O1\n") + line + " (C)\n");
    SCOPED_TRACE(line);
    ASSERT_EQ(plain.diagnostics.size(), general.diagnostics.size());
    for (std::size_t i = 0; i < plain.diagnostics.size(); ++i) {
      EXPECT_EQ(plain.diagnostics[i].code, general.diagnostics[i].code);
      EXPECT_EQ(plain.diagnostics[i].span.column, general.diagnostics[i].span.column);
    }
    const Program& a = *plain.programs[0];
    const Program& b = *general.programs[0];
    ASSERT_EQ(a.blocks.size(), b.blocks.size());
    ASSERT_EQ(a.words.size(), b.words.size());
    for (std::size_t i = 0; i < a.words.size(); ++i) {
      EXPECT_EQ(a.words[i].letter, b.words[i].letter);
      EXPECT_EQ(a.words[i].column, b.words[i].column);
      EXPECT_EQ(a.words[i].decimal_point, b.words[i].decimal_point);
      EXPECT_EQ(a.words[i].literal, b.words[i].literal);
      EXPECT_EQ(a.words[i].value, b.words[i].value);
      EXPECT_EQ(std::signbit(a.words[i].value), std::signbit(b.words[i].value));
      if (a.words[i].decimal_point) {
        EXPECT_EQ(a.words[i].decimals, b.words[i].decimals);
      }
    }
    EXPECT_EQ(a.sequence_index, b.sequence_index);
    for (std::size_t i = 0; i < a.blocks.size(); ++i) {
      EXPECT_EQ(a.blocks[i].sequence, b.blocks[i].sequence);
      EXPECT_EQ(a.blocks[i].kind, b.blocks[i].kind);
      EXPECT_EQ(a.blocks[i].column, b.blocks[i].column);
      EXPECT_EQ(a.blocks[i].error >= 0, b.blocks[i].error >= 0);
    }
  }
}

// FANUC 0i takes 8 digits in a number, every digit typed counted (0.00000001 has nine, .00000001
// eight); a profile may allow up to 15, and long fractions keep their value.
TEST(Parser, DigitsPerNumberFollowTheControl) {
  const std::string text = "O1\n#1=.00000001\n#2=0.00000001\nX12345.678\nX123456.789\nG01 X1. Y.123456789 (C)\n";
  auto eight = parse_text(text);
  ASSERT_EQ(eight.diagnostics.size(), 3u);
  const std::uint32_t lines[] = {3, 5, 6}, columns[] = {4, 2, 10};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(eight.diagnostics[i].code, "PS0003");
    EXPECT_EQ(eight.diagnostics[i].span.line, lines[i]);
    EXPECT_EQ(eight.diagnostics[i].span.column, columns[i]);
  }
  EXPECT_DOUBLE_EQ(eight.programs[0]->code[eight.programs[0]->blocks[1].value.begin].k, 1e-8);
  auto fifteen = parse(std::make_shared<SourceFile>("t.nc", text), ParseOptions{15});
  EXPECT_TRUE(fifteen.diagnostics.empty());
  auto r = parse(std::make_shared<SourceFile>("t.nc", "O1\nX.00555555555555 Y-.00000000000123\n#1=.017453292519943*2\nX1234567890123456\n"),
                 ParseOptions{15});
  ASSERT_EQ(r.diagnostics.size(), 1u);  // 16 digits
  EXPECT_EQ(r.diagnostics[0].span.line, 4u);
  const Program& p = *r.programs[0];
  EXPECT_DOUBLE_EQ(p.words[0].value, 0.00555555555555);
  EXPECT_DOUBLE_EQ(p.words[1].value, -1.23e-12);
  EXPECT_DOUBLE_EQ(p.code[p.blocks[1].value.begin].k, 0.017453292519943);
}
