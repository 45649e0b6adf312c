#include "machine/frame/transforms.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncurve::machine {

namespace {
constexpr double kDegree = std::numbers::pi / 180;
}  // namespace

V2 polar_point(V2 current, std::optional<double> radius, std::optional<double> angle_deg, bool incremental) {
  const double current_angle = std::atan2(current.y, current.x) / kDegree;  // about the origin
  double angle = current_angle;
  if (angle_deg) angle = incremental ? current_angle + *angle_deg : *angle_deg;
  const double a = angle * kDegree;
  if (incremental && radius) return {current.x + *radius * std::cos(a), current.y + *radius * std::sin(a)};
  const double r = radius ? *radius : std::hypot(current.x, current.y);
  return {r * std::cos(a), r * std::sin(a)};
}

bool Transforms::mirroring() const {
  return std::any_of(mirrored.begin(), mirrored.end(), [](bool m) { return m; });
}

AxisVector Transforms::mirror_and_scale(const AxisVector& program) const {
  AxisVector w = program;
  for (int a = 0; a < kAxes; ++a) {
    if (mirrored[a]) w[a] = 2 * mirror_at[a] - w[a];
    if (scaling) w[a] = scale_centre[a] + factor[a] * (w[a] - scale_centre[a]);
  }
  return w;
}

AxisVector Transforms::apply(const AxisVector& program) const {
  AxisVector w = mirror_and_scale(program);
  if (rotating) {
    const V2 r = geom::rotate({w[p] - centre.x, w[q] - centre.y}, angle_deg * kDegree);
    w[p] = centre.x + r.x;
    w[q] = centre.y + r.y;
  }
  return w;
}

AxisVector Transforms::invert(const AxisVector& work) const {
  AxisVector w = work;
  if (rotating) {
    const V2 r = geom::rotate({w[p] - centre.x, w[q] - centre.y}, -angle_deg * kDegree);
    w[p] = centre.x + r.x;
    w[q] = centre.y + r.y;
  }
  for (int a = 0; a < kAxes; ++a) {
    if (scaling) w[a] = scale_centre[a] + (w[a] - scale_centre[a]) / factor[a];
    if (mirrored[a]) w[a] = 2 * mirror_at[a] - w[a];
  }
  return w;
}

AxisVector Transforms::apply_vector(const AxisVector& v) const {
  AxisVector w = v;
  for (int a = 0; a < kAxes; ++a) {
    if (mirrored[a]) w[a] = -w[a];
    if (scaling) w[a] *= factor[a];
  }
  if (rotating) {
    const V2 r = geom::rotate({w[p], w[q]}, angle_deg * kDegree);
    w[p] = r.x;
    w[q] = r.y;
  }
  return w;
}

bool Transforms::reverses(int p_axis, int q_axis) const {
  int flips = 0;
  for (int a : {p_axis, q_axis}) {
    if (mirrored[a]) ++flips;
    if (scaling && factor[a] < 0) ++flips;
  }
  return flips % 2 == 1;
}

double Transforms::radius_factor(int p_axis, int q_axis) const {
  if (!scaling) return 1;
  return std::max(std::fabs(factor[p_axis]), std::fabs(factor[q_axis]));
}

}  // namespace ncurve::machine
