#include "gen/generate.hpp"


#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>

#include "base/bounds.hpp"
#include "base/memory.hpp"
#include "base/parallel.hpp"
#include "gen/forms.hpp"
#include "gen/measure.hpp"
#include "gen/measure_beside.hpp"
#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "report/summary.hpp"

namespace ncurve::gen {
namespace {

using geom::Sym;
using geom::SymOp;
using geom::Vec3;
using namespace detail;

}  // namespace

const char* to_string(Form f) {
  switch (f) {
    case Form::expanded: return "expanded";
    case Form::arcs: return "arcs";
    case Form::macro: return "macro";
    case Form::adaptive_macro: return "adaptive-macro";
    case Form::cycle: return "cycle";
  }
  return "";
}

bool parse_form(const std::string& text, Form& out) {
  for (Form f : {Form::expanded, Form::arcs, Form::macro, Form::adaptive_macro, Form::cycle}) {
    if (text == to_string(f)) {
      out = f;
      return true;
    }
  }
  return false;
}

AxisMap axis_map(const geom::Curve& curve, const Options& o) {
  AxisMap m;
  const bool uses_z = !curve.planar_z();
  const bool uses_y = curve.uses_y();
  if (is_lathe(o)) {
    if (uses_y && uses_z) throw std::runtime_error("a lathe cuts plane profiles: the curve uses y and z");
    if (uses_y) m.from = {1, -1, 0};  // profile drawn in x, y: Z along x, X (radius) along y
    else m.from = {0, -1, 2};
    // The imaginary tool tip sits a nose radius from the nose centre along X and Z, as the
    // control's tool-nose compensation places it.
    if (o.tip < 0 || o.tip > 9) throw std::runtime_error("the imaginary tool nose direction is 0..9");
    const machine::TipDirection d = machine::tip_direction(o.tip);
    if (o.tool_radius > 0) m.offset = {d.x * o.tool_radius, 0, d.z * o.tool_radius};
    return m;
  }
  if (!uses_z) {
    m.from = {0, 1, -1};
    m.offset = {0, 0, -o.depth};
  }
  return m;
}

geom::Plane plane_of(const machine::MachineProfile& p) {
  if (p.lathe()) return geom::Plane{2, 0};  // G18: Z, X
  return geom::Plane{0, 1};
}

// Refusal of a program beyond Options::max_moves.
static base::BoundExceeded too_many_moves(const Options& o) {
  return base::BoundExceeded(fmt::format(
      "the program needs more than {} lines or arcs{} within {} mm: raise --max-moves (or --tol, or give a shorter "
      "range of t)",
      o.max_moves, o.step_down > 0 ? " (all depth passes)" : "", o.tol));
}

namespace detail {

// The round trip, taking the measurement of a speculation (may be null) where it fits.
Stats round_trip(const std::string& text, const geom::Curve& curve, const Options& o, std::uint32_t first_line,
                 std::uint32_t last_line, Speculation* speculation);

}  // namespace detail

Stats round_trip(const std::string& text, const geom::Curve& curve, const Options& o, std::uint32_t first_line,
                 std::uint32_t last_line) {
  return detail::round_trip(text, curve, o, first_line, last_line, nullptr);
}

Stats detail::round_trip(const std::string& text, const geom::Curve& curve, const Options& o,
                         std::uint32_t first_line, std::uint32_t last_line, Speculation* speculation) {
  machine::ProgramLibrary lib(o.profile.parse_options());
  lib.add_text("<generated>", text, true);
  // The contour's moves, one group per pass: a feed move outside the contour (the plunge) ends one.
  // Each pass is measured against the curve at the pass's own depth, as far as it can be while
  // the program runs (with a core to spare).
  struct Pass {
    std::vector<ContourMove> moves;
    std::vector<std::size_t> index;  // of each among all the moves the program makes
    std::unique_ptr<Measurer> measurer;
    std::unique_ptr<Ahead> ahead;
  };
  struct Keep final : machine::MoveSink {
    const geom::Curve& curve;
    const Options& o;
    std::uint32_t first, last;
    bool spare_core = base::cores() > 1;
    std::vector<Pass> passes;
    std::size_t moves = 0;
    std::size_t seen = 0;  // moves and events so far
    bool between = true;
    Keep(const geom::Curve& c, const Options& options, std::uint32_t first_line, std::uint32_t last_line)
        : curve(c), o(options), first(first_line), last(last_line) {}
    void on_move(const machine::Move& m) override {
      const std::size_t index = seen++;
      if (m.kind != machine::MoveKind::line && m.kind != machine::MoveKind::arc) return;
      if (m.line < first || m.line > last) {
        between = true;
        return;
      }
      if (between) {
        if (!passes.empty() && passes.back().ahead) passes.back().ahead->stop();
        Pass& pass = passes.emplace_back();
        base::reserve_large(pass.moves, last - first + 1);  // an expanded contour: a move a line
        Options at_depth = o;
        if (detail::depth_passes(o)) at_depth.depth = -m.start[2];
        pass.measurer = std::make_unique<Measurer>(curve, at_depth, true);
      }
      between = false;
      if (++moves > o.max_moves) throw too_many_moves(o);
      Pass& pass = passes.back();
      if (pass.ahead && pass.moves.size() == pass.moves.capacity()) pass.ahead->stop();  // the moves will move
      pass.moves.push_back(ContourMove::of(m));
      pass.index.push_back(index);
      // a long contour (a run done, room for more): measure while the program runs
      if (spare_core && pass.moves.size() == Measurer::kRun + 1 && pass.moves.capacity() > 2 * Measurer::kRun)
        pass.ahead = std::make_unique<Ahead>(*pass.measurer, pass.moves);
      else if (pass.ahead)
        pass.ahead->arrived(pass.moves.size());
    }
  } keep(curve, o, first_line, last_line);
  machine::Interpreter interp(o.profile, lib);
  machine::RunResult r = interp.run(keep);
  for (Pass& pass : keep.passes)
    if (pass.ahead) pass.ahead->stop();
  if (!r.ok()) throw std::runtime_error("the generated program does not run: " + nc::format(*r.alarm));

  if (keep.passes.empty()) throw std::runtime_error("the generated program cuts no contour");
  if (keep.passes.size() > 1 && !detail::depth_passes(o))
    throw std::runtime_error("the generated program cuts its contour more than once");
  // the last pass is the finished contour
  std::vector<Stats> measured;
  std::optional<Stats> speculated;
  if (speculation && keep.passes.size() == 1 && !keep.passes[0].ahead) speculated = speculation->take(keep.passes[0].moves);
  for (Pass& pass : keep.passes) {
    if (speculated)
      measured.push_back(std::move(*speculated));
    else if (pass.ahead)
      measured.push_back(pass.measurer->measure(pass.moves, std::move(pass.ahead->measured()), pass.ahead->starts(),
                                                pass.ahead->ends()));
    else
      measured.push_back(pass.measurer->measure(pass.moves));
  }
  Stats s = measured.back();
  for (const auto& m : measured)
    if (m.max_deviation > s.max_deviation) s.max_deviation = m.max_deviation, s.worst_t = m.worst_t, s.worst_point = m.worst_point;
  s.passes = keep.passes.size();
  for (std::size_t p = 0; p < keep.passes.size(); ++p) {
    const std::vector<std::size_t>& index = keep.passes[p].index;
    s.run_index.insert(s.run_index.end(), index.begin(), index.end());
    s.run_deviation.insert(s.run_deviation.end(), measured[p].move_deviation.begin(), measured[p].move_deviation.end());
  }
  report::SourceStats source = report::source_stats(lib, lib.main()->file.get());  // as `ncurve run` counts
  s.words = source.words;
  s.bytes = source.bytes;
  s.blocks = source.blocks;
  return s;
}

ContourMove ContourMove::of(const machine::Move& m) {
  return {{m.start[0], m.start[1], m.start[2]}, {m.end[0], m.end[1], m.end[2]}, m.center, m.sweep, m.length,
          m.kind == machine::MoveKind::arc};
}

Stats measure(const std::vector<machine::Move>& contour, const geom::Curve& curve, const Options& o, bool require_end) {
  std::vector<ContourMove> moves;
  moves.reserve(contour.size());
  for (const machine::Move& m : contour) moves.push_back(ContourMove::of(m));
  return measure(moves, curve, o, require_end);
}

Stats measure(const std::vector<ContourMove>& contour, const geom::Curve& curve, const Options& o, bool require_end) {
  return Measurer(curve, o, require_end).measure(contour);
}

namespace {

Emitted expanded_or_arcs(const Context& c) {
  const Options& o = c.o;
  geom::Path path;
  std::shared_ptr<Speculation> speculation;
  std::string method;
  if (o.form == Form::arcs) {
    if (c.with_z)
      throw std::runtime_error("arcs on a mill are made in the XY plane (G17), and this curve moves in Z (use expanded "
                               "or macro; a lathe curve's arcs, in G18, come with a lathe profile: --machine fanuc-lathe)");
    path = geom::fit_arcs(c.fit);
    method = "biarcs";
  } else {
    path = geom::fit_lines(c.fit, o.lines);
    // (an inch program's moves are read in inches and converted: never the fit's bit for bit)
    if (!is_lathe(o) && !depth_passes(o) && !o.inch && path.pieces.size() <= Measurer::kRun && base::cores() > 1)
      speculation = std::make_shared<Speculation>(c.curve, o, path.pieces);
    method = o.lines == geom::LineMethod::equal_step    ? "equal parameter step"
             : o.lines == geom::LineMethod::equal_chord ? "equal chord"
             : o.lines == geom::LineMethod::equal_error ? "equal error, tolerance band"
             : o.lines == geom::LineMethod::radial_error ? "equal radial shape error"
                                                         : "equal error, points on the curve";
  }
  Writer w;
  w.text.reserve(1024 + 24 * path.pieces.size());  // "X-123.456 Y78.901" a piece, arcs longer
  w.block("%");
  w.lines(header(c.curve, o, method));
  begin_setup(w, o, c.dec);
  begin_passes(w, o, c.dec);
  modes_block(w, o);
  Frame fr = frame(o, c.words, c.start, c.end, c.dec, c.feed);
  w.lines(fr.before_start);
  w.lines(fr.to_depth);
  Emitted e;
  e.first = w.line + 1;
  // The contour's blocks, in parts on all cores: a block's G code depends only on the piece before.
  const std::vector<geom::Piece>& pieces = path.pieces;
  constexpr std::size_t kPart = 4096;
  std::vector<std::string> parts((pieces.size() + kPart - 1) / kPart);
  auto g_code = [](const geom::Piece& p) { return p.arc ? (p.ccw ? 3 : 2) : 1; };
  base::for_each_on_cores(parts.size(), [&](std::size_t k) {
    std::string& text = parts[k];
    const std::size_t first = k * kPart, last = std::min(pieces.size(), first + kPart);
    text.reserve(32 * (last - first));
    int motion = first == 0 ? 1 : g_code(pieces[first - 1]);
    for (std::size_t i = first; i < last; ++i) {
      const geom::Piece& p = pieces[i];
      const int g = g_code(p);
      if (g != motion) text += fmt::format("G0{} ", g);
      c.words.append(text, p.end);
      if (p.arc) text += ' ' + arc_words(c, p);
      text += '\n';
      motion = g;
    }
  });
  for (const std::string& part : parts) w.text += part;
  w.line += static_cast<std::uint32_t>(pieces.size());
  e.last = w.line;
  end_program(w, c);
  e.text = std::move(w.text);
  e.speculation = std::move(speculation);
  return e;
}

Emitted equal_step_macro(const Context& c) {
  const Options& o = c.o;
  geom::Path steps = geom::fit_lines(c.fit, geom::LineMethod::equal_step);
  const std::size_t n = steps.pieces.size();
  Writer w;
  macro_preamble(w, c, "equal parameter step");
  w.block(fmt::format("#112={} (SEGMENTS)", n));
  w.block("#113=[#111-#110]/#112 (T STEP)");
  w.block("#114=0 (SEGMENT COUNTER)");
  modes_block(w, o);
  w.block("#100=#110");
  int next = kFirstTemp;
  MacroWords mp = macro_words(point_axes(c.curve, c.map, o, c.with_z), next);
  approach(w, c, mp);
  w.block("WHILE [#114 LT #112] DO1");
  w.block("#114=#114+1");
  w.block("#100=#110+#114*#113");
  return close_loop(w, c, mp);
}

}  // namespace

namespace detail {

void end_program(Writer& w, const Context& c) {
  w.lines(frame(c.o, c.words, c.start, c.end, c.dec, c.feed).retract);
  end_passes(w, c.o);
  end_setup(w, c.o);
  w.block("M30");
  w.block("%");
}

Emitted close_loop(Writer& w, const Context& c, const MacroWords& move) {
  for (const auto& a : move.assignments) w.block(a);
  Emitted e;
  e.first = w.line + 1;
  w.block(fmt::format("G01 {}", move.words));
  e.last = w.line;
  w.block("END1");
  end_program(w, c);
  e.text = std::move(w.text);
  return e;
}

std::string arc_words(const Context& c, const geom::Piece& p) {
  if (c.o.profile.arcs_with_r) return fmt::format("R{}", number(p.r, c.dec));
  if (is_lathe(c.o))
    return fmt::format("I{} K{}", number(p.centre[0] - p.start[0], c.dec), number(p.centre[2] - p.start[2], c.dec));
  return fmt::format("I{} J{}", number(p.centre[0] - p.start[0], c.dec), number(p.centre[1] - p.start[1], c.dec));
}

void parameter_blocks(Writer& w, const geom::Curve& curve) {
  for (const auto& p : curve.params())
    w.block(fmt::format("#{}={} ({}: {})", p.var, number(p.value, 12), comment_text(p.name), comment_text(p.doc)));
}

void macro_preamble(Writer& w, const Context& c, const std::string& method, const std::string& more_variables,
                    int t_start) {
  w.block("%");
  w.lines(header(c.curve, c.o, method));
  begin_setup(w, c.o, c.dec);
  begin_passes(w, c.o, c.dec);
  w.block(fmt::format("(#100 = T OF THE {}{})", comment_text(c.curve.name()), more_variables));
  parameter_blocks(w, c.curve);
  w.block(fmt::format("#{}={} (T START)", t_start, number(c.curve.t0(), 12)));
  w.block(fmt::format("#111={} (T END)", number(c.curve.t1(), 12)));
}

void approach(Writer& w, const Context& c, const MacroWords& start) {
  const Options& o = c.o;
  if (is_lathe(o)) {
    w.block(fmt::format("G00 X{} Z{}", number(2 * (c.start[0] + o.clearance), c.dec),
                        number(c.start[2] + o.clearance, c.dec)));
    for (const auto& a : start.assignments) w.block(a);
    w.block(fmt::format("G01 {} F{}", start.words, feed_number(o, c.feed)));
    return;
  }
  w.block(fmt::format("G00 Z{}", number(o.clearance, c.dec)));
  for (const auto& a : start.assignments) w.block(a);
  w.block(fmt::format("G00 {}", start.words));
  if (!c.with_z) w.block(fmt::format("G01 {} F{}", plunge_z(o, -o.depth, c.dec), feed_number(o, c.feed)));
  else w.block(fmt::format("G01 F{}", feed_number(o, c.feed)));
}

}  // namespace detail

void check_options(const Options& o) {
  auto finite = [](double v, const char* what) {
    if (!std::isfinite(v)) throw std::runtime_error(fmt::format("{} must be a finite number, not {}", what, v));
  };
  finite(o.tol, "the tolerance");
  finite(o.feed, "the feed");
  finite(o.depth, "the depth");
  finite(o.clearance, "the clearance");
  finite(o.step_down, "the depth per pass");
  finite(o.tool_radius, "the tool radius");
  if (!(o.tol > 0)) throw std::runtime_error(fmt::format("the tolerance must be above 0 mm, not {}", o.tol));
  if (o.feed < 0) throw std::runtime_error(fmt::format("the feed must not be negative, not {}", o.feed));
  // the set-up
  const bool lathe = is_lathe(o);
  if (o.tool < 0 || o.tool > (lathe ? 64 : 9999))
    throw std::runtime_error(fmt::format("the tool must be 1..{}{}, not {}", lathe ? 64 : 9999,
                                         lathe ? " on a lathe (T with the offset of the same number)" : "", o.tool));
  if (o.spindle < 0 || o.css < 0 || o.max_rpm < 0)
    throw std::runtime_error("spindle speeds must not be negative");
  if (o.css > 0 && !lathe) throw std::runtime_error("a constant surface speed (G96) is for the lathe; give the spindle speed");
  if (o.css > 0 && o.spindle > 0)
    throw std::runtime_error("give the spindle speed or a constant surface speed (G96), not both");
  if (o.max_rpm > 0 && o.css == 0) throw std::runtime_error("the spindle clamp is for a constant surface speed (G96)");
  if (o.spindle_ccw && o.spindle == 0 && o.css == 0) throw std::runtime_error("the spindle's direction needs its speed");
  if (o.inch && o.form == Form::cycle)
    throw std::runtime_error(
        "the cycles' macros (O9010..O9019) are written in mm: for an inch program use --form adaptive-macro (the "
        "same loop, in the program)");
}

Result generate(const geom::Curve& contour, const Options& o) {
  check_options(o);
  geom::Survey survey = contour.validate();
  std::optional<geom::Curve> cutter_centre;
  if (o.tool_radius > 0) {
    const AxisMap placed = axis_map(contour, o);
    geom::Plane plane = plane_of(o.profile);
    cutter_centre.emplace(contour.offset(o.tool_radius, o.side == Side::left, placed.from[plane.u_axis],
                                         placed.from[plane.v_axis]));
    survey = cutter_centre->validate();
  } else if (o.tool_radius < 0) {
    throw std::runtime_error("the tool radius must not be negative");
  }
  const geom::Curve& measured = cutter_centre ? *cutter_centre : contour;
  const bool with_z = !is_lathe(o) && !measured.planar_z();
  if (o.step_down < 0) throw std::runtime_error("the depth per pass must not be negative");
  if (o.step_down > 0 && is_lathe(o)) throw std::runtime_error("depth passes are for the mill");
  if (o.step_down > 0 && with_z) throw std::runtime_error("depth passes need a plane curve; this one rises in Z");
  if (o.step_down > 0 && !(o.depth > 0)) throw std::runtime_error("depth passes need a depth > 0");
  if (const double passes = std::ceil(o.depth / o.step_down); o.step_down > 0 && passes > Options::kMostPasses)
    throw base::BoundExceeded(fmt::format("a depth of {:g} mm in passes of {:g} mm is {:.3g} passes, more than {:g}: "
                                         "raise --step-down",
                                         o.depth, o.step_down, passes, Options::kMostPasses));
  // An inch program: the curve and the options in inches, every form written as in mm; the round
  // trip runs it and measures in mm.
  std::optional<geom::Curve> inches;
  const Options inch_o = o.inch ? in_inches(o) : Options{};
  if (o.inch) {
    inches.emplace(measured.scaled(kMmPerInch));
    survey = inches->survey();
  }
  const geom::Curve& curve = o.inch ? *inches : measured;
  const Options& u = o.inch ? inch_o : o;  // in the program's units
  const int dec = decimals_of(u.profile.increment);
  geom::Vec3 increment{u.profile.increment, u.profile.increment, u.profile.increment};
  if (is_lathe(u) && u.profile.diameter_x) increment[0] = u.profile.increment / 2;
  if (is_lathe(u)) increment[1] = 0;
  if (!is_lathe(u) && !with_z) increment[2] = 0;  // a plane contour's Z is a constant
  const geom::Grid grid(increment);
  // (in mm: the fit's own messages would give inches)
  if (o.inch && !(u.tol * 0.999 > (o.form == Form::arcs ? 2 : 1) * grid.worst_error()))
    throw std::runtime_error(fmt::format(
        "tolerance {} mm is too close to the coordinate rounding of an inch program ({:.6f} mm: steps of {} in){}",
        o.tol, grid.worst_error() * kMmPerInch, u.profile.increment,
        o.form == Form::arcs ? "; arcs need twice that" : ""));
  // measured at the depth the program cuts at: an inch program's is rounded to its increment
  Options measured_o = o;
  if (o.inch && !is_lathe(o) && !with_z)
    measured_o.depth = kMmPerInch * machine::round_to_increment(u.depth, std::round(1 / u.profile.increment));
  const AxisMap map = axis_map(curve, u);
  // the fit aims a little inside the tolerance: the round trip measures the control's own path
  Context c{curve,
            u,
            map,
            with_z,
            dec,
            feed_of(u),
            AxisWords{u, dec, with_z},
            geom::Fit{curve, map, grid, plane_of(u.profile), u.tol * 0.999},
            grid.snap(map(curve.point(curve.t0()))),
            grid.snap(map(curve.point(curve.t1()))),
            measured,
            measured_o};
  c.fit.survey = &survey;
  c.fit.arcs_with_r = u.profile.arcs_with_r;
  c.fit.r_step = u.profile.increment;
  c.fit.arc_radius_limit = u.profile.arc_radius_tolerance * 0.999;
  for (const auto& p : curve.params()) {  // the spiral's centre; other curves: their origin
    if (p.name == "cx") c.fit.centre[0] = in_program_units(u, p.value);
    if (p.name == "cy") c.fit.centre[1] = in_program_units(u, p.value);
  }
  c.fit.centre = map(c.fit.centre);
  geom::PieceBudget budget;
  budget.most = o.max_moves;
  c.fit.budget = &budget;
  Emitted e;
  try {
    switch (o.form) {
      case Form::expanded:
      case Form::arcs: e = expanded_or_arcs(c); break;
      case Form::macro: e = equal_step_macro(c); break;
      case Form::adaptive_macro: e = adaptive_macro(c); break;
      case Form::cycle: e = cycle(c); break;
    }
  } catch (const geom::PieceBudget::TooManyPieces&) {
    throw too_many_moves(o);
  }
  Result r;
  r.text = std::move(e.text);
  r.parameters = e.parameters;
  r.macro = std::move(e.macro);
  Options on_control = measured_o;
  for (const auto& [key, value] : r.parameters) machine::set_parameter(on_control.profile, key, value);
  r.stats = detail::round_trip(r.text, measured, on_control, e.first, e.last, e.speculation.get());
  r.placement = axis_map(measured, measured_o);
  r.cutter_centre = std::move(cutter_centre);
  r.within_tolerance = r.stats.max_deviation <= o.tol;
  return r;
}

}  // namespace ncurve::gen
