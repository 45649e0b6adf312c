// cycle: the spiral as seed 001's custom G code, G102 (No.6050 = 102 calls O9010), with a chord
// error argument T instead of a fixed angle step; O9010 is copied after the main program.
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

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

}  // namespace

Emitted cycle(const Context& c) {
  if ((c.curve.name() != "spiral" && c.curve.name() != "spiral-cw") || c.o.tool_radius > 0 || is_lathe(c.o))
    throw std::runtime_error(
        "the cycle form is the G102 spiral cycle (macros/O9010.nc): for the built-in spiral or spiral-cw on a mill, "
        "without a tool radius; use adaptive-macro for other curves");
  const double rounding = c.fit.grid.worst_error();
  double chord_error = std::floor((c.fit.tol - rounding) * 1e6) / 1e6;
  if (!(chord_error > 0))
    throw std::runtime_error(fmt::format("tolerance {} mm is not above the coordinate rounding ({:.6f} mm)", c.o.tol,
                                         rounding));
  Options with_cycle = c.o;
  with_cycle.profile.g_code_macros[0] = 102;
  // O9010's step is from the local circle of curvature: check it, and tighten T if the
  // control's path is not within the tolerance
  for (int attempt = 0; attempt < 8; ++attempt, chord_error = std::floor(chord_error * 0.9 * 1e6) / 1e6) {
    Emitted e;
    e.text = cycle_text(c, chord_error, e.first, e.last);
    e.parameters = {{"6050", 102}};
    Stats s = round_trip(e.text, c.curve, with_cycle, e.first, e.last);
    if (s.max_deviation <= c.o.tol) return e;
  }
  throw std::runtime_error("the G102 cycle does not meet the tolerance on this spiral");
}

}  // namespace ncurve::gen::detail
