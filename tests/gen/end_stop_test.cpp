// ncurve gen on curves that stop at an end of their range (zero speed at t0 or t1): every form
// fits, runs and stays within the tolerance of the closed-form curve; a stop inside the range and
// a tool radius at a stop are refused with where.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gen/generate.hpp"
#include "gen/path_distance.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

// x = 30 cos t, y = 10 sin^2 t: the parabola y = 10 (1 - x^2 / 900), at rest at t = 0 and 180.
constexpr double kA = 30, kB = 10;
geom::Curve parabola_arc(double from, double to, double lift = 0) {
  geom::CurveSpec spec{"expr", "", {{"a", kA, ""}, {"b", kB, ""}}, "a*COS(t)",
                       lift ? fmt::format("b*SIN(t)*SIN(t)+{}", lift) : "b*SIN(t)*SIN(t)", "0", from, to, ""};
  return geom::Curve(spec, {});
}

// Length of y = b (1 - x^2/a^2) from x = 0 to x: with u = 2 b x / a^2, a^2/(4b) (u sqrt(1+u^2) + asinh u).
double arc_length_from_top(double x) {
  const double u = 2 * kB * x / (kA * kA);
  return kA * kA / (4 * kB) * (u * std::sqrt(1 + u * u) + std::asinh(u));
}

}  // namespace

TEST(GenEndStop, EveryFormFitsACurveAtRestAtEitherEnd) {
  const double tol = 0.005;
  struct Range {
    double from, to;
  };
  for (const Range range : {Range{0, 180}, Range{0, 90}, Range{90, 180}}) {
    for (const bool lathe : {false, true}) {
      // on the lathe the profile drawn in x, y is turned with Z along x and X (a radius) along y
      const double lift = lathe ? 5 : 0;
      const geom::Curve c = parabola_arc(range.from, range.to, lift);
      for (gen::Form form : {gen::Form::expanded, gen::Form::arcs, gen::Form::macro, gen::Form::adaptive_macro,
                             gen::Form::cycle}) {
        SCOPED_TRACE(fmt::format("t {}..{} {} {}", range.from, range.to, lathe ? "lathe" : "mill", gen::to_string(form)));
        gen::Options o;
        o.form = form;
        o.tol = tol;
        if (lathe) o.profile = machine::default_lathe();
        gen::Result r = gen::generate(c, o);
        EXPECT_TRUE(r.within_tolerance);
        // the length of the parabola between the ends, from its closed form
        const double x0 = kA * std::cos(range.from * std::numbers::pi / 180);
        const double x1 = kA * std::cos(range.to * std::numbers::pi / 180);
        const double length = std::fabs(arc_length_from_top(x0) - arc_length_from_top(x1));
        EXPECT_NEAR(r.stats.path_length, length, 0.01);
        // independently: the program runs, and every point of the curve lies within the tolerance
        // of a feed move (the contour; the plunge and the approach lie off the curve)
        for (const auto& [key, value] : r.parameters) machine::set_parameter(o.profile, key, value);
        const auto ran = test::run(r.text, o.profile);
        ASSERT_TRUE(ran.result.ok()) << r.text;
        const int u = lathe ? 2 : 0, v = lathe ? 0 : 1;  // the machine axes of the curve's x and y
        std::vector<std::pair<double, double>> points;
        for (int i = 0; i <= 2000; ++i) {
          const double t = (range.from + (range.to - range.from) * i / 2000.0) * std::numbers::pi / 180;
          points.emplace_back(kA * std::cos(t), kB * std::sin(t) * std::sin(t) + lift);
        }
        const double worst = test::farthest(points, test::feed_moves(ran.moves), u, v);
        EXPECT_LE(worst, tol + 1e-6);
        EXPECT_GT(worst, tol / 4);  // the tolerance is used, not a needlessly fine step
      }
    }
  }
}

TEST(GenEndStop, AStopInsideTheRangeAndAToolRadiusAtAStopAreRefused) {
  // the same parabola through its top at t = 90, traced there and back over 0..360: a cusp at 180
  try {
    gen::generate(parabola_arc(90, 270), gen::Options{});
    FAIL() << "no error for the cusp at t = 180";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the curve stops at t = 180 "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("split the range there"), std::string::npos) << e.what();
  }
  for (const double from : {0.0, 90.0}) {
    gen::Options o;
    o.tool_radius = 1;
    try {
      gen::generate(parabola_arc(from, from + 90), o);
      FAIL() << "no error for a tool radius at the stop";
    } catch (const std::runtime_error& e) {
      const std::string where = fmt::format("the curve stops at t = {}, where its direction", from == 0 ? 0 : 180);
      EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("tool radius"), std::string::npos) << e.what();
    }
  }
  // a little inside the stop, the cutter centre is programmed
  gen::Options o;
  o.tool_radius = 1;
  EXPECT_TRUE(gen::generate(parabola_arc(0.01, 90), o).within_tolerance);
}
