// Chamfering and corner R as a path stage, the first: a block's move with ,C ,R (a lathe's C, I,
// K, R) is held until the next move shows where the corner is cut; then both are cut back and the
// chamfer line or corner arc, which belongs to the first block, goes out between them. The words
// are read by the interpreter (chamfer.cpp), which arms the stage with the request.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "machine/path/chamfer.hpp"
#include "machine/path/stage.hpp"

namespace ncurve::machine {

// The block in hand and the offsets in force, as the control has them.
struct CornerContext {
  const nc::Program* prog = nullptr;
  const nc::Block* block = nullptr;
  std::uint64_t step = 0;  // the run's block count
  int side = 0;            // G41 +1, G42 -1, G40 0
  int d = 0;               // D number
  int lathe_offset = 0;    // lathe offset number
};

class CornerControl {
public:
  virtual CornerContext corner_context() const = 0;
  // The offset numbers the moves go out with: the held block's while its moves go out.
  virtual void set_offset_numbers(int d, int lathe_offset) = 0;
  // The block's move is held: it has its move in the plane, put out later.
  virtual void move_held() = 0;

protected:
  ~CornerControl() = default;
};

class CornerStage final : public PathStage {
public:
  // Raises the alarm at `where` (the callback throws).
  using Alarm = std::function<void(const nc::Span& where, const std::string& code, const std::string& message)>;

  CornerStage(bool lathe, CornerControl& control, Alarm alarm)
      : lathe_(lathe), control_(control), alarm_(std::move(alarm)) {}
  // The block's request, before its move.
  void arm(const CornerRequest& r) { armed_ = r; }
  // The armed request's column, which no move took (the request is dropped).
  std::optional<std::uint16_t> take_armed() {
    if (!armed_) return std::nullopt;
    const std::uint16_t column = armed_->column;
    armed_.reset();
    return column;
  }
  const HeldCorner* held() const { return held_ ? &*held_ : nullptr; }
  void drop_held() { held_.reset(); }
  void on_move(const Move& m) override {
    if (!held_ && !armed_) [[likely]] return next_->on_move(m);
    hold_or_cut(m);
  }

private:
  void hold_or_cut(Move m);
  void cut_held_corner(Move& next);
  nc::Span here() const;  // the block in hand
  [[noreturn]] void fail(const nc::Span& where, const std::string& code, const std::string& message) const;

  bool lathe_;
  CornerControl& control_;
  Alarm alarm_;
  std::optional<CornerRequest> armed_;  // this block's request, until its move comes
  std::optional<HeldCorner> held_;
};

}  // namespace ncurve::machine
