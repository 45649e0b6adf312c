// Rigid tapping of a mill (M29, or No.5200#0, with G84/G74): the words M29 allows before its cycle
// and what a rigid hole needs. FANUC 0i-MF / 30i-B operator's manuals, "Rigid tapping". The tapping
// motions: hole_cycles.cpp.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "machine/cycles/drilling.hpp"

namespace ncurve::machine {

// At a rigid tapping hole: the spindle speed and the feed it needs.
void Executor::rigid_tapping_check(std::uint16_t column) const {
  if (speed_ <= 0)
    alarm("PS0200", fmt::format("rigid tapping (G{}) without a spindle speed: give S with M29 (M29 S_)", modal_.cycle),
          column);
  if (feed_ <= 0)
    alarm("PS0201", fmt::format("rigid tapping (G{}) without a feed: give F (mm/min under G94, the lead under G95)",
                                modal_.cycle),
          column);
}

// M29 selects rigid tapping for the G84/G74 that follows (or stands in its block); between the two
// the manual allows neither an S command nor an axis move, nor M29 inside a tapping cycle.
void Executor::rigid_tapping_words() {
  if (profile_.lathe()) return;
  const Cmd* m29 = nullptr;
  for (const Cmd& c : cmds_)
    if (c.letter == 'M' && std::lround(c.value) == 29) m29 = &c;
  if (!m29 && !rigid_pending_) return;
  const bool tap_word = std::ranges::any_of(g_codes_, [](int g) { return g == 840 || g == 740; });
  const Cmd* axis = nullptr;
  for (const Cmd& c : cmds_) {
    const int a = axis_index(c.letter);
    if (a >= 0 && has_axis_[a] && !axis) axis = &c;
  }
  if (m29 && !tap_word && (modal_.cycle == 84 || modal_.cycle == 74))
    alarm("PS0203", "M29 in a tapping cycle: give M29 before the G84/G74 block or in it", m29->column);
  if (!m29 && has('S') && !tap_word)
    alarm("PS0203", "an S command between M29 and G84/G74: give S with M29 (M29 S_)", word('S').column);
  if (axis && !tap_word)
    alarm("PS0204", fmt::format("an axis move ({}) between M29 and G84/G74: rigid tapping allows none", axis->letter),
          axis->column);
  if (tap_word) {
    rigid_tapping_ = true;
    rigid_pending_ = false;
  } else {
    rigid_pending_ = true;
  }
}

}  // namespace ncurve::machine
