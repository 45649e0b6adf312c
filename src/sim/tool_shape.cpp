#include "sim/tool_shape.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ncurve::sim {

namespace {
void check_radius(double r) {
  if (!(r > 0) || !std::isfinite(r)) throw std::invalid_argument("a tool's radius must be positive");
}
}  // namespace

ToolShape ToolShape::flat(double radius) {
  check_radius(radius);
  ToolShape t;
  t.kind_ = Kind::flat;
  t.radius_ = radius;
  return t;
}

ToolShape ToolShape::ball(double radius) {
  ToolShape t = flat(radius);
  t.kind_ = Kind::ball;
  t.corner_ = radius;
  return t;
}

ToolShape ToolShape::bull_nose(double radius, double corner) {
  check_radius(radius);
  if (!(corner >= 0) || corner > radius) throw std::invalid_argument("a bull-nose corner radius must be in [0, radius]");
  if (corner == 0) return flat(radius);
  if (corner == radius) return ball(radius);
  ToolShape t = flat(radius);
  t.kind_ = Kind::bull_nose;
  t.corner_ = corner;
  return t;
}

ToolShape ToolShape::cone(double radius, double point_angle_deg) {
  check_radius(radius);
  if (!(point_angle_deg > 0 && point_angle_deg < 180))
    throw std::invalid_argument("a point angle must be between 0 and 180 degrees");
  ToolShape t = flat(radius);
  t.kind_ = Kind::cone;
  t.point_angle_deg_ = point_angle_deg;
  t.cot_half_ = 1 / std::tan(point_angle_deg * std::numbers::pi / 360);
  return t;
}

double ToolShape::lower(double u) const {
  const double r2 = radius_ * radius_;
  if (u > r2) return kUnreached;
  switch (kind_) {
    case Kind::flat: return 0;
    case Kind::ball: return radius_ - std::sqrt(std::max(r2 - u, 0.0));
    case Kind::bull_nose: {
      double e = std::sqrt(u) - (radius_ - corner_);  // past the flat bottom
      if (e <= 0) return 0;
      return corner_ - std::sqrt(std::max(corner_ * corner_ - e * e, 0.0));
    }
    case Kind::cone: return std::sqrt(u) * cot_half_;
  }
  return kUnreached;
}

double ToolShape::radius_at(double height) const {
  if (!(height >= 0)) return 0;
  if (height >= rim_height()) return radius_;
  switch (kind_) {
    case Kind::flat: return radius_;
    case Kind::ball: case Kind::bull_nose: {
      const double below = corner_ - height;  // under the corner's centre
      return radius_ - corner_ + std::sqrt(std::max(corner_ * corner_ - below * below, 0.0));
    }
    case Kind::cone: return height / cot_half_;
  }
  return radius_;
}

double ToolShape::rim_height() const {
  switch (kind_) {
    case Kind::flat: return 0;
    case Kind::ball: case Kind::bull_nose: return corner_;
    case Kind::cone: return radius_ * cot_half_;
  }
  return 0;
}

}  // namespace ncurve::sim
