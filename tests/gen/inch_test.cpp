// gen --inch: G20 programs with every coordinate and feed in inches on the inch increment (IS-B
// 0.0001 in, IS-C 0.00001 in), the curve and the options in mm; the program, as the control runs
// it, within the tolerance of the closed-form curve.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "gen/generate.hpp"
#include "gen/path_distance.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

// The most decimals of any axis, arc or R word with a number (not the feed).
int most_decimals(const std::string& text) {
  static const std::regex word(R"((^|[ \n])[XYZIJKR]-?[0-9]*\.([0-9]*))");
  int most = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator(); ++it)
    most = std::max(most, static_cast<int>((*it)[2].length()));
  return most;
}

bool has_line(const std::string& text, const std::string& line) {
  return text.find("\n" + line + "\n") != std::string::npos;
}

// the ellipse x = 40 cos t, y = 20 sin t, densely
std::vector<std::pair<double, double>> ellipse_points() {
  std::vector<std::pair<double, double>> out;
  for (int i = 0; i <= 4000; ++i) {
    const double t = 2 * std::numbers::pi * i / 4000;
    out.emplace_back(40 * std::cos(t), 20 * std::sin(t));
  }
  return out;
}

}  // namespace

TEST(GenInch, MillProgramsInInchesCutTheCurveInMm) {
  const geom::Curve ellipse(*geom::find_curve("ellipse"), {});
  for (gen::Form form : {gen::Form::expanded, gen::Form::arcs, gen::Form::macro, gen::Form::adaptive_macro}) {
    for (const bool is_c : {false, true}) {
      SCOPED_TRACE(fmt::format("{} IS-{}", gen::to_string(form), is_c ? 'C' : 'B'));
      gen::Options o;
      o.form = form;
      o.inch = true;
      o.tol = 0.005;
      if (is_c) o.profile.increment = 0.0001;
      const gen::Result r = gen::generate(ellipse, o);
      EXPECT_TRUE(r.within_tolerance);
      EXPECT_NE(r.text.find("\nG20 G17 G90 G94 G54\n"), std::string::npos);
      EXPECT_EQ(r.text.find("G21"), std::string::npos);
      // the numbers by hand: 5 mm = 0.19685 in, 1 mm = 0.03937 in, 200 mm/min = 7.874 in/min
      EXPECT_TRUE(has_line(r.text, is_c ? "G00 Z0.19685" : "G00 Z0.1969")) << r.text.substr(0, 400);
      if (form == gen::Form::expanded || form == gen::Form::arcs) {
        EXPECT_TRUE(has_line(r.text, is_c ? "X1.5748 Y0." : "X1.5748 Y0."));  // 40 mm = 1.574803 in
        EXPECT_TRUE(has_line(r.text, is_c ? "G01 Z-0.03937 F7.874" : "G01 Z-0.0394 F7.874"));
        EXPECT_LE(most_decimals(r.text), is_c ? 5 : 4);
      } else if (form == gen::Form::macro) {
        EXPECT_NE(r.text.find("G01 X[#101/25.4*COS[#100]] Y[#102/25.4*SIN[#100]]"), std::string::npos);  // mm to in
      } else {  // the vertex rounded on the inch increment, as the control will
        EXPECT_NE(r.text.find(is_c ? "*100000.]/100000." : "*10000.]/10000."), std::string::npos);
      }
      EXPECT_NE(r.text.find("(TOLERANCE 0.005 MM"), std::string::npos);
      // as the control runs it (in mm): every point of the ellipse within the tolerance of the
      // contour, at the depth the inch program gives (1 mm to the nearest increment)
      const auto ran = test::run(r.text, o.profile);
      ASSERT_TRUE(ran.result.ok());
      std::vector<machine::Move> contour;
      const double depth = -std::round(1 / 25.4 * (is_c ? 1e5 : 1e4)) / (is_c ? 1e5 : 1e4) * 25.4;
      for (const auto& m : test::feed_moves(ran.moves))
        if (std::fabs(m.start[2] - depth) < 1e-9 && std::fabs(m.end[2] - depth) < 1e-9) contour.push_back(m);
      ASSERT_GT(contour.size(), 10u);
      const double worst = test::farthest(ellipse_points(), contour, 0, 1);
      EXPECT_LE(worst, o.tol + 1e-6);
      EXPECT_GT(worst, o.tol / 2);
    }
  }
}

TEST(GenInch, LatheProgramsInInchesTakeDiametersAndFeedPerRevolution) {
  const geom::Curve hyperbola(*geom::find_curve("hyperbola"), {});
  for (gen::Form form : {gen::Form::expanded, gen::Form::arcs, gen::Form::macro, gen::Form::adaptive_macro}) {
    SCOPED_TRACE(gen::to_string(form));
    gen::Options o;
    o.form = form;
    o.inch = true;
    o.profile = machine::default_lathe();
    o.css = 180;
    o.max_rpm = 3000;
    const gen::Result r = gen::generate(hyperbola, o);
    EXPECT_TRUE(r.within_tolerance);
    EXPECT_NE(r.text.find("\nG20 G18 G99\n"), std::string::npos);
    EXPECT_TRUE(has_line(r.text, "G96 S591 M03"));  // 180 m/min = 590.55 ft/min
    EXPECT_NE(r.text.find(" F0.003937"), std::string::npos);  // 0.1 mm/rev
    if (form == gen::Form::expanded) {
      // t = -20: X = 2 * 100 / cos 20 = 212.836 mm = 8.3794 in (a diameter), Z = 202.4 tan -20 = -2.9003 in
      EXPECT_NE(r.text.find("X8.3794 Z-2.9003 F0.003937"), std::string::npos);
      EXPECT_LE(most_decimals(r.text), 4);
    }
    const auto ran = test::run(r.text, o.profile);
    ASSERT_TRUE(ran.result.ok());
    std::vector<std::pair<double, double>> points;  // (Z, X radius) of the hyperbola
    for (int i = 0; i <= 2000; ++i) {
      const double t = (-20 + 40.0 * i / 2000) * std::numbers::pi / 180;
      points.emplace_back(202.4 * std::tan(t), 100 / std::cos(t));
    }
    EXPECT_LE(test::farthest(points, test::feed_moves(ran.moves), 2, 0), o.tol + 1e-6);
  }
}

TEST(GenInch, CyclesAndAToleranceNearTheInchRoundingAreRefused) {
  const geom::Curve ellipse(*geom::find_curve("ellipse"), {});
  auto refused = [&](gen::Options o) -> std::string {
    try {
      gen::generate(ellipse, o);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  };
  gen::Options cycle;
  cycle.inch = true;
  cycle.form = gen::Form::cycle;
  EXPECT_NE(refused(cycle).find("the cycles' macros (O9010..O9019) are written in mm"), std::string::npos);
  gen::Options fine;
  fine.inch = true;
  fine.tol = 0.0015;  // IS-B inch: a coordinate is rounded by up to 0.00005 in = 0.00127 mm, 0.0018 mm on the plane
  EXPECT_NE(refused(fine).find("tolerance 0.0015 mm is too close to the coordinate rounding of an inch program "
                               "(0.001796 mm: steps of 0.0001 in)"),
            std::string::npos)
      << refused(fine);
}
