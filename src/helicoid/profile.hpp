// The end-section profile of a helical workpiece: a closed curve, star-shaped about the axis,
// and the first point where a line meets it (the heart of the directed distance).
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "geom/plane.hpp"

namespace ncurve::geom {
class Curve;
}

namespace ncurve::helicoid {

using geom::V2;

class EndProfile {
public:
  // Point and first derivative (per degree of u) of the unturned curve.
  using Eval = std::function<void(double u, V2& point, V2& d1)>;

  // `period` degrees of u close the curve. It is turned about the axis so that u = u0 faces +X
  // (unless `place` is false). Throws if the curve does not wind once around the axis with every
  // ray crossing it once.
  EndProfile(std::string name, Eval eval, double u0, double period, bool place = true);
  // A curve of `ncurve gen` (its range t0..t1 is one closed turn).
  static EndProfile from_curve(std::shared_ptr<const geom::Curve> curve);
  // Seed 004's screw-drill rotor (five lobes, root r = 35.5 mm at u = 0, crest 50.5 mm at u = 36),
  // evaluated natively: the same curve as `ncurve gen rotor`, several times faster.
  static EndProfile seed004_rotor();
  // A closed point list (x, y in mm, in order around the axis, the last not repeating the first)
  // through which a periodic cubic spline runs; u = 0..360 degrees by chord length from the first
  // point, which is turned to face +X.
  static EndProfile from_points(std::string name, const std::vector<V2>& points);

  const std::string& name() const { return name_; }
  double u0() const { return u0_; }
  double period() const { return period_; }
  double r_min() const { return r_min_; }
  double r_max() const { return r_max_; }
  V2 point(double u) const;
  V2 d1(double u) const;
  V2 outward_normal(double u) const;  // unit

  struct Hit {
    bool found = false;
    double x = 0;  // where the line meets the turned profile, world frame
    double u = 0;  // profile parameter there
  };
  // The profile turned by `phi` degrees about the axis; the line y = `y` travelled from x = +inf
  // towards -inf: where it first meets the profile.
  Hit first_hit(double phi, double y) const;

private:
  void point_and_d1(double u, V2& p, V2& d) const;
  double u_at_angle(double theta) const;  // table: profile polar angle (degrees) -> u
  double table_radius(double theta) const;
  double lookup(const std::vector<double>& table, double theta) const;  // periodic, linear

  std::string name_;
  Eval eval_;
  double u0_, period_;
  double turn_cos_ = 1, turn_sin_ = 0;  // placement
  double r_min_ = 0, r_max_ = 0;
  std::vector<double> theta_, u_, r_;  // table by increasing polar angle, one turn plus overlap
  double cell_ = 0;                    // polar step of the march, degrees
};

}  // namespace ncurve::helicoid
