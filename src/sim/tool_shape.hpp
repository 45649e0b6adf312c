// The cutting end of a mill tool with a vertical axis: the height of its lower surface above its
// tip at each radial distance, which is all the Z-map needs to cut with it.
#pragma once
#include <limits>

namespace ncurve::sim {

class ToolShape {
public:
  enum class Kind { flat, ball, bull_nose, cone };

  static ToolShape flat(double radius);
  static ToolShape ball(double radius);
  // corner radius 0 is a flat end mill, corner == radius a ball
  static ToolShape bull_nose(double radius, double corner);
  // a drill or chamfer point: the included angle in degrees (118 for a common drill, 90 a chamfer)
  static ToolShape cone(double radius, double point_angle_deg);

  Kind kind() const { return kind_; }
  double radius() const { return radius_; }
  double corner() const { return corner_; }
  double point_angle_deg() const { return point_angle_deg_; }

  // Height of the lower surface above the tip at radial distance d (0 <= d <= radius), from the
  // squared distance u = d^2; +infinity beyond the radius (the tool does not reach there).
  double lower(double u) const;
  // The lower surface's height at d = radius, its largest: flat 0, ball R, bull-nose r, cone R/tan.
  double rim_height() const;
  // The inverse of lower: the tool's radius at `height` above its tip (0 below the tip, the radius
  // from the rim up).
  double radius_at(double height) const;

private:
  Kind kind_ = Kind::flat;
  double radius_ = 0;
  double corner_ = 0;
  double point_angle_deg_ = 180;
  double cot_half_ = 0;  // cone: height per unit of radius
};

inline constexpr double kUnreached = std::numeric_limits<double>::infinity();

}  // namespace ncurve::sim
