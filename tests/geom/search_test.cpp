// The searches under the fits: maxima by samples and Brent's method, the longest step within a
// tolerance; against closed forms, with the number of evaluations they may spend.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "geom/search.hpp"

using namespace ncurve::geom;

TEST(Search, SampledMaximumPlacesAnInteriorPeakWithFewEvaluations) {
  // a chord's sag: h (1 - ((t - c) / w)^2) with a cubic skew, peak found by derivative
  int evaluations = 0;
  auto f = [&](double t) {
    ++evaluations;
    double u = (t - 0.37) / 0.5;
    return 2e-3 * (1 - u * u) + 1e-4 * u * u * u;
  };
  // closed form of the peak: f'(u) = -4e-3 u + 3e-4 u^2 = 0 -> u = 0 (the other root is outside)
  Maximum m = sampled_maximum(f, 0.0, 1.0, 6, 1e-6);
  EXPECT_NEAR(m.at, 0.37, 1e-6);
  EXPECT_NEAR(m.value, 2e-3, 1e-15);
  EXPECT_LE(evaluations, 7 + 10);  // samples, then parabolic steps (golden section alone takes ~26)
}

TEST(Search, SampledMaximumAtAnEndStopsThere) {
  int evaluations = 0;
  auto falling = [&](double t) { ++evaluations; return std::exp(-t); };
  Maximum m = sampled_maximum(falling, 0.0, 2.0, 6);
  EXPECT_EQ(m.at, 0.0);
  EXPECT_EQ(m.value, 1.0);
  EXPECT_LE(evaluations, 8);
  auto rising = [](double t) { return t * t; };
  EXPECT_EQ(sampled_maximum(rising, -1.0, 3.0, 6).at, 3.0);
}

TEST(Search, SampledMaximumFindsTheHigherOfTwoHumps) {
  // humps at 0.2 (height 1) and 0.8 (height 1.5): the search must not settle on the first
  auto f = [](double t) { return std::exp(-200 * (t - 0.2) * (t - 0.2)) + 1.5 * std::exp(-200 * (t - 0.8) * (t - 0.8)); };
  Maximum m = sampled_maximum(f, 0.0, 1.0, 8);
  EXPECT_NEAR(m.at, 0.8, 1e-6);
  EXPECT_NEAR(m.value, 1.5, 1e-9);
}

TEST(Search, LongestWithinSolvesASagToTheRequestedPrecision) {
  // err(t) = k t^2 - floor beyond the floor: the largest t with err <= tol is sqrt((tol + floor) / k)
  const double k = 3.7e-4, tol = 1e-3, floor = 0.9e-3;
  int evaluations = 0;
  auto err = [&](double t) {
    ++evaluations;
    return std::max(floor, k * t * t - floor);
  };
  const double exact = std::sqrt((tol + floor) / k);
  auto fail = [] { return std::string("never"); };
  for (double guess : {0.5 * exact, 0.97 * exact, 1.03 * exact, 3 * exact}) {
    evaluations = 0;
    double t = longest_within(0.0, 100.0, guess, tol, floor, err, 100.0, fail);
    EXPECT_LE(err(t), tol);
    EXPECT_NEAR(t, exact, 1e-4 * exact) << guess;
    // a guess near the answer (the fit's, from the last step) costs a few; a far one a few more
    EXPECT_LE(evaluations, std::fabs(guess / exact - 1) < 0.05 ? 6 : 10) << guess;
  }
  // the whole range when it fits
  EXPECT_EQ(longest_within(0.0, 1.0, 0.5, tol, floor, err, 1.0, fail), 1.0);
}

TEST(Search, LongestWithinNamesThePlaceWhenNoStepFits) {
  auto never = [](double) { return 1.0; };
  try {
    longest_within(5.0, 10.0, 6.0, 1e-3, 0.0, never, 5.0, [] { return std::string("no step from t = 5"); });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "no step from t = 5");
  }
}

TEST(Search, SampledMaximumRefinesAHumpThatItsSamplesStraddleBelowAnEnd) {
  // a narrow hump of height 1 at 0.41 between samples (1/3, 1/2 at 0.2 and 0.1) and an end at 0.97
  auto f = [](double t) { return std::exp(-std::pow((t - 0.41) / 0.06, 2)) + 0.97 * std::pow(t, 20); };
  Maximum m = sampled_maximum(f, 0.0, 1.0, 6, 1e-9);
  EXPECT_NEAR(m.at, 0.41, 1e-6);
  EXPECT_NEAR(m.value, f(0.41), 1e-12);  // 1 + 0.97 * 0.41^20: the end's tail adds 1.7e-8
}
