// The execution trace of a run for the time-travel debugger: what each executed block changed
// (variables with their old and new values, calls and returns, the modal state, the moves it
// delivered), so that any instant can be rebuilt without running the program again.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "machine/observer.hpp"

namespace ncurve::machine {

class ExecutionTrace final : public ExecutionObserver {
public:
  // The most records kept (executed blocks, variable writes, level entries, modal and tool offset
  // changes and system variable reads together, about 32 bytes each): past it the trace stops,
  // whole blocks only, and says so.
  static constexpr std::size_t kDefaultLimit = 2'000'000;
  static constexpr std::size_t kMaxLimit = 20'000'000;
  explicit ExecutionTrace(std::size_t limit = kDefaultLimit) : limit_(limit) {}

  struct Block {
    std::uint32_t file = 0;   // index in files()
    std::uint32_t line = 0;
    std::uint32_t stack = 0;  // index in stacks(): the call stack the block runs in
    std::uint64_t first_move = 0;  // moves delivered before it
  };
  // A variable write; values are NaN when vacant (a macro variable is never NaN).
  struct Write {
    std::int64_t block = -1;  // the block that wrote it; -1: before the first (--set presets)
    std::int32_t number = 0;
    std::int32_t level = -1;  // local level for #1..#33, else -1
    double old_value = 0, new_value = 0;
  };
  // A system variable the program read (#1000.., offsets, positions ...) and the value it got;
  // the same value read again in the same block is kept once.
  struct Read {
    std::int64_t block = 0;
    std::int32_t number = 0;
    double value = 0;  // NaN: vacant
  };
  // A macro call made this local level anew (all 33 vacant) before the block's writes.
  struct Entry {
    std::int64_t block = -1;
    std::int32_t level = 0;
  };
  // A modal variable (kModalVariables) took this value in force from `block` on.
  struct ModalChange {
    std::int64_t block = 0;  // == blocks().size(): the state after the last block
    std::int32_t variable = 0;
    double value = 0;        // NaN: vacant
  };

  // The tool offsets in force (ToolInForce) changed to these from `block` on.
  struct ToolChange {
    std::int64_t block = 0;  // == blocks().size(): the state after the last block
    ToolInForce tool;
  };

  static double encode(nc::Value v) { return v.vacant ? std::numeric_limits<double>::quiet_NaN() : v.v; }

  const std::vector<const nc::SourceFile*>& files() const { return files_; }
  const std::vector<std::vector<CallFrame>>& stacks() const { return stacks_; }
  const std::vector<Block>& blocks() const { return blocks_; }
  const std::vector<Write>& writes() const { return writes_; }
  const std::vector<Entry>& entries() const { return entries_; }
  const std::vector<Read>& reads() const { return reads_; }
  const ModalReadout& initial_modal() const { return initial_modal_; }
  const std::vector<ModalChange>& modal_changes() const { return modal_; }
  // The first is the state at the first block.
  const std::vector<ToolChange>& tool_changes() const { return tools_; }
  std::uint64_t total_moves() const { return total_moves_; }
  std::size_t limit() const { return limit_; }
  // Whether every executed block is in the trace; if not, why.
  bool complete() const { return complete_; }
  std::string limit_message() const;

  void block(const nc::Program& program, const nc::Block& block, std::uint64_t moves, const ModalReadout& modal) override;
  void tool(const ToolInForce& in_force) override { tool_told_ = in_force; }
  void entered(const CallFrame& frame) override;
  void left() override;
  void variable(int number, std::int32_t level, nc::Value old, nc::Value now) override;
  void read(int number, nc::Value value) override;
  void finished(std::uint64_t moves, const ModalReadout& modal) override;

private:
  bool room(std::size_t more, bool mid_block);  // false past the limit (the trace then ends with whole blocks)
  void note_modal(std::int64_t block, const ModalReadout& modal);
  void note_tool(std::int64_t block);
  std::size_t records() const {
    return blocks_.size() + writes_.size() + entries_.size() + modal_.size() + reads_.size() + tools_.size();
  }

  std::size_t limit_;
  bool complete_ = true;
  std::vector<const nc::SourceFile*> files_;
  std::vector<std::vector<CallFrame>> stacks_;
  std::vector<CallFrame> stack_;  // now
  bool stack_changed_ = true;
  std::vector<Block> blocks_;
  std::vector<Write> writes_;
  std::vector<Entry> entries_;
  std::vector<Read> reads_;
  std::vector<ModalChange> modal_;
  std::vector<ToolChange> tools_;
  ToolInForce tool_told_{};  // as the interpreter told it last
  ModalReadout initial_modal_{};
  ModalReadout modal_now_{};
  std::uint64_t total_moves_ = 0;
  std::uint64_t executed_ = 0;  // blocks run, recorded or not
};

}  // namespace ncurve::machine
