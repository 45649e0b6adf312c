// The programmed contour beside a compensated path in /api/run's moves ("programmed",
// "programmed_arcs"), the tool offsets in force at each step of the trace ("tool"), and /api/gen
// generating on the control of the request's "param" and "tool_offsets". Expected values are the
// programs' own coordinates and geometry worked out by hand.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "serve/api.hpp"

namespace ncurve::serve {
namespace {

using nlohmann::json;

Answer call(const json& request, const char* endpoint = "run") {
  const ServeConfig config;
  try {
    return std::string(endpoint) == "run" ? api_run(config, request.dump()) : api_gen(config, request.dump());
  } catch (const ApiError& e) {
    return Answer{e.status, e.what()};
  }
}

json run_ok(const json& request) {
  const Answer a = call(request);
  EXPECT_EQ(a.status, 200) << a.body.substr(0, 400);
  json j = json::parse(a.body);
  EXPECT_EQ(j["summary"]["ok"], true) << j["summary"]["alarm"];
  return j;
}

std::string profile_text(const char* name) {
  std::ifstream f(std::string(NCURVE_SOURCE_DIR) + "/profiles/" + name + ".toml");
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// the index of the last move made by a line
int last_move_of(const json& moves, int line) {
  int at = -1;
  for (std::size_t i = 0; i < moves["line"].size(); ++i)
    if (moves["line"][i] == line) at = static_cast<int>(i);
  return at;
}

// the programmed contour's entries: (line, start X Y, end X Y)
struct Entry {
  int line;
  double sx, sy, x, y;
};
std::vector<Entry> programmed(const json& moves) {
  const json& p = moves["programmed"];
  std::vector<Entry> out;
  for (std::size_t e = 0; e < p["index"].size(); ++e)
    out.push_back({moves["line"][p["index"][e].get<int>()].get<int>(), p["sx"][e].get<double>(), p["sy"][e].get<double>(),
                   p["x"][e].get<double>(), p["y"][e].get<double>()});
  return out;
}

// A 40 x 30 rectangle from (0, 0), clockwise under G41 D1 with a 5 mm cutter: the cutter on the
// left of its way is outside, its centre on the rectangle X-5..45, Y-5..35 (the sides' offset lines
// meeting at the 90° corners); the last side, before the G40 block, ends square to its end, at (0, -5).
const char* const kRectangle = "G90 G17 G21 G54 G00 X-20. Y-20. Z5.\nG01 Z-1. F200.\nG41 D1 G01 X0 Y0 F500.\n"
                               "Y30.\nX40.\nY0\nX0\nG40 G01 X-20. Y-20.\nG00 Z5.\nM30\n";

TEST(ProgrammedContour, ARectangleUnderG41IsTheProgramsCornersBesideTheOffsetPath) {
  const json j = run_ok({{"program", kRectangle}, {"tool_offsets", {{"1", {{"radius", 5}}}}}});
  const json& m = j["moves"];
  // the tool centre: the sides end on the offset rectangle's corners
  const double tool[4][2] = {{-5, 35}, {45, 35}, {45, -5}, {0, -5}};
  for (int side = 0; side < 4; ++side) {
    const int i = last_move_of(m, 4 + side);
    ASSERT_GE(i, 0);
    EXPECT_NEAR(m["x"][i].get<double>(), tool[side][0], 1e-6) << "line " << 4 + side;
    EXPECT_NEAR(m["y"][i].get<double>(), tool[side][1], 1e-6) << "line " << 4 + side;
  }
  // the programmed contour: the approach, the four sides through the program's corners, the G40 move
  const std::vector<Entry> p = programmed(m);
  const Entry want[] = {{3, -20, -20, 0, 0}, {4, 0, 0, 0, 30}, {5, 0, 30, 40, 30},
                        {6, 40, 30, 40, 0},  {7, 40, 0, 0, 0}, {8, 0, 0, -20, -20}};
  ASSERT_EQ(p.size(), std::size(want));
  for (std::size_t e = 0; e < p.size(); ++e) {
    EXPECT_EQ(p[e].line, want[e].line);
    EXPECT_NEAR(p[e].sx, want[e].sx, 1e-9) << e;
    EXPECT_NEAR(p[e].sy, want[e].sy, 1e-9) << e;
    EXPECT_NEAR(p[e].x, want[e].x, 1e-9) << e;
    EXPECT_NEAR(p[e].y, want[e].y, 1e-9) << e;
  }
  for (const auto& z : m["programmed"]["z"]) EXPECT_EQ(z, -1);
  EXPECT_TRUE(m["programmed_arcs"]["index"].empty());
  // without compensation there is no programmed contour apart from the path
  const json plain = run_ok({{"program", "G00 X0 Y0 Z5.\nG01 X40. F500.\nG02 X0 I-20.\nM30\n"}});
  EXPECT_TRUE(plain["moves"]["programmed"]["index"].empty());
  EXPECT_TRUE(plain["moves"]["programmed_arcs"]["index"].empty());
}

// The top side a half circle about (20, 30), G02 from (0, 30) to (40, 30): the tool centre's arc
// is concentric, of radius 20 + 5; the programmed arc keeps the centre and sweeps -180°.
TEST(ProgrammedContour, AnArcKeepsItsCentreAndSweep) {
  const json j = run_ok({{"program", "G90 G17 G21 G54 G00 X-20. Y-20. Z5.\nG01 Z-1. F200.\nG41 D1 G01 X0 Y0 F500.\n"
                                     "Y30.\nG02 X40. Y30. I20. J0\nG01 Y0\nX0\nG40 G01 X-20. Y-20.\nG00 Z5.\nM30\n"},
                         {"tool_offsets", {{"1", {{"radius", 5}}}}}});
  const json& m = j["moves"];
  const int arc = last_move_of(m, 5);
  const json& pa = m["programmed_arcs"];
  ASSERT_EQ(pa["index"], json::array({arc}));
  EXPECT_NEAR(pa["cx"][0].get<double>(), 20, 1e-9);
  EXPECT_NEAR(pa["cy"][0].get<double>(), 30, 1e-9);
  EXPECT_NEAR(pa["sweep_deg"][0].get<double>(), -180, 1e-9);
  EXPECT_NEAR(std::hypot(m["x"][arc].get<double>() - 20, m["y"][arc].get<double>() - 30), 25, 1e-6);
  const std::vector<Entry> p = programmed(m);
  ASSERT_GE(p.size(), 3u);
  EXPECT_EQ(p[2].line, 5);
  EXPECT_NEAR(p[2].sx, 0, 1e-9);
  EXPECT_NEAR(p[2].sy, 30, 1e-9);
  EXPECT_NEAR(p[2].x, 40, 1e-9);
  EXPECT_NEAR(p[2].y, 30, 1e-9);
}

// A lathe's quarter arc from X0 Z0 about X0 Z-10 (I0 K-10) to X20 (a diameter) Z-10 under G42,
// nose radius 0.8, tip 3: the put-out arc is the nose centre's moved by the imaginary tip, which
// is (-X, -Z) of the nose centre at tip 3: its centre X(dia) -1.6, Z -10.8; the programmed arc's is
// the program's, X0 Z-10. And the trace's tool: offset 1, nose R 0.8, tip 3 after T0101.
TEST(ProgrammedContour, ALathesArcCentreIsTheProgramsNotTheTipsAndTheTraceHasTheNose) {
  const json j = run_ok({{"program", "T0101\nG00 X0 Z5.\nG42 G01 X0 Z0 F0.1\nG03 X20. Z-10. I0 K-10.\nG01 Z-30.\n"
                                     "G40 G00 X40.\nM30\n"},
                         {"machine", profile_text("fanuc-lathe")},
                         {"tool_offsets", {{"1", {{"r", 0.8}, {"tip", 3}}}}},
                         {"trace", true}});
  const json& m = j["moves"];
  const int arc = last_move_of(m, 4);
  ASSERT_EQ(m["kinds"][m["kind"][arc].get<int>()], "arc");
  const json& pa = m["programmed_arcs"];
  ASSERT_EQ(pa["index"], json::array({arc}));
  EXPECT_NEAR(pa["cx"][0].get<double>(), 0, 1e-9);
  EXPECT_NEAR(pa["cz"][0].get<double>(), -10, 1e-9);
  EXPECT_NEAR(std::fabs(pa["sweep_deg"][0].get<double>()), 90, 1e-9);
  const json& arcs = m["arcs"];
  ASSERT_EQ(arcs["index"].size(), 1u);
  EXPECT_NEAR(arcs["cx"][0].get<double>(), -1.6, 1e-9);
  EXPECT_NEAR(arcs["cz"][0].get<double>(), -10.8, 1e-9);
  const std::vector<Entry> p = programmed(m);
  bool found = false;
  for (std::size_t e = 0; e < p.size(); ++e)
    if (p[e].line == 4) found = true;
  EXPECT_TRUE(found);
  const int i = std::find(m["programmed"]["index"].begin(), m["programmed"]["index"].end(), arc) -
                m["programmed"]["index"].begin();
  EXPECT_NEAR(m["programmed"]["x"][i].get<double>(), 20, 1e-9);
  EXPECT_NEAR(m["programmed"]["z"][i].get<double>(), -10, 1e-9);
  EXPECT_NEAR(m["programmed"]["sx"][i].get<double>(), 0, 1e-9);
  EXPECT_NEAR(m["programmed"]["sz"][i].get<double>(), 0, 1e-9);
  const json& tool = j["trace"]["tool"];
  EXPECT_EQ(tool["block"], json::array({0, 1}));  // T0101 is the first block: in force from the second
  EXPECT_EQ(tool["offset"], json::array({0, 1}));
  EXPECT_EQ(tool["radius"], json::array({0, 0.8}));
  EXPECT_EQ(tool["tip"], json::array({0, 3}));
}

// The trace's tool offsets on memory C, H and D apart: H1 length 100 from the block after G43 H1,
// D1 radius 5 from the block after G41 D1.
TEST(ToolAtStep, TheTraceHasTheOffsetsInForceFromTheBlockAfterTheirWords) {
  const std::string memory_c = "[machine]\noffset_memory = \"C\"\n";
  const json j = run_ok({{"program", "T1 M06\nG90 G17 G21 G54 G00 X-20. Y-20.\nG43 H1 Z5.\nG01 Z-1. F200.\n"
                                     "G41 D1 G01 X0 Y0 F500.\nY30.\nG40 G01 X-20. Y-20.\nG49 G00 Z5.\nM30\n"},
                         {"machine", memory_c},
                         {"tool_offsets", {{"1", {{"length", 100}, {"radius", 5}}}}},
                         {"trace", true}});
  const json& tool = j["trace"]["tool"];
  EXPECT_EQ(tool["block"], json::array({0, 3, 5}));
  EXPECT_EQ(tool["offset"], json::array({0, 0, 1}));
  EXPECT_EQ(tool["radius"], json::array({0, 0, 5}));
  EXPECT_EQ(tool["length"], json::array({0, 100, 100}));
  EXPECT_EQ(tool["tip"], json::array({0, 0, 0}));
  // T1 from the block after T1 M06 (#4120 among the modal words)
  const json& modal = j["trace"]["modal"];
  bool t1 = false;
  for (std::size_t c = 0; c < modal["var"].size(); ++c)
    if (modal["var"][c] == 4120 && modal["value"][c] == 1 && modal["block"][c] == 1) t1 = true;
  EXPECT_TRUE(t1);
}

// No.3410 = 1 (0.001 mm) allows an arc's end radius to differ from its start's by a micrometre: an
// ellipse as arcs generated on the factory control (0.020 mm) has arcs that alarm PS0020 on it; gen
// asked with the request's "param" fits its arcs within it, and the program runs there.
TEST(GenSettings, ParamIsTheControlGenFitsArcsFor) {
  const json gen{{"curve", "ellipse"}, {"params", {{"a", 20}, {"b", 10}}}, {"form", "arcs"}, {"tol", 0.005}};
  auto program = [](const json& request) {
    const Answer a = call(request, "gen");
    EXPECT_EQ(a.status, 200) << a.body.substr(0, 400);
    return json::parse(a.body)["program"].get<std::string>();
  };
  auto alarm_on_3410 = [](const std::string& text) {
    const Answer a = call({{"program", text}, {"param", {"3410=1"}}, {"moves", false}});
    const json s = json::parse(a.body)["summary"];
    return s["alarm"].is_null() ? std::string() : s["alarm"]["code"].get<std::string>();
  };
  EXPECT_EQ(alarm_on_3410(program(gen)), "PS0020");
  json with = gen;
  with["param"] = {{"3410", 1}};
  EXPECT_EQ(alarm_on_3410(program(with)), "");
  // refused in the words of /api/run
  with["param"] = json::array({"3410=x"});
  Answer a = call(with, "gen");
  EXPECT_EQ(a.status, 400);
  EXPECT_EQ(a.body, "--param: '3410=x' is not of the form 6050=102");
  with.erase("param");
  with["tool_offsets"] = {{"1", {{"r", 1}}}};
  a = call(with, "gen");
  EXPECT_EQ(a.status, 400);
  EXPECT_EQ(a.body, "\"tool_offsets\": offset 1: unknown mill offset field 'r' (length, length_wear, radius, radius_wear)");
}

}  // namespace
}  // namespace ncurve::serve
