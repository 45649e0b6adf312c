// Polar coordinate interpolation (G12.1) and cylindrical interpolation (G07.1) as a path stage:
// the moves of the programmed plane in, the linear and rotary axes' moves out, by pieces within the
// path tolerance of the contour (geometry: developed_path.hpp; the modes: frame/polar_cylindrical.cpp).
#pragma once
#include <cstdint>

#include "machine/path/stage.hpp"

namespace ncurve::machine {

// The axes of the mode, set at G12.1 / G07.1.
struct DevelopedMode {
  bool polar = true;           // G12.1, else G07.1
  int rotary = 5, linear = 0;  // axes (polar: No.5461, No.5460)
  int slot = 1;                // where the hypothetical (polar) or developed (G07.1) coordinate is kept
  int spare = -1;              // G07.1: where the real position of the axis at `slot` is kept (-1: held)
  int p = 0, q = 1;            // the plane's slots
  double held = 0, radius = 0; // held: the axis at `slot`, unmoved; radius: G07.1's r
  double angle0 = 0;           // polar: the rotary axis at G12.1 (deg)
};

// Off, it passes the moves on; on, it keeps where the machine is (and, polar, the linear axis's
// side of the centre and the angle), which the next move starts from.
class DevelopedConversion final : public PathStage {
public:
  // tolerance: mm from the contour; max_rotary_feed: deg/min, above which a polar piece is warned
  // (NC2060, once a block) through `warn`.
  DevelopedConversion(double tolerance, double max_rotary_feed, MoveAlarm warn)
      : tolerance_(tolerance), max_rotary_feed_(max_rotary_feed), warn_(std::move(warn)) {}
  void start(const DevelopedMode& mode, const AxisVector& machine);  // G12.1, G07.1 with r
  void stop() { on_ = false; }                                        // G13.1, G07.1 with 0
  bool on() const { return on_; }
  const DevelopedMode& mode() const { return mode_; }
  const AxisVector& machine() const { return machine_; }  // where the machine is
  void on_move(const Move& m) override {
    if (!on_) return next_->on_move(m);
    convert(m);
  }

private:
  void convert(const Move& m);
  void warn_polar_speed(const Move& m, double degrees, double length, double radius);

  double tolerance_, max_rotary_feed_;
  MoveAlarm warn_;
  bool on_ = false;
  DevelopedMode mode_;
  AxisVector machine_{};
  int sign_ = 1;        // polar: the linear axis's side of the centre
  double angle_ = 0;    // polar: the angle from angle0 (rad)
  std::uint32_t warned_line_ = 0;
};

}  // namespace ncurve::machine
