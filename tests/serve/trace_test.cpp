// The execution trace of POST /api/run: the variables rebuilt from it at any block equal the
// interpreter's own at that block (a run stopped there), and values worked out by hand.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "app/run_setup.hpp"
#include "machine/interpreter.hpp"
#include "serve/api.hpp"

namespace ncurve::serve {
namespace {

using nlohmann::json;

// Main program, two G65 calls of O9001 (the second repeated, L2: its locals start again from the
// arguments), an M98 subprogram that shares the main program's locals, a loop, a vacant #101.
// By hand (vacant counts as 0 in +):
//   #100=1; call 1: #1=2 #2=3 -> #1=5, #3=10, #100=11, the loop counts #1 down to 2
//   #102 = main #1 (vacant) + #100 = 11; O9002: main #1=7, #110=7
//   G65 A5. L2: each time #1=5+#2(vacant)=5, #3=10, #100 += 10 -> 21, then 31
constexpr const char* kProgram =
    "#100=1\n"            // 1
    "#101=#0\n"           // 2
    "G65 P9001 A2. B3.\n" // 3
    "#102=#1+#100\n"      // 4
    "M98 P9002\n"         // 5
    "G65 P9001 A5. L2\n"  // 6
    "M30\n"               // 7
    "O9001\n"             // 8
    "#1=#1+#2\n"          // 9
    "#3=#1*2\n"           // 10
    "#100=#100+#3\n"      // 11
    "WHILE [#1 GT 2] DO1\n"
    "#1=#1-1\n"
    "END1\n"
    "M99\n"
    "O9002\n"
    "#1=7\n"
    "#110=#1\n"
    "M99\n";

using Vars = std::map<int, std::optional<double>>;  // number -> value (nullopt: vacant)

// The variables after the first k blocks, rebuilt from the trace alone: locals (#1..#33) of the
// level of block k's innermost frame, and commons #100..#199.
Vars rebuild(const json& trace, std::size_t k) {
  std::map<std::pair<int, int>, std::optional<double>> locals;  // (level, number)
  std::map<int, std::optional<double>> globals;
  const json& w = trace["writes"];
  const json& lv = trace["levels"];
  std::size_t wi = 0, li = 0;
  for (long long b = -1; b < static_cast<long long>(k); ++b) {
    for (; li < lv["block"].size() && lv["block"][li].get<long long>() == b; ++li) {
      const int level = lv["level"][li];
      for (int n = 1; n <= 33; ++n) locals[{level, n}] = std::nullopt;
    }
    for (; wi < w["block"].size() && w["block"][wi].get<long long>() == b; ++wi) {
      std::optional<double> v;
      if (!w["new"][wi].is_null()) v = w["new"][wi].get<double>();
      const int n = w["var"][wi], level = w["level"][wi];
      if (level >= 0) locals[{level, n}] = v;
      else globals[n] = v;
    }
  }
  const json& stacks = trace["stacks"];
  const std::size_t blocks = trace["blocks"]["stack"].size();
  // the stack of block k (after the last block: that of the last block, for a program that ends in the main)
  const json& stack = stacks[trace["blocks"]["stack"][std::min(k, blocks - 1)].get<std::size_t>()];
  const int level = stack.back()["level"];
  Vars out;
  for (int n = 1; n <= 33; ++n) out[n] = locals.count({level, n}) ? locals[{level, n}] : std::nullopt;
  for (int n = 100; n <= 199; ++n) out[n] = globals.count(n) ? globals[n] : std::nullopt;
  return out;
}

// Stops a run before its block k (0-based): the interpreter then holds the state after k blocks.
struct StopAt final : machine::ExecutionObserver {
  std::size_t k, seen = 0;
  explicit StopAt(std::size_t k) : k(k) {}
  void block(const nc::Program&, const nc::Block&, std::uint64_t, const machine::ModalReadout&) override {
    if (seen++ == k) throw nc::Alarm(nc::Diagnostic{nc::Severity::error, "STOP", "stopped", {}});
  }
  void entered(const machine::CallFrame&) override {}
  void left() override {}
  void variable(int, std::int32_t, nc::Value, nc::Value) override {}
  void finished(std::uint64_t, const machine::ModalReadout&) override {}
};

Vars truth_after(const std::string& program, std::size_t k, const std::vector<std::string>& sets) {
  app::RunInputs in;
  in.program = "prog.nc";
  in.text = program;
  in.sets = sets;
  app::RunSetup s = app::prepare_run(in);
  machine::Interpreter interp(s.profile, *s.lib, s.options);
  StopAt stop(k);
  interp.observe(&stop);
  machine::NullSink sink;
  interp.run(sink);
  Vars out;
  for (int n : {0}) (void)n;
  for (int n = 1; n <= 33; ++n) {
    nc::Value v = interp.variable(n);
    out[n] = v.vacant ? std::nullopt : std::optional<double>(v.v);
  }
  for (int n = 100; n <= 199; ++n) {
    nc::Value v = interp.variable(n);
    out[n] = v.vacant ? std::nullopt : std::optional<double>(v.v);
  }
  return out;
}

json traced(const std::string& program, const json& set = json::object(), std::optional<std::size_t> limit = {}) {
  json req{{"program", program}, {"name", "prog.nc"}, {"trace", true}, {"set", set}};
  if (limit) req["trace_limit"] = *limit;
  Answer a = api_run(ServeConfig{}, req.dump());
  EXPECT_EQ(a.status, 200) << a.body.substr(0, 400);
  return json::parse(a.body);
}

TEST(Trace, RebuildsTheVariablesAtEveryBlock) {
  const json answer = traced(kProgram, {{"#150", 2.5}});
  ASSERT_EQ(answer["summary"]["ok"], true) << answer["summary"];
  const json& trace = answer["trace"];
  ASSERT_EQ(trace["complete"], true);
  const std::size_t blocks = trace["blocks"]["line"].size();
  ASSERT_EQ(blocks, answer["summary"]["blocks_executed"].get<std::size_t>());
  for (std::size_t k = 0; k <= blocks; ++k)
    EXPECT_EQ(rebuild(trace, k), truth_after(kProgram, k, {"#150=2.5"})) << "after " << k << " blocks";

  // by hand, at the end
  Vars end = rebuild(trace, blocks);
  EXPECT_EQ(end[100], 31.0);
  EXPECT_EQ(end[101], std::nullopt);
  EXPECT_EQ(end[102], 11.0);
  EXPECT_EQ(end[110], 7.0);
  EXPECT_EQ(end[150], 2.5);  // the preset, written before the first block
  EXPECT_EQ(end[1], 7.0);    // the main program's #1, set by the M98 subprogram
}

TEST(Trace, BlocksStacksAndWritesAsExecuted) {
  const json trace = traced(kProgram)["trace"];
  const json& lines = trace["blocks"]["line"];
  // main 1..3, O9001 lines 9..12, the loop: 13 14 12 three times (#1 5 -> 2), 15 (M99)
  const std::vector<int> first = {1, 2, 3, 9, 10, 11, 12, 13, 14, 12, 13, 14, 12, 13, 14, 12, 15, 4, 5, 17, 18, 19, 6};
  for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(lines[i], first[i]) << "block " << i;
  // block 3 (line 9) runs in O9001 called from line 3, on local level 1
  const json& stack = trace["stacks"][trace["blocks"]["stack"][3].get<int>()];
  ASSERT_EQ(stack.size(), 2u);
  EXPECT_EQ(stack[1]["kind"], "macro");
  EXPECT_EQ(stack[1]["program"], 9001);
  EXPECT_EQ(stack[1]["level"], 1);
  EXPECT_EQ(stack[1]["call_line"], 3);
  // the M98 subprogram (line 17) runs on the main program's level 0
  const json& sub = trace["stacks"][trace["blocks"]["stack"][19].get<int>()];
  EXPECT_EQ(sub[1]["kind"], "subprogram");
  EXPECT_EQ(sub[1]["level"], 0);
  // the first write of block 3 (#1=#1+#2 in the first call): #1 from 2 to 5 on level 1
  const json& w = trace["writes"];
  std::size_t i = 0;
  while (w["block"][i] != 3) ++i;
  EXPECT_EQ(w["var"][i], 1);
  EXPECT_EQ(w["level"][i], 1);
  EXPECT_EQ(w["old"][i], 2.0);
  EXPECT_EQ(w["new"][i], 5.0);
  // #101=#0: a write of vacant over vacant, both null
  i = 0;
  while (w["var"][i] != 101) ++i;
  EXPECT_TRUE(w["old"][i].is_null());
  EXPECT_TRUE(w["new"][i].is_null());
}

TEST(Trace, ModalStateAndMoves) {
  // block 0 G91 G01 ... moves, block 1 a variable, block 2 G90 G00
  const json answer = traced("G91 G01 X1. F200.\n#1=1\nG90 G00 X0\nM30\n");
  const json& t = answer["trace"];
  EXPECT_EQ(t["blocks"]["move"], json({0, 1, 1, 2}));
  EXPECT_EQ(t["moves"], 3);  // G01, G00 and M30
  std::map<std::pair<int, int>, double> changes;  // (block, variable) -> value
  for (std::size_t i = 0; i < t["modal"]["block"].size(); ++i)
    changes[{t["modal"]["block"][i].get<int>(), t["modal"]["var"][i].get<int>()}] = t["modal"]["value"][i];
  EXPECT_EQ((changes[{1, 4001}]), 1.0);   // G01 in force from block 1
  EXPECT_EQ((changes[{1, 4003}]), 91.0);  // G91
  EXPECT_EQ((changes[{1, 4109}]), 200.0); // F
  EXPECT_EQ((changes[{3, 4001}]), 0.0);   // G00 from block 3
  EXPECT_EQ((changes[{3, 4003}]), 90.0);
}

// A lathe's G71 reads its shape's blocks within its own step: the debugger's steps and the summary's
// blocks executed are one count. By hand: G00, the two G71 blocks (the shape skipped), G70 and the
// three shape blocks it runs, M30: 8 blocks, on lines 1 2 3 7 4 5 6 8.
TEST(Trace, ACycleReadingItsShapeIsOneStepAsTheSummaryCountsIt) {
  json req{{"program", "G00 X60. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X40.\nG01 Z-20.\n"
                       "N20 X60.\nG70 P10 Q20\nM30\n"},
           {"name", "prog.nc"}, {"trace", true}};
  ServeConfig lathe;
  lathe.machine = std::string(NCURVE_SOURCE_DIR) + "/profiles/fanuc-lathe.toml";
  Answer a = api_run(lathe, req.dump());
  ASSERT_EQ(a.status, 200) << a.body.substr(0, 400);
  const json answer = json::parse(a.body);
  ASSERT_EQ(answer["summary"]["ok"], true) << answer["summary"];
  EXPECT_EQ(answer["trace"]["blocks"]["line"], json({1, 2, 3, 7, 4, 5, 6, 8}));
  EXPECT_EQ(answer["summary"]["blocks_executed"], 8);
}

TEST(Trace, LimitKeepsWholeBlocksAndSaysSo) {
  const std::string program = "#1=0\nWHILE [#1 LT 1000] DO1\n#1=#1+1\nEND1\nM30\n";
  const json t = traced(program, json::object(), 100)["trace"];
  EXPECT_EQ(t["complete"], false);
  EXPECT_NE(t["message"].get<std::string>().find("trace_limit"), std::string::npos);
  const std::size_t blocks = t["blocks"]["line"].size();
  const std::size_t records = blocks + t["writes"]["block"].size() + t["levels"]["block"].size() +
                              t["modal"]["block"].size() + t["reads"]["block"].size();
  EXPECT_LE(records, 100u);
  EXPECT_GT(blocks, 10u);
  for (const auto& b : t["writes"]["block"]) EXPECT_LT(b.get<std::size_t>(), blocks);
  EXPECT_EQ(rebuild(t, blocks), truth_after(program, blocks, {}));
}

// The system variables a program reads, by hand: G00 to X10 Y20 from the origin (G54 all zero,
// no tool offset), so #5001 (end point, first axis X) is 10 and #5002 20; the G02 makes #4001
// (group 1) read 2: #100 = 10 + 10 = 20, #101 = 2 + 20 + 20 = 42. The same variable read twice with one value in one block is one record; a
// local or common read is not a system read.
TEST(Trace, SystemVariablesRead) {
  const json answer = traced(
      "G90 G00 X10. Y20.\n"          // block 0
      "#100=#5001+#5001\n"           // block 1: #5001 = 10, one record
      "G02 X30. Y20. R10. F100.\n"   // block 2
      "#101=#4001+#100+#5002\n"      // block 3: #4001 = 2, #5002 = 20
      "#102=#100\n"                  // block 4: no system read
      "M30\n");
  ASSERT_EQ(answer["summary"]["ok"], true) << answer["summary"];
  const json& r = answer["trace"]["reads"];
  EXPECT_EQ(r["block"], json({1, 3, 3}));
  EXPECT_EQ(r["var"], json({5001, 4001, 5002}));
  EXPECT_EQ(r["value"], json({10.0, 2.0, 20.0}));
  EXPECT_EQ(answer["trace"]["writes"]["new"][0], 20.0);  // #100
  EXPECT_EQ(answer["trace"]["writes"]["new"][1], 42.0);  // #101
}

// On a lathe programmed in diameter, #5001 reads X as the program wrote it (a diameter).
TEST(Trace, SystemVariableReadOnALathe) {
  std::ifstream f(std::string(NCURVE_SOURCE_DIR) + "/profiles/fanuc-lathe.toml");
  std::stringstream toml;
  toml << f.rdbuf();
  json req{{"program", "G00 X40. Z5.\n#100=#5001\n#101=#5002\nM30\n"}, {"machine", toml.str()}, {"trace", true}};
  Answer a = api_run(ServeConfig{}, req.dump());
  ASSERT_EQ(a.status, 200) << a.body.substr(0, 400);
  const json r = json::parse(a.body)["trace"]["reads"];
  EXPECT_EQ(r["var"], json({5001, 5002}));
  EXPECT_EQ(r["value"], json({40.0, 5.0}));
}

// Without the trace, a run reads the same values (the observer only watches).
TEST(Trace, ReadsAreOnlyRecordedWithATrace) {
  const std::string program = "G00 X10.\n#100=#5001\nM30\n";
  Answer a = api_run(ServeConfig{}, json{{"program", program}}.dump());
  EXPECT_EQ(json::parse(a.body).count("trace"), 0u);
  EXPECT_EQ(rebuild(traced(program)["trace"], 3)[100], 10.0);
}

// G71 reads its finishing shape (lines 4..6) to make the roughing: the trace shows the G71 block
// (line 3) making every roughing move, then the block after N20 (line 7), as FANUC goes on after
// the shape's last block; G70 runs the shape, so its blocks are in the trace, each with its move.
TEST(Trace, StockRemovalShapeIsTheCycleBlocks) {
  std::ifstream f(std::string(NCURVE_SOURCE_DIR) + "/profiles/fanuc-lathe.toml");
  std::stringstream toml;
  toml << f.rdbuf();
  const std::string program =
      "G99 G00 X40. Z2.\n"             // 1
      "G71 U2. R0.5\n"                 // 2
      "G71 P10 Q20 U0.4 W0.1 F0.2\n"   // 3
      "N10 G00 X20.\n"                 // 4
      "G01 Z-10.\n"                    // 5
      "N20 X42.\n"                     // 6
      "G70 P10 Q20\n"                  // 7
      "M30\n";                         // 8
  json req{{"program", program}, {"machine", toml.str()}, {"trace", true}};
  Answer a = api_run(ServeConfig{}, req.dump());
  ASSERT_EQ(a.status, 200) << a.body.substr(0, 400);
  const json answer = json::parse(a.body);
  ASSERT_EQ(answer["summary"]["ok"], true) << answer["summary"];
  const json& t = answer["trace"];
  EXPECT_EQ(t["blocks"]["line"], json({1, 2, 3, 7, 4, 5, 6, 8}));
  // moves made before each block: line 1 one rapid; G71's moves up to the G70 block; G70 runs the
  // shape, a move a block (G00 X20., G01 Z-10., X42.), then back to the start point by rapid (made
  // by line 7 after its last block, so before M30's)
  const json& first = t["blocks"]["move"];
  const json& lines = answer["moves"]["line"];
  std::size_t roughing = 0;
  for (const auto& l : lines) roughing += l == 3;
  EXPECT_GT(roughing, 3u);
  EXPECT_EQ(first[2], 1);                 // G71 starts after line 1's rapid
  EXPECT_EQ(first[3], 1 + roughing);      // and makes all the roughing
  EXPECT_EQ(first[5].get<int>() - first[4].get<int>(), 1);  // N10 G00 X20.: one move
  EXPECT_EQ(first[6].get<int>() - first[5].get<int>(), 1);  // G01 Z-10.
  EXPECT_EQ(lines[first[4].get<int>()], 4);
}

}  // namespace
}  // namespace ncurve::serve
