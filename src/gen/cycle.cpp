// cycle: a custom G code that calls a macro program in O9010..O9019, which is copied after the
// main program. The spiral is seed 001's G102 (No.6050 = 102 calls O9010), with a chord error
// argument T instead of a fixed angle step; every other curve gets its own cycle (G103 = ellipse
// in O9011 ...), the curve's parameters, its range and the tolerance as arguments, and the
// adaptive macro's loop inside.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "gen/forms.hpp"
#include "gen/macro_library.hpp"

namespace ncurve::gen::detail {
namespace {

double param(const geom::Curve& curve, const char* name) {
  for (const auto& p : curve.params())
    if (p.name == name) return p.value;
  throw std::runtime_error(fmt::format("{}: no parameter {}", curve.name(), name));
}

std::string cycle_text(const Context& c, double chord_error, std::uint32_t& first, std::uint32_t& last) {
  const Options& o = c.o;
  const geom::Vec3 centre = c.map({param(c.curve, "cx"), param(c.curve, "cy"), 0});
  Writer w;
  w.block("%");
  w.lines(header(c.curve, o, "G102 spiral cycle, chord error argument T"));
  w.block("(PARAMETER SETTING: NO.6050 = 102, G102 CALLS O9010)");
  w.block("(O9010 FOLLOWS THIS PROGRAM; NCURVE MACROS/O9010.NC)");
  begin_setup(w, o, c.dec);
  begin_passes(w, o, c.dec);
  modes_block(w, o);
  Frame fr = frame(o, c.words, c.start, c.end, c.dec, c.feed);
  w.lines(fr.before_start);
  w.lines(fr.to_depth);
  const bool clockwise = c.curve.name() == "spiral-cw";
  w.block(fmt::format("G102 X{} Y{} I{} J{} Q{} T{}{} F{}", number(c.end[0], c.dec), number(c.end[1], c.dec),
                      number(centre[0] - c.start[0], c.dec), number(centre[1] - c.start[1], c.dec),
                      number(param(c.curve, "pitch"), 6), number(chord_error, 6), clockwise ? " D2" : "",
                      feed_number(o, c.feed)));
  w.lines(fr.retract);
  end_passes(w, o);
  end_setup(w, o);
  w.block("M30");
  first = w.line + 1;
  std::string macro = o9010_text();  // one tape: the macro's own % lines go
  for (std::size_t pos; (pos = macro.find("%\n")) != std::string::npos;) macro.erase(pos, 2);
  w.lines(macro);
  last = w.line;
  w.block("%");
  return w.text;
}

// Local variables of the argument letters (argument specification I).
int local_of(char letter) {
  static constexpr std::string_view kLetters = "ABCIJKDEFHMQRSTUVWXYZ";
  static constexpr int kLocals[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 13, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
  return kLocals[kLetters.find(letter)];
}

// The curve's parameters as argument letters: the name's initial where it is free, else the next
// free one (E, F, S, T are the cycle's own; G L N O P are not arguments).
std::vector<std::pair<const geom::Curve::Param*, char>> argument_letters(const geom::Curve& curve) {
  static constexpr std::string_view kPool = "ABCDHIJKMQRUVWXYZ";
  std::string used;
  std::vector<std::pair<const geom::Curve::Param*, char>> out;
  for (const auto& p : curve.params()) {
    char initial = static_cast<char>(std::toupper(static_cast<unsigned char>(p.name.empty() ? 'A' : p.name[0])));
    char letter = 0;
    if (kPool.find(initial) != std::string_view::npos && used.find(initial) == std::string::npos) letter = initial;
    for (char l : kPool)
      if (!letter && used.find(l) == std::string::npos) letter = l;
    if (!letter) throw std::runtime_error(fmt::format("{}: too many parameters for a cycle's arguments", curve.name()));
    used += letter;
    out.emplace_back(&p, letter);
  }
  return out;
}

// The curves' places in O9010..O9019 (No.6050..6059, G102..G111).
int default_program(const std::string& curve) {
  static const std::pair<const char*, int> kSlots[] = {
      {"spiral", 9010},   {"spiral-cw", 9010}, {"ellipse", 9011}, {"parabola", 9012}, {"hyperbola", 9013},
      {"involute", 9014}, {"sine", 9015},      {"cycloid", 9016}, {"trochoid", 9017}, {"helix", 9018},
      {"rotor", 9019}};
  for (const auto& [name, program] : kSlots)
    if (curve == name) return program;
  return 9019;
}

struct Slot {
  int program, g, parameter;
};
Slot slot_of(const Context& c) {
  int program = c.o.cycle_program ? c.o.cycle_program : default_program(c.curve.name());
  if (program < 9010 || program > 9019)
    throw std::runtime_error(fmt::format("the cycle's program must be O9010..O9019 (No.6050..6059), not O{}", program));
  return {program, 102 + program - 9010, 6050 + program - 9010};
}

// The curve cycle's macro program: arguments checked, copied to the curve's variables, then the
// adaptive loop with the tolerance T.
std::string curve_macro(const Context& c, const Slot& slot, std::uint32_t first_line, std::uint32_t& contour_line) {
  const auto letters = argument_letters(c.curve);
  const geom::CurveSpec* spec = geom::find_curve(c.curve.name());
  const std::string t_doc = spec ? spec->t_doc : "t";
  const std::string rounding = number(c.fit.grid.worst_error(), 9);
  Writer w;
  w.line = first_line - 1;
  w.block(fmt::format("O{} (G{} {} CYCLE)", slot.program, slot.g, comment_text(c.curve.name())));
  std::string call = fmt::format("G{}", slot.g);
  for (const auto& [p, l] : letters) call += fmt::format(" {}_", l);
  w.block(fmt::format("(CALL: {} S_ E_ T_ [F_] WITH NO.{} = {}, FROM THE CURVE POINT AT S)", call, slot.parameter,
                      slot.g));
  for (const auto& [p, l] : letters)
    w.block(fmt::format("(#{:<3} {}  {}: {})", local_of(l), l, comment_text(p->name), comment_text(p->doc)));
  w.block(fmt::format("(#19  S  T START; #8 E T END: {})", comment_text(t_doc)));
  w.block(fmt::format("(#20  T  TOLERANCE, MM, ABOVE THE ROUNDING {})", rounding));
  w.block("(#9   F  FEED)");
  w.block("(WORK: LOCALS #1-#33 AFTER THE ARGUMENTS ARE READ, COMMONS #100-#199)");
  for (const auto& [p, l] : letters) w.block(fmt::format("IF [#{} EQ #0] GOTO 901", local_of(l)));
  w.block("IF [#19 EQ #0] GOTO 901");
  w.block("IF [#8 EQ #0] GOTO 901");
  w.block("IF [#8 LE #19] GOTO 901");
  w.block("IF [#20 EQ #0] GOTO 901");
  w.block(fmt::format("IF [#20 LE {}] GOTO 901", rounding));
  w.block("IF [#9 EQ #0] GOTO 1");
  w.block("G01 F#9");
  w.block("N1 #110=#19 (T START)");
  w.block("#111=#8 (T END)");
  for (const auto& [p, l] : letters) w.block(fmt::format("#{}=#{} ({})", p->var, local_of(l), comment_text(p->name)));
  w.block(fmt::format("#2=#20-{} (VERTEX OFFSET OUTWARD)", rounding));
  w.block("#1=#20 (AIM: DEVIATION AT A STEP'S MIDDLE)");
  w.block("#3=[#111-#110]/4 (LONGEST T STEP)");
  w.block("#13=[#111-#110]/64 (T STEP TRIED FIRST)");
  adaptive_start(w);
  contour_line = adaptive_loop(w, c, "");
  w.block("M99");
  w.block(fmt::format("N901 #3000=1 (G{} ARGUMENT MISSING OR OUT OF RANGE)", slot.g));
  return w.text;
}

std::string curve_cycle_text(const Context& c, const Slot& slot, double tolerance, std::uint32_t& first,
                             std::uint32_t& last, std::string& macro) {
  const Options& o = c.o;
  Writer w;
  w.block("%");
  w.lines(header(c.curve, o, fmt::format("G{} cycle, tolerance argument T", slot.g)));
  w.block(fmt::format("(PARAMETER SETTING: NO.{} = {}, G{} CALLS O{})", slot.parameter, slot.g, slot.g, slot.program));
  w.block(fmt::format("(O{} FOLLOWS THIS PROGRAM)", slot.program));
  begin_setup(w, o, c.dec);
  begin_passes(w, o, c.dec);
  modes_block(w, o);
  Frame fr = frame(o, c.words, c.start, c.end, c.dec, c.feed);
  w.lines(fr.before_start);
  w.lines(fr.to_depth);
  std::string call = fmt::format("G{}", slot.g);
  for (const auto& [p, l] : argument_letters(c.curve)) call += fmt::format(" {}{}", l, number(p->value, 9));
  call += fmt::format(" S{} E{} T{} F{}", number(c.curve.t0(), 9), number(c.curve.t1(), 9), number(tolerance, 6),
                      feed_number(o, c.feed));
  w.block(call);
  w.lines(fr.retract);
  end_passes(w, o);
  end_setup(w, o);
  w.block("M30");
  std::uint32_t contour = 0;
  macro = curve_macro(c, slot, w.line + 1, contour);
  w.lines(macro);
  first = last = contour;
  w.block("%");
  macro = "%\n" + macro + "%\n";
  return w.text;
}

double millionths(double v) { return std::floor(v * 1e6) / 1e6; }

}  // namespace

Emitted cycle(const Context& c) {
  if (c.o.tool_radius > 0)
    throw std::runtime_error(
        "the cycle form programs the contour itself: without --tool-radius (the control's G41/G42 offsets the cutter)");
  const double rounding = c.fit.grid.worst_error();
  double chord_error = millionths(c.fit.tol - rounding);
  if (!(chord_error > 0))
    throw std::runtime_error(fmt::format("tolerance {} mm is not above the coordinate rounding ({:.6f} mm)", c.o.tol,
                                         rounding));
  const bool spiral = c.curve.name() == "spiral" || c.curve.name() == "spiral-cw";
  if (spiral && c.o.cycle_program && c.o.cycle_program != 9010)
    throw std::runtime_error("the spiral's cycle is G102 in O9010");
  const Slot slot = slot_of(c);
  Options with_cycle = c.measured_o;
  with_cycle.profile.g_code_macros[static_cast<std::size_t>(slot.program - 9010)] = slot.g;
  // the largest T argument (in millionths) whose cycle the round trip finds within the tolerance
  const std::string failure =
      fmt::format("the G{} cycle does not meet the tolerance on this curve; use adaptive-macro", slot.g);
  auto with_parameter = [&](Emitted e) {
    e.parameters = {{std::to_string(slot.parameter), slot.g}};
    return e;
  };
  if (spiral) {
    if (is_lathe(c.o)) throw std::runtime_error("the G102 spiral cycle is for the mill (XY plane)");
    // O9010's step is from the local circle of curvature: tighten T if the control's path is not
    // within the tolerance
    return tightened(c, with_cycle, chord_error, millionths, [&](double t) {
      Emitted e;
      e.macro = o9010_text();
      e.text = cycle_text(c, t, e.first, e.last);
      return with_parameter(std::move(e));
    }, failure);
  }
  // the curve cycles' T is the tolerance itself
  return tightened(c, with_cycle, millionths(c.fit.tol), millionths, [&](double t) {
    Emitted e;
    e.text = curve_cycle_text(c, slot, t, e.first, e.last, e.macro);
    return with_parameter(std::move(e));
  }, failure);
}

}  // namespace ncurve::gen::detail
