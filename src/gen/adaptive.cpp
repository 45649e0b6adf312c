// adaptive-macro: a WHILE loop in which the control finds each move itself, as the equal-error
// fit does: the longest step whose deviation from the curve is within the aim. The deviation is
// estimated at the middle of the step from the curve's point and derivatives there (the hump of
// the parabola through them), with the vertices outward by the tolerance band and rounded to the
// increment as the control will round them; the next step is tried from the error model
// (sag + band grows as the step squared).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "gen/forms.hpp"

namespace ncurve::gen::detail {
namespace {

using geom::Sym;
using geom::Vec3;

constexpr int kTrials = 5;        // trials per move once one is within the aim
constexpr double kClose = 0.995;  // a trial within the aim and this close to it ends the search
constexpr double kShrink = 0.99;  // after a trial over the aim, the next is this much shorter
constexpr int kDigits = 9;        // decimals of the macro's constants

// The loop's variables. Locals keep the blocks short (a cycle's arguments are copied out before
// the loop): #1 aim, #2 band, #3 longest t step, #4 the chord's length squared (space), #5 t at
// the vertex A, #6 t step to try (0: the start vertex), #7 t tried, #8 longest step within the
// aim, #9 trials since one was within it (kTrials ends the search), #12 t of the best vertex,
// #13 first t step, #16..#20 and #33 scratch; from #21 the vectors A, B (tried), best B and the
// chord, dims each. #100 is #7 while the vertex is found, the middle of the step after. The
// curve's point and derivatives are common variables #120.., their shared parts temporaries
// from #150.
namespace var {
constexpr int vectors = 21;
constexpr int jet = 120;
}  // namespace var

struct Loop {
  const Context& c;
  std::vector<int> axes;  // machine axes in the loop (internal indices)
  int dims() const { return static_cast<int>(axes.size()); }
  int a(int i) const { return var::vectors + i; }
  int b(int i) const { return var::vectors + dims() + i; }
  int best_b(int i) const { return var::vectors + 2 * dims() + i; }
  int chord(int i) const { return var::vectors + 3 * dims() + i; }
  int p(int i) const { return var::jet + i; }
  int d1(int i) const { return var::jet + dims() + i; }
  int d2(int i) const { return var::jet + 2 * dims() + i; }
  int scratch(int i) const { return 17 + i; }  // three at most

  // sum over the axes of f(i), as macro text
  template <class F>
  std::string sum(F f) const {
    std::string s;
    for (int i = 0; i < dims(); ++i) {
      if (i) s += '+';
      s += f(i);
    }
    return s;
  }
  // "ROUND[[e]*1000.]/1000.": where the control puts a coordinate of axis i
  std::string rounded(int i, const std::string& e) const {
    const std::string m = number(c.fit.grid.per_mm()[static_cast<std::size_t>(axes[static_cast<std::size_t>(i)])], 6);
    return fmt::format("ROUND[[{}]*{}]/{}", e, m, m);
  }
  // The words of a move to the vertex in variables first.. (lathe X as a diameter); an axis the
  // curve keeps constant is written as its number where `constants` asks for it (the approach).
  std::string words(int first, bool constants) const {
    auto slot = [&](int axis) {
      for (int i = 0; i < dims(); ++i)
        if (axes[static_cast<std::size_t>(i)] == axis) return first + i;
      return -1;
    };
    std::string out;
    for (const WordAxis& axis : word_axes(c.o, c.with_z)) {
      std::string w;
      if (slot(axis.axis) >= 0)
        w = fmt::format("{}[{}#{}]", axis.letter, axis.diameter ? "2*" : "", slot(axis.axis));
      else if (constants)
        w = fmt::format("{}{}", axis.letter,
                        number((axis.diameter ? 2 : 1) * geom::simplify(axis_sym(c.curve, c.map, axis.axis))->k, c.dec));
      if (!w.empty()) out += (out.empty() ? "" : " ") + w;
    }
    return out;
  }
};

// The loop's axes: the plane's two, or in space those the curve moves (a space curve that keeps
// one axis constant, like a hyperbola in XZ on a mill, is a plane loop)
Loop loop_of(const Context& c) {
  Loop l{c, {}};
  if (!c.with_z) {
    l.axes = {c.fit.plane.u_axis, c.fit.plane.v_axis};
    return l;
  }
  for (int axis = 0; axis < 3; ++axis)
    if (geom::simplify(axis_sym(c.curve, c.map, axis))->op != geom::SymOp::konst) l.axes.push_back(axis);
  if (l.axes.size() < 2) l.axes = {0, 1, 2};
  return l;
}

Sym axis_derivative(const Context& c, int axis, int order) {
  if (c.map.from[axis] < 0) return geom::konst(0);
  return (order == 1 ? c.curve.first() : c.curve.second())[c.map.from[axis]];
}

void assign(Writer& w, int var, const Sym& e, int depth, int& next_temp) {
  std::vector<std::pair<int, Sym>> temps;
  Sym limited = geom::limit_depth(e, depth, next_temp, temps);
  for (const auto& [t, s] : temps) w.block(fmt::format("#{}={}", t, geom::to_macro(s)));
  w.block(fmt::format("#{}={}", var, geom::to_macro(limited)));
}

bool uses_any(const Sym& e, const std::set<int>& vars) {
  if (e->op == geom::SymOp::var) return vars.count(e->var) > 0;
  return (e->a && uses_any(e->a, vars)) || (e->b && uses_any(e->b, vars));
}

// The curve's point and derivatives at #100 into #120..; parts that do not change with t are
// written before the loop (to `before`).
void jet_blocks(const Loop& l, Writer& before, Writer& inside, int& next_temp) {
  const Context& c = l.c;
  std::vector<Sym> outputs;
  for (int order = 0; order < 3; ++order)
    for (int axis : l.axes)
      outputs.push_back(order == 0 ? geom::simplify(axis_sym(c.curve, c.map, axis)) : axis_derivative(c, axis, order));
  std::vector<std::pair<int, Sym>> temps;
  std::vector<int> jet_vars(outputs.size());
  for (std::size_t i = 0; i < outputs.size(); ++i) jet_vars[i] = var::jet + static_cast<int>(i);
  std::vector<Sym> shared = geom::share_subexpressions(outputs, next_temp, temps, jet_vars);
  std::set<int> varying{geom::kTVar};
  for (const auto& [t, e] : temps) {
    const bool moves = uses_any(e, varying);
    if (moves) varying.insert(t);
    assign(moves ? inside : before, t, e, 5, next_temp);
  }
  for (std::size_t i = 0; i < shared.size(); ++i)
    if (shared[i]->op != geom::SymOp::var || shared[i]->var != jet_vars[i])  // not assigned with the temporaries
      assign(inside, jet_vars[i], shared[i], 5, next_temp);
}

double printed(double v) { return std::stod(number(v, kDigits)); }

// A number below 1 as the control also reads it, without its leading zero (.5).
std::string fraction(const std::string& text) {
  const bool minus = text.starts_with('-');
  const std::string_view digits = std::string_view(text).substr(minus ? 1 : 0);
  if (!digits.starts_with("0.")) return text;
  std::string out(minus ? "-" : "");
  out += digits.substr(1);
  return out;
}

// The loop itself, from t = #5 to #111; returns the line of its G01. The first trial (#6 = 0) finds
// the start vertex A (#21..) and runs `approach`, then the steps start from #13.
std::uint32_t loop_blocks(const Loop& l, Writer& w, const std::string& jet_text, const std::string& approach) {
  const int n = l.dims();
  auto each = [&](auto f) {
    for (int i = 0; i < n; ++i) w.block(f(i));
  };
  w.block("WHILE [#5 LT #111] DO1");
  w.block("#8=0");
  w.block("#9=0");
  w.block(fmt::format("WHILE [#9 LT {}] DO2", kTrials));
  w.block("N8 #7=#5+#6");
  w.block("IF [#7 GT #111] THEN #7=#111");
  w.block("#100=#7");
  w.lines("N3 " + jet_text);
  w.block("IF [#100 NE #7] GOTO 2");
  // the vertex at #7: the curve point outward by the band (not at the start or the end), rounded
  if (n == 2) {
    w.block("#20=0");
    w.block(fmt::format("IF [#6*[#111-#7] GT 0] THEN #20=#2/SQRT[#{}*#{}+#{}*#{}]", l.d1(0), l.d1(0), l.d1(1),
                        l.d1(1)));
    w.block(fmt::format("IF [#{}*#{} GT #{}*#{}] THEN #20=-#20", l.d1(0), l.d2(1), l.d1(1), l.d2(0)));
    w.block(fmt::format("#{}={}", l.b(0), l.rounded(0, fmt::format("#{}-#20*#{}", l.p(0), l.d1(1)))));
    w.block(fmt::format("#{}={}", l.b(1), l.rounded(1, fmt::format("#{}+#20*#{}", l.p(1), l.d1(0)))));
  } else {
    w.block(fmt::format("#16=[{}]/[{}]", l.sum([&](int i) { return fmt::format("#{}*#{}", l.d1(i), l.d2(i)); }),
                        l.sum([&](int i) { return fmt::format("#{}*#{}", l.d1(i), l.d1(i)); })));
    each([&](int i) { return fmt::format("#{}=#{}-#16*#{}", l.scratch(i), l.d2(i), l.d1(i)); });
    w.block(fmt::format("#16=SQRT[{}]", l.sum([&](int i) { return fmt::format("#{}*#{}", l.scratch(i), l.scratch(i)); })));
    w.block("#20=0");
    w.block("IF [#16*#6*[#111-#7] GT 0] THEN #20=-#2/#16");
    each([&](int i) {
      return fmt::format("#{}={}", l.b(i), l.rounded(i, fmt::format("#{}+#20*#{}", l.p(i), l.scratch(i))));
    });
  }
  // the first trial: the start vertex
  w.block("IF [#6 GT 0] GOTO 6");
  each([&](int i) { return fmt::format("#{}=#{}", l.a(i), l.b(i)); });
  w.lines(approach);
  w.block("#6=#13");
  w.block("GOTO 8");
  // the chord B - A; the plane keeps its length in #19, space its length squared in #4
  each([&](int i) { return fmt::format("{}#{}=#{}-#{}", i ? "" : "N6 ", l.chord(i), l.b(i), l.a(i)); });
  const std::string squares = l.sum([&](int i) { return fmt::format("#{}*#{}", l.chord(i), l.chord(i)); });
  const int length = n == 2 ? 19 : 4;
  w.block(n == 2 ? fmt::format("#19=SQRT[{}]", squares) : fmt::format("#4={}", squares));
  w.block(fmt::format("IF [#{} EQ 0] THEN #{}=1", length, length));
  w.block("#100=.5*[#5+#7]");
  w.block("GOTO 3");
  // the middle of the step: distance #16 from the chord, its first (#33) and second (#20)
  // derivative across it, and the hump of the parabola through them, within the step (all three
  // times the chord's length in the plane, times the distance in space)
  if (n == 2) {
    w.block(fmt::format("N2 #16=[#{}-#{}]*#{}-[#{}-#{}]*#{}", l.p(1), l.a(1), l.chord(0), l.p(0), l.a(0),
                        l.chord(1)));
    w.block(fmt::format("#33=#{}*#{}-#{}*#{}", l.d1(1), l.chord(0), l.d1(0), l.chord(1)));
    w.block(fmt::format("#20=#{}*#{}-#{}*#{}", l.d2(1), l.chord(0), l.d2(0), l.chord(1)));
  } else {
    w.block(fmt::format("N2 #{}=#{}-#{}", l.scratch(0), l.p(0), l.a(0)));
    for (int i = 1; i < n; ++i) w.block(fmt::format("#{}=#{}-#{}", l.scratch(i), l.p(i), l.a(i)));
    w.block(fmt::format("#16=[{}]/#4", l.sum([&](int i) { return fmt::format("#{}*#{}", l.scratch(i), l.chord(i)); })));
    each([&](int i) { return fmt::format("#{}=#{}-#16*#{}", l.scratch(i), l.scratch(i), l.chord(i)); });
    w.block(fmt::format("#16={}", l.sum([&](int i) { return fmt::format("#{}*#{}", l.scratch(i), l.scratch(i)); })));
    w.block(fmt::format("#33={}", l.sum([&](int i) { return fmt::format("#{}*#{}", l.d1(i), l.scratch(i)); })));
    w.block(fmt::format("#20={}", l.sum([&](int i) { return fmt::format("#{}*#{}", l.d2(i), l.scratch(i)); })));
    w.block("#19=SQRT[#16]");
    w.block("IF [#19 EQ 0] THEN #19=1");
  }
  w.block("#17=0");
  w.block("IF [#20 NE 0] THEN #17=-#33/#20");
  w.block("#18=#7-#100");
  w.block("IF [#17 GT #18] THEN #17=#18");
  w.block("IF [#17 LT -#18] THEN #17=-#18");
  w.block("#16=ABS[#16+[#33+.5*#20*#17]*#17]/#19");
  // keep the longest step within the aim; stop close to the aim, at the end, or after the trials
  w.block("#18=#7-#5");
  w.block("IF [#16 GT #1] GOTO 4");
  w.block("IF [#18 LE #8] GOTO 5");
  w.block("#8=#18");
  w.block("#12=#7");
  each([&](int i) { return fmt::format("#{}=#{}", l.best_b(i), l.b(i)); });
  w.block(fmt::format("N5 IF [#16 GE {}*#1] THEN #9={}", fraction(number(kClose, 6)), kTrials));
  w.block("N4 IF [#8 GT 0] THEN #9=#9+1");
  // the next trial: sag + band grows as the step squared
  w.block("#6=#18*SQRT[[#1+#2]/[#16+#2]]");
  w.block(fmt::format("IF [#16 GT #1] THEN #6={}*#6", fraction(number(kShrink, 6))));
  w.block("IF [#6 GT #3] THEN #6=#3");
  w.block("END2");
  w.block(fmt::format("G01 {}", l.words(l.best_b(0), false)));
  const std::uint32_t move = w.line;
  w.block("#5=#12");
  each([&](int i) { return fmt::format("#{}=#{}", l.a(i), l.best_b(i)); });
  w.block("#6=#8");
  w.block("END1");
  return move;
}

double curve_length(const Context& c) {
  double length = 0;
  Vec3 prev = c.map(c.curve.point(c.curve.t0()));
  for (int i = 1; i <= 256; ++i) {
    Vec3 q = c.map(c.curve.point(c.curve.t0() + (c.curve.t1() - c.curve.t0()) * i / 256));
    length += std::hypot(q[0] - prev[0], q[1] - prev[1], q[2] - prev[2]);
    prev = q;
  }
  return length;
}

Emitted adaptive_text(const Context& c, double aim) {
  const Loop l = loop_of(c);
  const double offset = std::floor((c.fit.tol - c.fit.grid.worst_error()) * 1e9) / 1e9;
  const double nominal = 4 * std::sqrt(offset);
  // the first step from the curvature at the start (a chord of a quarter of the curve at most)
  const double least_k = std::pow(nominal / (0.25 * curve_length(c)), 2);
  const double span = c.curve.t1() - c.curve.t0();
  const geom::Curve::Jet at = c.curve.jet(c.curve.t0());
  const double speed = std::hypot(at.d1[0], at.d1[1], at.d1[2]), bend = std::hypot(at.d2[0], at.d2[1], at.d2[2]);
  double first;
  if (speed * speed < 1e-6 * nominal * bend)  // at rest (the curve stops at its start): a chord from rest
    first = std::min(span, std::sqrt(2 * nominal / std::sqrt(least_k) / bend));
  else
    first = std::min(span, nominal / std::sqrt(std::max(c.curve.curvature(c.curve.t0()), least_k)) / speed);

  Writer w;
  macro_preamble(w, c, "", fmt::format(", #{}.. JET THERE, #5 T AT VERTEX #{}..", var::jet, var::vectors), 5);
  w.block(fmt::format("#1={} (AIM, MM)", fraction(number(aim, kDigits))));
  w.block(fmt::format("#2={} (BAND: VERTEX OFFSET, MM)", fraction(number(offset, kDigits))));
  w.block(fmt::format("#3={} (LONGEST T STEP)", number(span / 4, kDigits)));
  w.block(fmt::format("#13={} (FIRST T STEP)", fraction(number(first, 6))));
  modes_block(w, c.o);
  adaptive_start(w, 5);
  Writer to_start;
  approach(to_start, c, MacroWords{{}, l.words(var::vectors, true)});
  Emitted e;
  e.first = e.last = adaptive_loop(w, c, to_start.text);
  end_program(w, c);
  e.text = std::move(w.text);
  return e;
}

}  // namespace

void adaptive_start(Writer& w, int t_start) {
  if (t_start != 5) w.block(fmt::format("#5=#{}", t_start));
  w.block("#6=0");
}

std::uint32_t adaptive_loop(Writer& w, const Context& c, const std::string& approach) {
  const Loop l = loop_of(c);
  Writer before, inside;
  int next = kFirstTemp;
  jet_blocks(l, before, inside, next);
  w.lines(before.text);
  return loop_blocks(l, w, inside.text, approach);
}

Emitted adaptive_macro(const Context& c) {
  const double rounding = c.fit.grid.worst_error();
  if (c.fit.tol <= rounding)
    throw std::runtime_error(fmt::format("tolerance {} mm is not above the coordinate rounding ({:.6f} mm)",
                                         c.o.tol, rounding));
  // the estimate at the middle is within about 1 % of the true deviation: aim lower until the
  // control's own path is within the tolerance
  return tightened(c, c.measured_o, printed(c.fit.tol), printed, [&](double aim) { return adaptive_text(c, aim); },
                   "adaptive macro: no aim keeps this curve within the tolerance");
}

}  // namespace ncurve::gen::detail
