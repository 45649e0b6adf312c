#include "helicoid/cutter.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "io/number_rows.hpp"

namespace ncurve::helicoid {

double ProfileElement::length() const {
  if (kind == Kind::line) return norm(end - start);
  return radius * std::abs(a1 - a0);
}

DiscCutter::DiscCutter(std::vector<ProfileElement> elements) : elements_(std::move(elements)) {
  if (elements_.empty()) throw std::runtime_error("cutter profile: no elements");
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const auto& e = elements_[i];
    if (!(e.length() > 0)) throw std::runtime_error(fmt::format("cutter profile: element {} has no length", i + 1));
    if (i > 0) {
      const auto& prev = elements_[i - 1].end;
      if (norm(prev - e.start) > 1e-9)
        throw std::runtime_error(fmt::format("cutter profile: element {} does not start where element {} ends", i + 1, i));
    }
    starts_.push_back(total_);
    total_ += e.length();
    outer_ = std::max({outer_, e.start.x, e.end.x});
    if (e.kind == ProfileElement::Kind::arc) {
      double lo = std::min(e.a0, e.a1), hi = std::max(e.a0, e.a1);
      if (lo <= 0 && hi >= 0) outer_ = std::max(outer_, e.centre.x + e.radius);
    }
  }
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    ends_.push_back(at_element(i, 0));
    ends_.push_back(at_element(i, elements_[i].length()));
  }
  for (std::size_t i = 1; i < elements_.size(); ++i) {
    // travelled with the material on the left, a convex corner turns left (towards the material)
    const V2 a = ends_[2 * i - 1].tangent, b = ends_[2 * i].tangent;
    if (cross(a, b) > 1e-9) vertices_.push_back({starts_[i], ends_[2 * i - 1].normal, ends_[2 * i].normal, i});
  }
}

DiscCutter DiscCutter::v_insert(double diameter, double corner_radius, double included_angle, double flank_depth) {
  if (!(diameter > 0) || !(corner_radius >= 0) || !(included_angle > 0 && included_angle < 180) || !(flank_depth > 0))
    throw std::runtime_error("cutter: diameter, flank depth > 0, corner radius >= 0 and 0 < included angle < 180 degrees");
  double half = included_angle / 2 * std::numbers::pi / 180;
  double R = diameter / 2;
  if (corner_radius * (1 - std::sin(half)) >= flank_depth || corner_radius >= R)
    throw std::runtime_error("cutter: the corner radius does not fit the insert");
  // Corner arc centre on the mid plane; tangent points where the flank normal is (sin half, +-cos half).
  V2 c{R - corner_radius, 0};
  double a = std::numbers::pi / 2 - half;
  V2 t_minus{c.x + corner_radius * std::cos(a), -corner_radius * std::sin(a)};
  V2 t_plus{t_minus.x, -t_minus.y};
  // Flanks run inwards at `half` from the radial direction down to rho = R - flank_depth.
  double run = (t_minus.x - (R - flank_depth)) / std::cos(half);
  V2 f_minus{R - flank_depth, t_minus.y - run * std::sin(half)};
  V2 f_plus{f_minus.x, -f_minus.y};
  std::vector<ProfileElement> e;
  e.push_back({ProfileElement::Kind::line, f_minus, t_minus, {}, 0, 0, 0, "flank-"});
  if (corner_radius > 0) e.push_back({ProfileElement::Kind::arc, t_minus, t_plus, c, corner_radius, -a, a, "corner"});
  e.push_back({ProfileElement::Kind::line, t_plus, f_plus, {}, 0, 0, 0, "flank+"});
  return DiscCutter(std::move(e));
}

namespace {

DiscCutter from_rows(const std::vector<io::NumberRow>& rows, const std::string& origin) {
  if (rows.size() < 2) throw std::runtime_error(fmt::format("{}: a cutter profile needs at least 2 vertices", origin));
  auto where = [&](std::size_t k) { return fmt::format("{}:{}:1", origin, rows[k].line); };
  if (rows.back().values.size() > 2 && rows.back().values[2] != 0)
    throw std::runtime_error(where(rows.size() - 1) + ": the last vertex ends the profile: no arc radius after it");
  if (!(rows.front().values[1] < rows.back().values[1]))
    throw std::runtime_error(where(0) + ": list the profile from the -w side over the rim to the +w side (w grows)");
  std::vector<ProfileElement> e;
  for (std::size_t k = 0; k + 1 < rows.size(); ++k) {
    const V2 a{rows[k].values[0], rows[k].values[1]}, b{rows[k + 1].values[0], rows[k + 1].values[1]};
    if (!(a.x > 0) || !(b.x > 0)) throw std::runtime_error(where(a.x > 0 ? k + 1 : k) + ": rho must be > 0 (off the cutter axis)");
    const double r = rows[k].values.size() > 2 ? rows[k].values[2] : 0;
    const std::string n = fmt::format("{}", e.size() + 1);
    if (r == 0) {
      e.push_back({ProfileElement::Kind::line, a, b, {}, 0, 0, 0, "line" + n});
      continue;
    }
    const double chord = norm(b - a), R = std::abs(r);
    if (!(chord > 0)) throw std::runtime_error(where(k) + ": the arc's ends coincide");
    if (R < chord / 2 - 1e-12)
      throw std::runtime_error(fmt::format("{}: arc radius {} is less than half the chord {:.6f}", where(k), R, chord / 2));
    // material on the left of the travel: a convex arc has its centre on the left of the chord
    const V2 left = perp((b - a) / chord);
    const double side = r > 0 ? 1 : -1, off = std::sqrt(std::max(0.0, R * R - chord * chord / 4));
    const V2 c = (a + b) / 2 + off * (side * left);
    const double a0 = std::atan2(a.y - c.y, a.x - c.x);
    double sweep = 2 * std::asin(std::min(1.0, chord / (2 * R)));
    e.push_back({ProfileElement::Kind::arc, a, b, c, R, a0, a0 + side * sweep, "arc" + n});
  }
  // the corner: the convex arc over the outermost point
  double outer = 0;
  for (const auto& x : e) outer = std::max({outer, x.start.x, x.end.x});
  for (auto& x : e)
    if (x.kind == ProfileElement::Kind::arc && x.a1 > x.a0 && x.a0 <= 0 && x.a1 >= 0 && x.centre.x + x.radius >= outer) {
      x.region = "corner";
      break;
    }
  return DiscCutter(std::move(e));
}

}  // namespace

DiscCutter DiscCutter::from_text(const std::string& text, const std::string& origin) {
  return from_rows(io::read_number_rows(text, origin, 2, 3), origin);
}

DiscCutter DiscCutter::from_file(const std::string& path) { return from_rows(io::read_number_file(path, 2, 3), path); }

DiscCutter::Point DiscCutter::at(double s) const {
  s = std::clamp(s, 0.0, total_);
  std::size_t i = 0;
  while (i + 1 < elements_.size() && s > starts_[i + 1]) ++i;
  return at_element(i, s - starts_[i]);
}

DiscCutter::Point DiscCutter::at_element(std::size_t i, double local) const {
  const auto& e = elements_[i];
  Point out;
  out.element = static_cast<int>(i);
  if (e.kind == ProfileElement::Kind::line) {
    double len = e.length();
    V2 t = (e.end - e.start) / len;
    out.p = e.start + local * t;
    out.tangent = t;
    out.normal = {t.y, -t.x};  // material on the left of the direction of travel
  } else {
    double dir = e.a1 > e.a0 ? 1 : -1;
    double ang = e.a0 + dir * local / e.radius;
    V2 radial{std::cos(ang), std::sin(ang)};
    out.p = e.centre + e.radius * radial;
    out.tangent = dir * perp(radial);
    out.normal = dir > 0 ? radial : -radial;
  }
  return out;
}

double DiscCutter::signed_distance(V2 q) const {
  double best = std::numeric_limits<double>::infinity(), sign = 1;
  auto consider = [&](V2 foot, V2 normal) {
    V2 d = q - foot;
    double dist = norm(d);
    if (dist < best) best = dist, sign = dot(d, normal) < 0 ? -1 : 1;
  };
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const auto& e = elements_[i];
    const Point& first = ends_[2 * i];
    consider(first.p, first.normal);
    consider(ends_[2 * i + 1].p, ends_[2 * i + 1].normal);
    if (e.kind == ProfileElement::Kind::line) {
      double len = e.length();
      V2 t = (e.end - e.start) / len;
      double along = dot(q - e.start, t);
      if (along > 0 && along < len) consider(e.start + along * t, first.normal);
    } else {
      double dir = e.a1 > e.a0 ? 1 : -1;
      double ang = std::atan2(q.y - e.centre.y, q.x - e.centre.x);
      double from_start = std::remainder(dir * (ang - e.a0) - std::numbers::pi, 2 * std::numbers::pi) + std::numbers::pi;
      if (from_start < std::abs(e.a1 - e.a0)) {
        V2 radial{std::cos(ang), std::sin(ang)};
        consider(e.centre + e.radius * radial, dir > 0 ? radial : -radial);
      }
    }
  }
  return sign * best;
}

double DiscCutter::corner_middle() const {
  // Outermost point: the largest rho along the profile (sampled, then the exact arc top).
  double best = 0, best_rho = -1;
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const auto& e = elements_[i];
    if (e.kind == ProfileElement::Kind::arc && std::min(e.a0, e.a1) <= 0 && std::max(e.a0, e.a1) >= 0) {
      double s = starts_[i] + e.radius * std::abs(0 - e.a0);
      if (e.centre.x + e.radius > best_rho) best_rho = e.centre.x + e.radius, best = s;
    }
    if (e.start.x > best_rho) best_rho = e.start.x, best = starts_[i];
    if (e.end.x > best_rho) best_rho = e.end.x, best = starts_[i] + e.length();
  }
  return best;
}

}  // namespace ncurve::helicoid
