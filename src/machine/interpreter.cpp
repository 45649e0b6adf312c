// The execution loop: blocks in FANUC order, macro statements, control flow and calls.
#include "machine/executor.hpp"
#include "machine/word_values.hpp"
#include "machine/file_checks.hpp"

#include <fmt/format.h>


#include <algorithm>
#include <chrono>
#include <cmath>

namespace ncurve::machine {

using nc::Block;
using nc::Statement;
using nc::Value;

namespace {
struct VarReader {
  Executor* in;
  Value read(int n, std::uint16_t column) { return in->read_var(n, column); }
};

// A word's expression: notes the first variable it read vacant (NC2072).
struct WordVarReader {
  Executor* in;
  int first_vacant = 0;
  Value read(int n, std::uint16_t column) {
    Value v = in->read_var(n, column);
    if (v.vacant && first_vacant == 0) first_vacant = n;
    return v;
  }
};




}  // namespace

double increments_per_mm(const MachineProfile& p) { return std::round(1 / p.increment); }

Executor::Executor(const MachineProfile& profile, const ProgramLibrary& library, RunOptions options)
    : profile_(profile), library_(library), options_(std::move(options)) {
  for (char a : profile_.axes) has_axis_[axis_index(a)] = true;
  init_rotary();
  per_unit_mm_ = increments_per_mm(profile_);
  per_unit_inch_ = std::round(10 / profile_.increment);
  auto on_grid = [](double per_unit) {  // k where per_unit is 10^k, up to 10^6
    double p = 1;
    for (int k = 0; k <= 6; ++k, p *= 10)
      if (per_unit == p) return k;
    return -1;
  };
  on_grid_mm_ = on_grid(per_unit_mm_);
  on_grid_inch_ = on_grid(per_unit_inch_);
  digit_limit_ = std::pow(10.0, profile_.number_digits);
  eval_options_.atan_signed = profile_.atan_signed;
  eval_options_.atan_comma = profile_.control == Control::fanuc_30i;
  eval_options_.adp_scale = 1.0 / profile_.increment;
  common_high_ = profile_.control == Control::fanuc_30i ? 499 : 199;
  common_.assign(1000, Value{});
  coords_.work_offsets = profile_.work_offsets;
  tool_offsets_ = profile_.tool_offsets;
  lathe_offsets_ = profile_.lathe_offsets;
  comp_ = &path_comp_.compensation();
  // the path stages, in order; --nose-centre's is linked in on a lathe only
  path_corner_.link(path_comp_);
  path_comp_.link(path_developed_);
  path_developed_.link(path_stroke_);
  if (options_.nose_centre && profile_.lathe()) {
    path_stroke_.link(path_nose_);
    path_nose_.link(path_stats_);
  } else {
    path_stroke_.link(path_stats_);
  }
}

CompensationSettings Executor::compensation_settings(const MachineProfile& p) {
  CompensationSettings cs;
  cs.startup_type_b = p.compensation.startup_type_b;
  cs.startup_type_c = p.compensation.startup_type_c;
  cs.blocks_without_motion = p.compensation.blocks_read - 2;
  cs.interference_check = p.compensation.interference_check;
  return cs;
}

void Executor::path_alarm(const Move& at, const std::string& code, const std::string& message) {
  throw nc::Alarm(nc::Diagnostic{nc::Severity::error, code, message, nc::Span{at.file, at.line, 1, 1}});
}

void Executor::path_warning(const Move& at, const std::string& code, const std::string& message) {
  if (result_.warnings.size() < 1000)
    result_.warnings.push_back(nc::Diagnostic{nc::Severity::warning, code, message, nc::Span{at.file, at.line, 1, 1}});
}

// A compensation whose alarms stop the run and whose warnings join the run's, at the block of the move.
RadiusCompensation Executor::radius_compensation(CompensationSettings settings,
                                                    RadiusCompensation::Deliver deliver) {
  return RadiusCompensation(
      settings, std::move(deliver),
      path_alarm, [this](const Move& at, const std::string& code, const std::string& message) {
        path_warning(at, code, message);
      });
}

// Innermost DO/WHILE around each block of a program, computed on its first GOTO.
const std::vector<std::int32_t>& Executor::loops_of(const nc::Program* p) {
  auto it = loop_of_.find(p);
  if (it != loop_of_.end()) return it->second;
  std::vector<std::int32_t> loop(p->blocks.size(), -1);
  std::vector<std::int32_t> open;
  for (std::size_t i = 0; i < p->blocks.size(); ++i) {
    const Block& b = p->blocks[i];
    loop[i] = open.empty() ? -1 : open.back();
    if ((b.kind == Statement::while_do || b.kind == Statement::do_loop) && b.match > static_cast<std::int32_t>(i))
      open.push_back(static_cast<std::int32_t>(i));
    else if (b.kind == Statement::end_loop && !open.empty() && b.match == open.back())
      open.pop_back();
  }
  return loop_of_.emplace(p, std::move(loop)).first->second;
}

nc::Span Executor::span(std::uint16_t column, std::uint32_t length) const {
  if (!prog_ || !block_) return {};
  return prog_->span_of(*block_, column, length);
}

void Executor::alarm(std::string code, std::string message, std::uint16_t column, std::uint32_t length) const {
  throw nc::Alarm(nc::Diagnostic{nc::Severity::error, std::move(code), std::move(message), span(column, length)});
}

void Executor::warn(std::string code, std::string message, std::uint16_t column) {
  if (result_.warnings.size() < 1000)
    result_.warnings.push_back(nc::Diagnostic{nc::Severity::warning, std::move(code), std::move(message), span(column)});
}

void Executor::warn_once(std::string code, std::string message, std::uint16_t column) {
  if (warned_once_.emplace(prog_, block_index_, code).second) warn(std::move(code), std::move(message), column);
}

// An expression run with `reader`, its fault an alarm; one instance a reader, each its own code.
template <class Reader>
Value Executor::evaluate_with(const nc::Expr& e, Reader& reader) {
  const nc::Instr* code = unit_->code.data();
  operations_ += e.end - e.begin;
  nc::EvalResult r = nc::evaluate(code + e.begin, code + e.end, reader, eval_options_);
  switch (r.fault) {
    case nc::EvalFault::none: return r.value;
    case nc::EvalFault::divide_by_zero: alarm("PS0112", "division by zero", r.column);
    case nc::EvalFault::domain: alarm("PS0119", "argument out of the function's range", r.column);
    case nc::EvalFault::overflow:
      alarm("PS0111", "calculated value out of range (a macro value lies within -1e47 .. 1e47)", r.column);
    case nc::EvalFault::not_on_this_control:
      alarm("PS0114", "ATAN[a,b] needs a 30i control; write ATAN[a]/[b]", r.column);
  }
  return r.value;
}

Value Executor::eval(const nc::Expr& e) {
  VarReader reader{this};
  return evaluate_with(e, reader);
}

// eval() noting the first variable the expression read vacant: a word's (NC2072).
Value Executor::eval_word(const nc::Expr& e, int& vacant_variable) {
  WordVarReader reader{this};
  const Value v = evaluate_with(e, reader);
  vacant_variable = reader.first_vacant;
  return v;
}

bool Executor::condition(const nc::Expr& e) {
  const double v = eval(e).number();
  if (std::isnan(v)) alarm("PS0111", "the condition has no value (NaN)");  // never taken as true
  return v != 0.0;
}

RunResult Executor::run(MoveSink& sink) {
  path_stats_.link(sink);
  path_stats_.restart();
  result_ = RunResult{};
  const nc::Program* main = library_.main();
  if (!main) {
    result_.alarm = nc::Diagnostic{nc::Severity::error, "", "no main program to run", {}};
    return result_;
  }
  frames_.clear();
  locals_.assign(1, {});
  Frame f;
  f.prog = main;
  frames_.push_back(f);
  if (observer_) observe_call(f);
  modal_.power_on(profile_);
  set_origin();
  for (int a = 0; a < kAxes; ++a) coords_.pos[a] = profile_.reference_points[0][a] - coords_.origin[a];  // power on at home
  init_stroke_check();

  reached_.clear();
  start_file_checks(*main);

  try {
    for (const auto& [n, v] : options_.presets) {
      prog_ = nullptr;
      write_var(n, Value::of(v), 0);
    }
    started_ = std::chrono::steady_clock::now();
    while (!finished_) {
      if (steps() >= options_.max_steps || (result_.stats.blocks & 0xFFFF) == 0)
        check_runaway();
      step();
    }
    if (corner_on_) corner_block_end(true);  // a chamfering block at the end of the program
    comp_->finish();
  } catch (const nc::Alarm& a) {
    result_.alarm = a.diagnostic;
    add_call_stack(*result_.alarm);
    try {
      comp_->abandon();
    } catch (const nc::Alarm&) {
    }
  }
  if (file_checks_) finish_file_checks(*main);
  if (observer_) {
    observer_->tool(tool_in_force());
    observer_->finished(moves_delivered(), modal_readout());
  }
  return result_;
}

std::uint64_t Executor::steps() const { return result_.stats.blocks + operations_ + block_moves_; }

// One block making move after move (a canned cycle's holes and pecks) is bounded as a loop is.
void Executor::count_block_move() {
  if (moving_block_ != result_.stats.blocks) {
    moving_block_ = result_.stats.blocks;
    moves_in_block_ = 0;
    return;
  }
  ++block_moves_;
  ++moves_in_block_;
  if (steps() >= options_.max_steps || (block_moves_ & 0xFFF) == 0) check_runaway();
}

// A runaway program stops at the loop that keeps it going, naming the option to raise.
void Executor::check_runaway() {
  const bool steps = this->steps() >= options_.max_steps;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const bool cancelled = options_.cancel && options_.cancel->load(std::memory_order_relaxed);
  if (!steps && !cancelled && !(options_.max_seconds > 0 && seconds > options_.max_seconds)) return;
  std::string where;
  // the block being run is named when its own moves are most of the work, else the loop
  const bool block_runs_away = moving_block_ == result_.stats.blocks && 2 * moves_in_block_ > this->steps();
  if (block_runs_away && block_) {
    where = fmt::format("; the block at {}:{} makes move after move", prog_->file->name(), block_->line);
  } else if (last_back_jump_ >= 0 && select_block(last_back_jump_prog_, last_back_jump_)) {
    const Block& b = *block_;
    where = fmt::format("; it keeps looping through {}:{}", prog_->file->name(), b.line);
    if (b.kind == Statement::end_loop && b.match >= 0)
      where += fmt::format(" (END {} of the loop at line {})", b.loop_id, line_of(prog_, b.match));
    select_block(last_back_jump_prog_, last_back_jump_);
  }
  if (steps)
    alarm("NC9000", fmt::format("program stopped after {} steps ({} blocks, {} moves past a block's first and {} "
                                "expression operations; raise --max-steps to let it run longer){}",
                                this->steps(), result_.stats.blocks, block_moves_, operations_, where));
  if (cancelled)
    alarm("NC9000", fmt::format("program stopped after {:.0f} s, {} blocks: the run was cancelled", seconds,
                                result_.stats.blocks));
  alarm("NC9000", fmt::format("program stopped after {:.0f} s, {} blocks (raise --max-seconds to let it run longer){}",
                              seconds, result_.stats.blocks, where));
}

// The piece holding block i of p, read again when it has gone; false past p's end.
bool Executor::select_piece(const nc::Program* p, std::int32_t i) {
  nc::Program::Piece piece = p->piece_of(i);
  if (!piece.piece) return false;
  unit_ = piece.piece;
  unit_prog_ = p;
  unit_first_ = piece.first;
  unit_end_ = piece.end;
  unit_hold_ = std::move(piece.hold);
  return true;
}

std::uint32_t Executor::line_of(const nc::Program* p, std::int32_t i) {
  const nc::Program::Piece piece = p->piece_of(i);
  return piece.piece ? piece.piece->blocks[i - piece.first].line : 0;
}

// A streamed DO or WHILE whose END is not read yet: read on to it, or to the alarm of its having none.
void Executor::settle_loop(const Block& b) {
  if (prog_->stream) prog_->stream->settle_loop(prog_->stream_index, frames_.back().pc);
  if (b.error >= 0) throw nc::Alarm(unit_->errors[b.error]);
}

// A program that ran out of blocks: the main one ends, a subprogram returns; the last block named.
void Executor::past_the_end() {
  const Frame& f = frames_.back();
  std::int32_t last = f.pc - 1;
  while (last >= 0 && !f.prog->piece_of(last).piece) --last;
  block_ = nullptr;
  if (last >= 0) select_block(f.prog, last);
  if (frames_.size() == 1) {
    warn("NC2002", "the program ends without M30 or M02");
    finished_ = true;
  } else {
    warn("NC2003", "the subprogram ends without M99");
    return_from_program(std::nullopt, 0);
  }
}

void Executor::step() {
  Frame& f = frames_.back();
  if (!select_block(f.prog, f.pc)) [[unlikely]] {
    past_the_end();
    return;
  }
  const Block& b = *block_;
  // a line of nothing but comments: not counted or traced, as the source's count leaves it out
  if (b.kind == Statement::empty && b.sequence < 0 && b.error < 0 && !b.block_skip) {
    ++f.pc;
    return;
  }
  ++result_.stats.blocks;
  if (shape_read_) [[unlikely]] ++result_.stats.shape_blocks;
  if (observer_) [[unlikely]] observe_block(b);
  if (b.block_skip && profile_.block_skip) {
    ++f.pc;
    return;
  }
  if (b.error >= 0) [[unlikely]] throw nc::Alarm(unit_->errors[b.error]);
  if (b.sequence >= 0) last_sequence_ = b.sequence;
  if (b.kind == Statement::nc) ++nc_blocks_since_;
  else if (b.kind != Statement::empty) ++statements_since_;
  switch (b.kind) {
    case Statement::empty:
      ++f.pc;
      if (parameter_input_ && b.sequence >= 0) [[unlikely]] parameter_input_block(b);  // N alone: no R
      break;
    case Statement::assign: exec_assignment(b); ++frames_.back().pc; break;
    case Statement::nc: {
      ++f.pc;
      if (parameter_input_) [[unlikely]] {
        parameter_input_block(b);
        break;
      }
      if (b.plain_motion != nc::PlainMotion::no && plain_lane_open(b)) {
        plain_motion_blocks(b);
        break;
      }
      const bool g40 = modal_.comp_side != 0;
      const bool from_cancel = modal_.comp_side == 0 && !comp_->offset_mode();
      macro_call_block_ = false;
      exec_nc(b);
      if (corner_on_) [[unlikely]] corner_block_end();
      if (compensating() && !macro_call_block_ && !shape_moves_)
        end_of_block_compensation(g40 && modal_.comp_side == 0, from_cancel && modal_.comp_side != 0);
      break;
    }
    case Statement::go_to: jump(b, eval(b.value).number()); break;
    case Statement::if_goto:
      if (condition(b.cond)) jump(b, eval(b.value).number());
      else ++f.pc;
      break;
    case Statement::if_then:
      if (condition(b.cond)) exec_assignment(b);
      ++frames_.back().pc;
      break;
    case Statement::while_do:
      if (b.match < 0) [[unlikely]] settle_loop(b);
      if (condition(b.cond)) ++f.pc;
      else f.pc = b.match + 1;
      break;
    case Statement::do_loop:
      if (b.match < 0) [[unlikely]] settle_loop(b);
      ++f.pc;
      break;
    case Statement::end_loop:
      f.pc = b.match;
      last_back_jump_ = block_index_;
      last_back_jump_prog_ = prog_;
      break;
    case Statement::popen: case Statement::pclos: case Statement::dprnt: case Statement::bprnt:
      external_output(b);
      ++frames_.back().pc;
      break;
  }
}

void Executor::exec_assignment(const Block& b) {
  int target = b.target_var;
  if (target < 0) {
    Value t = eval(b.target);
    if (t.vacant) alarm("PS0115", "the variable number is vacant", b.column);
    target = round_int(t.v);
  }
  Value v = eval(b.value);
  write_var(target, v, b.column);
}

void Executor::jump(const Block& b, double sequence) {
  Frame& f = frames_.back();
  if (!(sequence >= 1 && sequence <= 99999999))
    alarm("PS0128", fmt::format("GOTO {}: sequence numbers are 1 to 99999999", sequence), b.column);
  int n = round_int(sequence);
  const std::int32_t target = prog_->find_sequence(n);
  if (target < 0) alarm("PS0128", fmt::format("GOTO {}: no block N{} in this program", n, n), b.column);
  nc::ProgramStream::Loop inner;
  if (prog_->stream) {
    inner = prog_->stream->loop_around(prog_->stream_index, target);
  } else if (const std::int32_t at = loops_of(prog_)[target]; at >= 0) {
    const Block& d = prog_->blocks[at];
    inner = nc::ProgramStream::Loop{at, d.match, d.loop_id, d.line};
  }
  if (inner.begin >= 0 && (f.pc < inner.begin || f.pc > inner.end))
    alarm("PS0124", fmt::format("GOTO {} jumps into the DO {} loop of line {}: entering a loop from outside is not allowed",
                                n, inner.id, inner.line),
          b.column);
  if (target <= f.pc) {
    last_back_jump_ = block_index_;
    last_back_jump_prog_ = prog_;
  }
  f.pc = target;
}

// ---- the public face ----

Interpreter::Interpreter(const MachineProfile& profile, const ProgramLibrary& library, RunOptions options)
    : executor_(std::make_unique<Executor>(profile, library, std::move(options))) {}
Interpreter::~Interpreter() = default;
Interpreter::Interpreter(Interpreter&&) noexcept = default;
Interpreter& Interpreter::operator=(Interpreter&&) noexcept = default;
RunResult Interpreter::run(MoveSink& sink) { return executor_->run(sink); }
std::uint64_t Interpreter::plain_lane_blocks() const { return executor_->plain_lane_blocks(); }

nc::Value Interpreter::variable(int number) { return executor_->variable(number); }
void Interpreter::observe(ExecutionObserver* observer) { executor_->observe(observer); }

std::array<double, 2> Interpreter::nose_tip_now() const {
  const V2 tip = executor_->tip_of_move();
  return {tip.x, tip.y};
}

}  // namespace ncurve::machine
