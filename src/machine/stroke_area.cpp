// G22 X Y Z I J K: the area of stored stroke check 2 (path/stroke_check.hpp checks the moves).
#include <utility>

#include "machine/executor.hpp"

namespace ncurve::machine {

// The corners of the area in machine coordinates (lathe X and I as diameters), then check 2 on.
void Executor::stroke_area_command() {
  const char corner[3][2] = {{'X', 'I'}, {'Y', 'J'}, {'Z', 'K'}};
  for (int a = 0; a < 3; ++a) {
    if (!has_axis_[a]) continue;
    const double scale = a == 0 && profile_.lathe() && profile_.diameter_x ? 0.5 : 1.0;
    if (has(corner[a][0])) stroke_.area_plus[a] = dimension(word(corner[a][0])) * scale;
    if (has(corner[a][1])) stroke_.area_minus[a] = dimension(word(corner[a][1])) * scale;
    if (stroke_.area_plus[a] < stroke_.area_minus[a]) std::swap(stroke_.area_plus[a], stroke_.area_minus[a]);
  }
  stroke_.switch_area(true);
}

}  // namespace ncurve::machine
