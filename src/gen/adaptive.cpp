// adaptive-macro: a WHILE loop in which the control takes each next parameter step from the
// curvature ahead, with the vertices moved outward by the tolerance band (as the equal-error
// lines), so that the executed moves are about as few as the equal-error expansion.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gen/forms.hpp"
#include "geom/search.hpp"

namespace ncurve::gen::detail {
namespace {

using geom::Sym;
using geom::SymOp;
using geom::Vec3;

// Derivatives of the contour in the plane of the control's arcs (mill X, Y; lathe Z, X as a radius),
// or in space for a curve that rises in Z.
struct Local {
  Vec3 p, d1, d2;  // machine coordinates
};

Local local(const Context& c, double t) {
  geom::Curve::Jet j = c.curve.jet(t);
  Local l{c.map(j.p), {}, {}};
  for (int k = 0; k < 3; ++k) {
    l.d1[k] = c.map.from[k] >= 0 ? j.d1[c.map.from[k]] : 0.0;
    l.d2[k] = c.map.from[k] >= 0 ? j.d2[c.map.from[k]] : 0.0;
  }
  return l;
}

// Speed, signed curvature in the plane (space: unsigned), as the macro computes them.
struct Turning {
  double speed, signed_k, k;
};

Turning turning(const Context& c, const Local& l) {
  if (c.with_z) {
    double s2 = l.d1[0] * l.d1[0] + l.d1[1] * l.d1[1] + l.d1[2] * l.d1[2];
    double a2 = l.d2[0] * l.d2[0] + l.d2[1] * l.d2[1] + l.d2[2] * l.d2[2];
    double va = l.d1[0] * l.d2[0] + l.d1[1] * l.d2[1] + l.d1[2] * l.d2[2];
    double s = std::sqrt(s2);
    double k = std::sqrt(std::fabs(s2 * a2 - va * va)) / (s * s * s);
    return {s, k, k};
  }
  const int u = c.fit.plane.u_axis, v = c.fit.plane.v_axis;
  double s = std::sqrt(l.d1[u] * l.d1[u] + l.d1[v] * l.d1[v]);
  double k = (l.d1[u] * l.d2[v] - l.d1[v] * l.d2[u]) / (s * s * s);
  return {s, k, std::fabs(k)};
}

// Curvature past an inflection weighs this much of its extrapolated size at the end of the step.
constexpr double kEndWeight = 0.75;
constexpr int kDigits = 12;  // decimals of the macro's constants

// The vertex for parameter t: the curve point moved outward by the band (not at the curve's
// ends, and not for a space curve), snapped as the control rounds it.
Vec3 vertex(const Context& c, const AdaptiveRule& r, double t, const Local& l, const Turning& tn) {
  const int u = c.fit.plane.u_axis, v = c.fit.plane.v_axis;
  double off = tn.signed_k > 0 ? -r.offset : r.offset;
  if (t >= c.curve.t1() || t <= c.curve.t0()) off = 0;
  Vec3 p = l.p;
  if (!c.with_z) {
    p[u] += off * -l.d1[v] / tn.speed;
    p[v] += off * l.d1[u] / tn.speed;
  }
  return c.fit.grid.snap(p);
}

// The curvature the first step is taken for: the one whose step is the longest first move
// within the tolerance (the macro starts with it instead of a curvature behind the start).
// Constants as the macro prints them, so that the control computes with the same numbers.
double printed(double v) { return std::stod(number(v, kDigits)); }

double first_speed(const Context& c) { return printed(turning(c, local(c, c.curve.t0())).speed); }

double first_curvature(const Context& c, const AdaptiveRule& r) {
  return printed(std::pow(r.factor / (r.first_step * first_speed(c)), 2));
}

// The vertices the macro produces for a rule, step by step as the control computes them.
std::vector<std::pair<double, Vec3>> run_rule(const Context& c, const AdaptiveRule& r) {
  const double t0 = c.curve.t0(), t1 = c.curve.t1();
  std::vector<std::pair<double, Vec3>> out{{t0, c.start}};
  double t = t0;
  Turning tn = turning(c, local(c, t));
  const double k_first = first_curvature(c, r);
  tn.signed_k = tn.k = k_first;
  tn.speed = first_speed(c);
  double k_prev = k_first, dt_prev = t1 - t0;
  while (t < t1) {
    // signed curvature extrapolated along the last step: its middle and (weighted) its end
    double ahead = std::fabs(1.5 * tn.signed_k - 0.5 * k_prev);
    double at_end = std::fabs(2 * tn.signed_k - k_prev) * kEndWeight;
    if (ahead < at_end) ahead = at_end;
    if (ahead < 0.5 * tn.k) ahead = 0.5 * tn.k;
    if (ahead < r.min_curvature) ahead = r.min_curvature;
    k_prev = tn.signed_k;
    double dt = r.factor / std::sqrt(ahead) / tn.speed;
    if (dt > 1.5 * dt_prev) dt = 1.5 * dt_prev;
    dt_prev = dt;
    t += dt;
    if (t > t1) t = t1;
    Local l = local(c, t);
    tn = turning(c, l);
    out.emplace_back(t, vertex(c, r, t, l, tn));
    if (out.size() > 20'000'000) throw std::runtime_error("adaptive macro: more than 20 million moves");
  }
  return out;
}

double rule_error(const Context& c, const std::vector<std::pair<double, Vec3>>& vs) {
  double worst = 0;
  for (std::size_t i = 1; i < vs.size(); ++i) {
    const Vec3 &a = vs[i - 1].second, &b = vs[i].second;
    auto w = geom::max_distance(c.curve, c.fit.place, vs[i - 1].first, vs[i].first,
                                [&](const Vec3& p) { return geom::point_segment_distance(p, a, b); });
    worst = std::max(worst, w.distance);
  }
  return std::max(worst, geom::point_segment_distance(c.map(c.curve.point(c.curve.t1())), vs.back().second,
                                                      vs.back().second));
}

std::string assign(int var, const Sym& e, int& next_temp, std::vector<std::string>& blocks) {
  std::vector<std::pair<int, Sym>> temps;
  Sym limited = geom::limit_depth(e, 5, next_temp, temps);
  for (const auto& [t, s] : temps) blocks.push_back(fmt::format("#{}={}", t, geom::to_macro(s)));
  blocks.push_back(fmt::format("#{}={}", var, geom::to_macro(limited)));
  return blocks.back();
}

Sym axis_derivative(const Context& c, int axis, int order) {
  if (c.map.from[axis] < 0) return geom::konst(0);
  return (order == 1 ? c.curve.first() : c.curve.second())[c.map.from[axis]];
}

}  // namespace

AdaptiveRule adaptive_rule(const Context& c) {
  const double tol = c.fit.tol;
  const double rounding = c.fit.grid.worst_error();
  if (tol <= rounding)
    throw std::runtime_error(fmt::format("tolerance {} mm is not above the coordinate rounding ({:.6f} mm)", tol,
                                         rounding));
  AdaptiveRule r;
  // a plane contour's vertices sit outward by the band, the chords' middle inward by as much
  r.offset = printed(c.with_z ? 0.0 : tol - rounding);
  const double nominal = c.with_z ? std::sqrt(8 * (tol - rounding)) : 4 * std::sqrt(r.offset);
  double length = 0;
  Vec3 prev = c.map(c.curve.point(c.curve.t0()));
  for (int i = 1; i <= 256; ++i) {
    Vec3 q = c.map(c.curve.point(c.curve.t0() + (c.curve.t1() - c.curve.t0()) * i / 256));
    length += std::hypot(q[0] - prev[0], q[1] - prev[1], q[2] - prev[2]);
    prev = q;
  }
  // no chord longer than a quarter of the curve where it is straight
  r.min_curvature = printed(std::pow(nominal / (0.25 * length), 2));
  // the first move: the longest within the tolerance from the start point on the curve
  {
    const double t0 = c.curve.t0(), span = c.curve.t1() - t0;
    const Vec3 a = c.start;
    auto ok = [&](double dt) {
      double t = t0 + dt;
      Local l = local(c, t);
      Vec3 b = vertex(c, r, t, l, turning(c, l));
      auto w = geom::max_distance(c.curve, c.fit.place, t0, t,
                                  [&](const Vec3& p) { return geom::point_segment_distance(p, a, b); });
      return w.distance <= tol;
    };
    Turning tn = turning(c, local(c, t0));
    double guess = t0 + std::min(span, 0.8 * nominal / std::sqrt(std::max(tn.k, r.min_curvature)) / tn.speed);
    double lo = geom::longest_step(t0, t0 + span, guess, [&](double t) { return ok(t - t0); }, span, [] {
                  return std::string("adaptive macro: no first move within the tolerance");
                }) - t0;
    // not on the edge of a rounding cell: small changes of the control's arithmetic must not
    // move a vertex to the next increment
    auto robust = [&](double dt) { return ok(dt) && ok(dt * (1 - 1e-7)) && ok(dt * (1 + 1e-7)); };
    while (!robust(lo) && lo > 1e-12 * span) lo *= 1 - 1e-5;
    r.first_step = lo;
  }
  // the largest step factor whose moves stay within the tolerance (the rule is run exactly as
  // the control will run it and measured by optimisation on every move)
  auto passes_exactly = [&](double f) {
    AdaptiveRule trial = r;
    trial.factor = printed(f * nominal);
    return rule_error(c, run_rule(c, trial)) <= tol;
  };
  auto passes = [&](double f) {
    return passes_exactly(f) && passes_exactly(f * (1 - 1e-7)) && passes_exactly(f * (1 + 1e-7));
  };
  double lo = 1.0, hi = 1.25;
  if (passes(hi)) {
    lo = hi;
  } else if (!passes(lo)) {
    hi = lo;
    lo = 0.5;
    while (!passes(lo)) {
      hi = lo;
      lo *= 0.5;
      if (lo < 1e-3) throw std::runtime_error("adaptive macro: no step rule keeps this curve within the tolerance");
    }
  }
  for (int i = 0; i < 10 && hi > lo; ++i) {
    double mid = 0.5 * (lo + hi);
    if (passes(mid)) lo = mid; else hi = mid;
  }
  r.factor = printed(lo * nominal);
  return r;
}

Emitted adaptive_macro(const Context& c) {
  const Options& o = c.o;
  const AdaptiveRule rule = adaptive_rule(c);

  Writer w;
  macro_preamble(w, c, fmt::format("step from the curvature, {} band", c.with_z ? "chords" : "tolerance"));
  w.block(fmt::format("#115={} (VERTEX OFFSET OUTWARD, MM)", number(rule.offset, kDigits)));
  w.block(fmt::format("#116={} (STEP FACTOR: CHORD = #116/SQRT[CURVATURE])", number(rule.factor, kDigits)));
  w.block(fmt::format("#117={} (LEAST CURVATURE, 1/MM)", number(rule.min_curvature, kDigits)));
  w.block("(#118 #119 CURVATURE BEHIND, AHEAD; #120.. DERIVATIVES; #126 SPEED; #129 T STEP)");
  w.block(modes(o));
  w.block("#100=#110");
  w.block(fmt::format("#126={} (SPEED AT T START)", number(first_speed(c), kDigits)));
  w.block(fmt::format("#127={} (CURVATURE FOR THE FIRST STEP)", number(first_curvature(c, rule), kDigits)));
  w.block("#128=#127");
  w.block("#118=#127");
  w.block("#129=#111-#110");
  int next = kFirstTemp;
  MacroWords start = macro_words(point_axes(c.curve, c.map, o, c.with_z), next);
  approach(w, c, start);

  w.block("WHILE [#100 LT #111] DO1");
  step_blocks(w);
  w.block("#100=#100+#129");
  w.block("IF [#100 GT #111] THEN #100=#111");
  next = kFirstTemp;
  for (const auto& b : curvature_blocks(c, next)) w.block(b);
  return close_loop(w, c, macro_words(vertex_axes(c), next));
}

void step_blocks(Writer& w) {
  w.block("#119=ABS[1.5*#127-0.5*#118]");
  w.block(fmt::format("#131=ABS[2*#127-#118]*{}", number(kEndWeight, 6)));
  w.block("IF [#119 LT #131] THEN #119=#131");
  w.block("#131=0.5*#128");
  w.block("IF [#119 LT #131] THEN #119=#131");
  w.block("IF [#119 LT #117] THEN #119=#117");
  w.block("#118=#127");
  w.block("#131=1.5*#129");
  w.block("#129=#116/SQRT[#119]/#126");
  w.block("IF [#129 GT #131] THEN #129=#131");
}

std::vector<std::string> curvature_blocks(const Context& c, int& next) {
  const int u = c.fit.plane.u_axis, v = c.fit.plane.v_axis;
  std::vector<std::string> blocks;
  if (c.with_z) {
    for (int k = 0; k < 3; ++k) assign(120 + k, axis_derivative(c, k, 1), next, blocks);
    for (int k = 0; k < 3; ++k) assign(123 + k, axis_derivative(c, k, 2), next, blocks);
    blocks.push_back("#126=SQRT[#120*#120+#121*#121+#122*#122]");
    blocks.push_back(
        "#127=SQRT[ABS[#126*#126*[#123*#123+#124*#124+#125*#125]-[#120*#123+#121*#124+#122*#125]*[#120*#123+#121*"
        "#124+#122*#125]]]/[#126*#126*#126]");
    blocks.push_back("#128=#127");
  } else {
    assign(120, axis_derivative(c, u, 1), next, blocks);
    assign(121, axis_derivative(c, v, 1), next, blocks);
    assign(122, axis_derivative(c, u, 2), next, blocks);
    assign(123, axis_derivative(c, v, 2), next, blocks);
    blocks.push_back("#126=SQRT[#120*#120+#121*#121]");
    blocks.push_back("#127=[#120*#123-#121*#122]/[#126*#126*#126]");
    blocks.push_back("#128=ABS[#127]");
    blocks.push_back("#130=#115");
    blocks.push_back("IF [#127 GT 0] THEN #130=-#115");
    blocks.push_back("IF [#100 GE #111] THEN #130=0");
  }
  return blocks;
}

std::vector<std::pair<char, Sym>> vertex_axes(const Context& c) {
  const int u = c.fit.plane.u_axis, v = c.fit.plane.v_axis;
  std::vector<std::pair<char, Sym>> axes = point_axes(c.curve, c.map, c.o, c.with_z);
  if (c.with_z) return axes;
  // the curve point moved along the normal (-v', u') / speed by #130
  auto shift = [&](int axis) -> Sym {
    Sym n = axis == u ? geom::make(SymOp::neg, geom::variable(121)) : geom::variable(120);
    return geom::make(SymOp::div, geom::make(SymOp::mul, geom::variable(130), n), geom::variable(126));
  };
  for (auto& [letter, e] : axes) {
    int axis = letter == 'X' ? 0 : letter == 'Y' ? 1 : 2;
    if (axis != u && axis != v) continue;
    Sym moved = geom::make(SymOp::add, axis_sym(c.curve, c.map, axis), shift(axis));
    e = is_lathe(c.o) && axis == 0 ? geom::make(SymOp::mul, geom::konst(2), moved) : moved;
  }
  return axes;
}

}  // namespace ncurve::gen::detail
