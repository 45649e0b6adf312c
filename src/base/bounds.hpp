// A refusal of work beyond a documented bound (moves kept, servo ticks, passes, lattice points):
// the command says which option to change and exits 2, as for a bad argument.
#pragma once
#include <stdexcept>

namespace ncurve::base {

struct BoundExceeded : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace ncurve::base
