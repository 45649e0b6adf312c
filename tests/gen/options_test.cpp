// gen::generate's options: values that are not finite are refused, not looped on or ignored.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "gen/generate.hpp"

using namespace ncurve;

TEST(GenOptions, NumbersThatAreNotFiniteAreRefused) {
  const geom::Curve ellipse(*geom::find_curve("ellipse"), {});
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN(), kInf = std::numeric_limits<double>::infinity();
  struct Case {
    double gen::Options::*field;
    double value;
    const char* message;
  };
  const Case cases[] = {{&gen::Options::tol, kNaN, "the tolerance must be a finite number, not nan"},
                        {&gen::Options::tol, kInf, "the tolerance must be a finite number, not inf"},
                        {&gen::Options::tol, 0, "the tolerance must be above 0 mm, not 0"},
                        {&gen::Options::tool_radius, kNaN, "the tool radius must be a finite number, not nan"},
                        {&gen::Options::feed, -kInf, "the feed must be a finite number, not -inf"},
                        {&gen::Options::depth, kNaN, "the depth must be a finite number, not nan"},
                        {&gen::Options::clearance, kInf, "the clearance must be a finite number, not inf"},
                        {&gen::Options::step_down, kNaN, "the depth per pass must be a finite number, not nan"}};
  for (const Case& c : cases) {
    gen::Options o;
    o.*c.field = c.value;
    try {
      gen::generate(ellipse, o);
      ADD_FAILURE() << "accepted: " << c.message;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), c.message);
    }
  }
}
