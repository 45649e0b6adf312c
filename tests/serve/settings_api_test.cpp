// The command line's run settings over the API: "lib" among the server's --lib folders (GET
// /api/libs), "set" and "param" as the command line's values with its messages, "tool_offsets" over
// the profile's (the path of G41 D1 moved by the new radius, worked out by hand), the profile's
// offsets in its description, and gen's defaults in /api/curves.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "serve/api.hpp"

namespace ncurve::serve {
namespace {

using nlohmann::json;

const std::string kMacros = std::string(NCURVE_SOURCE_DIR) + "/macros";
// G102 calls O9010 of macros/ when No.6050 = 102 (examples/custom-cycle.nc)
const char* const kCycle = "G90 G17 G21 G54\nG00 X40. Y0. Z5.\nG01 Z-1. F200.\n"
                           "G102 X50. Y0. I-40. J0. Q10. A1. F1000.\nG00 Z5.\nM30\n";
// a 40 x 20 rectangle from (0, 0) counter-clockwise under G41 D1: the left side, inside
const char* const kContour = "G90 G17 G21 G54 G00 X-10. Y-10. Z5.\nG01 Z-1. F200.\nG41 D1 G01 X0 Y0 F500.\n"
                             "X40.\nY20.\nX0\nY0\nG40 G01 X-10. Y-10.\nG00 Z5.\nM30\n";

Answer call(const ServeConfig& config, const json& request, const char* endpoint = "run") {
  try {
    return std::string(endpoint) == "run" ? api_run(config, request.dump()) : api_analyze(config, request.dump());
  } catch (const ApiError& e) {
    return Answer{e.status, e.what()};
  }
}

// where the last move of a line ends, X and Y
std::pair<double, double> end_of(const json& j, int line) {
  const json& m = j["moves"];
  std::pair<double, double> at{NAN, NAN};
  for (std::size_t i = 0; i < m["x"].size(); ++i)
    if (m["line"][i].get<int>() == line) at = {m["x"][i].get<double>(), m["y"][i].get<double>()};
  return at;
}

// a shipped profile's TOML text (the test binary is not where the shipped files are looked for)
std::string profile_text(const char* name) {
  std::ifstream f(std::string(NCURVE_SOURCE_DIR) + "/profiles/" + name + ".toml");
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

ServeConfig with_macros() {
  ServeConfig c;
  c.libs = {kMacros};
  return c;
}

TEST(SettingsApi, LibChoosesAmongTheServersFolders) {
  const ServeConfig c = with_macros();
  const json libs = json::parse(api_libs(c).body)["libs"];
  ASSERT_EQ(libs.size(), 1u);
  EXPECT_EQ(libs[0]["name"], kMacros);
  EXPECT_EQ(libs[0]["program_count"], 10);
  EXPECT_EQ(libs[0]["programs"][0], "O9010.nc");
  EXPECT_EQ(json::parse(api_libs(ServeConfig{}).body)["libs"], json::array());

  const json base{{"program", kCycle}, {"param", {"6050=102"}}, {"moves", false}};
  // no "lib": every folder of the server, as before; the folder named: the same; none: O9010 not found
  for (const json& lib : {json(nullptr), json::array({kMacros})}) {
    json r = base;
    if (!lib.is_null()) r["lib"] = lib;
    const Answer a = call(c, r);
    ASSERT_EQ(a.status, 200) << a.body;
    EXPECT_TRUE(json::parse(a.body)["summary"]["ok"].get<bool>()) << a.body;
  }
  json none = base;
  none["lib"] = json::array();
  const json s = json::parse(call(c, none).body)["summary"];
  ASSERT_FALSE(s["ok"].get<bool>());
  EXPECT_FALSE(s["alarm"].is_null());

  // a folder the server was not given is refused, saying which it has
  json other = base;
  other["lib"] = {"/etc"};
  Answer a = call(c, other);
  EXPECT_EQ(a.status, 400);
  EXPECT_EQ(std::string(a.body).rfind("\"lib\": \"/etc\" is not a macro folder of this server (its --lib folders: " +
                                          kMacros + ")",
                                      0),
            0u)
      << a.body;
  a = call(ServeConfig{}, other);
  EXPECT_NE(a.body.find("the server was started with no --lib folder"), std::string::npos) << a.body;
  other["lib"] = kMacros;  // a string, not a list
  EXPECT_EQ(call(c, other).status, 400);
  other["lib"] = json::array({kMacros});
  EXPECT_EQ(call(c, other, "analyze").status, 200);
  other["lib"] = {"/etc"};
  EXPECT_EQ(call(c, other, "analyze").status, 400);
}

TEST(SettingsApi, SetAndParamAsTheCommandLinesValues) {
  const std::string alarm = "IF [#100 EQ #0] THEN #3000=1 (DEPTH NOT SET)\nG01 Z-#100 F100.\nM30\n";
  json r{{"program", alarm}, {"set", {"#100=2"}}};
  json j = json::parse(call({}, r).body);
  EXPECT_TRUE(j["summary"]["ok"].get<bool>());
  EXPECT_DOUBLE_EQ(j["moves"]["z"][0].get<double>(), -2);
  // the command line's messages for a bad value
  r["set"] = {"#abc=1"};
  Answer a = call({}, r);
  EXPECT_EQ(a.status, 400);
  EXPECT_STREQ(a.body.c_str(), "--set: '#abc=1' is not of the form #100=5");
  r["set"] = {"#100=2"};
  r["param"] = {"6050=abc"};
  a = call({}, r);
  EXPECT_EQ(a.status, 400);
  EXPECT_STREQ(a.body.c_str(), "--param: '6050=abc' is not of the form 6050=102");
  r["param"] = {"3401#0=1"};  // decimal point programming: X10 is 10 mm
  r["program"] = "G01 X10 F100\nM30\n";
  j = json::parse(call({}, r).body);
  EXPECT_DOUBLE_EQ(j["moves"]["x"][0].get<double>(), 10);
  r["param"] = json::array();
  j = json::parse(call({}, r).body);
  EXPECT_DOUBLE_EQ(j["moves"]["x"][0].get<double>(), 0.01);
  r["param"] = {102};  // not a string
  a = call({}, r);
  EXPECT_EQ(a.status, 400);
  EXPECT_NE(a.body.find("each entry is a string as --param takes it"), std::string::npos) << a.body;
  r["param"] = "6050=102";
  EXPECT_EQ(call({}, r).status, 400);
  r["param"] = {"6050=abc"};
  EXPECT_EQ(call({}, r, "analyze").status, 400);
}

TEST(SettingsApi, ToolOffsetsOverTheProfiles) {
  // offset 1 radius 5 (memory A: one value for H and D): the rectangle's sides 5 mm inside, the
  // bottom (line 4) ending at the right side's offset line X 35, the top (line 6) at X 5, Y 15
  for (const json& offset : {json(5), json{{"radius", 5}}, json{{"length", 5}}}) {
    const json r{{"program", kContour}, {"tool_offsets", {{"1", offset}}}};
    const Answer a = call({}, r);
    ASSERT_EQ(a.status, 200) << a.body;
    const json j = json::parse(a.body);
    ASSERT_TRUE(j["summary"]["ok"].get<bool>()) << a.body;
    EXPECT_EQ(end_of(j, 4), std::make_pair(35.0, 5.0)) << j["moves"].dump();
    EXPECT_EQ(end_of(j, 6), std::make_pair(5.0, 15.0));
    // the profile described as its file gives it: no offsets on the factory mill
    EXPECT_EQ(j["profile"]["tool_offsets"], json::object());
  }
  // fanuc-mill's offset 1 = 100, described; memory C apart
  const json mill = json::parse(call({}, {{"program", "M30\n"}, {"machine", profile_text("fanuc-mill")}}).body);
  EXPECT_EQ(mill["profile"]["tool_offsets"]["1"], (json{{"length", 100}, {"length_wear", 0}, {"radius", 100}, {"radius_wear", 0}}));
  const std::string memory_c = "[machine]\noffset_memory = \"C\"\n[tool_offsets]\n1 = { length = 50, radius = 3 }\n";
  json r{{"program", kContour}, {"machine", memory_c}, {"tool_offsets", {{"1", {{"radius", 5}}}}}};
  json j = json::parse(call({}, r).body);
  EXPECT_EQ(j["profile"]["tool_offsets"]["1"]["radius"], 3);
  EXPECT_EQ(j["profile"]["tool_offsets"]["1"]["length"], 50);
  EXPECT_EQ(end_of(j, 4), std::make_pair(35.0, 5.0)) << j["moves"].dump();
  r.erase("tool_offsets");
  EXPECT_EQ(end_of(json::parse(call({}, r).body), 4), std::make_pair(37.0, 3.0));
  // a lathe's offsets by their fields
  r = {{"program", "G00 X0 Z0\nM30\n"}, {"machine", profile_text("fanuc-lathe")}, {"tool_offsets", {{"1", {{"r", 0.8}, {"tip", 3}}}}}};
  EXPECT_EQ(call({}, r).status, 200);

  // refused, in the profile file's words
  auto refused = [&](const json& machine, const json& offsets, const std::string& message) {
    json q{{"program", kContour}, {"tool_offsets", offsets}};
    if (!machine.is_null()) q["machine"] = machine;
    const Answer a = call({}, q);
    EXPECT_EQ(a.status, 400) << a.body;
    EXPECT_EQ(a.body, message);
    EXPECT_EQ(call({}, q, "analyze").status, 400);
  };
  refused(nullptr, {{"1", {{"r", 5}}}},
          "\"tool_offsets\": offset 1: unknown mill offset field 'r' (length, length_wear, radius, radius_wear)");
  refused(nullptr, {{"1", {{"radius", "abc"}}}}, "\"tool_offsets\": offset 1: 'radius' must be a number (mm)");
  refused(nullptr, {{"1", {{"radius", 5000}}}},
          "\"tool_offsets\": offset 1: 'radius' = 5000 mm is beyond the control's range (a geometry value: -999.999 .. "
          "999.999 mm)");
  refused(nullptr, {{"1", {{"radius_wear", 1}}}},
          "\"tool_offsets\": offset 1: offset memory A has no wear values (offset_memory = \"B\" or \"C\")");
  refused(nullptr, {{"1", {{"length", 1}, {"radius", 2}}}},
          "\"tool_offsets\": offset 1: offset memory A holds one value for H and D: give length or radius, not both "
          "(offset_memory = \"C\" separates them)");
  refused(nullptr, {{"0", 5}}, "\"tool_offsets\": tool offset numbers are 1 .. 999");
  refused(nullptr, {{"D1", 5}}, "\"tool_offsets\": 'D1' is not a whole offset number");
  refused(nullptr, json::array({5}), "\"tool_offsets\" must be an object, e.g. {\"1\": {\"radius\": 5}}");
  refused(profile_text("fanuc-lathe"), {{"1", {{"radius", 5}}}},
          "\"tool_offsets\": offset 1: unknown lathe offset field 'radius' (x, z, r, tip, x_wear, z_wear, r_wear)");
  refused(profile_text("fanuc-lathe"), {{"1", {{"tip", 2.5}}}},
          "\"tool_offsets\": offset 1: the imaginary tool nose direction 'tip' is a whole number 0 .. 9, not 2.5");
  refused(profile_text("fanuc-lathe"), {{"65", {{"r", 1}}}}, "\"tool_offsets\": lathe offset numbers are 1 .. 64");
}

TEST(SettingsApi, CurvesGiveGensDefaults) {
  const json j = json::parse(api_curves().body);
  EXPECT_EQ(j["default_form"], "expanded");
  EXPECT_DOUBLE_EQ(j["default_tol"].get<double>(), 0.005);
}

}  // namespace
}  // namespace ncurve::serve
