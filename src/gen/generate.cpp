#include "gen/generate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "report/summary.hpp"

namespace ncurve::gen {
namespace {

using geom::Sym;
using geom::SymOp;
using geom::Vec3;

constexpr int kFirstTemp = 150;  // macro temporaries #150..

// Builds the text and remembers the contour's first and last line.
struct Writer {
  std::string text;
  std::uint32_t line = 0;
  void block(const std::string& b) {
    text += b;
    text += '\n';
    ++line;
  }
};

std::string comment_text(std::string s) {
  for (char& c : s) {
    if (c == '(' || c == ')') c = ' ';
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  if (s.size() > 200) s.resize(200);
  return s;
}

int decimals_of(double increment) { return std::max(0, static_cast<int>(std::lround(-std::log10(increment)))); }

std::string number(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
  }
  if (s == "-0." || s == "-0") s = "0.";
  if (s.find('.') == std::string::npos) s += '.';
  return s;
}

bool is_lathe(const Options& o) { return o.profile.lathe(); }

double feed_of(const Options& o) { return o.feed > 0 ? o.feed : (is_lathe(o) ? 0.1 : 200.0); }

// Letters and values for the machine axes of a point (lathe X as a diameter).
struct AxisWords {
  const Options& o;
  const AxisMap& map;
  int decimals;
  bool with_z;  // mill: Z follows the curve
  std::string operator()(const Vec3& p) const {
    if (is_lathe(o)) return fmt::format("X{} Z{}", number(2 * p[0], decimals), number(p[2], decimals));
    std::string s = fmt::format("X{} Y{}", number(p[0], decimals), number(p[1], decimals));
    if (with_z) s += fmt::format(" Z{}", number(p[2], decimals));
    return s;
  }
};

std::string header(const geom::Curve& curve, const Options& o, const std::string& method) {
  std::string params;
  for (const auto& p : curve.params()) params += fmt::format(" {}={:.10g}", p.name, p.value);
  return fmt::format("O{:04d} (NCURVE {} {})\n(CURVE {}{} T={:.10g}..{:.10g})\n(TOLERANCE {} MM, FORM {}{})\n",
                     o.program_number, comment_text(curve.name()), comment_text(to_string(o.form)),
                     comment_text(curve.name()), comment_text(params), curve.t0(), curve.t1(), o.tol,
                     comment_text(to_string(o.form)), method.empty() ? "" : ", " + comment_text(method));
}

std::string modes(const Options& o) {
  if (is_lathe(o)) return o.profile.gcode_system == 'A' ? "G21 G18 G99" : "G21 G18 G90 G95";
  return "G21 G17 G90 G94 G54";
}

// Approach before the contour and retract after it.
struct Frame {
  std::string before_start;  // rapid moves to above the start point
  std::string to_depth;      // feed to the start of the contour
  std::string retract;
};

Frame frame(const Options& o, const AxisWords& words, const Vec3& start, const Vec3& end, int dec, double feed) {
  Frame f;
  if (is_lathe(o)) {
    f.before_start = fmt::format("G00 X{} Z{}", number(2 * (start[0] + o.clearance), dec),
                                 number(start[2] + o.clearance, dec));
    f.to_depth = fmt::format("G01 {} F{}", words(start), number(feed, 4));
    f.retract = fmt::format("G00 X{}", number(2 * (end[0] + o.clearance), dec));
    return f;
  }
  f.before_start = fmt::format("G00 Z{}\nX{} Y{}", number(o.clearance, dec), number(start[0], dec),
                               number(start[1], dec));
  f.to_depth = fmt::format("G01 Z{} F{}", number(start[2], dec), number(feed, 4));
  f.retract = fmt::format("G00 Z{}", number(o.clearance, dec));
  return f;
}

Sym axis_sym(const geom::Curve& curve, const AxisMap& map, int axis, bool lathe) {
  Sym s = map.from[axis] >= 0 ? curve.position()[map.from[axis]] : geom::konst(0);
  s = geom::make(SymOp::add, s, geom::konst(map.offset[axis]));
  if (lathe && axis == 0) s = geom::make(SymOp::mul, geom::konst(2), s);
  return s;
}

// Assignments of temporaries and the axis words X[..] Y[..] for the curve point at #100.
struct MacroPoint {
  std::vector<std::string> assignments;
  std::string words;
};

MacroPoint macro_point(const geom::Curve& curve, const AxisMap& map, const Options& o, bool with_z) {
  MacroPoint mp;
  int next = kFirstTemp;
  std::vector<std::pair<int, Sym>> temps;
  std::vector<std::pair<char, Sym>> axes;
  if (is_lathe(o)) {
    axes = {{'X', axis_sym(curve, map, 0, true)}, {'Z', axis_sym(curve, map, 2, true)}};
  } else {
    axes = {{'X', axis_sym(curve, map, 0, false)}, {'Y', axis_sym(curve, map, 1, false)}};
    if (with_z) axes.emplace_back('Z', axis_sym(curve, map, 2, false));
  }
  for (auto& [letter, s] : axes) {
    Sym limited = geom::limit_depth(s, 4, next, temps);  // X[...] adds the fifth bracket
    mp.words += fmt::format("{}{}[{}]", mp.words.empty() ? "" : " ", letter, geom::to_macro(limited));
  }
  for (const auto& [var, s] : temps) mp.assignments.push_back(fmt::format("#{}={}", var, geom::to_macro(s)));
  return mp;
}

}  // namespace

const char* to_string(Form f) {
  switch (f) {
    case Form::expanded: return "expanded";
    case Form::arcs: return "arcs";
    case Form::macro: return "macro";
    case Form::adaptive_macro: return "adaptive-macro";
  }
  return "";
}

bool parse_form(const std::string& text, Form& out) {
  for (Form f : {Form::expanded, Form::arcs, Form::macro, Form::adaptive_macro}) {
    if (text == to_string(f)) {
      out = f;
      return true;
    }
  }
  return false;
}

Vec3 AxisMap::operator()(const Vec3& c) const {
  Vec3 out;
  for (int a = 0; a < 3; ++a) out[a] = (from[a] >= 0 ? c[from[a]] : 0.0) + offset[a];
  return out;
}

AxisMap axis_map(const geom::Curve& curve, const Options& o) {
  AxisMap m;
  const bool uses_z = !curve.planar_z();
  const bool uses_y = curve.uses_y();
  if (is_lathe(o)) {
    if (uses_y && uses_z) throw std::runtime_error("a lathe cuts plane profiles: the curve uses y and z");
    if (uses_y) m.from = {1, -1, 0};  // profile drawn in x, y: Z along x, X (radius) along y
    else m.from = {0, -1, 2};
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

Stats round_trip(const std::string& text, const geom::Curve& curve, const Options& o, std::uint32_t first_line,
                 std::uint32_t last_line) {
  machine::ProgramLibrary lib;
  lib.add_text("<generated>", text, true);
  struct Keep final : machine::MoveSink {
    std::uint32_t first, last;
    std::vector<machine::Move> moves;
    void on_move(const machine::Move& m) override {
      if ((m.kind == machine::MoveKind::line || m.kind == machine::MoveKind::arc) && m.line >= first && m.line <= last)
        moves.push_back(m);
    }
  } keep;
  keep.first = first_line;
  keep.last = last_line;
  machine::Interpreter interp(o.profile, lib);
  machine::RunResult r = interp.run(keep);
  if (!r.ok()) throw std::runtime_error("the generated program does not run: " + nc::format(*r.alarm));

  Stats s;
  report::SourceStats source = report::source_stats(lib, lib.main()->file.get());  // as `ncurve run` counts
  s.words = source.words;
  s.bytes = source.bytes;
  s.blocks = source.blocks;
  AxisMap map = axis_map(curve, o);
  geom::Placement place = [map](const Vec3& c) { return map(c); };
  geom::Plane plane = plane_of(o.profile);

  // a table of the curve to find where each move starts and ends
  constexpr int kTable = 8192;
  std::vector<double> ts(kTable + 1), along(kTable + 1, 0.0);
  std::vector<Vec3> pts(kTable + 1);
  for (int i = 0; i <= kTable; ++i) {
    ts[i] = curve.t0() + (curve.t1() - curve.t0()) * i / kTable;
    pts[i] = map(curve.point(ts[i]));
    if (i > 0) along[i] = along[i - 1] + std::sqrt(std::pow(pts[i][0] - pts[i - 1][0], 2) +
                                                   std::pow(pts[i][1] - pts[i - 1][1], 2) +
                                                   std::pow(pts[i][2] - pts[i - 1][2], 2));
  }
  auto dist = [](const Vec3& a, const Vec3& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  };
  // nearest curve parameter to p, searching forward from index `from` over about `reach` mm
  std::size_t cursor = 0;
  auto project = [&](const Vec3& p, double reach) {
    std::size_t best = cursor;
    double best_d = dist(p, pts[cursor]);
    for (std::size_t i = cursor + 1; i < pts.size() && along[i] - along[cursor] <= reach; ++i) {
      double d = dist(p, pts[i]);
      if (d < best_d) { best_d = d; best = i; }
    }
    double lo = ts[best > 0 ? best - 1 : 0], hi = ts[std::min(best + 1, pts.size() - 1)];
    if (best > cursor || cursor == 0) lo = std::max(lo, ts[cursor]);
    for (int k = 0; k < 100 && hi - lo > 1e-13; ++k) {
      double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (dist(p, map(curve.point(m1))) < dist(p, map(curve.point(m2)))) hi = m2; else lo = m1;
    }
    cursor = best;
    return 0.5 * (lo + hi);
  };

  if (keep.moves.empty()) throw std::runtime_error("the generated program cuts no contour");
  s.points = keep.moves.size() + 1;
  auto note = [&](double d, double t) {
    if (d > s.max_deviation) {
      s.max_deviation = d;
      s.worst_t = t;
      s.worst_point = map(curve.point(t));
    }
  };
  Vec3 first{keep.moves[0].start[0], keep.moves[0].start[1], keep.moves[0].start[2]};
  double t_prev = project(first, 1e-3 + 10 * o.tol);
  note(dist(first, map(curve.point(t_prev))), t_prev);
  const Vec3 curve_end = map(curve.point(curve.t1()));
  for (const auto& m : keep.moves) {
    const bool last_move = &m == &keep.moves.back();
    geom::Piece piece;
    piece.start = {m.start[0], m.start[1], m.start[2]};
    piece.end = {m.end[0], m.end[1], m.end[2]};
    piece.arc = m.kind == machine::MoveKind::arc;
    piece.centre = m.center;
    piece.ccw = m.sweep > 0;
    s.path_length += m.length;
    double t_end = project(piece.end, 3 * m.length + 10 * o.tol + 1e-3);
    if (last_move) {  // the contour must reach the end of the curve
      if (dist(piece.end, curve_end) > o.tol)
        throw std::runtime_error(fmt::format("the contour ends {:.4f} mm from the end of the curve (t = {:.6g})",
                                             dist(piece.end, curve_end), curve.t1()));
      t_end = curve.t1();
    }
    note(dist(piece.end, map(curve.point(t_end))), t_end);
    auto d = [&](const Vec3& p) {
      return piece.arc ? geom::point_arc_distance(p, piece, plane) : geom::point_segment_distance(p, piece.start, piece.end);
    };
    geom::Worst w = geom::max_distance(curve, place, t_prev, t_end, d);
    note(w.distance, w.t);
    t_prev = t_end;
  }
  return s;
}

Result generate(const geom::Curve& curve, const Options& o) {
  if (o.form == Form::adaptive_macro)
    throw std::runtime_error("the adaptive-macro form is not available yet (use expanded, arcs or macro)");
  curve.validate();
  AxisMap map = axis_map(curve, o);
  const bool with_z = !is_lathe(o) && !curve.planar_z();
  const int dec = decimals_of(o.profile.increment);
  AxisWords words{o, map, dec, with_z};
  geom::Grid grid;
  grid.step = {o.profile.increment, o.profile.increment, o.profile.increment};
  if (is_lathe(o) && o.profile.diameter_x) grid.step[0] = o.profile.increment / 2;
  if (is_lathe(o)) grid.step[1] = 0;
  geom::Placement place = [map](const Vec3& c) { return map(c); };
  // the fit aims a little inside the tolerance: the round trip measures the control's own path
  geom::Fit fit{curve, place, grid, plane_of(o.profile), o.tol * 0.999};
  const double feed = feed_of(o);
  Vec3 start = grid.snap(map(curve.point(curve.t0())));
  Vec3 end = grid.snap(map(curve.point(curve.t1())));

  Writer w;
  std::uint32_t first = 0, last = 0;
  auto emit_lines = [&](const std::string& text) {
    std::size_t pos = 0;
    while (pos <= text.size()) {
      std::size_t eol = text.find('\n', pos);
      if (eol == std::string::npos) eol = text.size();
      if (eol > pos) w.block(text.substr(pos, eol - pos));
      pos = eol + 1;
    }
  };
  w.block("%");
  Frame fr = frame(o, words, start, end, dec, feed);

  if (o.form == Form::expanded || o.form == Form::arcs) {
    geom::Path path;
    std::string method;
    if (o.form == Form::arcs) {
      if (with_z) throw std::runtime_error("arcs need a plane curve; this one rises in Z (use expanded or macro)");
      path = geom::fit_arcs(fit);
      method = "biarcs";
    } else {
      path = geom::fit_lines(fit, o.lines);
      method = o.lines == geom::LineMethod::equal_step    ? "equal parameter step"
               : o.lines == geom::LineMethod::equal_chord ? "equal chord"
               : o.lines == geom::LineMethod::equal_error ? "equal error, tolerance band"
                                                          : "equal error, points on the curve";
    }
    emit_lines(header(curve, o, method));
    w.block(modes(o));
    emit_lines(fr.before_start);
    emit_lines(fr.to_depth);
    first = w.line + 1;
    int motion = 1;
    for (const auto& p : path.pieces) {
      if (!p.arc) {
        w.block(fmt::format("{}{}", motion == 1 ? "" : "G01 ", words(p.end)));
        motion = 1;
        continue;
      }
      int g = p.ccw ? 3 : 2;
      std::string centre;
      if (is_lathe(o)) {
        centre = fmt::format("I{} K{}", number(p.centre[0] - p.start[0], dec), number(p.centre[2] - p.start[2], dec));
      } else {
        centre = fmt::format("I{} J{}", number(p.centre[0] - p.start[0], dec), number(p.centre[1] - p.start[1], dec));
      }
      w.block(fmt::format("{}{} {}", motion == g ? "" : fmt::format("G0{} ", g), words(p.end), centre));
      motion = g;
    }
    last = w.line;
  } else {
    geom::Path steps = geom::fit_lines(fit, geom::LineMethod::equal_step);
    const std::size_t n = steps.pieces.size();
    emit_lines(header(curve, o, "equal parameter step"));
    w.block("(VARIABLES)");
    w.block(fmt::format("(#100 = T, CURVE PARAMETER: {})", comment_text(fmt::format("{}", curve.name()))));
    for (const auto& p : curve.params())
      w.block(fmt::format("#{}={} ({}: {})", p.var, number(p.value, 12), comment_text(p.name), comment_text(p.doc)));
    w.block(fmt::format("#110={} (T START)", number(curve.t0(), 12)));
    w.block(fmt::format("#111={} (T END)", number(curve.t1(), 12)));
    w.block(fmt::format("#112={} (SEGMENTS)", n));
    w.block("#113=[#111-#110]/#112 (T STEP)");
    w.block("#114=0 (SEGMENT COUNTER)");
    w.block(modes(o));
    w.block("#100=#110");
    MacroPoint mp = macro_point(curve, map, o, with_z);
    if (is_lathe(o)) {
      w.block(fmt::format("G00 X{} Z{}", number(2 * (start[0] + o.clearance), dec), number(start[2] + o.clearance, dec)));
      for (const auto& a : mp.assignments) w.block(a);
      w.block(fmt::format("G01 {} F{}", mp.words, number(feed, 4)));
    } else {
      w.block(fmt::format("G00 Z{}", number(o.clearance, dec)));
      for (const auto& a : mp.assignments) w.block(a);
      w.block(fmt::format("G00 {}", mp.words));
      if (!with_z) w.block(fmt::format("G01 Z{} F{}", number(-o.depth, dec), number(feed, 4)));
      else w.block(fmt::format("G01 F{}", number(feed, 4)));
    }
    w.block("WHILE [#114 LT #112] DO1");
    w.block("#114=#114+1");
    w.block("#100=#110+#114*#113");
    for (const auto& a : mp.assignments) w.block(a);
    first = w.line + 1;
    w.block(fmt::format("G01 {}", mp.words));
    last = w.line;
    w.block("END1");
  }
  emit_lines(fr.retract);
  w.block("M30");
  w.block("%");

  Result r;
  r.text = std::move(w.text);
  r.stats = round_trip(r.text, curve, o, first, last);
  r.within_tolerance = r.stats.max_deviation <= o.tol;
  return r;
}

}  // namespace ncurve::gen
