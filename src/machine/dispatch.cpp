// An NC block in FANUC's order: its words read, its G codes, its motion, its M codes.
#include "machine/executor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "machine/g_codes.hpp"
#include "machine/word_values.hpp"

namespace ncurve::machine {

using nc::Block;
using nc::Value;

// ---- NC blocks ----

// Increments per program unit (1000 for IS-B mm) is an exact integer: dividing by it gives the
// nearest double to the decimal value (4552 / 1000 = 4.552), where multiplying by 0.001 would not.
double Executor::as_written(double value, bool literal, bool decimal_point) const {
  if (!literal || decimal_point || profile_.decimal_calculator) return value;
  return value / (modal_.inch ? per_unit_inch_ : per_unit_mm_);  // No.3401#0 = 0: X10 is ten increments
}

double Executor::dimension_raw(const Cmd& c) const {
  // a literal like X1.25 with no more decimals than the increment is on its grid: rounding gives it back
  if (c.literal && c.decimal_point && c.decimals <= (modal_.inch ? on_grid_inch_ : on_grid_mm_) &&
      std::fabs(c.value) < 1e9)
    return c.value + 0.0;  // -0. rounds to +0
  const double per_unit = modal_.inch ? per_unit_inch_ : per_unit_mm_;
  return round_to_increment(as_written(c.value, c.literal, c.decimal_point), per_unit);
}

double Executor::dimension_any(const Cmd& c) const { return modal_.inch ? dimension_raw(c) * 25.4 : dimension_raw(c); }

int Executor::integer(const Cmd& c, const char* what) const {
  if (c.literal && c.decimal_point)
    alarm("PS0007", fmt::format("{} does not take a decimal point ({}{})", what, c.letter, c.value), c.column);
  if (!(std::fabs(c.value) < 1e9)) alarm("PS0003", fmt::format("{} value out of range", what), c.column);
  return round_int(c.value);
}

std::vector<Executor::Arg> Executor::arguments(bool skip_p_l, int skip_g, int skip_m) const {
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

void Executor::exec_nc(const Block& b) {
  if (!read_words(b)) return;
  SubprogramCall sub;
  if (macro_call_block(b, sub)) return;  // G65, G66 and custom G/M codes take the whole block
  if (vacant_word_.variable != 0) [[unlikely]] warn_vacant_word();
  if (word_check_ || g_codes_.size() > 1) check_block_words();
  std::vector<int> one_shot;
  handle_g_codes(one_shot);
  if (rigid_pending_ || std::ranges::find(m_codes_, 29) != m_codes_.end()) rigid_tapping_words();
  word_settings(one_shot, sub);
  const bool moved = block_motion(one_shot);
  if (modal_.comp_side != 0 && moved && !profile_.lathe()) [[unlikely]] check_radius_offset();
  if (block_m_codes(b, sub)) return;  // M98, M99, M02, M30 leave the block
  if (sub.program != 0) {
    Frame f;
    f.kind = Frame::subprogram;
    f.custom = true;
    call_program(sub.program, f, sub.column);
    return;
  }
  if (moved && !modal_calls_.empty()) modal_call_after_move(b);
}

// G41/G42 moving with a radius offset of 0 (D0, no D, or an offset never set): the control accepts it
// and the tool's centre runs on the programmed contour. Checked once a start-up and D number.
void Executor::check_radius_offset() {
  if (radius_checked_ == d_) return;
  radius_checked_ = d_;
  if (radius_offset(d_) != 0) return;
  const char* code = modal_.comp_side > 0 ? "G41" : "G42";
  std::uint16_t column = has('D') ? word('D').column : 0;
  for (const Cmd& c : cmds_)
    if (c.letter == 'G' && (round_int(c.value * 10) == 410 || round_int(c.value * 10) == 420)) column = c.column;
  if (d_ == 0) {
    warn_once("NC2070", fmt::format("{} with D0 (or no D): offset number 0 is always 0, so the tool's centre runs on "
                                    "the programmed contour and the part is cut the tool's radius beyond it all "
                                    "round (the control gives no alarm); give the D number of the tool's radius",
                                    code),
              column);
    return;
  }
  const int l = profile_.offset_memory == OffsetMemory::A ? 11 : profile_.offset_memory == OffsetMemory::B ? 10 : 12;
  warn_once("NC2071", fmt::format("{} with D{}: offset {} is 0 mm in the machine profile, so the tool's centre runs on "
                                  "the programmed contour; give the tool's radius in the profile's [tool_offsets] or "
                                  "with G10 L{} P{} R.. to simulate the compensated path",
                                  code, d_, d_, l, d_),
            column);
}

// A mill's tool change (M06, given out, or calling its subprogram or macro): the first cutting
// move after it is checked for the tool length compensation (check_tool_length). A lathe indexes
// its turret on T, with the offset of the T word: no M06 there.
void Executor::note_tool_change() {
  if (profile_.lathe()) return;
  tool_changed_ = true;
  changed_tool_ = tool_;
  tool_change_line_ = span(0).line;
  tool_change_z_ = coords_.pos[2];
}

// NC2075: the first cutting move (G01, G02, G03, a cycle's feed) after a mill's tool change, made
// with no tool length compensation in force (G49, or G43/G44 with H0, whose offset is always 0):
// the programmed Z is then the spindle's gauge line, and the tool's tip reaches its length below
// it. The control gives no alarm. A G43/G44 H in force from before the change stays in force
// across M06, as on the control (the tool change is the machine's, not a G code), and is not warned.
// A feed move in X and Y alone at the height the tool change left the tool (CAM systems' G01 X Y
// F before their G43 Z) is not yet a cut: the check waits for a move at a height of the program's.
void Executor::check_tool_length(double to_z) {
  if (coords_.pos[2] == tool_change_z_ && to_z == tool_change_z_) return;
  tool_changed_ = false;
  const bool compensated = modal_.length_comp == 43 || modal_.length_comp == 44;
  if (compensated && h_ != 0) return;
  const std::string tool = changed_tool_ != 0 ? fmt::format("T{}", changed_tool_) : std::string("the tool");
  const std::string why = compensated ? fmt::format("G{} with H0 (offset number 0 is always 0)", modal_.length_comp)
                                      : std::string("no tool length compensation (G49)");
  std::uint16_t column = 0;
  for (const Cmd& c : cmds_)
    if (column == 0 && (c.letter == 'G' || axis_index(c.letter) >= 0)) column = c.column;
  warn_once("NC2075", fmt::format("{} cuts with no G43 H: the programmed Z is the spindle's gauge line, not the tool "
                                  "tip, which reaches the tool's length below it: the tool goes that much deeper than "
                                  "programmed, into the part or the fixture (the control gives no alarm); {} is in force since the tool change (M06) at line "
                                  "{}: give G43 H{} with the tool's length offset before the first cut",
                                  tool, why, tool_change_line_, changed_tool_ != 0 ? changed_tool_ : 1),
            column);
}

// A dimension or F word that read a vacant variable: the control ignores a word whose value is
// vacant, and counts a vacant variable as 0 in an expression, without an alarm. A macro's own
// arguments left out (X#24 with no X given) are its way of making a word optional: not warned.
void Executor::warn_vacant_word() {
  const VacantWord& v = vacant_word_;
  if (v.ignored) {
    if (frames_.back().kind == Frame::macro && v.variable >= 1 && v.variable <= 33) return;
    warn_once("NC2072", fmt::format("{}: #{} is vacant, so the control ignores the word {} (the block runs as if it "
                                    "were not written) without an alarm; check the variable",
                                    v.letter, v.variable, v.letter),
              v.column);
    return;
  }
  warn_once("NC2072", fmt::format("{}: #{} is vacant and counts as 0 in the word's expression, which gives {}{} "
                                  "without an alarm; check the variable",
                                  v.letter, v.variable, v.letter, v.value),
            v.column);
}

// The block's words, values evaluated; false for a block with none.
bool Executor::read_words(const Block& b) {
  cmds_.clear();
  have_.fill(false);
  g_codes_.clear();
  m_codes_.clear();
  word_check_ = false;
  vacant_word_.variable = 0;
  const nc::Word* const words = unit_->words.data();  // held: the stores below could alias unit_
  std::uint8_t slot = 0;                               // cmds_.size(), counted
  for (std::uint32_t i = b.words_begin; i < b.words_end; ++i) {
    const nc::Word& w = words[i];
    Cmd c{w.letter, w.decimal_point, w.literal, w.column, w.value, w.decimals};
    if (!w.literal) {
      int vacant = 0;
      Value v = eval_word(w.expr, vacant);
      if (vacant != 0 && vacant_word_.variable == 0 && (scaled_address(w.letter) || w.letter == 'F')) [[unlikely]]
        vacant_word_ = {vacant, w.letter, v.vacant, v.vacant ? 0.0 : v.v, w.column};
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
      if (c.literal && !c.decimal_point && std::fabs(c.value) < 1e8) {
        g_codes_.push_back(static_cast<int>(c.value) * 10);  // digits alone: a whole number (G01 is 10)
      } else {
        if (c.literal && c.decimal_point && c.value * 10 != std::floor(c.value * 10))
          alarm("PS0010", fmt::format("G{} is not a G code", c.value), c.column);
        g_codes_.push_back(round_int(c.value * 10));
      }
    } else if (c.letter == 'M') {
      m_codes_.push_back(round_int(c.value));  // checked when acted on: G65 M1.5 is an argument
    }
    have_[k] = true;
    slot_[k] = slot++;
    cmds_.push_back(c);
  }
  return !cmds_.empty();
}

// G65, G66/G67 and the custom macro calls by G and M codes (No.6050.., No.6080..): true when the
// block is a call, which takes the whole block. Notes in `sub` a subprogram an M code (No.6071..6079)
// calls, made after the block as M98 is.
bool Executor::macro_call_block(const Block& b, SubprogramCall& sub) {
  // most blocks: no G65, G66, G67 or M code, and the profile has no custom G code
  bool maybe = !m_codes_.empty();
  for (int g : g_codes_) maybe = maybe || g == 650 || g == 660 || g == 670;
  if (!maybe && std::ranges::all_of(profile_.g_code_macros, [](int code) { return code == 0; })) return false;
  return macro_call_codes(b, sub);
}

bool Executor::macro_call_codes(const Block& b, SubprogramCall& sub) {
  // Macro calls take the whole block.
  for (int g : g_codes_) {
    if (g == 650 || g == 660) {
      if (!has('P')) alarm("PS0076", fmt::format("G{} needs P (the program number)", g / 10), b.column);
      int number = integer(word('P'), "P");
      int repeat = has('L') ? integer(word('L'), "L") : 1;
      if (repeat < 1) return true;  // L0: no call
      std::vector<Arg> args = arguments(true, g, -1);
      if (g == 650) {
        call_macro(number, args, repeat, false, false, b.column);
      } else {
        modal_.modal_call = true;
        modal_calls_.push_back({number, repeat, std::move(args)});
      }
      return true;
    }
    if (g == 670) {  // cancels the latest G66; the one before it, if any, is in force again
      if (!modal_calls_.empty()) modal_calls_.pop_back();
      modal_.modal_call = !modal_calls_.empty();
      if (cmds_.size() == 1) return true;
    }
  }
  int g_macros = 0;  // nonzero when a G code calls a macro
  for (int code : profile_.g_code_macros) g_macros |= code;
  if (g_macros == 0 && m_codes_.empty()) return false;  // no code of the block can call
  if (!frames_.back().custom) {
    for (int g : g_codes_)
      for (int i = 0; i < 10 && g_macros != 0; ++i)
        if (profile_.g_code_macros[i] != 0 && g == profile_.g_code_macros[i] * 10) {
          std::vector<Arg> args = arguments(false, g, -1);
          call_macro(9010 + i, args, 1, true, false, b.column);
          return true;
        }
    for (int m : m_codes_) {
      for (int i = 0; i < 10; ++i)
        if (profile_.m_code_macros[i] != 0 && m == profile_.m_code_macros[i]) {
          if (m == 6) note_tool_change();  // M06 as a custom macro: the change is the macro's
          std::vector<Arg> args = arguments(false, -1, m);
          call_macro(9020 + i, args, 1, true, false, b.column);
          return true;
        }
      // No.6071..6079: a subprogram call as M98 makes it, so after the block's move and its other
      // M codes; the calling M code is not given out (below)
      for (int i = 0; i < 9; ++i)
        if (sub.program == 0 && profile_.m_code_subprograms[i] != 0 && m == profile_.m_code_subprograms[i]) {
          sub.program = 9001 + i;
          sub.m = m;
          sub.column = b.column;
        }
    }
  }
  return false;
}

// F, S, H, D and T of the block (a T code with No.6001#5 calls O9000 after the block, in `sub`).
void Executor::word_settings(const std::vector<int>& one_shot, SubprogramCall& sub) {
  if (has('F')) {
    double f = word('F').value;
    if (f < 0) alarm("PS0006", fmt::format("F{}: a feed rate takes no minus sign", f), word('F').column);
    feed_ = modal_.inch ? f * 25.4 : f;
  }
  if (has('S')) {  // on a lathe, S with G50 (G92 on systems B/C) is the spindle speed limit
    bool limit = profile_.lathe() && std::ranges::any_of(one_shot, [](int g) { return g == 500 || g == 920; });
    (limit ? max_spindle_ : speed_) = word('S').value;
    const double machine = profile_.spindle_limit();
    if (!limit && !modal_.css && machine > 0 && speed_ > machine * (1 + 1e-9)) [[unlikely]]
      warn_spindle_limit(speed_, word('S').column);
  }
  if (has('H')) {
    h_ = integer(word('H'), "H");
    // an H alone in G43/G44 mode changes the tool length offset to the new number's value
    const bool length_code = std::ranges::any_of(g_codes_, [](int g) { return g == 430 || g == 440 || g == 490; });
    const bool position_offset = std::ranges::any_of(g_codes_, [](int g) { return g >= 450 && g <= 480; });
    if (!profile_.lathe() && (modal_.length_comp == 43 || modal_.length_comp == 44) && !length_code && !position_offset)
      coords_.tool_shift[2] = (modal_.length_comp == 43 ? 1 : -1) * length_offset(h_);
  }
  if (has('D') && !(profile_.lathe() && profile_.series10_format)) d_ = integer(word('D'), "D");  // else a cycle's depth
  if (has('T')) {
    int t = integer(word('T'), "T");
    if (profile_.t_code_calls_o9000 && !frames_.back().custom) {  // O9000 does the tool's work
      write_var(149, Value::of(t), word('T').column);
      if (sub.program == 0) {
        sub.program = 9000;
        sub.column = word('T').column;
      }
    } else {
      tool_ = t;
      if (profile_.lathe()) {  // a turret indexes on T; a mill changes on M06
        select_lathe_offset(t % 100, word('T').column);
        emit_event(MoveKind::tool_change, t);
      }
    }
  }
}

// The block's motion: its one-shot codes' actions, a canned cycle's holes, or its axis words' move.
bool Executor::block_motion(const std::vector<int>& one_shot) {
  if (position_offset_ != 0) [[unlikely]] check_position_offset(one_shot);
  bool moved = false;
  if (!one_shot.empty()) {
    if (std::ranges::any_of(one_shot, [](int g) { return g != 40; })) end_lathe_cycle_data();
    for (int g : one_shot)
      if (const GAction act = g_action(g, g_machine(profile_))) moved = act(*this, g) || moved;
  } else if (modal_.cycle != 0) {
    moved = profile_.lathe() ? lathe_drilling_block() : canned_cycle_block();
  } else {
    AxisVector target = coords_.pos;
    bool axes = axis_target(target);
    bool full_circle_ijk = (modal_.motion == 2 || modal_.motion == 3) && (has('I') || has('J') || has('K'));
    if (position_offset_ != 0) [[unlikely]] apply_position_offset(target);
    if (axes || full_circle_ijk) {
      if (rolls_) roll_over(target);
      if (corner_on_ || (profile_.lathe() && (has('C') || has('I') || has('K') || has('R')))) [[unlikely]]
        arm_corner(target);
      motion(target);
      moved = true;
    }
  }
  return moved;
}

// The block's M codes, after its motion; true when one left the block (a call, a return, the end).
bool Executor::block_m_codes(const Block& b, const SubprogramCall& sub) {
  if (m_codes_.empty()) return false;  // read_words lists every M word
  for (const Cmd& c : cmds_) {
    if (c.letter != 'M') continue;
    int m = integer(c, "M");
    last_m_ = m;
    if (m == 6) note_tool_change();
    if (m == sub.m) continue;  // calls its subprogram below, as M98 does; not given out
    if (m == cycle_clamp_m_) [[unlikely]] {  // given out by the lathe's drilling cycle at each hole
      cycle_clamp_m_ = -1;
      continue;
    }
    switch (m) {
      case 98: {
        if (!has('P') && has('Q')) {  // M98 Q: the block N(q) of the program being run, as a subprogram
          const int seq = integer(word('Q'), "Q (sequence number)");
          const std::int32_t at = prog_->find_sequence(seq);
          if (at < 0)
            alarm("PS0078", fmt::format("M98 Q{}: no block N{} in this program", seq, seq), word('Q').column);
          const int repeat = has('L') ? integer(word('L'), "L") : 1;
          if (repeat < 1) break;
          Frame f;
          f.kind = Frame::subprogram;
          f.repeat = repeat - 1;
          call_program(prog_->number, f, word('Q').column, at);
          return true;
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
        return true;
      }
      case 99: {
        std::optional<int> seq;
        if (has('P')) seq = integer(word('P'), "P");
        if (frames_.size() == 1) {  // M99 in the main program: run it again from the top (or from N)
          Frame& f = frames_.back();
          if (seq) {
            const std::int32_t at = prog_->find_sequence(*seq);
            if (at < 0) alarm("PS0078", fmt::format("M99 P{}: no block N{}", *seq, *seq));
            f.pc = at;
          } else {
            f.pc = 0;
          }
          last_back_jump_ = block_index_;
          last_back_jump_prog_ = prog_;
          return true;
        }
        return_from_program(seq, b.column);
        return true;
      }
      case 2: case 30: end_program(m); return true;
      default:
        if (!cycle_m_done_) m_code_event(m);  // else made at the hole's positioning (canned_cycles.cpp)
        break;
    }
  }
  return false;
}

// After a move, the latest G66 in force; in a macro a G66 called, the G66 before that one (the
// manual's nesting of modal calls: the inner macro's moves call the outer macro).
void Executor::modal_call_after_move(const Block& b) {
  const std::size_t n = std::min(modal_calls_.size(), frames_.back().modal_limit);
  if (n > 0) {
    const ModalCall call = modal_calls_[n - 1];  // a copy: the macro may give G66 or G67
    modal_limit_next_ = n - 1;
    call_macro(call.program, call.args, call.repeat, false, true, b.column);
  }
}

// The event of an M code that neither calls nor ends a program, as its block makes it.
void Executor::m_code_event(int m) {
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
