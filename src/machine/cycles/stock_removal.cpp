// Tool paths of the lathe multiple repetitive cycles from a finishing shape (see stock_removal.hpp).
#include "machine/cycles/stock_removal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncurve::machine::mrc {

namespace {
constexpr double kTol = 1e-7;  // mm: a point this close to a level is on it
constexpr double kTwoPi = 2 * std::numbers::pi;

int sign(double v, double tol = kTol) { return v > tol ? 1 : v < -tol ? -1 : 0; }
double radius(const Element& e) { return std::hypot(e.start.x - e.centre.x, e.start.y - e.centre.y); }
double start_angle(const Element& e) { return std::atan2(e.start.x - e.centre.x, e.start.y - e.centre.y); }

// The parameter t in (0, 1) at which an arc reaches angle theta, or -1.
double arc_param(const Element& e, double theta) {
  double delta = std::fmod(theta - start_angle(e), kTwoPi);
  if (e.sweep > 0 && delta < 0) delta += kTwoPi;
  if (e.sweep < 0 && delta > 0) delta -= kTwoPi;
  const double t = delta / e.sweep;
  return t > 1e-12 && t < 1 - 1e-12 ? t : -1;
}

// Rate of change of X (axis 0) or Z (axis 1) along the element at t.
double rate(const Element& e, int axis, double t) {
  if (!e.arc) return axis == 0 ? e.end.x - e.start.x : e.end.y - e.start.y;
  const double th = start_angle(e) + t * e.sweep;
  return axis == 0 ? std::cos(th) * e.sweep : -std::sin(th) * e.sweep;
}

// Where, inside the element, the coordinate turns (arcs only), ascending.
std::vector<double> turns(const Element& e, int axis) {
  std::vector<double> ts;
  if (!e.arc) return ts;
  const double pi = std::numbers::pi;
  for (double th : axis == 0 ? std::vector<double>{pi / 2, -pi / 2} : std::vector<double>{0, pi})
    if (double t = arc_param(e, th); t > 0) ts.push_back(t);
  std::sort(ts.begin(), ts.end());
  return ts;
}

// Where, inside the element, X equals `level`, ascending.
std::vector<double> crossings(const Element& e, double level) {
  std::vector<double> ts;
  if (!e.arc) {
    const double dx = e.end.x - e.start.x;
    if (std::fabs(dx) > 1e-12) {
      const double t = (level - e.start.x) / dx;
      if (t > 1e-12 && t < 1 - 1e-12) ts.push_back(t);
    }
    return ts;
  }
  const double v = (level - e.centre.x) / radius(e);
  if (std::fabs(v) > 1) return ts;
  const double th = std::asin(std::clamp(v, -1.0, 1.0));
  for (double a : {th, std::numbers::pi - th})
    if (double t = arc_param(e, a); t > 0) ts.push_back(t);
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end(), [](double a, double b) { return b - a < 1e-12; }), ts.end());
  return ts;
}

struct Loc {
  int elem = 0;
  double t = 0;
};

P2 at_loc(const Shape& c, Loc l) { return point_at(c[l.elem], l.t); }

// The place on the shape nearest p.
Loc locate(const Shape& c, P2 p) {
  Loc best;
  double best_d = 1e300;
  for (int i = 0; i < static_cast<int>(c.size()); ++i) {
    const Element& e = c[i];
    double t = 0;
    if (!e.arc) {
      const double dx = e.end.x - e.start.x, dz = e.end.y - e.start.y, len2 = dx * dx + dz * dz;
      t = len2 > 0 ? std::clamp(((p.x - e.start.x) * dx + (p.y - e.start.y) * dz) / len2, 0.0, 1.0) : 0;
    } else {
      const double th = std::atan2(p.x - e.centre.x, p.y - e.centre.y);
      t = arc_param(e, th);
      if (t < 0) {
        const P2 s = e.start, en = e.end;
        t = std::hypot(p.x - s.x, p.y - s.y) <= std::hypot(p.x - en.x, p.y - en.y) ? 0 : 1;
      }
    }
    const P2 q = point_at(e, t);
    const double dist = std::hypot(q.x - p.x, q.y - p.y);
    if (dist < best_d - 1e-12) best_d = dist, best = {i, t};
  }
  return best;
}

class Builder {
public:
  explicit Builder(P2 start) : at_(start) {}
  void line(bool rapid, P2 to) {
    if (std::hypot(to.x - at_.x, to.y - at_.y) > 1e-9) push(Step{rapid, to, false, {}, 0});
    at_ = to;
  }
  // The shape from one place to a later one, as its elements are (G00 elements as rapids if kept).
  void along(const Shape& c, Loc from, Loc to, bool keep_rapid) {
    for (int i = from.elem; i <= to.elem && i < static_cast<int>(c.size()); ++i) {
      const Element& e = c[i];
      const double ta = i == from.elem ? from.t : 0, tb = i == to.elem ? to.t : 1;
      if (tb <= ta) continue;
      const P2 end = point_at(e, tb);
      if (!e.arc) {
        line(keep_rapid && e.rapid, end);
      } else if (std::hypot(end.x - at_.x, end.y - at_.y) > 1e-9 || tb - ta > 0.5) {
        push(Step{false, end, true, e.centre, e.sweep * (tb - ta)});
        at_ = end;
      }
    }
  }
  P2 at() const { return at_; }
  Path take() { return std::move(path_); }

private:
  void push(const Step& s) {
    if (path_.size() >= kMaxCyclePath) throw PathTooLong();
    path_.push_back(s);
  }
  P2 at_;
  Path path_;
};

// From `from`, along the shape (forward, or back towards its start) while it moves away from the
// depth (X against d): stops where X reaches `stop`, where the shape turns, or at the shape's end.
Loc walk(const Shape& c, Loc from, double stop, int d, bool forward) {
  const int n = static_cast<int>(c.size());
  int i = from.elem;
  double t = from.t;
  const int step = forward ? 1 : -1;
  for (;;) {
    if (forward && t >= 1 - 1e-12) {
      if (i + 1 >= n) return {n - 1, 1};
      ++i, t = 0;
    } else if (!forward && t <= 1e-12) {
      if (i == 0) return {0, 0};
      --i, t = 1;
    }
    const Element& e = c[i];
    const P2 here = point_at(e, t);
    if (d * (here.x - stop) <= kTol) return {i, t};  // at the level already
    // the direction of travel just past t: moving deeper means the shape turned
    const double probe = std::clamp(t + step * 1e-9, 0.0, 1.0);
    if (d * rate(e, 0, probe) * step > 1e-12) return {i, t};
    std::vector<double> cand = crossings(e, stop);
    for (double u : turns(e, 0)) cand.push_back(u);
    double next = forward ? 1.0 : 0.0;
    bool hit = false;
    for (double u : cand)
      if (forward ? (u > t + 1e-12 && u <= next) : (u < t - 1e-12 && u >= next)) next = u, hit = true;
    if (hit) return {i, next};
    t = next;
  }
}

// The extreme X of the shape towards d over the Z range lo..hi (in cutting order u = s * z).
double extreme_x(const Shape& c, int s, double lo, double hi, int d) {
  double best = d > 0 ? -1e300 : 1e300;
  auto take = [&](P2 p) {
    const double u = s * p.y;
    if (u >= lo - kTol && u <= hi + kTol) best = d > 0 ? std::max(best, p.x) : std::min(best, p.x);
  };
  for (const Element& e : c) {
    std::vector<double> ts{0, 1};
    for (double t : turns(e, 0)) ts.push_back(t);
    for (double bound : {lo, hi}) {  // where the element enters or leaves the range
      const double z = bound * s;
      if (!e.arc) {
        const double dz = e.end.y - e.start.y;
        if (std::fabs(dz) > 1e-12) ts.push_back(std::clamp((z - e.start.y) / dz, 0.0, 1.0));
      } else {
        const double v = (z - e.centre.y) / radius(e);
        if (std::fabs(v) <= 1)
          for (double a : {std::acos(v), -std::acos(v)})
            if (double t = arc_param(e, a); t > 0) ts.push_back(t);
      }
    }
    for (double t : ts) take(point_at(e, t));
  }
  return best;
}

int cut_direction(const Shape& c) {
  const int s = sign(c.back().end.y - c.front().start.y);
  return s != 0 ? s : -1;
}

int infeed_direction(const Roughing& r) {
  const Shape& c = r.shape;
  const int d = sign(c.front().start.x - r.start.x);
  if (d != 0) return d;
  const int s = cut_direction(c);
  return extreme_x(c, s, -1e300, 1e300, -1) < r.start.x - kTol ? -1 : 1;
}

}  // namespace

P2 point_at(const Element& e, double t) {
  if (t <= 0) return e.start;
  if (t >= 1) return e.end;
  if (!e.arc) return {e.start.x + t * (e.end.x - e.start.x), e.start.y + t * (e.end.y - e.start.y)};
  const double r = radius(e), th = start_angle(e) + t * e.sweep;
  return {e.centre.x + r * std::sin(th), e.centre.y + r * std::cos(th)};
}

Shape translated(const Shape& s, P2 by) {
  Shape out = s;
  for (Element& e : out) {
    e.start.x += by.x, e.start.y += by.y;
    e.end.x += by.x, e.end.y += by.y;
    e.centre.x += by.x, e.centre.y += by.y;
  }
  return out;
}

P2 transposed(P2 p) { return {p.y, p.x}; }

Shape transposed(const Shape& s) {
  Shape out = s;
  for (Element& e : out) {
    e.start = transposed(e.start), e.end = transposed(e.end), e.centre = transposed(e.centre);
    e.sweep = -e.sweep;
  }
  return out;
}

Path transposed(const Path& p) {
  Path out = p;
  for (Step& s : out) {
    s.end = transposed(s.end), s.centre = transposed(s.centre);
    s.sweep = -s.sweep;
  }
  return out;
}

int first_reversal(const Shape& s, int axis) {
  int dir = 0;
  for (int i = 0; i < static_cast<int>(s.size()); ++i) {
    const Element& e = s[i];
    for (double t : turns(e, axis)) {  // an arc that turns inside itself, by more than the tolerance
      auto along = [&](P2 p) { return axis == 0 ? p.x : p.y; };
      const double at = along(point_at(e, t));
      if (std::min(std::fabs(at - along(e.start)), std::fabs(at - along(e.end))) > kTol) return i;
    }
    const int here = sign(rate(e, axis, 0.5), 1e-12);
    if (here == 0) continue;
    if (dir != 0 && here != dir) return i;
    dir = here;
  }
  return -1;
}

std::vector<Span> spans_at(const Shape& c, double z0, double level, int d) {
  std::vector<Span> out;
  if (c.empty()) return out;
  const int s = cut_direction(c);
  const double u0 = s * z0;
  auto allowed = [&](double x) { return d * (x - level) >= -kTol; };
  std::vector<std::pair<double, double>> r;  // allowed ranges of u = s * z
  const P2 first = c.front().start;
  if (s * first.y > u0 + kTol && allowed(first.x)) r.emplace_back(u0, s * first.y);
  for (const Element& e : c) {
    std::vector<double> ts{0};
    for (double t : crossings(e, level)) ts.push_back(t);
    ts.push_back(1);
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      if (!allowed(point_at(e, (ts[k] + ts[k + 1]) / 2).x)) continue;
      const double ua = s * point_at(e, ts[k]).y, ub = s * point_at(e, ts[k + 1]).y;
      r.emplace_back(std::min(ua, ub), std::max(ua, ub));
    }
  }
  std::sort(r.begin(), r.end());
  std::vector<std::pair<double, double>> merged;
  for (auto [lo, hi] : r) {
    if (!merged.empty() && lo <= merged.back().second + kTol) merged.back().second = std::max(merged.back().second, hi);
    else merged.emplace_back(lo, hi);
  }
  for (auto [lo, hi] : merged) {
    lo = std::max(lo, u0);
    if (hi - lo >= kTol) out.push_back(Span{s * lo, s * hi});
  }
  return out;
}

std::vector<double> roughing_levels(const Roughing& r) {
  std::vector<double> levels;
  if (r.shape.empty() || !(r.depth > 0)) return levels;
  const int d = infeed_direction(r);
  const double deepest = extreme_x(r.shape, cut_direction(r.shape), -1e300, 1e300, d);
  const double x0 = r.start.x;
  for (int k = 1; d * (deepest - x0) > kTol; ++k) {
    const double level = x0 + d * k * r.depth;
    if (d * (level - deepest) >= -kTol) {
      levels.push_back(deepest);
      break;
    }
    levels.push_back(level);
  }
  return levels;
}

Path stock_removal(const Roughing& r) {
  Builder b(r.start);
  const Shape& c = r.shape;
  if (c.empty()) return {};
  const int d = infeed_direction(r), s = cut_direction(c);
  const double x0 = r.start.x, z0 = r.start.y, e = r.escape;
  const std::vector<double> grid = roughing_levels(r);

  if (!r.pockets) {  // type I: one cut per level from the start line, 45-degree escape, back along Z
    for (double level : grid) {
      const std::vector<Span> sp = spans_at(c, z0, level, d);
      if (sp.empty() || std::fabs(sp[0].a - z0) > kTol || s * (sp[0].b - z0) <= kTol) continue;
      b.line(r.rapid_infeed, {level, z0});
      b.line(false, {level, sp[0].b});
      b.line(true, {level - d * e, sp[0].b - s * e});
      b.line(true, {level - d * e, z0});
    }
  } else {  // type II: a region at a time, the one nearest the start first, each pass ending up the shape
    struct Region {
      double lo, hi, top;  // u range; the level above it that has been cut
    };
    auto pass = [&](const Span& span, double level, double above) {
      if (d * (b.at().x - above) > kTol) b.line(true, {above - d * e, b.at().y});  // out of a pocket cut before
      if (std::fabs(span.a - z0) <= kTol) {
        b.line(true, {b.at().x, z0});
        b.line(r.rapid_infeed, {level, z0});
      } else {  // into a pocket: down to where its wall starts, then along the wall
        const Loc wall = locate(c, {level, span.a});
        const Loc entry = walk(c, wall, above, d, false);
        const P2 top = at_loc(c, entry);
        b.line(true, {b.at().x, top.y});
        b.line(true, top);
        b.along(c, entry, wall, false);
      }
      b.line(false, {level, span.b});
      const Loc end = locate(c, {level, span.b});
      const P2 on = at_loc(c, end);
      if (std::hypot(on.x - level, on.y - span.b) < 1e-6) b.along(c, end, walk(c, end, above, d, true), false);
      b.line(true, {b.at().x - d * e, b.at().y - s * e});
    };
    auto region = [&](auto& self, Region g) -> void {
      std::vector<Region> pockets;
      double above = g.top;
      const double bottom = extreme_x(c, s, g.lo, g.hi, d);
      for (std::size_t k = 0;; ++k) {
        double level = k < grid.size() ? grid[k] : bottom;
        if (d * (level - above) <= kTol) {
          if (k < grid.size()) continue;
          break;
        }
        if (d * (level - bottom) > kTol) level = bottom;  // the region's own bottom
        if (d * (level - above) <= kTol) break;
        std::vector<Span> sp;
        for (const Span& x : spans_at(c, z0, level, d))
          if (s * x.b >= g.lo - kTol && s * x.a <= g.hi + kTol) sp.push_back(x);
        if (sp.empty()) break;
        for (std::size_t i = 1; i < sp.size(); ++i) pockets.push_back({s * sp[i].a, s * sp[i].b, above});
        pass(sp[0], level, above);
        g.lo = s * sp[0].a, g.hi = s * sp[0].b;
        above = level;
        if (level == bottom) break;
      }
      std::sort(pockets.begin(), pockets.end(), [](const Region& a, const Region& b) { return a.lo < b.lo; });
      for (const Region& p : pockets) self(self, p);
    };
    region(region, Region{s * z0, 1e300, x0});
    if (d * (b.at().x - x0) > kTol) b.line(true, {x0, b.at().y});
    b.line(true, {x0, z0});
  }
  if (r.finish_pass) {  // along the shape moved by the allowance, A'' to B''
    b.line(r.rapid_infeed, c.front().start);
    b.along(c, {0, 0}, {static_cast<int>(c.size()) - 1, 1}, true);
  }
  b.line(true, r.start);
  return b.take();
}

Path pattern_repeating(const Pattern& p) {
  Builder b(p.start);
  if (p.shape.empty()) return {};
  const int n = std::max(p.count, 1);
  for (int j = 1; j <= n; ++j) {
    const double f = n > 1 ? static_cast<double>(n - j) / (n - 1) : 0.0;
    const P2 by{p.allowance.x + p.relief.x * f, p.allowance.y + p.relief.y * f};
    Shape moved = translated(p.shape, by);
    b.line(moved.front().rapid, moved.front().end);  // the first block from A to its moved end
    moved.erase(moved.begin());
    if (!moved.empty()) b.along(moved, {0, 0}, {static_cast<int>(moved.size()) - 1, 1}, true);
    b.line(true, p.start);
  }
  return b.take();
}

Path peck_cycle(const Pecking& p) {
  Builder b(p.start);
  const int sx = sign(p.end.x - p.start.x), sz = sign(p.end.y - p.start.y);
  const double relief = sx != 0 ? -sx * std::fabs(p.relief) : p.relief;
  double x = p.start.x;
  for (;;) {
    if (sz != 0 && p.peck > 0) {
      for (double z = p.start.y;;) {
        double next = z + sz * p.peck;
        if (sz * (next - p.end.y) >= -kTol) next = p.end.y;
        b.line(false, {x, next});
        if (next == p.end.y) break;
        b.line(true, {x, next - sz * p.back});
        z = next;
      }
    }
    b.line(true, {x + relief, p.end.y});
    b.line(true, {x + relief, p.start.y});
    if (sx == 0 || !(p.shift > 0) || std::fabs(x - p.end.x) <= kTol) break;
    double next = x + sx * p.shift;
    if (sx * (next - p.end.x) >= -kTol) next = p.end.x;
    b.line(true, {next, p.start.y});
    x = next;
  }
  b.line(true, p.start);
  return b.take();
}

}  // namespace ncurve::machine::mrc
