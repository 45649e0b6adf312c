// Helicoid contacts: seed 004's sanity values, closed forms, and the robust search against brute force.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>

#include "geom/curve.hpp"
#include "helicoid/contact.hpp"

namespace ncurve::helicoid {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

ContactSearch seed_search(double included_angle, Lattice lattice = {}) {
  Workpiece work{EndProfile::seed004_rotor(), 860, 1, 5};
  auto cutter = DiscCutter::v_insert(252, 1.2, included_angle, 18);
  return ContactSearch(work, cutter, Setting{helix_angle(860, 43), 177.7}, lattice);
}

std::vector<double> range(double from, double to, double step) {
  std::vector<double> v;
  for (int i = 0; from + i * step <= to + 1e-9; ++i) v.push_back(from + i * step);
  return v;
}

// What `ncurve helicoid --example seed004 [--included-angle DEG] [--hand left] [--ref-radius R]
// [--flank-depth F] [--alpha-range DEG]` searches: the seed's rotor and insert, flanks 3 mm
// deeper than the rotor's profile (15 mm), the swing at the reference radius (by default the mean
// of root and crest, 43 mm), the default lattice over the cutter's reach plus 2 degrees, and the
// start distance 177.7 mm.
ContactSearch cli_search(double included_angle, int hand = 1, double ref_radius = 43, double flank_depth = 18,
                         double alpha_range = 0) {
  Workpiece work{EndProfile::seed004_rotor(), 860, hand, 5};
  const double outer = 126, depth = 15;
  Lattice lattice;
  lattice.alpha_max = alpha_range > 0 ? alpha_range
                                      : std::min(89.0, std::acos(std::max(-1.0, (outer - depth - flank_depth) / outer)) / kDeg + 2);
  return ContactSearch(work, DiscCutter::v_insert(2 * outer, 1.2, included_angle, flank_depth),
                       Setting{helix_angle(860, ref_radius), 177.7}, lattice);
}

// The checks `ncurve helicoid` makes: parallel normals at every contact (it stops at 1e-3 deg,
// here 1e-4), and no interference (1e-6 mm) at the contacts `checked` says.
void expect_contacts_pass_the_checks(const ContactSearch& cs, const std::vector<Contact>& contacts,
                                     const std::function<bool(std::size_t)>& checked, const std::string& what) {
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const auto& c = contacts[i];
    EXPECT_LT(c.normal_angle, 1e-4) << what << " psi " << c.psi << " " << c.region << " s " << c.s;
    if (checked(i)) {
      EXPECT_LT(cs.deepest_penetration(c.psi, c.A), 1e-6) << what << " psi " << c.psi;
    }
  }
}

// The indices either side of each change of the cutter element that touches.
std::vector<std::size_t> around_the_jumps(const std::vector<Contact>& contacts) {
  std::vector<std::size_t> at;
  for (std::size_t i = 1; i < contacts.size(); ++i)
    if (contacts[i].region != contacts[i - 1].region) at.push_back(i - 1), at.push_back(i);
  return at;
}

// Turned half a turn about the X axis (the line from the rotor's axis to the cutter's centre),
// rotor and cutter are themselves again (the rotor's profile is symmetric about its root, the
// insert about its mid plane, with its flanks swapped), whatever the hand and the swing: A(psi) =
// A(period - psi), the contact on the other flank.
void expect_symmetric(const std::vector<Contact>& contacts, double period, const std::string& what, bool regions = true) {
  auto mirror = [](const std::string& region) {
    return region == "flank+" ? std::string("flank-") : region == "flank-" ? std::string("flank+") : region;
  };
  for (const auto& c : contacts)
    for (const auto& m : contacts)
      if (std::abs(c.psi + m.psi - period) < 1e-9) {
        EXPECT_NEAR(c.A, m.A, 1e-6) << what << " psi " << c.psi;
        if (regions) {
          EXPECT_EQ(c.region, mirror(m.region)) << what << " psi " << c.psi;
        }
      }
}

TEST(Helicoid, NativeRotorIsTheCatalogueCurve) {
  auto spec = *geom::find_curve("rotor");
  spec.to = 360;
  auto native = EndProfile::seed004_rotor();
  auto generic = EndProfile::from_curve(std::make_shared<geom::Curve>(spec, std::map<std::string, double>{}));
  for (double u = 0; u < 360; u += 7.3) {
    EXPECT_NEAR(native.point(u).x, generic.point(u).x, 1e-9) << u;
    EXPECT_NEAR(native.point(u).y, generic.point(u).y, 1e-9) << u;
    EXPECT_NEAR(native.d1(u).x, generic.d1(u).x, 1e-9) << u;
    EXPECT_NEAR(native.d1(u).y, generic.d1(u).y, 1e-9) << u;
  }
  EXPECT_NEAR(native.r_min(), 35.5, 1e-6);
  EXPECT_NEAR(native.r_max(), 50.5, 1e-6);
}

TEST(Helicoid, FirstHitOfTheTurnedProfile) {
  auto p = EndProfile::seed004_rotor();
  // On the X axis the first hit is the radius in that direction: root at phase 0, crest at 36.
  EXPECT_NEAR(p.first_hit(0, 0).x, 35.5, 1e-9);
  EXPECT_NEAR(p.first_hit(36, 0).x, 50.5, 1e-9);
  // Off the axis the hit lies on the turned curve, and nothing on the line further out does.
  for (double phi : {3.0, 17.0, 50.0}) {
    for (double y : {-12.0, 4.0, 20.0}) {
      auto h = p.first_hit(phi, y);
      ASSERT_TRUE(h.found);
      V2 q = p.point(h.u);
      double c = std::cos(phi * kDeg), s = std::sin(phi * kDeg);
      EXPECT_NEAR(c * q.x - s * q.y, h.x, 1e-9);
      EXPECT_NEAR(s * q.x + c * q.y, y, 1e-9);
      for (double u = 0; u < 360; u += 0.01) {
        V2 r = p.point(u);
        double x = c * r.x - s * r.y, yy = s * r.x + c * r.y;
        if (std::abs(yy - y) < 0.01) {
          EXPECT_LE(x, h.x + 0.01 * 40) << phi << " " << y << " " << u;
        }
      }
    }
  }
  EXPECT_FALSE(p.first_hit(0, 51).found);
}

TEST(Helicoid, GradientMatchesDifferences) {
  auto cs = seed_search(35);
  for (double psi : {5.0, 20.0}) {
    for (auto [a, s] : {std::pair{0.3, 19.0}, {-1.0, 20.5}, {2.0, 26.0}}) {
      auto d = cs.distance(psi, a, s);
      ASSERT_TRUE(d.hit);
      const double h = 1e-5;
      double da = (cs.distance(psi, a + h, s).d - cs.distance(psi, a - h, s).d) / (2 * h);
      double ds = (cs.distance(psi, a, s + h).d - cs.distance(psi, a, s - h).d) / (2 * h);
      EXPECT_NEAR(d.d_alpha, da, 1e-5 * (1 + std::abs(da)));
      EXPECT_NEAR(d.d_s, ds, 1e-5 * (1 + std::abs(ds)));
    }
  }
}

TEST(Helicoid, SeedSanityValues) {
  auto cs = seed_search(35);
  auto contacts = cs.run(range(0, 72, 1), Method::robust);
  ASSERT_EQ(contacts.size(), 73u);
  EXPECT_NEAR(contacts[0].A, 35.5 + 126, 1e-6);   // root faces the cutter
  EXPECT_NEAR(contacts[36].A, 50.5 + 126, 1e-6);  // crest
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    EXPECT_NEAR(contacts[i].A, contacts[72 - i].A, 1e-6) << contacts[i].psi;  // A(psi) = A(72 - psi)
    EXPECT_LT(contacts[i].normal_angle, 1e-4) << contacts[i].psi;              // meshing condition
    EXPECT_LT(cs.deepest_penetration(contacts[i].psi, contacts[i].A), 1e-6) << contacts[i].psi;
    // Touching: a micrometre closer and the cutter cuts.
    EXPECT_GT(cs.deepest_penetration(contacts[i].psi, contacts[i].A - 1e-3), 0.9e-3) << contacts[i].psi;
  }
  for (double psi : {0.0, 18.0, 36.0}) EXPECT_LT(cs.deepest_penetration(psi, 177.7), 0) << psi;  // start is clear
  // Plane programming is exact at root and crest only.
  EXPECT_NEAR(contacts[0].plane_A, contacts[0].A, 1e-6);
  EXPECT_NEAR(contacts[36].plane_A, contacts[36].A, 1e-6);
  EXPECT_GT(std::abs(contacts[18].plane_A - contacts[18].A), 0.01);
}

// Mirroring the whole set-up in the XZ plane turns a right-hand helicoid into a left-hand one,
// the cutter's swing with it, and psi into -psi. The seed's profile is its own mirror, so the
// left-hand rotor has A_left(psi) = A_right(-psi) = A_right(psi), with the contact mirrored.
TEST(Helicoid, LeftHandIsTheMirrorImage) {
  auto right = seed_search(35);
  Workpiece left_work{EndProfile::seed004_rotor(), 860, -1, 5};
  ContactSearch left(left_work, DiscCutter::v_insert(252, 1.2, 35, 18), Setting{helix_angle(860, 43), 177.7}, {});
  auto r = right.run(range(-30, 0, 6), Method::robust);
  auto l = left.run(range(0, 30, 6), Method::robust);
  ASSERT_EQ(r.size(), l.size());
  for (std::size_t i = 0; i < l.size(); ++i) {
    const auto& mirror = r[r.size() - 1 - i];  // at -psi
    EXPECT_NEAR(l[i].A, mirror.A, 1e-7) << l[i].psi;
    EXPECT_NEAR(l[i].work_point[0], mirror.work_point[0], 1e-6) << l[i].psi;
    EXPECT_NEAR(l[i].work_point[1], -mirror.work_point[1], 1e-6) << l[i].psi;
    EXPECT_NEAR(l[i].work_point[2], mirror.work_point[2], 1e-6) << l[i].psi;
    EXPECT_LT(left.deepest_penetration(l[i].psi, l[i].A), 1e-6) << l[i].psi;
  }
}

TEST(Helicoid, CylinderProfileTouchesAtTheTip) {
  auto eval = [](double u, V2& p, V2& d) {
    p = {40 * std::cos(u * kDeg), 40 * std::sin(u * kDeg)};
    d = {-40 * std::sin(u * kDeg) * kDeg, 40 * std::cos(u * kDeg) * kDeg};
  };
  Workpiece work{EndProfile("circle", eval, 0, 360), 860, 1, 1};
  ContactSearch cs(work, DiscCutter::v_insert(252, 1.2, 35, 18), Setting{helix_angle(860, 40), 0}, Lattice{});
  for (const auto& c : cs.run(range(0, 90, 15), Method::robust)) {
    EXPECT_NEAR(c.A, 40 + 126, 1e-6) << c.psi;
    EXPECT_EQ(c.region, "corner");
    EXPECT_NEAR(c.alpha, 0, 1e-4);
  }
}

// A straight (zero lead) circle of radius rho centred e off the axis, and a disc of radius R with
// corner radius rc square to it.
struct EccentricCircle {
  static constexpr double e = 8, rho = 30, rc = 1.2, R = 126;
  ContactSearch search() const {
    auto eval = [](double u, V2& p, V2& d) {
      p = {e + rho * std::cos(u * kDeg), rho * std::sin(u * kDeg)};
      d = {-rho * std::sin(u * kDeg) * kDeg, rho * std::cos(u * kDeg) * kDeg};
    };
    Workpiece work{EndProfile("eccentric circle", eval, 0, 360), 0, 1, 1};
    return ContactSearch(work, DiscCutter::v_insert(2 * R, rc, 35, 20), Setting{0, 0}, Lattice{});
  }
};

TEST(Helicoid, StraightEccentricCircleIsTwoCircles) {
  // Zero twist: in the end section the corner circle (radius rc) touches the profile circle.
  constexpr EccentricCircle g;
  const double e = g.e, rho = g.rho, rc = g.rc, R = g.R;
  auto cs = g.search();
  for (const auto& c : cs.run(range(0, 360, 30), Method::robust)) {
    double ey = e * std::sin(c.psi * kDeg);
    double expected = R - rc + e * std::cos(c.psi * kDeg) + std::sqrt((rho + rc) * (rho + rc) - ey * ey);
    EXPECT_NEAR(c.A, expected, 1e-6) << c.psi;
    EXPECT_NEAR(c.plane_A, expected, 1e-6) << c.psi;  // without twist plane programming is exact
  }
}

// Without twist the corner cuts a circle of radius rc in the end section: two passes leave a cusp
// between two circles tangent to the profile circle, highest on the bisector of their centres.
TEST(Helicoid, CuspOfStraightEccentricCircleIsClosedForm) {
  constexpr EccentricCircle g;
  const double e = g.e, rho = g.rho, rc = g.rc, R = g.R;
  auto cs = g.search();
  auto contacts = cs.run(range(0, 90, 0.5), Method::robust);
  // Closed form from A alone: the corner circle's centre turned back into the workpiece frame.
  auto cusp = [&](const Contact& a, const Contact& b) {
    auto bearing = [&](const Contact& c) {
      double x = (c.A - R + rc) * std::cos(c.psi * kDeg) - e, y = -(c.A - R + rc) * std::sin(c.psi * kDeg);
      return std::atan2(y, x);
    };
    double half = std::remainder(bearing(b) - bearing(a), 2 * std::numbers::pi) / 2;
    return std::sqrt(rho * rho + (rho + rc) * (rho + rc) - 2 * rho * (rho + rc) * std::cos(half)) - rc;
  };
  for (std::size_t i = 0; i + 12 < contacts.size(); i += 29) {
    EXPECT_NEAR(cs.stock(contacts[i], contacts[i].u), 0, 1e-7) << contacts[i].psi;
    EXPECT_NEAR(cs.cusp(contacts[i], contacts[i + 1]).height, cusp(contacts[i], contacts[i + 1]), 1e-7) << contacts[i].psi;
    EXPECT_NEAR(cs.cusp(contacts[i], contacts[i + 12]).height, cusp(contacts[i], contacts[i + 12]), 1e-7) << contacts[i].psi;
  }
  // The fewest passes: every gap within the tolerance, and none could reach one step farther.
  const double tol = 0.1;
  auto plan = cs.fewest_passes(contacts, tol);
  ASSERT_EQ(plan.passes.front(), 0u);
  ASSERT_EQ(plan.passes.back(), contacts.size() - 1);
  ASSERT_EQ(plan.cusps.size() + 1, plan.passes.size());
  EXPECT_LT(plan.passes.size(), contacts.size() / 2);  // 0.5 deg steps leave about 11 um
  for (std::size_t k = 0; k + 1 < plan.passes.size(); ++k) {
    const auto& a = contacts[plan.passes[k]];
    EXPECT_LE(cusp(a, contacts[plan.passes[k + 1]]), tol + 1e-9) << a.psi;
    EXPECT_NEAR(plan.cusps[k].height, cusp(a, contacts[plan.passes[k + 1]]), 1e-7) << a.psi;
    if (plan.passes[k + 1] + 1 < contacts.size()) {
      EXPECT_GT(cusp(a, contacts[plan.passes[k + 1] + 1]), tol) << a.psi;
    }
  }
  EXPECT_THROW(cs.fewest_passes(contacts, 0.001), std::runtime_error);  // 0.5 deg steps are too coarse for 1 um
}

// The stock a pass leaves is measured from the surfaces themselves (a point's distance to the
// cutter), not from the directed distance the search minimises: at every contact they agree.
TEST(Helicoid, PassesTouchAtTheirContactsOnTheSeedRotor) {
  auto cs = seed_search(35);
  auto contacts = cs.run(range(0, 72, 6), Method::robust);
  for (const auto& c : contacts) {
    EXPECT_NEAR(cs.stock(c, c.u), 0, 1e-7) << c.psi;
    EXPECT_GT(cs.stock(c, c.u + 0.5), 1e-3) << c.psi;
    EXPECT_GT(cs.stock(c, c.u - 0.5), 1e-3) << c.psi;
  }
  auto plan = cs.fewest_passes(cs.run(range(0, 72, 0.5), Method::robust), 0.05);
  for (const auto& c : plan.cusps) EXPECT_LE(c.height, 0.05);
  EXPECT_LT(plan.passes.size(), 145u);
}

// Final motion along Z at a fixed centre distance: where the cutter stops it touches (no point
// of it inside the rotor, a micrometre further along the travel it cuts), and by the screw
// symmetry the touch moves along Z by lead/360 per degree of psi while it stays in one gap.
TEST(Helicoid, AxialFinalMotionStopsAtTheFirstTouch) {
  auto cs = seed_search(35);
  const double twist = cs.workpiece().twist();
  for (int direction : {-1, 1}) {
    AxialMotion motion{170, 0.0, direction};
    auto contacts = cs.run_axial(range(0, 12, 3), Method::robust, motion);
    ASSERT_EQ(contacts.size(), 5u);
    for (const auto& c : contacts) {
      EXPECT_NEAR(c.phase, c.psi + twist * c.z, 1e-9);
      EXPECT_NEAR(c.A, 170, 1e-9);
      EXPECT_GT(direction * c.z, 0) << "travelled the wrong way";
      EXPECT_LT(cs.deepest_penetration(c.phase, 170), 1e-6) << c.psi;
      double further = c.psi + twist * (c.z + direction * 1e-3);
      EXPECT_GT(cs.deepest_penetration(further, 170), 1e-5) << c.psi;
      EXPECT_NEAR(c.z + c.psi / twist, contacts[0].z, 1e-7) << c.psi;  // same contact, shifted along the helix
    }
  }
  EXPECT_THROW(cs.run_axial({0}, Method::robust, AxialMotion{180, {}, -1}), std::runtime_error);   // never reaches
  EXPECT_THROW(cs.run_axial({36}, Method::robust, AxialMotion{170, 0.0, -1}), std::runtime_error);  // start not clear
  auto backed = cs.run_axial({36}, Method::robust, AxialMotion{170, {}, -1});  // backs up to clear, then travels
  EXPECT_GT(backed[0].z, 0);
  EXPECT_LT(cs.deepest_penetration(backed[0].phase, 170), 1e-6);
}

// The robust search lands on brute force's lattice minimum at every step, for the seed's 35 deg
// insert and for a 70 deg reading, where the contact jumps from the corner to a flank and back.
void expect_robust_is_brute(double included_angle, double psi_step = 1) {
  Lattice coarse{0.2, 0.2, 30};
  auto cs = seed_search(included_angle, coarse);
  auto psis = range(0, 72, psi_step);
  auto brute = cs.run(psis, Method::brute);
  auto robust = cs.run(psis, Method::robust);
  ASSERT_EQ(brute.size(), robust.size());
  bool flank = false;
  std::int64_t robust_evaluations = 0;
  for (std::size_t i = 0; i < psis.size(); ++i) {
    EXPECT_NEAR(robust[i].A, brute[i].A, 1e-9) << psis[i];
    EXPECT_EQ(robust[i].region, brute[i].region) << psis[i];
    flank = flank || brute[i].region != "corner";
    robust_evaluations += robust[i].evaluations;
  }
  EXPECT_EQ(flank, included_angle > 60);
  EXPECT_LT(robust_evaluations * 100, static_cast<std::int64_t>(psis.size()) * coarse.size(cs.cutter().length()));
}

TEST(Helicoid, RobustEqualsBruteSeedInsert) { expect_robust_is_brute(35); }
TEST(Helicoid, RobustEqualsBruteWideInsert) { expect_robust_is_brute(70); }
// Coarser phase steps: the traces' predictions are poorer and the contact jumps farther.
TEST(Helicoid, RobustEqualsBruteInCoarseSteps) {
  expect_robust_is_brute(70, 3);
  expect_robust_is_brute(80, 4.5);
}

// The target for the seed's example on the default lattice: fewer than 30 distance
// evaluations per step on average, refinement and safeguards included.
TEST(Helicoid, RobustSearchNeedsFewerThanThirtyEvaluationsPerStep) {
  auto cs = seed_search(35);
  auto contacts = cs.run(range(0, 72, 1), Method::robust);
  std::int64_t evaluations = 0;
  for (const auto& c : contacts) evaluations += c.evaluations;
  EXPECT_LT(static_cast<double>(evaluations) / static_cast<double>(contacts.size()), 30.0);
}

// What users run: `ncurve helicoid --example seed004 [--hand left]` at its default 1 deg steps over
// a lobe, the robust search, every contact checked as the command checks it.
TEST(Helicoid, DefaultsPassTheChecksAtEveryDegreeSeedInsert) {
  std::vector<Contact> right;
  for (int hand : {1, -1}) {
    auto cs = cli_search(35, hand);
    auto contacts = cs.run(range(0, 72, 1), Method::robust);
    const std::string what = hand > 0 ? "right" : "left";
    expect_contacts_pass_the_checks(cs, contacts, [](std::size_t) { return true; }, what);
    EXPECT_NEAR(contacts[0].A, 161.5, 1e-6) << what;   // root
    EXPECT_NEAR(contacts[36].A, 176.5, 1e-6) << what;  // crest
    expect_symmetric(contacts, 72, what);
    for (const auto& c : contacts) EXPECT_EQ(c.region, "corner") << what << " psi " << c.psi;
    if (hand > 0) right = contacts;
    else
      for (std::size_t i = 0; i < contacts.size(); ++i) EXPECT_NEAR(contacts[i].A, right[i].A, 1e-6) << contacts[i].psi;
  }
}

// `ncurve helicoid --example seed004 --included-angle 70`: the contact jumps from the corner to
// flank+ at psi = 17 deg, slides back over the joint to the corner at 20 deg (where a refinement
// with the stencil's Hessian stopped 0.002 deg from parallel normals), and the mirror image at 53
// and 56 deg.
TEST(Helicoid, DefaultsPassTheChecksAtEveryDegreeWideInsert) {
  std::vector<Contact> right;
  for (int hand : {1, -1}) {
    auto cs = cli_search(70, hand);
    auto contacts = cs.run(range(0, 72, 1), Method::robust);
    const std::string what = hand > 0 ? "right" : "left";
    expect_contacts_pass_the_checks(cs, contacts, [](std::size_t) { return true; }, what);
    EXPECT_NEAR(contacts[0].A, 161.5, 1e-6) << what;
    EXPECT_NEAR(contacts[36].A, 176.5, 1e-6) << what;
    expect_symmetric(contacts, 72, what);
    EXPECT_EQ(around_the_jumps(contacts).size(), 8u) << what;  // 4 jumps
    const std::string out = hand > 0 ? "flank+" : "flank-";  // the left hand is the mirror image
    EXPECT_EQ(contacts[16].region, "corner") << what;
    EXPECT_EQ(contacts[17].region, out) << what;
    EXPECT_EQ(contacts[20].region, "corner") << what;
    if (hand > 0) right = contacts;
    else
      for (std::size_t i = 0; i < contacts.size(); ++i) EXPECT_NEAR(contacts[i].A, right[i].A, 1e-6) << contacts[i].psi;
  }
}

// Brute force on the default lattice (0.7 s a phase) at the phases either side of the first two
// jumps; the last two are their mirror images (checked above).
TEST(Helicoid, WideInsertRobustIsBruteAroundTheJumps) {
  auto cs = cli_search(70);
  auto robust = cs.run(range(0, 36, 1), Method::robust);
  auto at = around_the_jumps(robust);
  ASSERT_EQ(at.size(), 4u);
  std::vector<double> psis;
  for (auto i : at) psis.push_back(robust[i].psi);
  auto brute = cs.run(psis, Method::brute);
  for (std::size_t k = 0; k < at.size(); ++k) {
    EXPECT_NEAR(robust[at[k]].A, brute[k].A, 1e-6) << psis[k];
    EXPECT_EQ(robust[at[k]].region, brute[k].region) << psis[k];
    EXPECT_LT(brute[k].normal_angle, 1e-4) << psis[k];
  }
}

// Other settings of the swing (--ref-radius at the root, near the crest) and both hands, with
// both inserts: the jumps move (at a 36 mm reference the contact leaves the corner at 15 deg,
// 3 mm up the flank, where a flank trace resting on the corner's shoulder never looked), and
// the contacts stay symmetric and pass the checks around every jump.
TEST(Helicoid, OtherReferenceRadiiAndHandsPassTheChecks) {
  for (double angle : {35.0, 70.0})
    for (int hand : {1, -1})
      for (double ref : {36.0, 50.0}) {
        auto cs = cli_search(angle, hand, ref);
        auto contacts = cs.run(range(0, 72, 1), Method::robust);
        const std::string what = fmt::format("{} deg, hand {}, ref {}", angle, hand, ref);
        auto at = around_the_jumps(contacts);
        expect_contacts_pass_the_checks(
            cs, contacts, [&](std::size_t i) { return i == 0 || i == 36 || std::find(at.begin(), at.end(), i) != at.end(); },
            what);
        EXPECT_NEAR(contacts[0].A, 161.5, 1e-6) << what;
        EXPECT_NEAR(contacts[36].A, 176.5, 1e-6) << what;
        expect_symmetric(contacts, 72, what);
        EXPECT_EQ(at.empty(), angle < 60) << what;
      }
}

// Quarter-degree steps (as for `--step 0.25 --program-tol`): the traces' predictions are finer, the
// rates per step smaller; the contacts are those of the 1 deg run where they meet.
TEST(Helicoid, QuarterDegreeStepsWideInsert) {
  auto cs = cli_search(70);
  auto fine = cs.run(range(0, 72, 0.25), Method::robust);
  auto coarse = cs.run(range(0, 72, 1), Method::robust);
  auto at = around_the_jumps(fine);
  expect_contacts_pass_the_checks(
      cs, fine, [&](std::size_t i) { return std::find(at.begin(), at.end(), i) != at.end(); }, "0.25 deg");
  expect_symmetric(fine, 72, "0.25 deg");
  for (std::size_t i = 0; i < coarse.size(); ++i) EXPECT_NEAR(fine[4 * i].A, coarse[i].A, 1e-6) << coarse[i].psi;
}

// Widening the searched region (--alpha-range, --flank-depth) must leave every contact where it
// is: it used to move the contact at psi = 20 deg further from parallel normals (0.12 deg with
// 25 mm flanks).
TEST(Helicoid, WideningTheSearchKeepsTheContacts) {
  auto psis = range(0, 72, 1);
  auto cs = cli_search(70);
  auto reference = cs.run(psis, Method::robust);
  auto wide_alpha = cli_search(70, 1, 43, 18, 60).run(psis, Method::robust);
  auto deep_flanks = cli_search(70, 1, 43, 25).run(psis, Method::robust);
  for (std::size_t i = 0; i < psis.size(); ++i) {
    EXPECT_NEAR(wide_alpha[i].A, reference[i].A, 1e-6) << psis[i];
    EXPECT_NEAR(deep_flanks[i].A, reference[i].A, 1e-6) << psis[i];
    EXPECT_LT(wide_alpha[i].normal_angle, 1e-4) << psis[i];
    EXPECT_LT(deep_flanks[i].normal_angle, 1e-4) << psis[i];
  }
}

// A V insert without a corner radius touches with its tip, an edge of the cutter where the two
// flanks' normals fan out: the rotor's normal lies in the fan (the command's check measures the
// angle to the nearest normal of it), the contact lies on the edge itself (Newton across the
// kink only hopped from side to side, 1.2 um short at psi = 24 deg), and the interference check
// sees the tip (every 8th row alone never came within 0.05 mm of it).
TEST(Helicoid, SharpTipTouchesWithItsEdge) {
  Workpiece work{EndProfile::seed004_rotor(), 860, 1, 5};
  Lattice lattice;
  lattice.alpha_max = 44.4;
  ContactSearch cs(work, DiscCutter::v_insert(252, 0, 35, 18), Setting{helix_angle(860, 43), 177.7}, lattice);
  ASSERT_EQ(cs.cutter().vertices().size(), 1u);
  const double tip = cs.cutter().vertices()[0].s;
  auto contacts = cs.run(range(0, 72, 6), Method::robust);
  expect_contacts_pass_the_checks(cs, contacts, [](std::size_t) { return true; }, "sharp");
  EXPECT_NEAR(contacts[0].A, 161.5, 1e-9);  // the tip on the root
  EXPECT_NEAR(contacts[6].A, 176.5, 1e-9);  // and on the crest
  expect_symmetric(contacts, 72, "sharp");
  for (const auto& c : contacts) {
    EXPECT_EQ(c.s, tip) << c.psi;
    EXPECT_EQ(c.region, "flank-/flank+") << c.psi;
    EXPECT_GT(cs.deepest_penetration(c.psi, c.A - 1e-3), 0.9e-3) << c.psi;  // a micrometre closer it cuts
  }
  auto brute = cs.run({24, 60}, Method::brute);
  EXPECT_NEAR(brute[0].A, contacts[4].A, 1e-9);
  EXPECT_NEAR(brute[1].A, contacts[10].A, 1e-9);
  // A cutter file of lines: a flat rim 2 mm wide between two edges. It cannot reach the bottom of
  // the root, where its edges touch the root's sides first; the crest it touches in the middle.
  auto rim = DiscCutter::from_text("108,-14\n126,-1\n126,1\n108,14\n", "rim.csv");
  ASSERT_EQ(rim.vertices().size(), 2u);
  ContactSearch flat(work, rim, Setting{helix_angle(860, 43), 177.7}, lattice);
  auto on_rim = flat.run(range(0, 72, 6), Method::robust);
  expect_contacts_pass_the_checks(flat, on_rim, [](std::size_t) { return true; }, "rim");
  EXPECT_GT(on_rim[0].A, 161.5 + 0.01);
  EXPECT_TRUE(on_rim[0].region == "line1/line2" || on_rim[0].region == "line2/line3") << on_rim[0].region;
  EXPECT_NEAR(on_rim[6].A, 176.5, 1e-9);
  EXPECT_EQ(on_rim[6].region, "line2");
  expect_symmetric(on_rim, 72, "rim", false);  // the edges' names do not mirror
  auto rim_brute = flat.run({0, 18}, Method::brute);
  EXPECT_NEAR(rim_brute[0].A, on_rim[0].A, 1e-9);
  EXPECT_NEAR(rim_brute[1].A, on_rim[3].A, 1e-9);
}

TEST(Helicoid, PlainNinePointIsCaughtWhereTheContactJumps) {
  auto cs = seed_search(70);
  auto psis = range(0, 72, 1);
  auto plain = cs.run(psis, Method::nine_point);
  auto robust = cs.run(psis, Method::robust);
  double worst = 0;
  for (std::size_t i = 0; i < psis.size(); ++i) {
    EXPECT_LE(plain[i].A, robust[i].A + 1e-9) << psis[i];  // a local minimum is never past the first touch
    worst = std::max(worst, robust[i].A - plain[i].A);
    EXPECT_LT(cs.deepest_penetration(psis[i], robust[i].A), 1e-6) << psis[i];
  }
  EXPECT_GT(worst, 0.1);  // the seed's search alone would cut 0.1 mm and more into the rotor
}

TEST(Helicoid, GeneralCutterProfileIsTheInsertItDescribes) {
  // The seed's insert written as vertices (the corner as a convex arc) gives the same contacts.
  auto insert = DiscCutter::v_insert(252, 1.2, 35, 18);
  const auto& e = insert.elements();
  ASSERT_EQ(e.size(), 3u);
  std::string text = "rho,w,radius  # the seed's insert\n";
  text += fmt::format("{:.15g},{:.15g}\n{:.15g},{:.15g},1.2\n{:.15g},{:.15g}\n{:.15g},{:.15g}\n", e[0].start.x,
                      e[0].start.y, e[1].start.x, e[1].start.y, e[2].start.x, e[2].start.y, e[2].end.x, e[2].end.y);
  auto general = DiscCutter::from_text(text, "insert.csv");
  ASSERT_EQ(general.elements().size(), 3u);
  EXPECT_EQ(general.elements()[1].region, "corner");
  EXPECT_NEAR(general.outer_radius(), 126, 1e-12);
  EXPECT_NEAR(general.length(), insert.length(), 1e-12);
  for (double s = 0; s <= insert.length(); s += insert.length() / 37) {
    auto a = insert.at(s), b = general.at(s);
    EXPECT_NEAR(a.p.x, b.p.x, 1e-12);
    EXPECT_NEAR(a.p.y, b.p.y, 1e-12);
    EXPECT_NEAR(a.normal.x, b.normal.x, 1e-12);
    EXPECT_NEAR(a.normal.y, b.normal.y, 1e-12);
  }
  Workpiece work{EndProfile::seed004_rotor(), 860, 1, 5};
  ContactSearch mine(work, general, Setting{helix_angle(860, 43), 177.7}, {});
  auto contacts = mine.run(range(0, 36, 6), Method::robust);
  EXPECT_NEAR(contacts[0].A, 161.5, 1e-6);
  EXPECT_NEAR(contacts[6].A, 176.5, 1e-6);
  auto reference = seed_search(35).run(range(0, 36, 6), Method::robust);
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    EXPECT_NEAR(contacts[i].A, reference[i].A, 1e-9) << contacts[i].psi;
    EXPECT_NEAR(contacts[i].plane_A, reference[i].plane_A, 1e-9) << contacts[i].psi;  // the corner is found
  }
  // a concave arc bends the other way: its middle lies inside the chord (towards the material)
  auto dish = DiscCutter::from_text("100,-5,-20\n100,5\n", "dish.csv");
  EXPECT_LT(dish.at(dish.length() / 2).p.x, 100);
  EXPECT_GT(DiscCutter::from_text("100,-5,20\n100,5\n", "bulge.csv").at(5).p.x, 100);
}

TEST(Helicoid, GeneralCutterProfileErrorsNameTheRow) {
  auto message = [](const std::string& text) {
    try {
      DiscCutter::from_text(text, "c.csv");
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("100,-5,1\n100,5\n").find("c.csv:1:1: arc radius 1 is less than half the chord"), 0u);
  EXPECT_EQ(message("100,5\n100,-5\n").find("c.csv:1:1: list the profile from the -w side"), 0u);
  EXPECT_EQ(message("100,-5\n100, 5x\n").find("c.csv:2:6: '5x' is not a number"), 0u);
  EXPECT_EQ(message("100,-5\n100,5,3\n").find("c.csv:2:1: the last vertex ends the profile"), 0u);
  EXPECT_EQ(message("100\n").find("c.csv:1:1: 1 numbers where 2 to 3 are expected"), 0u);
}

TEST(Helicoid, PointListProfileFollowsTheCurve) {
  // 360 points of the seed's rotor: the spline through them is the rotor to well under a micrometre
  // (cubic spline error ~ h^4 curvature^3 / 384), and so are the contacts.
  auto rotor = EndProfile::seed004_rotor();
  std::vector<V2> points;
  for (int k = 0; k < 360; ++k) points.push_back(rotor.point(k));
  auto spline = EndProfile::from_points("rotor points", points);
  EXPECT_NEAR(spline.r_min(), 35.5, 1e-4);
  EXPECT_NEAR(spline.r_max(), 50.5, 1e-4);
  // every point of the spline is within 1 um of the rotor (its nearest rotor point: scan, then refine)
  for (double u = 0.37; u < 360; u += 9.1) {
    V2 p = spline.point(u);
    auto dist = [&](double v) {
      V2 q = rotor.point(v);
      return std::hypot(p.x - q.x, p.y - q.y);
    };
    double best_v = 0;
    for (double v = 0; v < 360; v += 0.01)
      if (dist(v) < dist(best_v)) best_v = v;
    double lo = best_v - 0.01, hi = best_v + 0.01;
    for (int k = 0; k < 100; ++k) {
      double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (dist(m1) < dist(m2)) hi = m2;
      else lo = m1;
    }
    EXPECT_LT(dist((lo + hi) / 2), 1e-3) << u;  // 0.13 um at worst
  }
  Workpiece work{spline, 860, 1, 5};
  ContactSearch cs(work, DiscCutter::v_insert(252, 1.2, 35, 18), Setting{helix_angle(860, 43), 177.7}, {});
  auto contacts = cs.run(range(0, 36, 9), Method::robust);
  auto reference = seed_search(35).run(range(0, 36, 9), Method::robust);
  for (std::size_t i = 0; i < contacts.size(); ++i) EXPECT_NEAR(contacts[i].A, reference[i].A, 1e-3) << contacts[i].psi;
  EXPECT_THROW(EndProfile::from_points("three", {{1, 0}, {0, 1}, {-1, 0}}), std::runtime_error);
}

TEST(Helicoid, BadInput) {
  auto eight = [](double u, V2& p, V2& d) {  // a figure eight does not wind around the axis
    p = {std::sin(u * kDeg) + 0.1, std::sin(2 * u * kDeg)};
    d = {std::cos(u * kDeg) * kDeg, 2 * std::cos(2 * u * kDeg) * kDeg};
  };
  EXPECT_THROW(EndProfile("eight", eight, 0, 360), std::runtime_error);
  EXPECT_THROW(DiscCutter::v_insert(252, 1.2, 190, 18), std::runtime_error);
  EXPECT_THROW(method_from_name("fast"), std::runtime_error);
}

}  // namespace
}  // namespace ncurve::helicoid
