// POST /api/run with "verify" and "setup": the part cut, its findings among the diagnostics, the
// part's grid, a debugger's step (cut_moves), and the bounds.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>
#include <string>

#include "serve/api.hpp"

namespace ncurve::serve {
namespace {

using nlohmann::json;

// a 40 x 40 x 20 block, top at Z0; T1 a 10 mm end mill in the spindle
const char* const kSetup = R"(tool_in_spindle = 1
[stock]
shape = "box"
min = [-20, -20, -20]
max = [20, 20, 0]
[tools.1]
kind = "flat"
diameter = 10
)";
// a slot 1 deep from X-10 to X10, then a rapid 2 mm into the block at X0 Y10 (line 7)
const char* const kProgram =
    "M03 S1000\nG90 G00 X-10. Y0 Z5.\nG01 Z-1. F200.\nX10.\nG00 Z5.\nG00 X0 Y10.\nG00 Z-2.\nG00 Z5.\nM30\n";

// the answer, or the refusal as the server sends it
Answer call(const json& request) {
  try {
    return api_run(ServeConfig{}, request.dump());
  } catch (const ApiError& e) {
    return Answer{e.status, e.what()};
  }
}

json run(json request) {
  const Answer a = call(request);
  EXPECT_EQ(a.status, 200) << a.body;
  return json::parse(a.body);
}

TEST(PartApi, VerifyCutsTheSetupsStockAndListsTheFindings) {
  const json r = run({{"program", kProgram}, {"name", "slot.nc"}, {"setup", kSetup}, {"resolution", 0.1}});
  const json& v = r["summary"]["verify"];
  ASSERT_TRUE(v["verified"].get<bool>());
  EXPECT_EQ(v["zmap"]["cells"], json::array({400, 400}));
  // the slot: 20 x 10 x 1 with round ends (pi 25), and the rapid's 2 mm deep disc of radius 5
  const double exact = 20 * 10 * 1 + M_PI * 25 * 1 + M_PI * 25 * 2;
  EXPECT_NEAR(v["volume_removed_mm3"].get<double>(), exact, 0.1 * 1.5 * (40 + 4 * M_PI * 5 + 2 * M_PI * 5));
  ASSERT_EQ(v["findings"].size(), 1u);
  EXPECT_EQ(v["findings"][0]["code"], "NC2080");
  EXPECT_EQ(v["findings"][0]["line"], 7);
  bool listed = false;  // the editor's list has it
  for (const json& d : r["diagnostics"]) listed |= d["code"] == "NC2080" && d["line"] == 7;
  EXPECT_TRUE(listed);
  const json& part = r["part"];
  EXPECT_EQ(part["nx"], 400);
  EXPECT_EQ(part["ny"], 400);
  EXPECT_DOUBLE_EQ(part["top"].get<double>(), 0);
  EXPECT_EQ(part["heights"].get<std::string>().size(), (400u * 400u * 4u + 2u) / 3u * 4u);  // base64 of float32
}

TEST(PartApi, CutMovesStopsAtADebuggersStep) {
  // the first three motions: the rapid over, the plunge and the slot; not the rapid into the block
  const json r = run({{"program", kProgram}, {"setup", kSetup}, {"resolution", 0.1}, {"cut_moves", 3}, {"moves", false}});
  const json& v = r["summary"]["verify"];
  EXPECT_EQ(v["findings"].size(), 0u);
  EXPECT_EQ(v["moves_not_cut"]["after"], 4);  // of the seven motions
  const double slot = 20 * 10 * 1 + M_PI * 25 * 1;
  EXPECT_NEAR(v["volume_removed_mm3"].get<double>(), slot, 0.1 * 1.5 * (40 + 2 * M_PI * 5));
  const json none = run({{"program", kProgram}, {"setup", kSetup}, {"resolution", 0.1}, {"cut_moves", 0}});
  EXPECT_EQ(none["summary"]["verify"]["volume_removed_mm3"], 0);
}

TEST(PartApi, BoundsAndBadSetups) {
  // a map finer than the server allows is refused, naming the bound; the default fits within it
  Answer fine = call({{"program", kProgram}, {"setup", kSetup}, {"resolution", 0.001}});
  EXPECT_EQ(fine.status, 400);
  EXPECT_NE(fine.body.find("allowed"), std::string::npos) << fine.body;
  const json wide = run({{"program", kProgram},
                         {"setup", "tool_in_spindle = 1\n[stock]\nshape = \"box\"\nmin = [-2000, -20, -20]\n"
                                   "max = [2000, 20, 0]\n[tools.1]\nkind = \"flat\"\ndiameter = 10\n"}});
  const json& cells = wide["summary"]["verify"]["zmap"]["cells"];
  EXPECT_LE(cells[0].get<double>() * cells[1].get<double>(), kMostPartCells);
  // a setup with an error: 400, the error at its line and column of the setup named
  Answer bad = call({{"program", kProgram}, {"setup", "[stock]\nshape = \"ball\"\n"}, {"setup_name", "job.setup.toml"}});
  EXPECT_EQ(bad.status, 400);
  EXPECT_NE(bad.body.find("job.setup.toml:2:"), std::string::npos) << bad.body;
  // an STL stock or fixture names a file on the server: a setup sent as text reads none, 400
  for (const char* stl : {"[stock]\nshape = \"stl\"\nfile = \"/etc/passwd\"\n",
                          "[[fixtures]]\nname = \"f\"\nshape = \"stl\"\nfile = \"/etc/passwd\"\n"}) {
    Answer named = call({{"program", kProgram}, {"setup", stl}, {"setup_name", "job.setup.toml"}});
    EXPECT_EQ(named.status, 400);
    EXPECT_NE(named.body.find("job.setup.toml: error: an STL stock or fixture names a file, and a setup sent as text "
                              "reads none"),
              std::string::npos)
        << named.body;
  }
  // "cells": the shorter side in so many cells (a debugger's step asks 400); a bad count is a 400
  const json coarse = run({{"program", kProgram}, {"setup", kSetup}, {"cells", 100}});
  EXPECT_EQ(coarse["summary"]["verify"]["zmap"]["cells"], json::array({100, 100}));
  EXPECT_EQ(call({{"program", kProgram}, {"setup", kSetup}, {"cells", 5}}).status, 400);
  EXPECT_EQ(call({{"program", kProgram}, {"setup", kSetup}, {"cells", 100.5}}).status, 400);
  // without "verify" or "setup" there is no part
  const json plain = run({{"program", kProgram}});
  EXPECT_FALSE(plain.contains("part"));
  EXPECT_FALSE(plain["summary"].contains("verify"));
}

// base64 (RFC 4648) of float32, as the part's contours come
std::vector<float> floats(const std::string& b64) {
  static const std::string abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string bytes;
  unsigned acc = 0;
  int bits = 0;
  for (char c : b64) {
    const auto k = abc.find(c);
    if (k == std::string::npos) break;  // '=' ends it
    acc = (acc << 6) | static_cast<unsigned>(k);
    bits += 6;
    if (bits >= 8) bits -= 8, bytes.push_back(static_cast<char>((acc >> bits) & 0xff));
  }
  std::vector<float> out(bytes.size() / sizeof(float));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(float));
  return out;
}

// A lathe's part: a D50 bar faced 2 mm past its centre by a sharp tip-3 insert; the answer's part is
// the half-section, the rectangle Z-100..-2 by radius 0..25 (uncut at a debugger's step 0: Z-100..0).
TEST(PartApi, LathePartIsTheHalfSection) {
  const char* setup = "[stock]\nshape = \"cylinder\"\ndiameter = 50\nlength = 100\n"
                      "[tools.1]\nkind = \"insert\"\nnose_radius = 0\ntip = 3\n";
  const char* program = "G21 G99\nT0101\nG00 X60. Z5.\nG00 X52. Z-2.\nG01 X-1. F0.2\nG00 Z5.\nM30\n";
  const char* lathe = "[machine]\ntype = \"lathe\"\naxes = [\"X\", \"Z\"]\ndiameter_programming = true\n";
  auto section = [](const json& part) {
    EXPECT_TRUE(part["lathe"].get<bool>());
    EXPECT_DOUBLE_EQ(part["radius"].get<double>(), 25);
    EXPECT_EQ(part["contours"].size(), 1u);
    return floats(part["contours"][0].get<std::string>());
  };
  auto corners = [](std::vector<float> c, float back, float face) {
    std::vector<std::pair<float, float>> got, want{{back, 0}, {face, 0}, {face, 25}, {back, 25}};
    for (std::size_t i = 0; i + 1 < c.size(); i += 2) got.push_back({c[i], c[i + 1]});
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    return got == want;
  };
  const json r = run({{"program", program}, {"machine", lathe}, {"setup", setup}, {"moves", false}});
  const json& v = r["summary"]["verify"];
  ASSERT_TRUE(v["verified"].get<bool>());
  EXPECT_NEAR(v["volume_removed_mm3"].get<double>(), M_PI * 25 * 25 * 2, 1e-3);
  EXPECT_TRUE(corners(section(r["part"]), -100, -2));
  const json step = run({{"program", program}, {"machine", lathe}, {"setup", setup}, {"cut_moves", 0}});
  EXPECT_EQ(step["summary"]["verify"]["volume_removed_mm3"], 0);
  EXPECT_EQ(step["summary"]["verify"]["moves_not_cut"]["after"], 4);
  EXPECT_TRUE(corners(section(step["part"]), -100, 0));
}

}  // namespace
}  // namespace ncurve::serve

namespace ncurve::serve {
namespace {

// "curve": the slot's walls (away from the rapid's hole) against a line 0.02 beside its path (+Y):
// the +Y wall 0.02 short of the design, the -Y one 0.02 beyond it; the part's "deviation" has each
// wall point for the page
TEST(PartApi, CurveMeasuresTheWallsAndColoursThePart) {
  const json r = run({{"program", kProgram}, {"setup", kSetup}, {"resolution", 0.1}, {"tol", 0.01},
                      {"curve", {{"name", "expr"}, {"x", "t"}, {"y", "0.02"}, {"t", "-9:-6"}}}});
  const json& c = r["summary"]["verify"]["curve"];
  EXPECT_EQ(c["design"], "groove");
  EXPECT_NEAR(c["largest_gouge_mm"].get<double>(), 0.02, 1e-6);
  EXPECT_NEAR(c["largest_left_mm"].get<double>(), 0.02, 1e-6);
  // with the verifier's: the rapid into the block (line 7), then the walls' two at the slot's cut (line 4)
  const json& found = r["summary"]["verify"]["findings"];
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[1]["code"], "NC2088");  // the +Y wall, measured first
  EXPECT_EQ(found[1]["line"], 4);
  EXPECT_EQ(found[2]["code"], "NC2087");
  bool listed = false;
  for (const json& d : r["diagnostics"]) listed |= d["code"] == "NC2087" && d["line"] == 4;
  EXPECT_TRUE(listed);
  EXPECT_FALSE(c.contains("findings"));  // listed once, among the verifier's
  const json& dev = r["part"]["deviation"];
  EXPECT_EQ(dev["tol"], 0.01);
  // base64 of float32 X Y error: 4 characters for 3 bytes, 12 bytes a point
  EXPECT_EQ(dev["points"].get<std::string>().size(), c["points"].get<std::size_t>() * 12 / 3 * 4);
  // a rapid of two axes at one rate: its corner where the shorter one arrives (X-10 Y0 Z5 -> X0 Y10:
  // both 10 long, no corner), and "corners" is there
  EXPECT_TRUE(r["moves"].contains("corners"));

  EXPECT_EQ(call({{"program", kProgram}, {"curve", {{"name", "nosuch"}}}}).status, 400);
  EXPECT_EQ(call({{"program", kProgram}, {"curve", "spiral"}}).status, 400);
  EXPECT_EQ(call({{"program", kProgram}, {"curve", {{"name", "spiral"}, {"params", {{"pitch", "x"}}}}}}).status, 400);
  EXPECT_EQ(call({{"program", kProgram}, {"curve", {{"name", "spiral"}}}, {"wall", "side"}}).status, 400);
  EXPECT_EQ(call({{"program", kProgram}, {"curve", {{"name", "spiral"}}}, {"tol", 0}}).status, 400);
}

}  // namespace
}  // namespace ncurve::serve
