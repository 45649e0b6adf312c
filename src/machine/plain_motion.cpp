// The lane of an expanded program's blocks: G00/G01 with literal X, Y, Z and F, each once
// (nc::Block::plain_motion), run where nothing else acts on them. It has the general path's effect
// (exec_nc: read_words, handle_g_codes, word_settings, block_motion, linear) in a few steps; the
// tests run every program both ways and compare.
#include <algorithm>

#include "machine/executor.hpp"

namespace ncurve::machine {

// No cycle, compensation, transform, developed path, corner or macro call can act on the block,
// the machine is a mill with X, Y and Z, and the block's motion is G00 or G01.
bool Executor::plain_lane_open(const nc::Block& b) const {
  if (!options_.plain_lane || modal_.cycle != 0 || modal_.comp_side != 0 || corner_on_ || tool_changed_ ||
      rigid_pending_ || xf_hook_ || developed_hook_ || developed_ || rolls_ || shape_moves_ || !modal_calls_.empty() ||
      profile_.lathe() || !has_axis_[0] || !has_axis_[1] || !has_axis_[2] || compensating() || comp_->offset_mode())
    return false;
  if (b.plain_motion == nc::PlainMotion::modal) return modal_.motion == 0 || modal_.motion == 1;
  return !g01_macro_;
}

bool Executor::g01_calls_macro() const {
  return std::ranges::find(profile_.g_code_macros, 1) != profile_.g_code_macros.end();
}

// The words are not kept as the general path's cmds_: nothing reads them after the block.
void Executor::plain_motion_block(const nc::Block& b) {
  ++plain_lane_blocks_;
  exact_stop_once_ = false;
  position_offset_ = 0;
  cycle_m_done_ = false;
  AxisVector target = coords_.pos;
  bool axes = false;
  for (std::uint32_t i = b.words_begin; i < b.words_end; ++i) {
    const nc::Word& w = unit_->words[i];
    if (w.letter == 'G') {
      modal_.motion = w.value == 0 ? 0 : 1;
    } else if (w.letter == 'F') {
      feed_ = modal_.inch ? w.value * 25.4 : w.value;
    } else {
      const double v = dimension(Cmd{w.letter, w.decimal_point, w.literal, w.column, w.value, w.decimals});
      const int a = w.letter - 'X';
      target[a] = modal_.incremental ? target[a] + v : v;
      axes = true;
    }
  }
  if (axes) linear(modal_.motion == 0 ? MoveKind::rapid : MoveKind::line, target);
}

}  // namespace ncurve::machine
