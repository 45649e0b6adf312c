// Calls and returns: M98/M99 subprograms, G65/G66 macros and custom G/M codes, the call stack.
#include "machine/executor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "machine/word_values.hpp"

namespace ncurve::machine {

using nc::Block;
using nc::Value;

// ---- calls ----

// The calling blocks of an alarm raised at the block in hand, innermost first.
void Executor::add_call_stack(nc::Diagnostic& d) const {
  if (frames_.size() < 2 || !prog_ || !block_ || d.span.file != prog_->file.get() || d.span.line != block_->line)
    return;
  for (std::size_t i = frames_.size() - 1; i >= 1; --i) {
    const Frame& f = frames_[i];
    if (!f.caller || f.call_line == 0) break;
    d.called_from.push_back(nc::Span{f.caller->file.get(), f.call_line, f.call_column, 1});
  }
}

void Executor::call_program(int number, Frame frame, std::uint16_t column, std::int32_t entry) {
  const nc::Program* p = entry >= 0 ? prog_ : library_.find(number);
  if (!p) {
    if (const ProgramLibrary::Unread* u = library_.unread(number))
      alarm("PS0076", fmt::format("program O{:04} not found: it is in {} at line {}, after the '%' of line {} that "
                                  "ends the file, and the control reads nothing after that '%'",
                                  number, u->file->name(), u->where.line, u->where.end_line),
            column);
    alarm("PS0076", fmt::format("program O{:04} not found (in this file or the --lib folders)", number), column);
  }
  if (const nc::Diagnostic* twice = library_.duplicate(number)) alarm(twice->code, twice->message, column);
  if (p->file != library_.main()->file && std::ranges::find(reached_, p) == reached_.end()) {
    reached_.push_back(p);
    warn_mixed_decimal_points(*p);
  }
  frame.prog = p;
  frame.pc = frame.entry = std::max(entry, 0);
  // a program called from a macro that G66 called calls no more than that macro (nor itself again)
  frame.modal_limit = std::min(modal_limit_next_, frames_.back().modal_limit);
  modal_limit_next_ = SIZE_MAX;
  frame.caller = prog_;
  frame.call_line = block_ ? block_->line : 0;
  frame.call_column = block_ ? block_->column : 0;
  if (frame.kind == Frame::subprogram) {
    if (sub_depth_ >= profile_.subprogram_nesting)
      alarm("PS0077", fmt::format("subprogram calls nested more than {} deep", profile_.subprogram_nesting), column);
    ++sub_depth_;
    frame.level = frames_.back().level;
  } else {
    if (macro_depth_ >= profile_.macro_nesting)
      alarm("PS0122", fmt::format("macro calls (G65/G66/custom codes) nested more than {} deep", profile_.macro_nesting),
            column);
    ++macro_depth_;
    frame.level = static_cast<std::int32_t>(locals_.size());
    locals_.push_back(frame.initial);
  }
  frames_.push_back(frame);
  if (observer_) [[unlikely]] observe_call(frame);
}

void Executor::call_macro(int number, const std::vector<Arg>& args, int repeat, bool custom, bool modal,
                             std::uint16_t column) {
  macro_call_block_ = true;  // a macro statement, as FANUC counts them (not a block without motion)
  Frame f;
  f.kind = Frame::macro;
  f.custom = custom || (frames_.back().custom);
  f.modal = modal || frames_.back().modal;
  f.repeat = repeat - 1;
  // Argument specification I and II, mixed as FANUC does: I, J, K repeat in groups (#4..#33).
  int group = 0;
  bool seen_i = false, seen_j = false, seen_k = false;
  for (const Arg& a : args) {
    int var = 0;
    if (a.letter == 'I' || a.letter == 'J' || a.letter == 'K') {
      int slot = a.letter - 'I';
      bool restart = (slot == 0 && (seen_i || seen_j || seen_k)) || (slot == 1 && (seen_j || seen_k)) ||
                     (slot == 2 && seen_k);
      if (restart) {
        ++group;
        seen_i = seen_j = seen_k = false;
      }
      if (group > 9) alarm("PS0009", "more than 10 groups of I, J, K arguments", column);
      (slot == 0 ? seen_i : slot == 1 ? seen_j : seen_k) = true;
      var = 4 + 3 * group + slot;
    } else {
      var = argument_variable(a.letter);
    }
    if (var == 0) alarm("PS0009", fmt::format("address {} cannot be a macro argument", a.letter), column);
    double v = scaled_address(a.letter) ? as_written(a.value, a.literal, a.decimal_point) : a.value;
    f.initial[var - 1] = Value::of(v);
  }
  call_program(number, f, column);
}

void Executor::return_from_program(std::optional<int> sequence, std::uint16_t column) {
  Frame& f = frames_.back();
  if (f.repeat > 0) {
    --f.repeat;
    f.pc = f.entry;
    if (observer_) [[unlikely]] observe_repeat(f);
    if (f.kind == Frame::macro) locals_[f.level] = f.initial;
    return;
  }
  if (f.kind == Frame::subprogram) --sub_depth_;
  else {
    --macro_depth_;
    locals_.pop_back();
  }
  frames_.pop_back();
  if (observer_) [[unlikely]] observer_->left();
  prog_ = frames_.back().prog;
  if (sequence) {
    const std::int32_t at = prog_->find_sequence(*sequence);
    if (at < 0)
      alarm("PS0078", fmt::format("M99 P{}: no block N{} in the calling program", *sequence, *sequence), column);
    frames_.back().pc = at;
  }
}

void Executor::end_program(int m_code) {
  emit_event(MoveKind::program_end, m_code);
  parts_done_ += 1;
  finished_ = true;
}

}  // namespace ncurve::machine
