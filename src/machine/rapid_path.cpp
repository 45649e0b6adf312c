#include "machine/rapid_path.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ncurve::machine {

std::vector<AxisVector> rapid_path(const AxisVector& start, const AxisVector& end, const AxisVector& rates, bool linear) {
  if (linear) return {start, end};
  // each axis arrives at |d| / rate; a corner at each arrival before the last
  std::array<double, kAxes> arrive{};
  for (int a = 0; a < kAxes; ++a) {
    const double d = std::fabs(end[a] - start[a]), rate = rates[a];
    arrive[a] = d == 0 ? 0 : rate > 0 ? d / rate : 0;
  }
  std::array<double, kAxes> times = arrive;
  std::sort(times.begin(), times.end());
  std::vector<AxisVector> path{start};
  const double last = times.back();
  for (double t : times) {
    if (t <= 0 || t >= last) continue;
    AxisVector p;
    for (int a = 0; a < kAxes; ++a)
      p[a] = arrive[a] <= t ? end[a] : start[a] + (end[a] - start[a]) * (t / arrive[a]);
    if (p != path.back()) path.push_back(p);
  }
  if (end != path.back() || path.size() == 1) path.push_back(end);
  return path;
}

}  // namespace ncurve::machine
