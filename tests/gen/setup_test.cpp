// gen's program set-up and end (Options::tool, spindle, css, coolant): the blocks FANUC programs
// carry, once, in their place, and the program still runs and meets the tolerance in every form.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  for (std::size_t eol; (eol = text.find('\n', pos)) != std::string::npos; pos = eol + 1)
    out.push_back(text.substr(pos, eol - pos));
  return out;
}

std::size_t count(const std::vector<std::string>& lines, const std::string& line) {
  return static_cast<std::size_t>(std::count(lines.begin(), lines.end(), line));
}

// the lines from the one after the header comments (the first not "%", "O.." or "(..") on
std::vector<std::string> body(const std::string& text) {
  auto lines = lines_of(text);
  auto first = std::find_if(lines.begin(), lines.end(),
                            [](const std::string& l) { return l != "%" && l[0] != 'O' && l[0] != '('; });
  return {first, lines.end()};
}

std::vector<machine::Move> events(const test::Ran& ran, machine::MoveKind kind) {
  std::vector<machine::Move> out;
  for (const auto& m : ran.moves)
    if (m.kind == kind) out.push_back(m);
  return out;
}

}  // namespace

TEST(GenSetup, WithoutOptionsTheProgramOpensWithItsModesAndTheApproach) {
  const geom::Curve ellipse(*geom::find_curve("ellipse"), {});
  const auto lines = body(gen::generate(ellipse, gen::Options{}).text);
  ASSERT_GE(lines.size(), 4u);
  EXPECT_EQ(lines[0], "G21 G17 G90 G94 G54");
  EXPECT_EQ(lines[1], "G00 Z5.");
  EXPECT_EQ(lines[2], "X40. Y0.");
  EXPECT_EQ(lines[3], "G01 Z-1. F200.");
  EXPECT_EQ(lines[lines.size() - 3], "G00 Z5.");
  EXPECT_EQ(lines[lines.size() - 2], "M30");
}

TEST(GenSetup, MillToolSpindleAndCoolantOnceInEveryForm) {
  const geom::Curve ellipse(*geom::find_curve("ellipse"), {});
  for (gen::Form form : {gen::Form::expanded, gen::Form::arcs, gen::Form::macro, gen::Form::adaptive_macro,
                         gen::Form::cycle}) {
    for (const double step_down : {0.0, 0.4}) {
      SCOPED_TRACE(fmt::format("{} step-down {}", gen::to_string(form), step_down));
      gen::Options o;
      o.form = form;
      o.step_down = step_down;
      o.tool = 3;
      o.spindle = 2400;
      o.coolant = true;
      const gen::Result r = gen::generate(ellipse, o);
      EXPECT_TRUE(r.within_tolerance);
      // the set-up after the header, before any depth-pass loop: done once
      const auto lines = body(r.text);
      ASSERT_GE(lines.size(), 5u);
      EXPECT_EQ(lines[0], "G21 G17 G90 G94 G54");
      EXPECT_EQ(lines[1], "T3 M06");
      EXPECT_EQ(lines[2], "S2400 M03");
      EXPECT_EQ(lines[3], "G00 G43 Z5. H3");  // the tool length offset, at the clearance plane
      EXPECT_EQ(lines[4], "M08");
      EXPECT_EQ(count(lines, "G21 G17 G90 G94 G54"), 1u);
      const auto m30 = std::find(lines.begin(), lines.end(), "M30");
      ASSERT_NE(m30, lines.end());
      ASSERT_GE(m30 - lines.begin(), 2);
      EXPECT_EQ(*(m30 - 2), "M09");
      EXPECT_EQ(*(m30 - 1), "M05");
      // as the control runs it: one tool change to T3, the spindle on then off, coolant on then off,
      // and the contour cut at 2400 rev/min
      for (const auto& [key, value] : r.parameters) machine::set_parameter(o.profile, key, value);
      const auto ran = test::run(r.text, o.profile);
      ASSERT_TRUE(ran.result.ok());
      const auto tools = events(ran, machine::MoveKind::tool_change);
      ASSERT_EQ(tools.size(), 1u);
      EXPECT_EQ(tools[0].code, 3);
      const auto spindle = events(ran, machine::MoveKind::spindle);
      ASSERT_EQ(spindle.size(), 2u);
      EXPECT_EQ(spindle[0].code, 3);
      EXPECT_EQ(spindle[1].code, 5);
      const auto coolant = events(ran, machine::MoveKind::coolant);
      ASSERT_EQ(coolant.size(), 2u);
      EXPECT_EQ(coolant[0].code, 8);
      EXPECT_EQ(coolant[1].code, 9);
      for (const auto& m : ran.motions())
        if (m.kind != machine::MoveKind::rapid) {
          EXPECT_EQ(m.spindle, 2400);
        }
    }
  }
}

TEST(GenSetup, LatheTurretSurfaceSpeedAndClamp) {
  geom::Curve hyperbola(*geom::find_curve("hyperbola"), {});
  for (gen::Form form : {gen::Form::expanded, gen::Form::arcs, gen::Form::macro, gen::Form::adaptive_macro,
                         gen::Form::cycle}) {
    SCOPED_TRACE(gen::to_string(form));
    gen::Options o;
    o.form = form;
    o.profile = machine::default_lathe();
    o.tool = 2;
    o.css = 180;
    o.max_rpm = 3000;
    o.spindle_ccw = true;
    o.coolant = true;
    const gen::Result r = gen::generate(hyperbola, o);
    EXPECT_TRUE(r.within_tolerance);
    const auto lines = body(r.text);
    ASSERT_GE(lines.size(), 5u);
    EXPECT_EQ(lines[0], "G21 G18 G99");
    EXPECT_EQ(lines[1], "T0202");         // tool 2, offset 2
    EXPECT_EQ(lines[2], "G50 S3000");     // the clamp before G96 (G-code system A)
    EXPECT_EQ(lines[3], "G96 S180 M04");
    EXPECT_EQ(lines[4], "M08");
    for (const auto& [key, value] : r.parameters) machine::set_parameter(o.profile, key, value);
    const auto ran = test::run(r.text, o.profile);
    ASSERT_TRUE(ran.result.ok());
    const auto tools = events(ran, machine::MoveKind::tool_change);
    ASSERT_EQ(tools.size(), 1u);
    EXPECT_EQ(tools[0].code, 202);
    EXPECT_EQ(events(ran, machine::MoveKind::spindle).front().code, 4);
  }
  // a spindle speed in rev/min on a lathe cancels the surface speed: G97
  gen::Options o;
  o.profile = machine::default_lathe();
  o.spindle = 1200;
  const auto lines = body(gen::generate(hyperbola, o).text);
  EXPECT_EQ(lines[1], "G97 S1200 M03");
  // systems B and C clamp with G92
  o.spindle = 0;
  o.css = 150;
  o.max_rpm = 2500;
  o.profile.gcode_system = 'B';
  const auto b = body(gen::generate(hyperbola, o).text);
  EXPECT_EQ(b[0], "G21 G18 G90 G95");
  EXPECT_EQ(b[1], "G92 S2500");
  EXPECT_EQ(b[2], "G96 S150 M03");
}

TEST(GenSetup, OptionsThatDoNotGoTogetherAreRefused) {
  const geom::Curve ellipse(*geom::find_curve("ellipse"), {});
  auto refused = [&](gen::Options o) -> std::string {
    try {
      gen::generate(ellipse, o);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  };
  gen::Options css_on_mill;
  css_on_mill.css = 100;
  EXPECT_EQ(refused(css_on_mill), "a constant surface speed (G96) is for the lathe; give the spindle speed");
  gen::Options both;
  both.profile = machine::default_lathe();
  both.css = 100;
  both.spindle = 1000;
  EXPECT_EQ(refused(both), "give the spindle speed or a constant surface speed (G96), not both");
  gen::Options clamp_alone;
  clamp_alone.max_rpm = 3000;
  EXPECT_EQ(refused(clamp_alone), "the spindle clamp is for a constant surface speed (G96)");
  gen::Options direction_alone;
  direction_alone.spindle_ccw = true;
  EXPECT_EQ(refused(direction_alone), "the spindle's direction needs its speed");
  gen::Options lathe_tool;
  lathe_tool.profile = machine::default_lathe();
  lathe_tool.tool = 65;
  EXPECT_EQ(refused(lathe_tool), "the tool must be 1..64 on a lathe (T with the offset of the same number), not 65");
}
