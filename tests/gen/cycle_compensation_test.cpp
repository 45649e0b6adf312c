// A curve's custom cycle cut with the control's cutter compensation (G42 D1 around the G103 call,
// a 5 mm cutter) and the same curve offset exactly (geom::Curve::offset, what --tool-radius
// programs) must agree: the compensated cut keeps to the exact offset curve within the bound the
// geometry gives. The cycle's lines span the band -T..+T about the curve; at each vertex the
// offset lines of an outer corner meet r (sec(theta/2) - 1) ~ r theta^2 / 8 farther out, and with
// a sag of at most 2T a chord turns by theta^2 <= 16 T kappa, so the cut stays within
// T (1 + 2 r kappa), kappa the largest curvature (a / b^2 on an ellipse), plus the rounding.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "gen/generate.hpp"
#include "geom/curve.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

TEST(CycleCompensation, ControlOffsetAgreesWithTheExactOffsetCurve) {
  const double a = 40, b = 20, tol = 0.01, r = 5;
  const geom::Curve ellipse(*geom::find_curve("ellipse"), {{"a", a}, {"b", b}});
  gen::Options o;
  o.form = gen::Form::cycle;
  o.tol = tol;
  auto result = gen::generate(ellipse, o);
  ASSERT_TRUE(result.within_tolerance);
  std::string text = result.text;
  // the tool is set and the cycle wrapped: start-up onto the curve's start, cancel after it
  auto replace = [&](const std::string& from, const std::string& to) {
    auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from << "\n" << text;
    text.replace(at, from.size(), to);
  };
  replace("G21 G17 G90 G94 G54\n", "G21 G17 G90 G94 G54\nG10 L11 P1 R5.\n");
  replace("X40. Y0.\nG01 Z-1.", "X50. Y-10.\nG01 Z-1.");
  replace("\nG103 A", "\nG42 G01 X40. Y0. D1\nG103 A");
  replace("G00 Z5.\nM30", "G40 G01 X50. Y10.\nG00 Z5.\nM30");
  auto profile = machine::default_mill();
  profile.g_code_macros[1] = 103;
  auto ran = test::run(text, profile);
  ASSERT_TRUE(ran.result.ok()) << nc::format(*ran.result.alarm);
  for (const auto& w : ran.result.warnings) EXPECT_NE(w.code, "NC2101") << nc::format(w);
  std::vector<machine::Move> cut;
  for (const auto& m : ran.motions())
    if (m.program == 9011 && m.compensated && !m.corner) cut.push_back(m);
  ASSERT_GT(cut.size(), 50u);
  // the exact offset of the ellipse, outside (G42 on a counter-clockwise contour): the point
  // (a cos t, b sin t) moved r along its outward normal (b cos t, a sin t) / |..|
  auto offset_point = [&](double t) {
    double nx = b * std::cos(t), ny = a * std::sin(t), n = std::hypot(nx, ny);
    return std::array<double, 2>{a * std::cos(t) + r * nx / n, b * std::sin(t) + r * ny / n};
  };
  auto distance = [&](double x, double y) {
    auto d = [&](double t) {
      auto p = offset_point(t);
      return std::hypot(x - p[0], y - p[1]);
    };
    double best_t = 0, best = d(0);
    for (int i = 1; i < 3600; ++i) {
      double t = 2 * std::numbers::pi * i / 3600;
      if (d(t) < best) best = d(t), best_t = t;
    }
    double lo = best_t - 2 * std::numbers::pi / 3600, hi = best_t + 2 * std::numbers::pi / 3600;
    for (int k = 0; k < 100; ++k) {  // golden section on the bracket
      double m1 = hi - (hi - lo) * 0.618033988749895, m2 = lo + (hi - lo) * 0.618033988749895;
      (d(m1) < d(m2) ? hi : lo) = d(m1) < d(m2) ? m2 : m1;
    }
    return d((lo + hi) / 2);
  };
  double worst = 0;
  for (const auto& m : cut)
    for (int k = 0; k <= 8; ++k) {
      double f = k / 8.0;
      worst = std::max(worst, distance(m.start[0] + f * (m.end[0] - m.start[0]), m.start[1] + f * (m.end[1] - m.start[1])));
    }
  const double kappa = a / (b * b);
  const double rounding = 0.0005 * std::sqrt(2.0);
  EXPECT_LE(worst, tol * (1 + 2 * r * kappa) + rounding);
  // and the compensation is doing the work: the cut is the offset, not the curve
  EXPECT_GT(worst, 0.0);
}
