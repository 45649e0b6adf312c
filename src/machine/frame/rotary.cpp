// Rotary axes (No.1006#0 ROTx = 1): degrees without inch conversion, roll-over (No.1008#0 ROAx)
// with the shorter way or the sign's way for absolute commands (#1 RABx), and the feed of a move that
// turns one. FANUC 16i/18i-MB operator's manual B-63534EN, "Rotary axis roll-over".
#include <cmath>

#include "machine/executor.hpp"

namespace ncurve::machine {

namespace {
double within_turn(double v, double turn) {  // 0 <= result < turn
  double r = std::fmod(v, turn);
  if (r < 0) r += turn;
  return r >= turn ? 0.0 : r;
}
}  // namespace

void Executor::init_rotary() {
  for (int a = 3; a < kAxes; ++a) {
    rotary_[a] = has_axis_[a] && profile_.rotary[a].rotary;
    rolls_ = rolls_ || (rotary_[a] && profile_.rotary[a].roll_over);
    extra_axes_ = extra_axes_ || has_axis_[a];
  }
}

// A rotary axis word in degrees: the least increment is the mm one whatever G20/G21 say.
double Executor::angle(const Cmd& c) const {
  const double v = c.literal && !c.decimal_point && !profile_.decimal_calculator ? c.value / per_unit_mm_ : c.value;
  return round_to_increment(v, per_unit_mm_);
}

// The end of an absolute command on a roll-over axis: the position within one turn, reached the
// shorter way (RABx = 0; half a turn goes the positive way) or the way of the word's sign, the
// target then being its absolute value (RABx = 1). The move's end is its start plus the turn it
// makes, so that end - start is the travel; wrap_rotary() brings the position back afterwards.
void Executor::roll_over(AxisVector& target) const {
  for (int a = 3; a < kAxes; ++a) {
    if (!roll_word_[a]) continue;
    const RotaryAxis& r = profile_.rotary[a];
    const double turn = r.per_turn;
    const double from = within_turn(coords_.pos[a], turn);
    const double v = roll_value_[a];
    double travel;
    if (r.by_sign) {
      const double to = within_turn(std::fabs(v), turn);
      travel = std::signbit(v) ? -within_turn(from - to, turn) : within_turn(to - from, turn);
    } else {
      travel = within_turn(v, turn) - from;
      if (travel > turn / 2) travel -= turn;
      else if (travel <= -turn / 2) travel += turn;
    }
    target[a] = coords_.pos[a] + travel;
  }
}

void Executor::wrap_rotary() {
  for (int a = 3; a < kAxes; ++a)
    if (rotary_[a] && profile_.rotary[a].roll_over) coords_.pos[a] = within_turn(coords_.pos[a], profile_.rotary[a].per_turn);
}

// The length F applies to in a move that turns A, B or C: FANUC takes the vector of every axis,
// degrees counted as mm (as inches under G20). `linear` is the X Y Z length.
double Executor::combined_length(const AxisVector& from, const AxisVector& to, double linear) const {
  double sq = linear * linear;
  for (int a = 3; a < kAxes; ++a) {
    const double d = (to[a] - from[a]) * (rotary_[a] && modal_.inch ? 25.4 : 1.0);
    sq += d * d;
  }
  return std::sqrt(sq);
}

}  // namespace ncurve::machine
