// The A, B and C axes of a profile, which the drawings (of X, Y and Z) leave out: whether each is
// there and rotary, and the range it moved over in the run, so that a drawing can say so.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "machine/move.hpp"
#include "machine/profile.hpp"

namespace ncurve::report {

struct OtherAxes {
  std::array<bool, 3> present{}, rotary{};
  std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};

  explicit OtherAxes(const machine::MachineProfile& profile) {
    for (int k = 0; k < 3; ++k) {
      present[k] = profile.axes.find("ABC"[k]) != std::string::npos;
      rotary[k] = profile.rotary[3 + k].rotary;
    }
  }
  void add(const machine::Move& m) {
    for (int k = 0; k < 3; ++k)
      if (present[k])
        lo[k] = std::min({lo[k], m.start[3 + k], m.end[3 + k]}), hi[k] = std::max({hi[k], m.start[3 + k], m.end[3 + k]});
  }
  // axis k (0: A) is on the machine and was away from 0 in a motion
  bool moved(int k) const { return present[k] && lo[k] <= hi[k] && !(lo[k] == 0 && hi[k] == 0); }
};

}  // namespace ncurve::report
