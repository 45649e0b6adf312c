// What the workbench colours by: /api/analyze's feeds per move and /api/gen's curve and
// deviations, against values worked out by hand (docs/serve.md).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "serve/api.hpp"

namespace ncurve::serve {
namespace {

using nlohmann::json;

// A server whose requests without "machine" take this shipped profile (by its file: the test
// binary has no shipped folder beside it).
ServeConfig on(const std::string& profile) {
  ServeConfig c;
  c.machine = std::string(NCURVE_SOURCE_DIR) + "/profiles/" + profile + ".toml";
  return c;
}

json call(Answer (*api)(const ServeConfig&, const std::string&), const json& body, const ServeConfig& c = on("fanuc-mill")) {
  const Answer a = api(c, body.dump());
  EXPECT_EQ(a.status, 200) << a.body.substr(0, 500);
  return json::parse(a.body);
}

// The moves of a run as points: the end of move i, and its start (the previous end, or where
// the answer's "starts" says).
struct RunPoints {
  std::vector<double> x, y, z, sx, sy, sz;
  std::vector<int> kind;
  std::vector<std::string> kinds;
};
RunPoints run_points(const json& program, const std::string& machine = "fanuc-mill") {
  const json r = call(api_run, {{"program", program}}, on(machine));
  const json& m = r["moves"];
  RunPoints p;
  p.x = m["x"].get<std::vector<double>>(), p.y = m["y"].get<std::vector<double>>(), p.z = m["z"].get<std::vector<double>>();
  p.kind = m["kind"].get<std::vector<int>>();
  p.kinds = m["kinds"].get<std::vector<std::string>>();
  const auto& s = m["starts"];
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    if (k < s["index"].size() && s["index"][k] == i) {
      p.sx.push_back(s["x"][k]), p.sy.push_back(s["y"][k]), p.sz.push_back(s["z"][k]), ++k;
    } else {
      p.sx.push_back(p.x[i - 1]), p.sy.push_back(p.y[i - 1]), p.sz.push_back(p.z[i - 1]);
    }
  }
  return p;
}

// A straight G01 at F1000 from X0 to X100 on the mill (acceleration 1000 mm/s^2 on X, no jerk
// limit; docs/analyze.md "Feed planning"), a dwell, then 0.1 mm at F3000 from rest to rest.
// By hand: F1000 is 16.67 mm/s, reached after v^2/(2a) = 0.139 mm, far less than the 50 mm to the
// middle, so the peak is 1000 mm/min, and the line stops before the dwell (end 0). The short line
// must stop within its 0.1 mm: it speeds up over half of it, v^2 = 2a(L/2) = a*L, v = sqrt(1000 *
// 0.1) = 10 mm/s = 600 mm/min, below its 3000 (and below L / block_time = 0.1 / 0.001 s = 6000).
// The dwell and the program end are events: 0.
TEST(ColourApi, AnalyzeFeedsPerMove) {
  const std::string program = "G01 X100. F1000.\nG04 P100\nG01 X100.1 F3000.\nM30\n";
  const json j = call(api_analyze, {{"program", program}, {"moves", true}});
  const RunPoints run = run_points(program);
  ASSERT_EQ(run.kind.size(), 4u);
  EXPECT_EQ(run.kinds[run.kind[0]], "line");
  EXPECT_EQ(run.kinds[run.kind[1]], "dwell");
  EXPECT_EQ(run.kinds[run.kind[2]], "line");
  EXPECT_EQ(run.kinds[run.kind[3]], "program_end");
  const json& m = j["moves"];
  ASSERT_EQ(m["count"], 4) << m;  // indexed as /api/run's moves
  EXPECT_EQ(m["complete"], true);
  const auto programmed = m["feed_programmed"].get<std::vector<double>>();
  const auto peak = m["feed_peak"].get<std::vector<double>>();
  const auto end = m["feed_end"].get<std::vector<double>>();
  EXPECT_EQ(programmed, (std::vector<double>{1000, 0, 3000, 0}));
  EXPECT_NEAR(peak[0], 1000, 0.05);
  EXPECT_NEAR(end[0], 0, 0.05);
  EXPECT_NEAR(peak[2], 60 * std::sqrt(1000 * 0.1), 0.05);
  EXPECT_EQ(peak[1], 0);
  EXPECT_EQ(peak[3], 0);
  // the existing keys are all there, and without "moves" the answer has none
  EXPECT_EQ(j["motions"], 2);
  EXPECT_FALSE(call(api_analyze, {{"program", program}}).contains("moves"));
  // a server that keeps 2 moves an answer: the first 2, and says so
  ServeConfig small = on("fanuc-mill");
  small.max_moves = 2;
  const json cut = call(api_analyze, {{"program", program}, {"moves", true}}, small);
  EXPECT_EQ(cut["moves"]["count"], 2);
  EXPECT_EQ(cut["moves"]["complete"], false);
  EXPECT_NE(cut["moves"]["message"].get<std::string>().find("first 2 moves of 4"), std::string::npos);
  EXPECT_NEAR(cut["moves"]["feed_peak"][0].get<double>(), 1000, 0.05);
}

// A circle of radius 10 (the ellipse with a = b) in G01 chords of equal angle. Each move's
// deviation is worked out here from the chord's ends P, Q as the program has them (rounded to
// 0.001): the curve's farthest point from the chord is where the radius is normal to it, r - d
// from it (d = |P x Q| / |PQ|, the chord line's distance from the centre), and the ends lie
// ||P| - r| and ||Q| - r| off the circle. With the ends on the circle that is the sagitta
// r (1 - cos(dθ/2)), which the rounding of the ends changes by less than a micrometre.
TEST(ColourApi, GenDeviationOfCircleChords) {
  const double r = 10, tol = 0.005;
  const json g = call(api_gen, {{"curve", "ellipse"}, {"params", {{"a", r}, {"b", r}}}, {"tol", tol}, {"form", "expanded"},
                                {"lines", "equal-step"}});
  ASSERT_EQ(g["within_tolerance"], true);
  const RunPoints run = run_points(g["program"]);
  const auto index = g["move_deviation"]["index"].get<std::vector<std::size_t>>();
  const auto mm = g["move_deviation"]["mm"].get<std::vector<double>>();
  ASSERT_EQ(index.size(), mm.size());
  ASSERT_GT(index.size(), 20u);
  const double dtheta = 2 * std::numbers::pi / static_cast<double>(index.size());
  const double sagitta = r * (1 - std::cos(dtheta / 2));
  double most = 0;
  for (std::size_t k = 0; k < index.size(); ++k) {
    const std::size_t i = index[k];
    ASSERT_LT(i, run.x.size());
    EXPECT_EQ(run.kinds[run.kind[i]], "line");
    const double px = run.sx[i], py = run.sy[i], qx = run.x[i], qy = run.y[i];
    EXPECT_NEAR(run.z[i], -1, 1e-9);  // at the depth
    const double d = std::fabs(px * qy - py * qx) / std::hypot(qx - px, qy - py);
    const double truth = std::max({r - d, std::fabs(std::hypot(px, py) - r), std::fabs(std::hypot(qx, qy) - r)});
    EXPECT_NEAR(mm[k], truth, 1e-8) << "move " << i << " from " << px << "," << py << " to " << qx << "," << qy;
    EXPECT_NEAR(mm[k], sagitta, 1e-3);
    EXPECT_LE(mm[k], tol);
    most = std::max(most, mm[k]);
  }
  EXPECT_NEAR(most, g["max_deviation"].get<double>(), 1e-9);  // the moves' largest is gen's figure
}

// The ellipse a = 20, b = 10 at the default depth of 1 mm: the polyline lies on it (x^2/a^2 +
// y^2/b^2 = 1 at Z-1), from its start to its end, and between two of its points the ellipse
// keeps within a tenth of the tolerance of the chord (checked at 64 points of each piece of
// eccentric angle, the angle of a point being atan2(y/b, x/a)).
TEST(ColourApi, GenCurvePolylineOnTheEllipse) {
  const double a = 20, b = 10, tol = 0.005;
  const json g = call(api_gen, {{"curve", "ellipse"}, {"params", {{"a", a}, {"b", b}}}, {"tol", tol}, {"form", "arcs"}});
  const json& ref = g["reference"];
  const auto x = ref["x"].get<std::vector<double>>(), y = ref["y"].get<std::vector<double>>(), z = ref["z"].get<std::vector<double>>();
  ASSERT_EQ(x.size(), ref["count"].get<std::size_t>());
  ASSERT_GT(x.size(), 100u);
  EXPECT_LE(ref["within_mm"].get<double>(), tol / 10);
  EXPECT_NEAR(x.front(), a, 1e-9);
  EXPECT_NEAR(y.front(), 0, 1e-9);
  EXPECT_NEAR(x.back(), a, 1e-9);
  EXPECT_NEAR(y.back(), 0, 1e-9);
  double worst = 0, chord = 0;
  double prev = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    worst = std::max(worst, std::fabs(x[i] * x[i] / (a * a) + y[i] * y[i] / (b * b) - 1));
    EXPECT_NEAR(z[i], -1, 1e-12);
    double t = std::atan2(y[i] / b, x[i] / a);
    while (t < prev - 1e-9) t += 2 * std::numbers::pi;  // rising, one turn
    if (i > 0) {
      EXPECT_GT(t, prev);
      for (int k = 1; k < 64; ++k) {
        const double s = prev + (t - prev) * k / 64, cx = a * std::cos(s), cy = b * std::sin(s);
        const double ux = x[i] - x[i - 1], uy = y[i] - y[i - 1];
        const double u = std::clamp(((cx - x[i - 1]) * ux + (cy - y[i - 1]) * uy) / (ux * ux + uy * uy), 0.0, 1.0);
        chord = std::max(chord, std::hypot(cx - x[i - 1] - u * ux, cy - y[i - 1] - u * uy));
      }
    }
    prev = t;
  }
  EXPECT_LE(worst, 1e-9);
  EXPECT_NEAR(prev, 2 * std::numbers::pi, 1e-9);
  EXPECT_LE(chord, tol / 10);
  // arcs: each arc's deviation within the tolerance, the largest gen's own figure
  const auto mm = g["move_deviation"]["mm"].get<std::vector<double>>();
  ASSERT_FALSE(mm.empty());
  EXPECT_LE(*std::max_element(mm.begin(), mm.end()), tol);
  EXPECT_NEAR(*std::max_element(mm.begin(), mm.end()), g["max_deviation"].get<double>(), 1e-9);
}

// On a lathe the curve's y is X (a diameter, as /api/run gives X) and its x is Z: the ellipse
// from 0 to 180 degrees has (X/2)^2/b^2 + Z^2/a^2 = 1, and the deviations index the run's moves.
TEST(ColourApi, GenCurveOnTheLathe) {
  const double a = 20, b = 10;
  const json g = call(api_gen, {{"curve", "ellipse"}, {"params", {{"a", a}, {"b", b}}}, {"from", 0}, {"to", 180},
                                {"tol", 0.005}},
                      on("fanuc-lathe"));
  const json& ref = g["reference"];
  for (std::size_t i = 0; i < ref["count"].get<std::size_t>(); ++i) {
    const double x = ref["x"][i].get<double>() / 2, zz = ref["z"][i].get<double>();
    ASSERT_NEAR(x * x / (b * b) + zz * zz / (a * a), 1, 1e-9) << i;
    ASSERT_GE(x, -1e-9);
  }
  const RunPoints run = run_points(g["program"], "fanuc-lathe");
  for (std::size_t i : g["move_deviation"]["index"].get<std::vector<std::size_t>>()) {
    ASSERT_LT(i, run.x.size());
    EXPECT_EQ(run.kinds[run.kind[i]], "line");
    // each move ends on the ellipse within the tolerance (X a diameter in both)
    const double x = run.x[i] / 2, zz = run.z[i];
    EXPECT_NEAR(std::sqrt(x * x / (b * b) + zz * zz / (a * a)), 1, 0.005 / b);
  }
}

}  // namespace
}  // namespace ncurve::serve
