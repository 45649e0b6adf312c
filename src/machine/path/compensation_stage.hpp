// Cutter / tool-nose radius compensation as a path stage: the programmed moves in, the tool centre's
// (tip's) moves out once the read-ahead has the next move (RadiusCompensation, compensation.hpp).
// Off (G40 and no vector left), it passes the moves on.
#pragma once
#include <optional>

#include "machine/path/compensation.hpp"
#include "machine/path/stage.hpp"

namespace ncurve::machine {

// Where the control keeps the modes compensation reads at each move (a view: read on every move's path).
struct OffsetModes {
  const int* side;         // +1 G41, -1 G42, 0 G40
  const bool* suspended;   // G28/G30/G53 in offset mode: the moves go without the vector
  const bool* drop;        // and the vector goes even where the move stays put in the plane
  const int* plane;        // the offset plane: 17, 18, 19
  const std::optional<V2>* cancel_direction;  // I J K of the G40 block, in the plane
};

// The offset of a move in the plane, as the control has it.
struct OffsetOfMove {
  bool mirrored = false;   // a mirror image reverses the plane: G41 and G42 swap
  double radius = 0;       // D, or the nose radius; negative puts the tool on the other side
  std::optional<V2> tip;   // lathe: the imaginary tip from the nose centre
};

class CompensationControl {
public:
  virtual OffsetOfMove offset_of_move(const PlaneAxes& plane) const = 0;
  virtual double rapid_seconds(const AxisVector& from, const AxisVector& to) const = 0;

protected:
  ~CompensationControl() = default;
};

class CompensationStage final : public PathStage {
public:
  CompensationStage(CompensationSettings settings, OffsetModes modes, const CompensationControl& control,
                    MoveAlarm alarm, MoveAlarm warn)
      : modes_(modes), control_(control),
        comp_(settings, [this](Move& m) { next_->on_move(m); }, std::move(alarm), std::move(warn)) {}
  CompensationStage(const CompensationStage&) = delete;
  CompensationStage& operator=(const CompensationStage&) = delete;

  // The offset is in force, or its vector still is.
  bool active() const { return *modes_.side != 0 || comp_.offset_mode() || comp_.tool_position().has_value(); }
  void on_move(const Move& m) override {
    if (!active()) return next_->on_move(m);
    offset(m);
  }
  // The NC block in hand has a move in the plane that is put out later (held for its corner).
  void note_plane_motion() { plane_motion_ = true; }
  bool block_moved_in_plane() const { return plane_motion_; }
  // An NC block in offset mode without motion in the plane (`at`: the block, its modal motion kind
  // and feed): a G40 (or G41/G42 from cancel mode) ends (starts) the offset by the start-up type's
  // rule; any other such block is one the read-ahead must look past.
  void block_without_plane_motion(const Move& at, bool g40, bool g41);
  void end_block() { plane_motion_ = false; }
  RadiusCompensation& compensation() { return comp_; }

private:
  void offset(const Move& m);

  OffsetModes modes_;
  const CompensationControl& control_;
  RadiusCompensation comp_;
  bool plane_motion_ = false;  // the NC block in hand moved in the offset plane
};

}  // namespace ncurve::machine
