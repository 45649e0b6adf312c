// cycle: a custom G code that calls a macro program in O9010..O9019, which is copied after the
// main program. The spiral is seed 001's G102 (No.6050 = 102 calls O9010), with a chord error
// argument T instead of a fixed angle step; every other curve gets its own cycle (G103 = ellipse
// in O9011 ...), the curve's parameters, its range and the chord error as arguments, and the
// adaptive macro's step from the curvature inside.
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
  begin_passes(w, o, c.dec);
  w.block(modes(o));
  Frame fr = frame(o, c.words, c.start, c.end, c.dec, c.feed);
  w.lines(fr.before_start);
  w.lines(fr.to_depth);
  const bool clockwise = c.curve.name() == "spiral-cw";
  w.block(fmt::format("G102 X{} Y{} I{} J{} Q{} T{}{} F{}", number(c.end[0], c.dec), number(c.end[1], c.dec),
                      number(centre[0] - c.start[0], c.dec), number(centre[1] - c.start[1], c.dec),
                      number(param(c.curve, "pitch"), 6), number(chord_error, 6), clockwise ? " D2" : "",
                      number(c.feed, 4)));
  w.lines(fr.retract);
  end_passes(w, o);
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

// The chord error the macro aims at, a first step shorter by this (its start is on the curve, not
// on the band) and no step longer than this part of the range.
constexpr double kFirstMove = 0.85;
constexpr double kLongestStep = 0.125;

// The curve cycle's macro program: arguments checked, copied to the curve's variables, then the
// adaptive loop with the rule from the chord error T.
std::string curve_macro(const Context& c, const Slot& slot, std::uint32_t first_line, std::uint32_t& contour_line) {
  const auto letters = argument_letters(c.curve);
  const geom::CurveSpec* spec = geom::find_curve(c.curve.name());
  const std::string t_doc = spec ? spec->t_doc : "t";
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
  w.block("(#20  T  CHORD ERROR, MM: EACH STEP FROM THE CURVATURE)");
  w.block("(#9   F  FEED)");
  w.block("(WORK: COMMON VARIABLES #100-#199)");
  for (const auto& [p, l] : letters) w.block(fmt::format("IF [#{} EQ #0] GOTO 901", local_of(l)));
  w.block("IF [#19 EQ #0] GOTO 901");
  w.block("IF [#8 EQ #0] GOTO 901");
  w.block("IF [#8 LE #19] GOTO 901");
  w.block("IF [#20 EQ #0] GOTO 901");
  w.block("IF [#20 LE 0] GOTO 901");
  w.block("IF [#9 EQ #0] GOTO 1");
  w.block("G01 F#9");
  w.block("N1 #110=#19 (T START)");
  w.block("#111=#8 (T END)");
  for (const auto& [p, l] : letters) w.block(fmt::format("#{}=#{} ({})", p->var, local_of(l), comment_text(p->name)));
  // the band: vertices T outward, chords' middle T inward (a space curve: chords of sag T)
  w.block(c.with_z ? "#115=0" : "#115=#20 (VERTEX OFFSET OUTWARD)");
  w.block(c.with_z ? "#116=SQRT[8*#20] (STEP FACTOR: CHORD = #116/SQRT[CURVATURE])"
                   : "#116=4*SQRT[#20] (STEP FACTOR: CHORD = #116/SQRT[CURVATURE])");
  w.block("#117=0.000000001 (LEAST CURVATURE)");
  w.block(fmt::format("#132=[#111-#110]*{} (LONGEST T STEP)", number(kLongestStep, 6)));
  w.block("#100=#110");
  int next = kFirstTemp;
  auto curvature_at_100 = [&] {
    next = kFirstTemp;
    for (const auto& b : curvature_blocks(c, next)) w.block(b);
  };
  curvature_at_100();
  w.block("#118=#127");
  w.block("#119=#128");
  w.block("IF [#119 LT #117] THEN #119=#117");
  w.block(fmt::format("#129=#116/SQRT[#119]/#126*{} (FIRST STEP, x1.5 NEXT)", number(kFirstMove / 1.5, 12)));
  w.block("WHILE [#100 LT #111] DO1");
  step_blocks(w);
  w.block("IF [#129 GT #132] THEN #129=#132");
  // corrected (twice at most) by the curvature and speed at the middle of the step: the rule
  // above extrapolates from behind, which misses an inflection ahead or a quickly changing speed
  w.block("#135=#100 (T AT THE LAST VERTEX)");
  w.block("#134=1");
  w.block("WHILE [#134 LE 2] DO2");
  w.block("#100=#135+0.5*#129");
  curvature_at_100();
  w.block("IF [#128 LT #119] THEN #128=#119");
  w.block("#131=#116/SQRT[#128]/#126");
  w.block("#134=#134+1");
  w.block("IF [#131 GE #129] THEN #134=3");
  w.block("IF [#131 LT #129] THEN #129=#131");
  w.block("END2");
  w.block("#100=#135");
  // the last move ends on the curve: no longer than the first; one before it takes what is over
  w.block(fmt::format("#133=#111-#100-{}*#129", number(kFirstMove, 6)));
  w.block("IF [#133 LT #129] THEN #129=#133");
  w.block("IF [#133 LE 0] THEN #129=#111-#100");
  w.block("#100=#100+#129");
  w.block("IF [#100 GT #111] THEN #100=#111");
  curvature_at_100();
  MacroWords move = macro_words(vertex_axes(c), next);
  for (const auto& a : move.assignments) w.block(a);
  w.block(fmt::format("G01 {}", move.words));
  contour_line = w.line;
  w.block("END1");
  w.block("M99");
  w.block(fmt::format("N901 #3000=1 (G{} ARGUMENT MISSING OR OUT OF RANGE)", slot.g));
  return w.text;
}

std::string curve_cycle_text(const Context& c, const Slot& slot, double chord_error, std::uint32_t& first,
                             std::uint32_t& last, std::string& macro) {
  const Options& o = c.o;
  Writer w;
  w.block("%");
  w.lines(header(c.curve, o, fmt::format("G{} cycle, chord error argument T", slot.g)));
  w.block(fmt::format("(PARAMETER SETTING: NO.{} = {}, G{} CALLS O{})", slot.parameter, slot.g, slot.g, slot.program));
  w.block(fmt::format("(O{} FOLLOWS THIS PROGRAM)", slot.program));
  begin_passes(w, o, c.dec);
  w.block(modes(o));
  Frame fr = frame(o, c.words, c.start, c.end, c.dec, c.feed);
  w.lines(fr.before_start);
  w.lines(fr.to_depth);
  std::string call = fmt::format("G{}", slot.g);
  for (const auto& [p, l] : argument_letters(c.curve)) call += fmt::format(" {}{}", l, number(p->value, 9));
  call += fmt::format(" S{} E{} T{} F{}", number(c.curve.t0(), 9), number(c.curve.t1(), 9), number(chord_error, 6),
                      number(c.feed, 4));
  w.block(call);
  w.lines(fr.retract);
  end_passes(w, o);
  w.block("M30");
  std::uint32_t contour = 0;
  macro = curve_macro(c, slot, w.line + 1, contour);
  w.lines(macro);
  first = last = contour;
  w.block("%");
  macro = "%\n" + macro + "%\n";
  return w.text;
}

// The largest chord error (in millionths) whose cycle the round trip finds within the tolerance.
template <class Text>
Emitted tightened(const Context& c, const Options& with_cycle, const Slot& slot, double chord_error, Text text) {
  for (int attempt = 0; attempt < 12; ++attempt, chord_error = std::floor(chord_error * 0.9 * 1e6) / 1e6) {
    if (!(chord_error > 0)) break;
    Emitted e;
    e.text = text(chord_error, e.first, e.last, e.macro);
    e.parameters = {{std::to_string(slot.parameter), slot.g}};
    Stats s = round_trip(e.text, c.curve, with_cycle, e.first, e.last);
    if (s.max_deviation <= c.o.tol) return e;
  }
  throw std::runtime_error(
      fmt::format("the G{} cycle does not meet the tolerance on this curve; use adaptive-macro", slot.g));
}

}  // namespace

Emitted cycle(const Context& c) {
  if (c.o.tool_radius > 0)
    throw std::runtime_error(
        "the cycle form programs the contour itself: without --tool-radius (the control's G41/G42 offsets the cutter)");
  const double rounding = c.fit.grid.worst_error();
  double chord_error = std::floor((c.fit.tol - rounding) * 1e6) / 1e6;
  if (!(chord_error > 0))
    throw std::runtime_error(fmt::format("tolerance {} mm is not above the coordinate rounding ({:.6f} mm)", c.o.tol,
                                         rounding));
  const bool spiral = c.curve.name() == "spiral" || c.curve.name() == "spiral-cw";
  if (spiral && c.o.cycle_program && c.o.cycle_program != 9010)
    throw std::runtime_error("the spiral's cycle is G102 in O9010");
  const Slot slot = slot_of(c);
  Options with_cycle = c.o;
  with_cycle.profile.g_code_macros[static_cast<std::size_t>(slot.program - 9010)] = slot.g;
  if (spiral) {
    if (is_lathe(c.o)) throw std::runtime_error("the G102 spiral cycle is for the mill (XY plane)");
    // O9010's step is from the local circle of curvature: tighten T if the control's path is not
    // within the tolerance
    return tightened(c, with_cycle, slot, chord_error,
                     [&](double t, std::uint32_t& first, std::uint32_t& last, std::string& macro) {
                       macro = o9010_text();
                       return cycle_text(c, t, first, last);
                     });
  }
  return tightened(c, with_cycle, slot, chord_error,
                   [&](double t, std::uint32_t& first, std::uint32_t& last, std::string& macro) {
                     return curve_cycle_text(c, slot, t, first, last, macro);
                   });
}

}  // namespace ncurve::gen::detail
