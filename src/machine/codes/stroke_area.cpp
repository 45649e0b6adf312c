// Stored stroke limits as the control keeps them: the profile's at power-on, G22's area and
// G22/G23 (path/stroke_check.hpp checks the moves against them).
#include <utility>

#include "machine/executor.hpp"

namespace ncurve::machine {

void Executor::init_stroke_check() {
  stroke_ = StrokeLimits::power_on(profile_, has_axis_);
  stroke_area_switch(!profile_.stroke2_off_at_power_on);
}

// G22 X Y Z I J K: the corners of the area of check 2 in machine coordinates (lathe X and I as
// diameters), then check 2 on.
void Executor::stroke_area_command() {
  const char corner[3][2] = {{'X', 'I'}, {'Y', 'J'}, {'Z', 'K'}};
  for (int a = 0; a < 3; ++a) {
    if (!has_axis_[a]) continue;
    const double scale = a == 0 && profile_.lathe() && profile_.diameter_x ? 0.5 : 1.0;
    if (has(corner[a][0])) stroke_.area_plus[a] = dimension(word(corner[a][0])) * scale;
    if (has(corner[a][1])) stroke_.area_minus[a] = dimension(word(corner[a][1])) * scale;
    if (stroke_.area_plus[a] < stroke_.area_minus[a]) std::swap(stroke_.area_plus[a], stroke_.area_minus[a]);
  }
  stroke_area_switch(true);
}

void Executor::stroke_area_switch(bool on) {
  modal_.stroke2_on = on;
  stroke_.update(on);
}

}  // namespace ncurve::machine
