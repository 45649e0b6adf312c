#include "machine/coordinates.hpp"

namespace ncurve::machine {

AxisVector Coordinates::select(int work_index) {
  const AxisVector old = origin;
  const AxisVector& work = work_index <= 6 ? work_offsets[work_index] : extended[work_index - 6];
  AxisVector delta{};
  for (int a = 0; a < kAxes; ++a) {
    origin[a] = work_offsets[0][a] + work[a] + local[a] + shift[a];
    delta[a] = old[a] - origin[a];
    pos[a] += delta[a];
  }
  return delta;
}

// The manual's local coordinate system notes: G92 cancels the G52 offset of the axes it names (those
// it does not name keep theirs); the origin stays put, the local offset folds into the shift.
AxisVector Coordinates::set_current(const AxisVector& given, unsigned named_axes) {
  AxisVector delta{};
  for (int a = 0; a < kAxes; ++a) {
    if (named_axes & (1u << a)) {
      shift[a] += local[a];
      local[a] = 0;
    }
    shift[a] += pos[a] - given[a];
    origin[a] += pos[a] - given[a];
    delta[a] = given[a] - pos[a];
  }
  pos = given;
  return delta;
}

}  // namespace ncurve::machine
