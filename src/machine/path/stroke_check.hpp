// Stored stroke checks as a path stage: limit 1 (No.1320/No.1321, OT0500/OT0501) and the area of
// check 2 (G22/G23, No.1322/No.1323, No.1300#0 OUT; OT0502/OT0503), on the moves as the tool makes
// them, in machine coordinates (docs/reference-moves.md).
#pragma once
#include <array>

#include "machine/path/stage.hpp"

namespace ncurve::machine {

// The limits, machine coordinates (mm, lathe X a radius). The control keeps them (G22 sets the
// area; whether check 2 is on is its modal state); the stage reads them.
struct StrokeLimits {
  AxisVector limit1_plus{}, limit1_minus{};  // stored stroke limit 1: +-infinity on an axis without one
  AxisVector area_plus{}, area_minus{};      // the area of check 2, plus >= minus
  unsigned area_axes = 0;                    // the axes check 2 works on (bits of X, Y, Z)
  bool area_outside = false;                 // No.1300#0 OUT = 1: the outside of the area is forbidden
  bool in_force = false;                     // some limit is: moves are checked

  // The profile's limits at power-on, on the axes the machine has (update() says whether in force).
  static StrokeLimits power_on(const MachineProfile& p, const std::array<bool, kAxes>& has_axis);
  // in_force, with check 2 on (G22, its area set first) or off (G23).
  void update(bool area_on);
};

// What the check reads of the control's state.
class StrokeFrame {
public:
  virtual AxisVector machine_shift() const = 0;  // machine coordinates = work coordinates + this
  virtual double program_units(int axis, double mm) const = 0;  // a position as the messages show it
  virtual bool area_check_on() const = 0;  // G22: check 2 on

protected:
  ~StrokeFrame() = default;
};

// A move past a limit is an alarm at its block (the control stops the tool at the limit, No.1300#7
// BFA: ncurve stops before the move); without a limit in force the stage costs one flag test.
class StrokeCheck final : public PathStage {
public:
  StrokeCheck(const StrokeLimits& limits, const StrokeFrame& frame, MoveAlarm alarm)
      : limits_(limits), frame_(frame), alarm_(std::move(alarm)) {}
  void on_move(const Move& m) override {
    if (limits_.in_force) [[unlikely]] check(m);
    next_->on_move(m);
  }

private:
  void check(const Move& m) const;
  [[noreturn]] void fail(const Move& m, const char* code, const std::string& message) const;

  const StrokeLimits& limits_;
  const StrokeFrame& frame_;
  MoveAlarm alarm_;
};

}  // namespace ncurve::machine
