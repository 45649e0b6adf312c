// The checks of typed numbers and names (app/cli_checks.hpp): messages in the option's units,
// NaN and infinities refused, whole numbers, and the nearest name for a misspelt one.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/cli_checks.hpp"
#include "app/gen_command.hpp"
#include "geom/curve.hpp"

using namespace ncurve::app;

namespace {

// What CLI11 says when --v VALUE is checked by `check` ("" when it is accepted).
std::string parse_error(const CLI::Validator& check, const std::string& value) {
  CLI::App app;
  double v = 0;
  app.add_option("--v", v)->check(check);
  std::vector<std::string> args{value, "--v"};  // parse() takes them in reverse
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CliChecks, NumbersAreReadWholeOrNotAtAll) {
  EXPECT_EQ(read_number("1.5"), 1.5);
  EXPECT_EQ(read_number("+2"), 2.0);
  EXPECT_EQ(read_number("-1e-3"), -0.001);
  for (const char* bad : {"", "abc", "1.5mm", " 1", "1 ", "0:90", "++1", "+-1", "0x10"})
    EXPECT_FALSE(read_number(bad).has_value()) << bad;
  EXPECT_TRUE(std::isnan(*read_number("nan")));  // read, and refused by every rule
}

TEST(CliChecks, ValidatorsSayWhatTheOptionTakesInItsUnits) {
  EXPECT_EQ(parse_error(positive_mm(), "0.01"), "");
  EXPECT_EQ(parse_error(positive_mm(), "0"), "--v: must be a length above 0 mm, got 0");
  EXPECT_EQ(parse_error(positive_mm(), "-1"), "--v: must be a length above 0 mm, got -1");
  EXPECT_EQ(parse_error(positive_mm(), "abc"), "--v: 'abc' is not a number (expected a length above 0 mm)");
  for (const char* not_finite : {"nan", "inf", "-inf", "NaN", "infinity"}) {
    EXPECT_EQ(parse_error(positive_mm(), not_finite), std::string("--v: must be a length above 0 mm, got ") + not_finite);
    EXPECT_NE(parse_error(finite(), not_finite), "") << not_finite;
    EXPECT_NE(parse_error(degrees(), not_finite), "") << not_finite;
    EXPECT_NE(parse_error(non_negative_mm(), not_finite), "") << not_finite;
  }
  EXPECT_EQ(parse_error(non_negative_mm(), "0"), "");
  EXPECT_EQ(parse_error(non_negative_mm(), "-0.5"), "--v: must be a length of at least 0 mm, got -0.5");
  EXPECT_EQ(parse_error(range_mm(1, 2), "2"), "");
  EXPECT_EQ(parse_error(range_mm(1, 2), "2.5"), "--v: must be a length from 1 to 2 mm, got 2.5");
  EXPECT_EQ(parse_error(degrees(), "-720"), "");
  EXPECT_EQ(parse_error(degrees(), "inf"), "--v: must be an angle in degrees, got inf");
  EXPECT_EQ(parse_error(finite(), "nan"), "--v: must be a finite number, got nan");
  EXPECT_EQ(parse_error(positive("a spindle speed", "rpm"), "0"), "--v: must be a spindle speed above 0 rpm, got 0");
  EXPECT_EQ(parse_error(whole(1, 9999), "9999"), "");
  EXPECT_EQ(parse_error(whole(1, 9999), "1.5"), "--v: must be a whole number from 1 to 9999, got 1.5");
  EXPECT_EQ(parse_error(whole(1, 9999), "0"), "--v: must be a whole number from 1 to 9999, got 0");
  EXPECT_EQ(parse_error(whole(1, 9999), "1e300"), "--v: must be a whole number from 1 to 9999, got 1e300");
}

TEST(CliChecks, ChoicesAndNamesSuggestTheNearest) {
  const CLI::Validator form = one_of("a form", {"expanded", "arcs", "macro"});
  EXPECT_EQ(form("arcs"), "");
  EXPECT_EQ(form("arc"), "'arc' is not a form (expanded, arcs, macro); did you mean arcs?");
  EXPECT_EQ(form("zzz"), "'zzz' is not a form (expanded, arcs, macro)");
  const std::vector<std::string> options{"tol", "form", "feed", "clearance", "tool-radius", "r0", "pitch"};
  EXPECT_EQ(nearest_name("tolerance", options), "tol");  // the option begins the word
  EXPECT_EQ(nearest_name("feedrate", options), "feed");
  EXPECT_EQ(nearest_name("fomr", options), "form");      // two letters swapped
  EXPECT_EQ(nearest_name("pich", options), "pitch");     // one left out
  EXPECT_EQ(nearest_name("R0", options), "r0");          // case
  EXPECT_EQ(nearest_name("toolradius", options), "tool-radius");
  EXPECT_EQ(nearest_name("b", {"a", "x"}), std::nullopt);  // one letter is one edit from any other
  EXPECT_EQ(nearest_name("radius", options), std::nullopt);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("ab", "ba"), 1u);
}

TEST(CliChecks, CurveTextNamesItsParametersAndCalls) {
  const auto uses = ncurve::geom::names_in("a*COS(t)+PI*bb - cOz [t] + sqrt[a]");
  ASSERT_EQ(uses.size(), 4u);  // each use; t, PI and the functions (any case) are not names
  EXPECT_EQ(uses[0].name, "a");
  EXPECT_EQ(uses[0].column, 1u);
  EXPECT_FALSE(uses[0].called);
  EXPECT_EQ(uses[1].name, "bb");
  EXPECT_EQ(uses[1].column, 13u);
  EXPECT_EQ(uses[2].name, "cOz");
  EXPECT_EQ(uses[2].column, 18u);
  EXPECT_TRUE(uses[2].called);  // followed by a bracket, past a space
  EXPECT_EQ(uses[3].name, "a");
  EXPECT_EQ(uses[3].column, 33u);
}

// gen's list of the common variables a program sets: assignments to #100..#199 and #500..#999,
// not those in comments, nor locals and system variables.
TEST(GenOutput, CommonVariablesSetSkipsCommentsLocalsAndSystemVariables) {
  const std::string text = "O1000 (#105 = T)\n#100=1.\n#101 = #100+#105\n#33=2\nIF [#1 GT 0] THEN #500=3\n"
                           "#3000=1 (#120=0)\n#199=#102\nG01 X#110\n";
  EXPECT_EQ(common_variables_set(text), (std::vector<int>{100, 101, 199, 500}));
  EXPECT_EQ(variable_ranges({100, 101, 102, 110, 111, 120, 500}), "#100..#102, #110, #111, #120, #500");
  EXPECT_EQ(variable_ranges({}), "");
}
