#include "machine/path/statistics.hpp"

#include <algorithm>

namespace ncurve::machine {

void Statistics::note_extent(const AxisVector& p) {
  RunStats& s = stats_;
  if (!s.has_extent) {
    s.min = s.max = p;
    s.has_extent = true;
    return;
  }
  for (int a = 0; a < kAxes; ++a) {
    s.min[a] = std::min(s.min[a], p[a]);
    s.max[a] = std::max(s.max[a], p[a]);
  }
}

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
  const Setup now = setup_source_.setup_now();
  if (!setup_sent_ || !(now == setup_)) {
    setup_ = now;
    setup_sent_ = true;
    next_->on_setup(now);
  }
  next_->on_move(m);
}

}  // namespace ncurve::machine
