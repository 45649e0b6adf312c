// The deviation of a piece searched on the quintic between two jets and confirmed on the curve,
// and the equal-error fit built on it (steps on the quintic, long curves cut and fit on threads):
// against closed forms and against the search on the curve alone.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "base/parallel.hpp"
#include "geom/approx.hpp"
#include "geom/quintic.hpp"

using namespace ncurve::geom;

namespace {

Curve expression(const std::string& x, const std::string& y, double from, double to, const std::string& z = "0") {
  CurveSpec spec;
  spec.name = "expr";
  spec.x = x;
  spec.y = y;
  spec.z = z;
  spec.from = from;
  spec.to = to;
  return Curve(spec, {});
}

const Placement kSame;

}  // namespace

TEST(Quintic, ReproducesAQuinticAndConvergesAsTheSixthPower) {
  // a quintic curve is its own quintic: p(t) = (t^5 - 2t^3, 3t^4 + t, 1) on [0.5, 2]
  auto p = [](double t) { return Vec3{std::pow(t, 5) - 2 * t * t * t, 3 * std::pow(t, 4) + t, 1}; };
  auto d1 = [](double t) { return Vec3{5 * std::pow(t, 4) - 6 * t * t, 12 * t * t * t + 1, 0}; };
  auto d2 = [](double t) { return Vec3{20 * t * t * t - 12 * t, 36 * t * t, 0}; };
  Quintic q = Quintic::through(p(0.5), d1(0.5), d2(0.5), p(2), d1(2), d2(2), 1.5);
  for (double s : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    Vec3 exact = p(0.5 + 1.5 * s), model = q.at(s);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(model[a], exact[a], 1e-12) << "s = " << s;
  }
  // a unit circle: the quintic between jets an angle h apart misses it by ~h^6 / 46080
  auto miss = [](double h) {
    auto at = [](double a) { return Vec3{std::cos(a), std::sin(a), 0}; };
    auto v = [](double a) { return Vec3{-std::sin(a), std::cos(a), 0}; };
    auto acc = [](double a) { return Vec3{-std::cos(a), -std::sin(a), 0}; };
    Quintic c = Quintic::through(at(0), v(0), acc(0), at(h), v(h), acc(h), h);
    Vec3 mid = c.at(0.5);
    return std::fabs(std::hypot(mid[0], mid[1]) - 1);
  };
  const double h = 0.4;
  EXPECT_NEAR(miss(h), std::pow(h, 6) / 46080, 0.05 * std::pow(h, 6) / 46080);
  EXPECT_NEAR(miss(h) / miss(h / 2), 64, 2);
}

TEST(Approx, DeviationFromJetsIsTheSagOfAChord) {
  // circle of radius 50 (t in degrees): a chord over an angle a sags 50 (1 - cos(a / 2))
  Curve circle = expression("50*COS[t]", "50*SIN[t]", 0, 360);
  for (double a : {0.5, 3.0, 20.0}) {
    const double ta = 10, tb = 10 + a;
    PlacedJet ja = placed_jet(circle, kSame, ta), jb = placed_jet(circle, kSame, tb);
    Segment chord(ja.p, jb.p);
    Worst w = max_distance(circle, kSame, ta, tb, ja, jb, [&](const Vec3& p) { return chord.distance(p); }, 1e-9);
    const double sag = 50 * (1 - std::cos(a / 2 * std::numbers::pi / 180));
    EXPECT_NEAR(w.distance, sag, 1e-12 + 1e-9 * sag) << a << " degrees";
    EXPECT_NEAR(w.t, 10 + a / 2, 1e-2 * a) << a << " degrees";
  }
}

TEST(Approx, DeviationFromJetsAgreesWithTheSearchOnTheCurve) {
  // a spiral's offset segments (ends off the curve, humps at both ends and in the middle)
  Curve spiral = expression("[5+2*t/360]*COS[t]", "[5+2*t/360]*SIN[t]", 0, 3600);
  for (double ta = 3; ta < 3600; ta += 397) {
    const double tb = ta + 2.5;
    PlacedJet ja = placed_jet(spiral, kSame, ta), jb = placed_jet(spiral, kSame, tb);
    Segment s(Vec3{ja.p[0] * 1.0001, ja.p[1] * 1.0001, 0}, Vec3{jb.p[0] * 1.0001, jb.p[1] * 1.0001, 0});
    auto d = [&](const Vec3& p) { return s.distance(p); };
    Worst model = max_distance(spiral, kSame, ta, tb, ja, jb, d, 1e-9);
    Worst curve = max_distance(spiral, kSame, ta, tb, d);
    EXPECT_NEAR(model.distance, curve.distance, 1e-12) << "t = " << ta;
  }
}

// The segment's own search (Newton's method on the distance across it, a polynomial on the
// quintic) finds what the search on the curve finds, in the plane and in space, with the hump in
// the middle or, for a chord across an inflection, two humps near the quarters.
TEST(Approx, SegmentDeviationByNewtonAgreesWithTheSearchOnTheCurve) {
  Curve spiral = expression("[5+2*t/360]*COS[t]", "[5+2*t/360]*SIN[t]", 0, 3600);
  Curve helix = expression("10*COS[t]", "10*SIN[t]", 0, 3600, "t/36");
  Curve wave = expression("t", "SIN[t]", 0, 360);
  struct Case {
    const Curve* curve;
    double ta, tb, outward;
  };
  std::vector<Case> cases;
  for (double ta = 3; ta < 3600; ta += 397) cases.push_back({&spiral, ta, ta + 2.5, 1.0001});
  for (double ta = 3; ta < 3600; ta += 397) cases.push_back({&helix, ta, ta + 4, 1.0002});
  cases.push_back({&wave, 170, 190, 1});  // across the inflection at 180
  for (const Case& k : cases) {
    PlacedJet ja = placed_jet(*k.curve, kSame, k.ta), jb = placed_jet(*k.curve, kSame, k.tb);
    Segment s(Vec3{ja.p[0] * k.outward, ja.p[1] * k.outward, ja.p[2]}, Vec3{jb.p[0] * k.outward, jb.p[1] * k.outward, jb.p[2]});
    Worst model = max_distance(*k.curve, kSame, k.ta, k.tb, ja, jb, s, 1e-9);
    Worst curve = max_distance(*k.curve, kSame, k.ta, k.tb, [&](const Vec3& p) { return s.distance(p); });
    ASSERT_GT(curve.distance, 0);
    EXPECT_NEAR(model.distance, curve.distance, 1e-12 + 1e-9 * curve.distance) << "t = " << k.ta;
    EXPECT_NEAR(model.t, curve.t, 1e-3 * (k.tb - k.ta)) << "t = " << k.ta;
  }
}

// Many segments at once (their confirming jets in batches) give what each gives alone, also where
// the quintic misleads (the search on the curve) and for a piece of no length.
TEST(Approx, SegmentDeviationsTogetherAgreeWithEachAlone) {
  Curve spiral = expression("[5+2*t/360]*COS[t]", "[5+2*t/360]*SIN[t]", 0, 3600);
  Curve wave = expression("t", "SIN[t]", 0, 540);
  for (const Curve* c : {&spiral, &wave}) {
    std::vector<SegmentPiece> pieces;
    auto add = [&](double ta, double tb, double outward) {
      PlacedJet ja = placed_jet(*c, kSame, ta), jb = placed_jet(*c, kSame, tb);
      pieces.push_back({ta, tb, ja, jb, Segment(Vec3{ja.p[0] * outward, ja.p[1] * outward, 0}, Vec3{jb.p[0], jb.p[1], 0})});
    };
    for (double ta = 3; ta < 500; ta += 7.3) add(ta, ta + 2.5 + 0.01 * ta, 1.0001);
    add(10, 10, 1);  // no length
    if (c == &wave) add(0, 540, 1);  // one and a half waves: the search on the curve
    std::vector<Worst> together(pieces.size());
    max_distances(*c, kSame, pieces, 1e-9, together);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const SegmentPiece& p = pieces[i];
      const Worst alone = p.tb > p.ta ? max_distance(*c, kSame, p.ta, p.tb, p.a, p.b, p.segment, 1e-9)
                                      : Worst{p.segment.distance(p.a.p), p.ta};
      EXPECT_NEAR(together[i].distance, alone.distance, 1e-12 + 1e-9 * alone.distance) << i;
      EXPECT_NEAR(together[i].t, alone.t, 1e-6 * (p.tb - p.ta) + 1e-12) << i;
    }
    if (c == &wave) {
      EXPECT_NEAR(together.back().distance, 1, 1e-12) << "a crest of the wave";
    }
  }
}

TEST(Approx, DeviationFromJetsSearchesTheCurveWhereTheQuinticMisleads) {
  // one and a half waves of a sine in one step: the ends' jets cannot see the crests (height 1)
  Curve wave = expression("t", "SIN[t]", 0, 540);
  PlacedJet ja = placed_jet(wave, kSame, 0), jb = placed_jet(wave, kSame, 540);
  Segment axis(ja.p, jb.p);
  Worst w = max_distance(wave, kSame, 0, 540, ja, jb, [&](const Vec3& p) { return axis.distance(p); }, 1e-6);
  EXPECT_NEAR(w.distance, 1, 1e-12);
  EXPECT_TRUE(std::fabs(w.t - 90) < 1e-3 || std::fabs(w.t - 450) < 1e-3) << w.t;
}

// Steps scanned on the quintic find the longer steps that the rounding of the end vertex offers
// (about 1 % fewer segments at a tolerance a few increments wide) where the search on the curve
// settles for the first one it brackets.
TEST(Approx, StepsScannedOnTheQuinticAreFewerThanStepsSearchedOnTheCurve) {
  Curve spiral = expression("[5+2*t/360]*COS[t]", "[5+2*t/360]*SIN[t]", 0, 1800);
  Fit fit{spiral, kSame, Grid{{0.0001, 0.0001, 0}}, Plane{0, 1}, 0.0005};
  Path modelled = fit_lines(fit, LineMethod::equal_error);
  fit.model_steps = false;
  Path searched = fit_lines(fit, LineMethod::equal_error);
  ASSERT_GT(searched.pieces.size(), 1000u);
  EXPECT_LE(modelled.pieces.size(), searched.pieces.size() * 0.995);
  EXPECT_LE(modelled.max_deviation, fit.tol);
  // each piece's deviation, searched on the curve alone
  for (const auto& p : modelled.pieces) {
    Segment s(p.start, p.end);
    Worst w = max_distance(spiral, kSame, p.t0, p.t1, [&](const Vec3& q) { return s.distance(q); });
    ASSERT_LE(w.distance, fit.tol) << "piece from t = " << p.t0;
  }
}

TEST(Approx, LongCurvesAreFitInJoinedChunksTheSameEveryTime) {
  // ~20,000 segments: fit in chunks on threads; joined end to end, and identical when repeated
  Curve spiral = expression("[5+2*t/360]*COS[t]", "[5+2*t/360]*SIN[t]", 0, 14400);
  Fit fit{spiral, kSame, Grid{{0.0001, 0.0001, 0}}, Plane{0, 1}, 0.0003};
  Path first = fit_lines(fit, LineMethod::equal_error);
  Path again = fit_lines(fit, LineMethod::equal_error);
  ASSERT_GT(first.pieces.size(), 4 * 4096u);
  ASSERT_EQ(first.pieces.size(), again.pieces.size());
  for (std::size_t i = 0; i < first.pieces.size(); ++i) {
    ASSERT_EQ(first.pieces[i].end, again.pieces[i].end) << i;
    if (i > 0) {
      ASSERT_EQ(first.pieces[i].start, first.pieces[i - 1].end) << i;
      ASSERT_EQ(first.pieces[i].t0, first.pieces[i - 1].t1) << i;
    }
  }
  EXPECT_EQ(first.pieces.front().t0, 0);
  EXPECT_EQ(first.pieces.back().t1, 14400);
  EXPECT_LE(first.max_deviation, fit.tol);
  // at most one segment more per join than the greedy fit in one piece
  Fit whole = fit;
  whole.chunk_segments = 0;
  Path one = fit_lines(whole, LineMethod::equal_error);
  EXPECT_LE(first.pieces.size(), one.pieces.size() + first.pieces.size() / 4096);
  bool same = first.pieces.size() == one.pieces.size();
  for (std::size_t i = 0; same && i < one.pieces.size(); ++i) same = first.pieces[i].end == one.pieces[i].end;
  EXPECT_FALSE(same) << "no cut was made";
}

// The prediction of steps from the survey validate() gives, or from the curve's own jets: the
// same fit. On a machine's axes (a lathe's: the curve's y is X, its x is Z) it is the fit of the
// curve with its coordinates moved there. Cut into parts of a few segments, where the prediction
// places every cut.
TEST(Approx, FitWithTheValidatedSurveyIsTheFitWithout) {
  const Curve curve = expression("40*COS[t]+t/20", "15*SIN[2*t]", 0, 330);
  const Curve moved = expression("15*SIN[2*t]", "0", 0, 330, "40*COS[t]+t/20");
  Placement lathe;
  lathe.from = {1, -1, 0};
  auto fit_of = [](const Curve& c, const Placement& place, const Survey* survey) {
    Fit fit{c, place, Grid{}, Plane{2, 0}, 0.002};
    fit.chunk_segments = 10;
    fit.survey = survey;
    return fit_lines(fit, LineMethod::equal_error);
  };
  auto same = [](const Path& a, const Path& b) {
    if (a.pieces.size() != b.pieces.size()) return false;
    for (std::size_t i = 0; i < a.pieces.size(); ++i)
      if (a.pieces[i].end != b.pieces[i].end || a.pieces[i].t1 != b.pieces[i].t1) return false;
    return true;
  };
  const Survey survey = curve.validate();
  EXPECT_TRUE(same(fit_of(curve, kSame, &survey), fit_of(curve, kSame, nullptr)));
  const Path on_lathe = fit_of(curve, lathe, &survey);
  EXPECT_TRUE(same(on_lathe, fit_of(curve, lathe, nullptr)));
  EXPECT_TRUE(same(on_lathe, fit_of(moved, kSame, nullptr)));
  EXPECT_FALSE(same(on_lathe, fit_of(curve, kSame, nullptr))) << "the placement changed nothing";
}

// Fit from both ends at once and joined where they meet: over every built-in curve at three
// tolerances no more segments in all than the fit from the start alone, and at most one more on
// any one (each greedy step is searched only to a fraction of a per cent, and the rounding of its
// end decides the rest: either greedy fit may be a segment off the fewest); each piece within the
// tolerance on the curve, end to end from t0 to t1.
TEST(Approx, FitFromBothEndsNeedsNoMoreSegmentsThanFromTheStart) {
  int differ = 0;
  std::size_t both_total = 0, ahead_total = 0;
  for (const CurveSpec& spec : catalogue()) {
    Curve curve(spec, {});
    for (double tol : {0.002, 0.005, 0.01}) {
      Fit fit{curve, kSame, Grid{}, Plane{0, 1}, tol};
      const Path both = fit_lines(fit, LineMethod::equal_error);
      fit.both_ways = false;
      const Path ahead = fit_lines(fit, LineMethod::equal_error);
      const std::string what = fmt::format("{} at {}", spec.name, tol);
      both_total += both.pieces.size();
      ahead_total += ahead.pieces.size();
      EXPECT_LE(both.pieces.size(), ahead.pieces.size() + 1) << what;
      EXPECT_LE(both.max_deviation, tol) << what;
      EXPECT_EQ(both.pieces.front().t0, curve.t0()) << what;
      EXPECT_EQ(both.pieces.back().t1, curve.t1()) << what;
      double worst = 0;
      for (std::size_t i = 0; i < both.pieces.size(); ++i) {
        const Piece& p = both.pieces[i];
        ASSERT_LT(p.t0, p.t1) << what << " piece " << i;
        if (i > 0) {
          ASSERT_EQ(p.start, both.pieces[i - 1].end) << what << " piece " << i;
          ASSERT_EQ(p.t0, both.pieces[i - 1].t1) << what << " piece " << i;
        }
        const Segment s(p.start, p.end);
        worst = std::max(worst, max_distance(curve, kSame, p.t0, p.t1, [&](const Vec3& q) { return s.distance(q); }).distance);
      }
      EXPECT_LE(worst, tol) << what;
      EXPECT_NEAR(both.max_deviation, worst, 1e-4 * tol) << what;
      bool same = both.pieces.size() == ahead.pieces.size();
      for (std::size_t i = 0; same && i < both.pieces.size(); ++i) same = both.pieces[i].end == ahead.pieces[i].end;
      differ += !same;
    }
  }
  EXPECT_LE(both_total, ahead_total);
  EXPECT_GT(differ, 0) << "the fit from both ends was never used";
}

// The fit from both ends gives the same path when the second core is busy (its half then runs
// after the first, on the same thread) as when it is free.
TEST(Approx, FitFromBothEndsIsTheSameOnOneThread) {
  Curve spiral = expression("[1+2*t/360]*COS[t]", "[1+2*t/360]*SIN[t]", 0, 720);
  Fit fit{spiral, kSame, Grid{{0.0001, 0.0001, 0}}, Plane{0, 1}, 0.001};
  const Path free = fit_lines(fit, LineMethod::equal_error);
  std::vector<Path> nested(2);
  ncurve::base::for_each_on_cores(2, [&](std::size_t k) { nested[k] = fit_lines(fit, LineMethod::equal_error); });
  ASSERT_GT(free.pieces.size(), 100u);
  for (const Path& p : nested) {
    ASSERT_EQ(p.pieces.size(), free.pieces.size());
    for (std::size_t i = 0; i < p.pieces.size(); ++i) {
      ASSERT_EQ(p.pieces[i].end, free.pieces[i].end) << i;
      ASSERT_EQ(p.pieces[i].t1, free.pieces[i].t1) << i;
    }
  }
}

TEST(Grid, SnapsToTheNearestIncrement) {
  const Grid grid{{0.001, 0.0001, 0}};
  for (int i = -2000; i <= 2000; ++i) {
    const double x = i * 0.0123456789 + 1e-7, y = -i * 0.0009876543 - 3e-9;
    const Vec3 p = grid.snap({x, y, 7.25});
    EXPECT_EQ(p[0], std::round(x / 0.001) * 0.001) << x;
    EXPECT_EQ(p[1], std::round(y / 0.0001) * 0.0001) << y;
    EXPECT_EQ(p[2], 7.25);  // no increment: as it is
  }
  // beyond 2^51 increments, still the nearest (within the last bit of 1e7)
  const Grid fine{{1e-9, 1e-9, 1e-9}};
  EXPECT_NEAR(fine.snap({1e7 + 3e-10, 0, 0})[0], 1e7, 2e-9);
}
