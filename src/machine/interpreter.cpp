// The execution loop: blocks in FANUC order, macro statements, control flow and calls.
#include "machine/interpreter.hpp"

#include <fmt/format.h>

#include "machine/profile_hints.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace ncurve::machine {

using nc::Block;
using nc::Statement;
using nc::Value;

namespace {
struct VarReader {
  Interpreter* in;
  Value read(int n, std::uint16_t column) { return in->read_var(n, column); }
};

int round_int(double v) {  // half away from zero, saturated to the int range
  double r = v < 0 ? -std::floor(-v + 0.5) : std::floor(v + 0.5);
  if (!(r > -2147483647.0)) return -2147483647;
  if (!(r < 2147483647.0)) return 2147483647;
  return static_cast<int>(r);
}

// Argument specification I: address -> local variable number.
int argument_variable(char letter) {
  switch (letter) {
    case 'A': return 1;  case 'B': return 2;  case 'C': return 3;  case 'I': return 4;
    case 'J': return 5;  case 'K': return 6;  case 'D': return 7;  case 'E': return 8;
    case 'F': return 9;  case 'H': return 11; case 'M': return 13; case 'Q': return 17;
    case 'R': return 18; case 'S': return 19; case 'T': return 20; case 'U': return 21;
    case 'V': return 22; case 'W': return 23; case 'X': return 24; case 'Y': return 25;
    case 'Z': return 26; default: return 0;
  }
}

bool scaled_address(char c) {  // dimension words read in least input increments without a decimal point
  switch (c) {
    case 'X': case 'Y': case 'Z': case 'U': case 'V': case 'W': case 'A': case 'B': case 'C':
    case 'I': case 'J': case 'K': case 'R': case 'Q': return true;
    default: return false;
  }
}

// Whether a block holds a literal M98.
bool calls_subprogram(const nc::Program& p, const nc::Block& b) {
  for (std::uint32_t w = b.words_begin; w < b.words_end; ++w)
    if (p.words[w].letter == 'M' && p.words[w].literal && p.words[w].value == 98) return true;
  return false;
}

// Whether a block holds a literal G code from g_lo to g_hi (x10).
bool block_has_g(const nc::Program& p, const nc::Block& b, int g_lo, int g_hi) {
  for (std::uint32_t w = b.words_begin; w < b.words_end; ++w) {
    const nc::Word& word = p.words[w];
    if (word.letter == 'G' && word.literal && word.value * 10 >= g_lo && word.value * 10 <= g_hi) return true;
  }
  return false;
}

// A number as the control shows it: at most `decimals` places, no trailing zeros.
std::string shown_number(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, std::max(decimals, 0));
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}
}  // namespace

double increments_per_mm(const MachineProfile& p) { return std::round(1 / p.increment); }

Interpreter::Interpreter(const MachineProfile& profile, const ProgramLibrary& library, RunOptions options)
    : profile_(profile), library_(library), options_(std::move(options)) {
  for (char a : profile_.axes) has_axis_[axis_index(a)] = true;
  init_rotary();
  per_unit_mm_ = increments_per_mm(profile_);
  per_unit_inch_ = std::round(10 / profile_.increment);
  digit_limit_ = std::pow(10.0, profile_.number_digits);
  eval_options_.atan_signed = profile_.atan_signed;
  eval_options_.atan_comma = profile_.control == Control::fanuc_30i;
  eval_options_.adp_scale = 1.0 / profile_.increment;
  common_high_ = profile_.control == Control::fanuc_30i ? 499 : 199;
  common_.assign(1000, Value{});
  work_offsets_ = profile_.work_offsets;
  tool_offsets_ = profile_.tool_offsets;
  lathe_offsets_ = profile_.lathe_offsets;
  CompensationSettings cs;
  cs.startup_type_b = profile_.compensation.startup_type_b;
  cs.startup_type_c = profile_.compensation.startup_type_c;
  cs.blocks_without_motion = profile_.compensation.blocks_read - 2;
  cs.interference_check = profile_.compensation.interference_check;
  comp_.emplace(radius_compensation(cs, [this](Move& m) { deliver(m); }));
}

// A compensation whose alarms stop the run and whose warnings join the run's, at the block of the move.
RadiusCompensation Interpreter::radius_compensation(CompensationSettings settings,
                                                    RadiusCompensation::Deliver deliver) {
  return RadiusCompensation(
      settings, std::move(deliver),
      [](const Move& at, const std::string& code, const std::string& message) {
        throw nc::Alarm(nc::Diagnostic{nc::Severity::error, code, message, nc::Span{at.file, at.line, 1, 1}});
      },
      [this](const Move& at, const std::string& code, const std::string& message) {
        if (result_.warnings.size() < 1000)
          result_.warnings.push_back(
              nc::Diagnostic{nc::Severity::warning, code, message, nc::Span{at.file, at.line, 1, 1}});
      });
}

// Innermost DO/WHILE around each block of a program, computed on its first GOTO.
const std::vector<std::int32_t>& Interpreter::loops_of(const nc::Program* p) {
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

nc::Span Interpreter::span(std::uint16_t column, std::uint32_t length) const {
  if (!prog_ || !block_) return {};
  return prog_->span_of(*block_, column, length);
}

void Interpreter::alarm(std::string code, std::string message, std::uint16_t column, std::uint32_t length) const {
  throw nc::Alarm(nc::Diagnostic{nc::Severity::error, std::move(code), std::move(message), span(column, length)});
}

void Interpreter::warn(std::string code, std::string message, std::uint16_t column) {
  if (result_.warnings.size() < 1000)
    result_.warnings.push_back(nc::Diagnostic{nc::Severity::warning, std::move(code), std::move(message), span(column)});
}

void Interpreter::warn_once(std::string code, std::string message, std::uint16_t column) {
  if (warned_once_.emplace(block_, code).second) warn(std::move(code), std::move(message), column);
}

Value Interpreter::eval(const nc::Expr& e) {
  VarReader reader{this};
  const nc::Instr* code = prog_->code.data();
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

bool Interpreter::condition(const nc::Expr& e) {
  const double v = eval(e).number();
  if (std::isnan(v)) alarm("PS0111", "the condition has no value (NaN)");  // never taken as true
  return v != 0.0;
}

// Programs that mix dimension words with and without a decimal point are a classic source of
// scrapped parts. A word of a macro call (G65, G66, a custom G code) is an argument, not an axis.
void Interpreter::warn_mixed_decimal_points(const nc::Program& program) {
  auto is_call = [&](const nc::Program& p, const nc::Block& b) {
    for (std::uint32_t w = b.words_begin; w < b.words_end; ++w) {
      const nc::Word& word = p.words[w];
      if (word.letter != 'G' || !word.literal) continue;
      int g = round_int(word.value * 10);
      if (g == 650 || g == 660 || g == 661) return true;
      for (int code : profile_.g_code_macros)
        if (code != 0 && g == std::abs(code) * 10) return true;
    }
    return false;
  };
  const int decimals = static_cast<int>(std::lround(-std::log10(profile_.increment)));
  {
    const nc::Program* p = &program;
    const nc::Word* with = nullptr;
    const nc::Word* without = nullptr;
    std::uint32_t without_line = 0;
    bool without_is_argument = false;
    for (const auto& b : p->blocks) {
      if (b.kind != nc::Statement::nc) continue;  // DPRNT's range indexes Program::prints
      for (std::uint32_t w = b.words_begin; w < b.words_end; ++w) {
        const nc::Word& word = p->words[w];
        if (!word.literal || !scaled_address(word.letter)) continue;
        if (word.letter == 'Q' && profile_.lathe() && block_has_g(*p, b, 700, 730)) continue;  // Q: a sequence number
        if (word.letter == 'Q' && profile_.lathe()) continue;  // and a start angle (G32, G92), a depth in increments (G76)
        if (word.letter == 'Q' && !profile_.lathe() && block_has_g(*p, b, 330, 330)) continue;  // G33's start angle
        if (word.letter == 'Q' && calls_subprogram(*p, b)) continue;  // M98 Q: a sequence number
        if (word.decimal_point) with = with ? with : &word;
        else if (word.value != 0 && !without) {
          without = &word;
          without_line = b.line;
          without_is_argument = is_call(*p, b);
        }
      }
    }
    if (!with || !without) return;
    const std::string word = fmt::format("{}{}", without->letter, shown_number(without->value, 0));
    const std::string read_as = profile_.decimal_calculator
                                    ? shown_number(without->value, 0)
                                    : shown_number(without->value * profile_.increment, decimals);
    const std::string what = without_is_argument ? fmt::format("argument {} of a macro call is read as {}", word, read_as)
                                                 : fmt::format("{} is read as {} mm", word, read_as);
    result_.warnings.push_back(nc::Diagnostic{
        nc::Severity::warning, "NC2001",
        profile_.decimal_calculator
            ? fmt::format("words with and without a decimal point in one program; {} (calculator-type input, "
                          "No.3401#0 = 1)", what)
            : fmt::format("words with and without a decimal point in one program; {} ({} least input increments, "
                          "No.3401#0 = 0)", what, shown_number(without->value, 0)),
        nc::Span{p->file.get(), without_line, without->column, 1}});
  }
}

RunResult Interpreter::run(MoveSink& sink) {
  sink_ = &sink;
  setup_sent_ = false;
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
  motion_ = profile_.power_on_g01 ? 1 : 0;
  plane_ = profile_.power_on_plane;
  incremental_ = profile_.power_on_g91;
  feed_per_rev_ = profile_.power_on_feed_per_rev;
  look_ahead_ = profile_.motion.look_ahead_at_power_on;
  set_origin();
  for (int a = 0; a < kAxes; ++a) pos_[a] = profile_.reference_points[0][a] - origin_[a];  // power on at home
  init_stroke_check();

  reached_.clear();
  for (const auto& p : library_.programs())  // the main file's; a library program's when it is called
    if (p->file == main->file) warn_mixed_decimal_points(*p);
  for (nc::Diagnostic& d : profile_hints(library_, profile_)) result_.warnings.push_back(std::move(d));

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
  if (observer_) observer_->finished(moves_delivered(), modal_state());
  sink_ = nullptr;
  return result_;
}

std::uint64_t Interpreter::steps() const { return result_.stats.blocks + operations_ + block_moves_; }

// One block making move after move (a canned cycle's holes and pecks) is bounded as a loop is.
void Interpreter::count_block_move() {
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
void Interpreter::check_runaway() {
  const bool steps = this->steps() >= options_.max_steps;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const bool cancelled = options_.cancel && options_.cancel->load(std::memory_order_relaxed);
  if (!steps && !cancelled && !(options_.max_seconds > 0 && seconds > options_.max_seconds)) return;
  std::string where;
  // the block being run is named when its own moves are most of the work, else the loop
  const bool block_runs_away = moving_block_ == result_.stats.blocks && 2 * moves_in_block_ > this->steps();
  if (block_runs_away && block_) {
    where = fmt::format("; the block at {}:{} makes move after move", prog_->file->name(), block_->line);
  } else if (last_back_jump_) {
    const Block& b = *last_back_jump_;
    where = fmt::format("; it keeps looping through {}:{}", last_back_jump_prog_->file->name(), b.line);
    if (b.kind == Statement::end_loop && b.match >= 0)
      where += fmt::format(" (END {} of the loop at line {})", b.loop_id, last_back_jump_prog_->blocks[b.match].line);
    prog_ = last_back_jump_prog_;
    block_ = last_back_jump_;
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

void Interpreter::step() {
  Frame& f = frames_.back();
  prog_ = f.prog;
  if (f.pc >= static_cast<std::int32_t>(prog_->blocks.size())) {
    block_ = prog_->blocks.empty() ? nullptr : &prog_->blocks.back();
    if (frames_.size() == 1) {
      warn("NC2002", "the program ends without M30 or M02");
      finished_ = true;
    } else {
      warn("NC2003", "the subprogram ends without M99");
      return_from_program(std::nullopt, 0);
    }
    return;
  }
  const Block& b = prog_->blocks[f.pc];
  block_ = &b;
  // a line of nothing but comments: not counted or traced, as the source's count leaves it out
  if (b.kind == Statement::empty && b.sequence < 0 && b.error < 0 && !b.block_skip) {
    ++f.pc;
    return;
  }
  ++result_.stats.blocks;
  if (observer_) [[unlikely]] observe_block(b);
  if (b.block_skip && profile_.block_skip) {
    ++f.pc;
    return;
  }
  if (b.error >= 0) throw nc::Alarm(prog_->errors[b.error]);
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
      const bool g40 = comp_side_ != 0;
      const bool from_cancel = comp_side_ == 0 && !comp_->offset_mode();
      macro_call_block_ = false;
      exec_nc(b);
      if (corner_on_) [[unlikely]] corner_block_end();
      if (compensating() && !macro_call_block_ && !shape_moves_)
        end_of_block_compensation(g40 && comp_side_ == 0, from_cancel && comp_side_ != 0);
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
      if (condition(b.cond)) ++f.pc;
      else f.pc = b.match + 1;
      break;
    case Statement::do_loop: ++f.pc; break;
    case Statement::end_loop:
      f.pc = b.match;
      last_back_jump_ = &b;
      last_back_jump_prog_ = prog_;
      break;
    case Statement::popen: case Statement::pclos: case Statement::dprnt: case Statement::bprnt:
      external_output(b);
      ++frames_.back().pc;
      break;
  }
}

void Interpreter::exec_assignment(const Block& b) {
  int target = b.target_var;
  if (target < 0) {
    Value t = eval(b.target);
    if (t.vacant) alarm("PS0115", "the variable number is vacant", b.column);
    target = round_int(t.v);
  }
  Value v = eval(b.value);
  write_var(target, v, b.column);
}

void Interpreter::jump(const Block& b, double sequence) {
  Frame& f = frames_.back();
  if (!(sequence >= 1 && sequence <= 99999999))
    alarm("PS0128", fmt::format("GOTO {}: sequence numbers are 1 to 99999999", sequence), b.column);
  int n = round_int(sequence);
  auto it = prog_->sequence_index.find(n);
  if (it == prog_->sequence_index.end()) alarm("PS0128", fmt::format("GOTO {}: no block N{} in this program", n, n), b.column);
  std::int32_t target = it->second;
  const auto& loops = loops_of(prog_);
  std::int32_t inner = loops[target];
  if (inner >= 0) {
    std::int32_t end = prog_->blocks[inner].match;
    if (f.pc < inner || f.pc > end)
      alarm("PS0124", fmt::format("GOTO {} jumps into the DO {} loop of line {}: entering a loop from outside is not allowed",
                                  n, prog_->blocks[inner].loop_id, prog_->blocks[inner].line),
            b.column);
  }
  if (target <= f.pc) {
    last_back_jump_ = &b;
    last_back_jump_prog_ = prog_;
  }
  f.pc = target;
}

// ---- calls ----

// The calling blocks of an alarm raised at the block in hand, innermost first.
void Interpreter::add_call_stack(nc::Diagnostic& d) const {
  if (frames_.size() < 2 || !prog_ || !block_ || d.span.file != prog_->file.get() || d.span.line != block_->line)
    return;
  for (std::size_t i = frames_.size() - 1; i >= 1; --i) {
    const Frame& f = frames_[i];
    if (!f.caller || !f.call_block) break;
    d.called_from.push_back(f.caller->span_of(*f.call_block));
  }
}

void Interpreter::call_program(int number, Frame frame, std::uint16_t column, std::int32_t entry) {
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
  frame.call_block = block_;
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

void Interpreter::call_macro(int number, const std::vector<Arg>& args, int repeat, bool custom, bool modal,
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

void Interpreter::return_from_program(std::optional<int> sequence, std::uint16_t column) {
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
    auto it = prog_->sequence_index.find(*sequence);
    if (it == prog_->sequence_index.end())
      alarm("PS0078", fmt::format("M99 P{}: no block N{} in the calling program", *sequence, *sequence), column);
    frames_.back().pc = it->second;
  }
}

void Interpreter::end_program(int m_code) {
  emit_event(MoveKind::program_end, m_code);
  parts_done_ += 1;
  finished_ = true;
}

// ---- NC blocks ----

// Increments per program unit (1000 for IS-B mm) is an exact integer: dividing by it gives the
// nearest double to the decimal value (4552 / 1000 = 4.552), where multiplying by 0.001 would not.
double Interpreter::as_written(double value, bool literal, bool decimal_point) const {
  if (!literal || decimal_point || profile_.decimal_calculator) return value;
  return value / (inch_ ? per_unit_inch_ : per_unit_mm_);  // No.3401#0 = 0: X10 is ten increments
}

double Interpreter::dimension_raw(const Cmd& c) const {
  const double per_unit = inch_ ? per_unit_inch_ : per_unit_mm_;
  return round_to_increment(as_written(c.value, c.literal, c.decimal_point), per_unit);
}

double Interpreter::dimension(const Cmd& c) const { return inch_ ? dimension_raw(c) * 25.4 : dimension_raw(c); }

int Interpreter::integer(const Cmd& c, const char* what) const {
  if (c.literal && c.decimal_point)
    alarm("PS0007", fmt::format("{} does not take a decimal point ({}{})", what, c.letter, c.value), c.column);
  if (!(std::fabs(c.value) < 1e9)) alarm("PS0003", fmt::format("{} value out of range", what), c.column);
  return round_int(c.value);
}

std::vector<Interpreter::Arg> Interpreter::arguments(bool skip_p_l, int skip_g, int skip_m) const {
  std::vector<Arg> args;
  for (const Cmd& c : cmds_) {
    if (c.letter == 'G') {
      if (round_int(c.value * 10) == skip_g) continue;
      alarm("PS0129", "G cannot be a macro argument", c.column);
    }
    if (skip_p_l && (c.letter == 'P' || c.letter == 'L')) continue;
    if (c.letter == 'M' && round_int(c.value) == skip_m) continue;
    if (c.letter == 'N' || c.letter == 'O') continue;
    args.push_back(Arg{c.letter, c.value, c.decimal_point, c.literal});
  }
  return args;
}

void Interpreter::exec_nc(const Block& b) {
  cmds_.clear();
  have_.fill(false);
  g_codes_.clear();
  m_codes_.clear();
  word_check_ = false;
  for (std::uint32_t i = b.words_begin; i < b.words_end; ++i) {
    const nc::Word& w = prog_->words[i];
    Cmd c{w.letter, w.decimal_point, w.literal, w.column, w.value};
    if (!w.literal) {
      Value v = eval(w.expr);
      if (v.vacant) continue;  // a word whose value is vacant is not there at all
      c.value = v.v;
      check_word_digits(w.letter, c.value, scaled_address(w.letter), w.column);
    }
    int k = c.letter - 'A';
    if (k >= 26) [[unlikely]] {  // ,C ,R ,A: the parser writes their letters in lower case
      comma_cmds_.push_back(c);
      corner_on_ = true;
      continue;
    }
    if (word_needs_check(c.letter, c.value)) word_check_ = true;
    if (c.letter == 'G') {
      if (c.literal && c.decimal_point && c.value * 10 != std::floor(c.value * 10))
        alarm("PS0010", fmt::format("G{} is not a G code", c.value), c.column);
      g_codes_.push_back(round_int(c.value * 10));
    } else if (c.letter == 'M') {
      m_codes_.push_back(round_int(c.value));  // checked when acted on: G65 M1.5 is an argument
    }
    have_[k] = true;
    slot_[k] = static_cast<std::uint8_t>(cmds_.size());
    cmds_.push_back(c);
  }
  if (cmds_.empty()) return;

  const Frame& here = frames_.back();
  // A subprogram called by an M code (No.6071..6079) or the T code (No.6001#5): made after the block
  // as M98 is; 0 for none.
  int sub_call = 0, sub_call_m = -1;
  std::uint16_t sub_call_column = 0;
  // Macro calls take the whole block.
  for (int g : g_codes_) {
    if (g == 650 || g == 660) {
      if (!has('P')) alarm("PS0076", fmt::format("G{} needs P (the program number)", g / 10), b.column);
      int number = integer(word('P'), "P");
      int repeat = has('L') ? integer(word('L'), "L") : 1;
      if (repeat < 1) return;  // L0: no call
      std::vector<Arg> args = arguments(true, g, -1);
      if (g == 650) {
        call_macro(number, args, repeat, false, false, b.column);
      } else {
        modal_call_ = true;
        modal_calls_.push_back({number, repeat, std::move(args)});
      }
      return;
    }
    if (g == 670) {  // cancels the latest G66; the one before it, if any, is in force again
      if (!modal_calls_.empty()) modal_calls_.pop_back();
      modal_call_ = !modal_calls_.empty();
      if (cmds_.size() == 1) return;
    }
  }
  if (!here.custom) {
    for (int g : g_codes_)
      for (int i = 0; i < 10; ++i)
        if (profile_.g_code_macros[i] != 0 && g == profile_.g_code_macros[i] * 10) {
          std::vector<Arg> args = arguments(false, g, -1);
          call_macro(9010 + i, args, 1, true, false, b.column);
          return;
        }
    for (int m : m_codes_) {
      for (int i = 0; i < 10; ++i)
        if (profile_.m_code_macros[i] != 0 && m == profile_.m_code_macros[i]) {
          std::vector<Arg> args = arguments(false, -1, m);
          call_macro(9020 + i, args, 1, true, false, b.column);
          return;
        }
      // No.6071..6079: a subprogram call as M98 makes it, so after the block's move and its other
      // M codes; the calling M code is not given out (below)
      for (int i = 0; i < 9; ++i)
        if (sub_call == 0 && profile_.m_code_subprograms[i] != 0 && m == profile_.m_code_subprograms[i]) {
          sub_call = 9001 + i;
          sub_call_m = m;
          sub_call_column = b.column;
        }
    }
  }

  if (word_check_ || g_codes_.size() > 1) check_block_words();
  std::vector<int> one_shot;
  handle_g_codes(one_shot);
  if (rigid_pending_ || std::ranges::find(m_codes_, 29) != m_codes_.end()) rigid_tapping_words();

  if (has('F')) {
    double f = word('F').value;
    if (f < 0) alarm("PS0006", fmt::format("F{}: a feed rate takes no minus sign", f), word('F').column);
    feed_ = inch_ ? f * 25.4 : f;
  }
  if (has('S')) {  // on a lathe, S with G50 (G92 on systems B/C) is the spindle speed limit
    bool limit = profile_.lathe() && std::ranges::any_of(one_shot, [](int g) { return g == 500 || g == 920; });
    (limit ? max_spindle_ : speed_) = word('S').value;
  }
  if (has('H')) {
    h_ = integer(word('H'), "H");
    // an H alone in G43/G44 mode changes the tool length offset to the new number's value
    const bool length_code = std::ranges::any_of(g_codes_, [](int g) { return g == 430 || g == 440 || g == 490; });
    const bool position_offset = std::ranges::any_of(g_codes_, [](int g) { return g >= 450 && g <= 480; });
    if (!profile_.lathe() && (length_comp_ == 43 || length_comp_ == 44) && !length_code && !position_offset)
      tool_shift_[2] = (length_comp_ == 43 ? 1 : -1) * length_offset(h_);
  }
  if (has('D') && !(profile_.lathe() && profile_.series10_format)) d_ = integer(word('D'), "D");  // else a cycle's depth
  if (has('T')) {
    int t = integer(word('T'), "T");
    if (profile_.t_code_calls_o9000 && !here.custom) {  // O9000 does the tool's work
      write_var(149, Value::of(t), word('T').column);
      if (sub_call == 0) {
        sub_call = 9000;
        sub_call_column = word('T').column;
      }
    } else {
      tool_ = t;
      if (profile_.lathe()) {  // a turret indexes on T; a mill changes on M06
        select_lathe_offset(t % 100, word('T').column);
        emit_event(MoveKind::tool_change, t);
      }
    }
  }

  if (position_offset_ != 0) [[unlikely]] check_position_offset(one_shot);
  bool moved = false;
  if (!one_shot.empty()) {
    if (std::ranges::any_of(one_shot, [](int g) { return g != 40; })) end_lathe_cycle_data();
    for (int g : one_shot) {
      switch (g) {
        case 760: multiple_threading_cycle(); moved = true; break;  // G76 on a lathe (threading.cpp)
        case 40: dwell(); break;
        case 280: case 300: reference_return(g); moved = true; break;
        case 530: machine_coordinate_move(); moved = true; break;
        case 100: data_setting(); break;
        case 520: case 920: case 500: set_coordinate_system(g); break;
        case 700: case 710: case 720: case 730: case 740: case 750: moved = repetitive_cycle(g) || moved; break;
        case 270: reference_check(); moved = true; break;  // reference_moves.cpp
        case 290: return_from_reference(); moved = true; break;
        case 301: reference_return(g); moved = true; break;
        case 921: workpiece_preset(); break;
        case 600: moved = single_direction_block() || moved; break;  // single_direction.cpp
        case 310: case 311: case 312: case 313: case 314: moved = skip_move(g) || moved; break;  // skip.cpp
        case 220: stroke_area_command(); break;  // stroke_check.cpp
        default: break;
      }
    }
  } else if (cycle_ != 0) {
    moved = profile_.lathe() ? lathe_drilling_block() : canned_cycle_block();
  } else {
    AxisVector target = pos_;
    bool axes = axis_target(target);
    bool full_circle_ijk = (motion_ == 2 || motion_ == 3) && (has('I') || has('J') || has('K'));
    if (position_offset_ != 0) [[unlikely]] apply_position_offset(target);
    if (axes || full_circle_ijk) {
      if (rolls_) roll_over(target);
      if (corner_on_ || (profile_.lathe() && (has('C') || has('I') || has('K') || has('R')))) [[unlikely]]
        arm_corner(target);
      motion(target);
      moved = true;
    }
  }

  // M codes act after the motion of their block.
  for (const Cmd& c : cmds_) {
    if (c.letter != 'M') continue;
    int m = integer(c, "M");
    last_m_ = m;
    if (m == sub_call_m) continue;  // calls its subprogram below, as M98 does; not given out
    if (m == cycle_clamp_m_) [[unlikely]] {  // given out by the lathe's drilling cycle at each hole
      cycle_clamp_m_ = -1;
      continue;
    }
    switch (m) {
      case 98: {
        if (!has('P') && has('Q')) {  // M98 Q: the block N(q) of the program being run, as a subprogram
          const int seq = integer(word('Q'), "Q (sequence number)");
          auto it = prog_->sequence_index.find(seq);
          if (it == prog_->sequence_index.end())
            alarm("PS0078", fmt::format("M98 Q{}: no block N{} in this program", seq, seq), word('Q').column);
          const int repeat = has('L') ? integer(word('L'), "L") : 1;
          if (repeat < 1) break;
          Frame f;
          f.kind = Frame::subprogram;
          f.repeat = repeat - 1;
          call_program(prog_->number, f, word('Q').column, static_cast<std::int32_t>(it->second));
          return;
        }
        if (!has('P')) alarm("PS0076", "M98 needs P (the subprogram number) or Q (a sequence number of this program)", b.column);
        const Cmd& p = word('P');
        int pv = integer(p, "P");
        int repeat = has('L') ? integer(word('L'), "L") : 1;
        int number = pv;
        if (!has('L') && p.literal && pv > 9999) {  // M98 P LLLL NNNN: repeat count in the upper digits
          number = pv % 10000;
          repeat = pv / 10000;
        }
        if (repeat < 1) break;
        Frame f;
        f.kind = Frame::subprogram;
        f.repeat = repeat - 1;
        call_program(number, f, p.column);
        return;
      }
      case 99: {
        std::optional<int> seq;
        if (has('P')) seq = integer(word('P'), "P");
        if (frames_.size() == 1) {  // M99 in the main program: run it again from the top (or from N)
          Frame& f = frames_.back();
          if (seq) {
            auto it = prog_->sequence_index.find(*seq);
            if (it == prog_->sequence_index.end()) alarm("PS0078", fmt::format("M99 P{}: no block N{}", *seq, *seq));
            f.pc = it->second;
          } else {
            f.pc = 0;
          }
          last_back_jump_ = &b;
          last_back_jump_prog_ = prog_;
          return;
        }
        return_from_program(seq, b.column);
        return;
      }
      case 2: case 30: end_program(m); return;
      default:
        if (!cycle_m_done_) m_code_event(m);  // else made at the hole's positioning (canned_cycles.cpp)
        break;
    }
  }

  if (sub_call != 0) {
    Frame f;
    f.kind = Frame::subprogram;
    f.custom = true;
    call_program(sub_call, f, sub_call_column);
    return;
  }

  // After a move, the latest G66 in force; in a macro a G66 called, the G66 before that one (the
  // manual's nesting of modal calls: the inner macro's moves call the outer macro).
  if (moved && !modal_calls_.empty()) {
    const std::size_t n = std::min(modal_calls_.size(), here.modal_limit);
    if (n > 0) {
      const ModalCall call = modal_calls_[n - 1];  // a copy: the macro may give G66 or G67
      modal_limit_next_ = n - 1;
      call_macro(call.program, call.args, call.repeat, false, true, b.column);
    }
  }
}

// The event of an M code that neither calls nor ends a program, as its block makes it.
void Interpreter::m_code_event(int m) {
  switch (m) {
    case 0: case 1:
      emit_event(MoveKind::program_stop, m);
      if (m == 0) warn("NC2004", "M00 program stop: the control waits for cycle start here");
      break;
    case 3: case 4: case 5: case 19: emit_event(MoveKind::spindle, m); break;
    case 6: emit_event(MoveKind::tool_change, tool_); break;
    case 7: case 8: case 9: emit_event(MoveKind::coolant, m); break;
    default: emit_event(MoveKind::m_code, m); break;
  }
}

}  // namespace ncurve::machine
