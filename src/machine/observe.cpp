// The interpreter's side of an ExecutionObserver: what it is told, gathered only when there is one.
#include "machine/executor.hpp"

namespace ncurve::machine {

using nc::Value;

namespace {
// Clears a pointer for a scope: the write below is the interpreter's own, not observed twice.
struct Unobserved {
  ExecutionObserver*& slot;
  ExecutionObserver* kept;
  explicit Unobserved(ExecutionObserver*& s) : slot(s), kept(s) { slot = nullptr; }
  ~Unobserved() { slot = kept; }
};
}  // namespace

std::uint64_t Executor::moves_delivered() const {
  std::uint64_t n = 0;
  for (std::uint64_t k : result_.stats.by_kind) n += k;
  return n;
}

ModalReadout Executor::modal_readout() {
  ModalReadout s;
  for (std::size_t i = 0; i < kModalVariables.size(); ++i) s[i] = read_system(kModalVariables[i], 0);
  return s;
}

// Only an NC block changes the modal state: after a macro statement the state read before stands.
void Executor::observe_block(const nc::Block& b) {
  if (shape_read_) return;
  if (modal_stale_) observed_modal_ = modal_readout();
  modal_stale_ = b.kind == nc::Statement::nc;
  observer_->tool(tool_in_force());
  observer_->block(*prog_, b, moves_delivered(), observed_modal_);
}

ToolInForce Executor::tool_in_force() const {
  ToolInForce t;
  if (profile_.lathe()) {
    t.offset = lathe_offset_;
    t.radius = nose_radius();
    if (auto it = lathe_offsets_.find(lathe_offset_); it != lathe_offsets_.end()) t.tip = static_cast<int>(it->second.tip);
  } else {
    t.offset = d_;
    t.radius = radius_offset(d_);
    t.length = length_offset(h_);
  }
  return t;
}

void Executor::observe_call(const Frame& f) {
  CallFrame c;
  c.kind = f.kind == Frame::main ? CallFrame::main : f.kind == Frame::subprogram ? CallFrame::subprogram : CallFrame::macro;
  c.program = f.prog ? f.prog->number : -1;
  c.level = f.level;
  c.custom = f.custom;
  c.modal = f.modal;
  if (f.caller && f.call_line) {
    c.call_file = f.caller->file.get();
    c.call_line = f.call_line;
  }
  observer_->entered(c);
  if (f.kind != Frame::macro) return;
  for (int i = 0; i < 33; ++i)
    if (!f.initial[i].vacant) observer_->variable(i + 1, f.level, Value{}, f.initial[i]);
}

void Executor::observe_repeat(const Frame& f) {
  if (f.kind != Frame::macro) return;
  const auto& now = locals_[f.level];
  for (int i = 0; i < 33; ++i) {
    const Value& a = now[i];
    const Value& b = f.initial[i];
    if (a.vacant != b.vacant || (!a.vacant && a.v != b.v)) observer_->variable(i + 1, f.level, a, b);
  }
}

void Executor::observed_write(int n, Value v, std::uint16_t column) {
  const bool local = n >= 1 && n <= 33;
  const std::int32_t level = local ? (frames_.empty() ? 0 : frames_.back().level) : -1;
  Value old;
  if (local || (n >= 100 && n <= common_high_) || (n >= 500 && n <= 999)) {
    old = read_var(n, column);
  } else if (n != 0) {
    try {  // a system variable that cannot be read (write-only) was vacant to the program
      old = read_system(n, column);
    } catch (const nc::Alarm&) {
    }
  }
  ExecutionObserver* observer = observer_;
  {
    Unobserved off(observer_);
    write_var(n, v, column);
  }
  observer->variable(n, level, old, v);
}

Value Executor::observed_read(int n, std::uint16_t column) {
  const Value v = read_system(n, column);  // (an alarm on reading is not a read)
  observer_->read(n, v);
  return v;
}

}  // namespace ncurve::machine
