#include "machine/trace.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace ncurve::machine {

namespace {
bool same(const nc::Value& a, const nc::Value& b) { return a.vacant == b.vacant && (a.vacant || a.v == b.v); }
}  // namespace

std::string ExecutionTrace::limit_message() const {
  if (complete_) return {};
  return fmt::format("the trace holds the first {} of the {} blocks executed: it keeps at most {} records (blocks, "
                     "variable writes, modal and tool offset changes and system variable reads; raise trace_limit, at most {})",
                     blocks_.size(), executed_, limit_, kMaxLimit);
}

bool ExecutionTrace::room(std::size_t more, bool mid_block) {
  if (!complete_) return false;
  if (records() + more <= limit_) return true;
  complete_ = false;
  // a block cut short is taken out whole, with what it wrote
  if (mid_block && !blocks_.empty()) {
    const auto last = static_cast<std::int64_t>(blocks_.size()) - 1;
    std::erase_if(writes_, [&](const Write& w) { return w.block == last; });
    std::erase_if(entries_, [&](const Entry& e) { return e.block == last; });
    std::erase_if(modal_, [&](const ModalChange& m) { return m.block == last; });
    std::erase_if(reads_, [&](const Read& r) { return r.block == last; });
    std::erase_if(tools_, [&](const ToolChange& t) { return t.block == last; });
    blocks_.pop_back();
  }
  return false;
}

void ExecutionTrace::note_modal(std::int64_t block, const ModalReadout& modal) {
  for (std::size_t i = 0; i < modal.size(); ++i) {
    if (same(modal[i], modal_now_[i])) continue;
    modal_now_[i] = modal[i];
    modal_.push_back({block, kModalVariables[i], encode(modal[i])});
  }
}

void ExecutionTrace::note_tool(std::int64_t block) {
  if (tools_.empty() || !(tools_.back().tool == tool_told_)) tools_.push_back({block, tool_told_});
}

void ExecutionTrace::block(const nc::Program& program, const nc::Block& b, std::uint64_t moves,
                           const ModalReadout& modal) {
  ++executed_;
  if (!room(2 + modal.size(), false)) return;
  const nc::SourceFile* file = program.file.get();
  auto it = std::find(files_.begin(), files_.end(), file);
  const auto file_index = static_cast<std::uint32_t>(it - files_.begin());
  if (it == files_.end()) files_.push_back(file);
  if (stack_changed_) {
    stacks_.push_back(stack_);
    stack_changed_ = false;
  }
  const auto index = static_cast<std::int64_t>(blocks_.size());
  if (index == 0) initial_modal_ = modal_now_ = modal;
  else note_modal(index, modal);
  note_tool(index);
  blocks_.push_back({file_index, b.line, static_cast<std::uint32_t>(stacks_.size() - 1), moves});
}

void ExecutionTrace::entered(const CallFrame& frame) {
  stack_.push_back(frame);
  stack_changed_ = true;
  if (frame.kind == CallFrame::macro && room(1, true))
    entries_.push_back({static_cast<std::int64_t>(blocks_.size()) - 1, frame.level});
}

void ExecutionTrace::left() {
  if (!stack_.empty()) stack_.pop_back();
  stack_changed_ = true;
}

void ExecutionTrace::variable(int number, std::int32_t level, nc::Value old, nc::Value now) {
  if (!room(1, true)) return;
  writes_.push_back({static_cast<std::int64_t>(blocks_.size()) - 1, number, level, encode(old), encode(now)});
}

void ExecutionTrace::read(int number, nc::Value value) {
  if (blocks_.empty() || !complete_) return;
  const auto block = static_cast<std::int64_t>(blocks_.size()) - 1;
  const double v = encode(value);
  // a variable read twice in one block with the same value (#1=#5001+#5001) is one record
  for (auto it = reads_.rbegin(); it != reads_.rend() && it->block == block; ++it)
    if (it->number == number) {
      if (it->value == v || (std::isnan(it->value) && std::isnan(v))) return;
      break;
    }
  if (!room(1, true)) return;
  reads_.push_back({block, number, v});
}

void ExecutionTrace::finished(std::uint64_t moves, const ModalReadout& modal) {
  total_moves_ = moves;
  if (complete_ && !blocks_.empty()) {
    note_modal(static_cast<std::int64_t>(blocks_.size()), modal);
    note_tool(static_cast<std::int64_t>(blocks_.size()));
  }
}

}  // namespace ncurve::machine
