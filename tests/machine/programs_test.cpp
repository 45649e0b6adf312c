// Hand-checked programs: each tests/programs/FEATURE/NAME.expected.moves lists the motions a FANUC
// control makes for NAME.nc, worked out from the manuals' rules (see its header). NAME.toml is the
// machine, a "(PARAM n=v)" comment sets a parameter. Lathe X is a diameter in the file.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "support/run_program.hpp"

using namespace ncurve;
namespace fs = std::filesystem;

namespace {

struct Expected {
  std::uint32_t line;
  std::string kind;
  double x, y, z;
  bool arc = false;
  double cx = 0, cy = 0, cz = 0;
  std::string dir;
  std::vector<std::pair<int, double>> rotary;  // "A=90" after x y z: A, B or C at the end
  double value = 0;                           // events: the M code (spindle, program_stop) or the dwell in s
};

bool is_event(const std::string& kind) {
  return kind == "spindle" || kind == "coolant" || kind == "dwell" || kind == "program_stop";
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void check_program(const fs::path& expected_file) {
  const std::string name = expected_file.filename().string().substr(0, expected_file.filename().string().find('.'));
  const fs::path dir = expected_file.parent_path();
  SCOPED_TRACE(name);
  machine::MachineProfile profile = machine::default_mill();
  if (fs::exists(dir / (name + ".toml"))) profile = machine::load_profile((dir / (name + ".toml")).string());
  const std::string text = slurp(dir / (name + ".nc"));
  std::smatch m;
  std::string rest = text;
  static const std::regex param(R"(\(PARAM ([0-9#]+)=([-0-9.]+)\))");
  while (std::regex_search(rest, m, param)) {
    machine::set_parameter(profile, m[1].str(), std::stod(m[2].str()));
    rest = m.suffix();
  }
  std::vector<Expected> want;
  bool events = false;  // the file lists spindle events, dwells and stops too
  std::istringstream lines(slurp(expected_file));
  for (std::string l; std::getline(lines, l);) {
    if (l.empty() || l[0] == '#') continue;
    std::istringstream row(l);
    Expected e;
    row >> e.line >> e.kind;
    if (is_event(e.kind)) {  // "12 spindle 19", "12 dwell 0.5"
      row >> e.value;
      events = true;
      want.push_back(e);
      continue;
    }
    row >> e.x >> e.y >> e.z;
    std::vector<std::string> rest;
    for (std::string t; row >> t;) {
      if (t.size() > 2 && t[1] == '=' && machine::axis_index(t[0]) >= 3) e.rotary.emplace_back(machine::axis_index(t[0]), std::stod(t.substr(2)));
      else rest.push_back(t);
    }
    if (rest.size() == 4) {
      e.cx = std::stod(rest[0]), e.cy = std::stod(rest[1]), e.cz = std::stod(rest[2]), e.dir = rest[3];
      e.arc = true;
    }
    want.push_back(e);
  }
  machine::ProgramLibrary lib(profile.parse_options());
  lib.add_file((dir / (name + ".nc")).string(), true);
  machine::Interpreter interp(profile, lib);
  test::Collect sink;
  auto result = interp.run(sink);
  ASSERT_TRUE(result.ok()) << nc::format(*result.alarm);
  std::vector<machine::Move> got;
  for (const auto& mv : sink.moves)
    if (mv.is_motion() || (events && is_event(machine::to_string(mv.kind)))) got.push_back(mv);
  const double xs = profile.lathe() && profile.diameter_x ? 2 : 1;
  std::string listing;
  for (const auto& mv : got)
    listing += mv.is_motion() ? fmt::format("{} {} {:.4f} {:.4f} {:.4f} A={:.4f}\n", mv.line, machine::to_string(mv.kind),
                                            mv.end[0] * xs, mv.end[1], mv.end[2], mv.end[3])
                              : fmt::format("{} {} {}\n", mv.line, machine::to_string(mv.kind),
                                            mv.kind == machine::MoveKind::dwell ? mv.seconds : mv.code);
  ASSERT_EQ(got.size(), want.size()) << listing;
  for (std::size_t i = 0; i < want.size(); ++i) {
    const auto& e = want[i];
    const auto& g = got[i];
    SCOPED_TRACE(fmt::format("move {} (expected line {} {})\n{}", i, e.line, e.kind, listing));
    EXPECT_EQ(g.line, e.line);
    EXPECT_EQ(machine::to_string(g.kind), e.kind);
    if (is_event(e.kind)) {
      EXPECT_NEAR(g.kind == machine::MoveKind::dwell ? g.seconds : g.code, e.value, 1e-9);
      continue;
    }
    for (auto [axis, v] : e.rotary) EXPECT_NEAR(g.end[axis], v, 6e-4) << "axis " << "XYZABC"[axis];
    EXPECT_NEAR(g.end[0] * xs, e.x, 6e-4);
    EXPECT_NEAR(g.end[1], e.y, 6e-4);
    EXPECT_NEAR(g.end[2], e.z, 6e-4);
    if (e.arc) {
      EXPECT_NEAR(g.center[0] * xs, e.cx, 6e-4);
      EXPECT_NEAR(g.center[1], e.cy, 6e-4);
      EXPECT_NEAR(g.center[2], e.cz, 6e-4);
      EXPECT_EQ(g.clockwise ? "G02" : "G03", e.dir);
    }
  }
}

std::vector<fs::path> expected_files() {
  std::vector<fs::path> files;
  // a test is named by NAME alone (Programs/HandChecked.MovesAsWorkedOut/NAME), whatever its folder
  for (const auto& f : fs::recursive_directory_iterator(fs::path(NCURVE_SOURCE_DIR) / "tests" / "programs"))
    if (f.path().string().ends_with(".expected.moves")) files.push_back(f.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

class HandChecked : public ::testing::TestWithParam<fs::path> {};

TEST_P(HandChecked, MovesAsWorkedOut) { check_program(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Programs, HandChecked, ::testing::ValuesIn(expected_files()),
                         [](const ::testing::TestParamInfo<fs::path>& info) {
                           std::string n = info.param.filename().string();
                           return n.substr(0, n.find('.'));
                         });
