#include "machine/path/statistics.hpp"

namespace ncurve::machine {

void Statistics::on_move(const Move& m) {
  RunStats& s = stats_;
  ++s.by_kind[static_cast<int>(m.kind)];
  if (m.is_motion()) {
    ++s.motions;
    if (m.kind == MoveKind::rapid) s.rapid_length += m.length;
    else s.feed_length += m.length;
    if (s.motions == 1) note_extent(m.start);
    note_extent(m.end);
  }
  s.seconds += m.seconds;
  if (!setup_sent_ || !setup_view_.same_as(setup_)) [[unlikely]] {
    setup_ = setup_view_.now();
    setup_sent_ = true;
    next_->on_setup(setup_);
  }
  next_->on_move(m);
}

}  // namespace ncurve::machine
