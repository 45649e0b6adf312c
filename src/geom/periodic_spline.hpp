// A closed curve through points: the periodic cubic spline (C2) parametrised by chord length.
#pragma once
#include <array>
#include <vector>

namespace ncurve::geom {

class PeriodicSpline {
public:
  // At least 4 distinct points; the last joins the first (do not repeat it). Throws on
  // coincident neighbours.
  explicit PeriodicSpline(const std::vector<std::array<double, 2>>& points);
  double length() const { return total_; }  // of the chord polygon: the parameter's period
  // Point and first derivative (per unit of parameter) at s, taken modulo length().
  void eval(double s, std::array<double, 2>& point, std::array<double, 2>& d1) const;

private:
  std::vector<double> s_;                    // knot parameters, s_[0] = 0, size n + 1
  std::vector<std::array<double, 2>> p_, m_;  // points and second derivatives, size n + 1 (wrapped)
  double total_ = 0;
};

}  // namespace ncurve::geom
