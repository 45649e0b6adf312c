// The lane of an expanded program's blocks: G00/G01 with literal X, Y, Z and F, each once
// (nc::Block::plain_motion), run where nothing else acts on them. It has the general path's effect
// (exec_nc: read_words, handle_g_codes, word_settings, block_motion, linear) in a few steps; the
// tests run every program both ways and compare.
#include <algorithm>
#include <cmath>

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

void Executor::plain_motion_blocks(const nc::Block& first) {
  Move m;  // one for the run of blocks: each sets what linear() sets, emit() the rest
  plain_motion_block(first, m);
  if (observer_ || shape_read_ || parameter_input_) return;  // each block seen, counted apart, or read as data
  Frame& f = frames_.back();
  const nc::Block* const end = unit_->blocks.data() + (unit_end_ - unit_first_);
  for (const nc::Block* b = block_ + 1; b != end; ++b) {
    // what step() and plain_lane_open() would look at; the rest of the state no lane block changes
    if (b->plain_motion == nc::PlainMotion::no || (b->plain_motion == nc::PlainMotion::coded && g01_macro_) ||
        b->error >= 0 || b->block_skip || steps() >= options_.max_steps || (result_.stats.blocks & 0xFFFF) == 0)
      return;
    block_ = b;
    block_index_ = f.pc++;
    ++result_.stats.blocks;
    if (b->sequence >= 0) last_sequence_ = b->sequence;
    ++nc_blocks_since_;
    plain_motion_block(*b, m);
  }
}

// A literal on the increment's grid in mm is its value, as dimension() gives it; others go there.
double Executor::plain_dimension(const nc::Word& w) const {
  if (w.decimal_point && !modal_.inch && w.decimals <= on_grid_mm_ && std::fabs(w.value) < 1e9) return w.value + 0.0;
  return dimension(Cmd{w.letter, w.decimal_point, w.literal, w.column, w.value, w.decimals});
}

// The words are not kept as the general path's cmds_: nothing reads them after the block.
void Executor::plain_motion_block(const nc::Block& b, Move& m) {
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
      const double v = plain_dimension(w);
      const int a = w.letter - 'X';
      target[a] = modal_.incremental ? target[a] + v : v;
      axes = true;
    }
  }
  if (axes) linear_into(m, modal_.motion == 0 ? MoveKind::rapid : MoveKind::line, target);
}

}  // namespace ncurve::machine
