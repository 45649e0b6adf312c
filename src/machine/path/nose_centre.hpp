// Lathe, --nose-centre: the moves as the tool-nose centre makes them, not the imaginary tip (the
// tip's path less the tip's offset from the centre), a stage between the stroke check and the statistics.
#pragma once
#include "geom/plane.hpp"
#include "machine/path/stage.hpp"

namespace ncurve::machine {

// The imaginary tip from the nose centre, (Z, X as a radius), for the move in hand.
class NoseTipSource {
public:
  virtual geom::V2 nose_tip_now() const = 0;

protected:
  ~NoseTipSource() = default;
};

class NoseCentre final : public PathStage {
public:
  explicit NoseCentre(const NoseTipSource& tip) : tip_(tip) {}
  void on_move(const Move& m) override {
    const geom::V2 tip = m.is_motion() ? tip_.nose_tip_now() : geom::V2{};
    if (tip.x == 0 && tip.y == 0) return next_->on_move(m);
    Move centre = m;
    centre.start[2] -= tip.x, centre.start[0] -= tip.y;
    centre.end[2] -= tip.x, centre.end[0] -= tip.y;
    if (m.kind == MoveKind::arc) centre.center[2] -= tip.x, centre.center[0] -= tip.y;
    next_->on_move(centre);
  }

private:
  const NoseTipSource& tip_;
};

}  // namespace ncurve::machine
