// The control's state and the execution of a Program: what Interpreter (interpreter.hpp) runs.
// Private to machine/: the rest of ncurve uses Interpreter.
#pragma once
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "machine/interpreter.hpp"
#include "machine/coordinates.hpp"
#include "machine/modal.hpp"
#include "machine/path/chamfer.hpp"
#include "machine/path/compensation.hpp"
#include "machine/path/compensation_stage.hpp"
#include "machine/path/corner_stage.hpp"
#include "machine/path/developed_conversion.hpp"
#include "machine/path/nose_centre.hpp"
#include "machine/path/statistics.hpp"
#include "machine/path/stroke_check.hpp"
#include "machine/frame/transforms.hpp"

namespace ncurve::machine {

namespace mrc {
struct Step;
}

class Executor final : private CornerControl, CompensationControl, StrokeFrame, NoseTipSource {
public:
  Executor(const MachineProfile& profile, const ProgramLibrary& library, RunOptions options = {});
  ~Executor();
  RunResult run(MoveSink& sink);

  // Variable value after (or during) a run, as a program would read it.
  nc::Value variable(int number);
  // Tell this observer each block, call, return and variable write of the next runs (null: none).
  void observe(ExecutionObserver* observer) { observer_ = observer; }
  std::uint64_t plain_lane_blocks() const { return plain_lane_blocks_; }
  // The imaginary tip's offset from the nose centre for the move being delivered (lathe).
  V2 tip_of_move() const { return nose_tip_now(); }

  // ---- what the G-code table's actions (g_actions.cpp and a code's own file) use ----
  struct Cmd {  // a word of the block in hand, its value evaluated
    Cmd() = default;
    Cmd(char letter, bool decimal_point, bool literal, std::uint16_t column, double value, std::uint8_t decimals = 255)
        : letter(letter), literal(literal), decimal_point(decimal_point), decimals(decimals), column(column),
          value(value) {}
    // in nc::Word's order and 16 bytes: a block's words are copied into cmds_ as they are
    char letter = 0;
    bool literal = true;
    bool decimal_point = false;
    std::uint8_t decimals = 255;  // a literal's digits after its point
    std::uint16_t column = 0;
    double value = 0;
  };
  bool has(char letter) const { return have_[letter - 'A']; }
  const Cmd& word(char letter) const { return cmds_[slot_[letter - 'A']]; }
  // program units -> mm, decimal point rule applied; in line for the common word, a literal in mm
  // with a point (dimension_raw's rule: on the grid already, or rounded to it)
  double dimension(const Cmd& c) const {
    if (!modal_.inch && c.literal && c.decimal_point) {
      if (c.decimals <= on_grid_mm_ && std::fabs(c.value) < 1e9) return c.value + 0.0;  // -0. rounds to +0
      return round_to_increment(c.value, per_unit_mm_);
    }
    return dimension_any(c);
  }
  double dimension_any(const Cmd& c) const;
  int integer(const Cmd& c, const char* what) const;
  bool incremental() const { return modal_.incremental; }
  const MachineProfile& profile() const { return profile_; }
  [[noreturn]] void alarm(std::string code, std::string message, std::uint16_t column = 0,
                          std::uint32_t length = 1) const;
  void warn(std::string code, std::string message, std::uint16_t column = 0);
  void dwell();
  void reference_return(int g);
  void machine_coordinate_move();
  void set_coordinate_system(int g);
  void data_setting();
  bool repetitive_cycle(int g);      // one G70..G75 block; whether the tool moved
  void multiple_threading_cycle();                 // G76 (group 00)
  void reference_check();                 // G27
  void return_from_reference();           // G29
  void workpiece_preset();                // G92.1 (G50.3 on system A)
  bool single_direction_block();          // a one-shot G60 block
  bool skip_move(int g);                  // G31, G31 P1..P4, G31.1..G31.4
  void stroke_area_command();             // G22 with its area
  // ---- end of what the actions use ----

private:
  struct Frame;
  struct Arg {
    char letter;
    double value;
    bool decimal_point;
    bool literal;
  };

  // execution
  void step();
  void check_runaway();  // --max-steps and --max-seconds
  void count_block_move();  // a block's moves past its first count as steps
  std::uint64_t steps() const;
  // an NC block in FANUC's order (dispatch.cpp)
  struct SubprogramCall {  // a subprogram an M or T code calls after its block, as M98 does
    int program = 0, m = -1;
    std::uint16_t column = 0;
  };
  void exec_nc(const nc::Block& b);
  bool read_words(const nc::Block& b);
  bool plain_lane_open(const nc::Block& b) const;
  // Runs `first` and the lane blocks after it in its piece as step() would run them one by one.
  void plain_motion_blocks(const nc::Block& first);
  void plain_motion_block(const nc::Block& b, Move& m);
  double plain_dimension(const nc::Word& w) const;
  std::uint64_t plain_lane_blocks_ = 0;
  bool g01_calls_macro() const;  // No.6050..6059 make G01 a macro call
  bool macro_call_block(const nc::Block& b, SubprogramCall& sub);
  bool macro_call_codes(const nc::Block& b, SubprogramCall& sub);  // macro_call_block's search
  void word_settings(const std::vector<int>& one_shot, SubprogramCall& sub);
  bool block_motion(const std::vector<int>& one_shot);
  bool block_m_codes(const nc::Block& b, const SubprogramCall& sub);
  void modal_call_after_move(const nc::Block& b);
  void check_radius_offset();  // NC2070: G41/G42 moving with a radius offset of 0
  void note_tool_change();     // a mill's M06: the first cut after it is checked (NC2075)
  void check_tool_length(double to_z);  // NC2075: the first cut after a tool change, without G43/G44 H
  void warn_vacant_word();  // NC2072
  void exec_assignment(const nc::Block& b);
  void jump(const nc::Block& b, double sequence);
  const std::vector<std::int32_t>& loops_of(const nc::Program* p);
  bool condition(const nc::Expr& e);
  nc::Value eval(const nc::Expr& e);
  nc::Value eval_word(const nc::Expr& e, int& vacant_variable);  // and the first variable it read vacant
  template <class Reader> nc::Value evaluate_with(const nc::Expr& e, Reader& reader);  // interpreter.cpp
  // entry >= 0: the block of the program being run where the call starts (M98 Q)
  void call_program(int number, Frame frame, std::uint16_t column, std::int32_t entry = -1);
  void call_macro(int number, const std::vector<Arg>& args, int repeat, bool custom, bool modal, std::uint16_t column);
  void return_from_program(std::optional<int> sequence, std::uint16_t column);
  void end_program(int m_code);
  void external_output(const nc::Block& b);  // POPEN PCLOS DPRNT BPRNT (macro_output.cpp)
  // programmable parameter input, G10 L52 .. G11 (parameter_input.cpp)
  void start_parameter_input();
  void parameter_input_block(const nc::Block& b);
  void set_parameters_by_program(int n, const std::vector<std::pair<std::string, double>>& changes,
                                 std::uint16_t column);
  bool parameter_input_ = false;

  // words and units
  double as_written(double value, bool literal, bool decimal_point) const;  // decimal point rule, program units
  double dimension_raw(const Cmd& c) const;  // program units, decimal point rule and rounding, no inch
  std::vector<Arg> arguments(bool skip_p_l, int skip_g, int skip_m) const;
  // checks on the block's words before they act (block_words.cpp)
  // A minus sign where the address takes none (T-1, S-100), or a letter again but G: check_block_words
  static bool takes_no_sign(char letter) {
    return letter == 'M' || letter == 'S' || letter == 'T' || letter == 'H' || letter == 'D';
  }
  bool word_needs_check(char letter, double value) const {
    return (letter != 'G' && have_[letter - 'A']) || (value < 0 && takes_no_sign(letter));
  }
  void check_block_words();
  void check_word_digits(char letter, double value, bool dimension, std::uint16_t column) const;
  void assign_arguments(const std::vector<Arg>& args);

  // motion (motion.cpp)
  void handle_g_codes(std::vector<int>& one_shot);
  bool axis_target(AxisVector& target, bool force_absolute = false);
  void motion(const AxisVector& target);
  void linear(MoveKind kind, const AxisVector& target);
  void linear_into(Move& m, MoveKind kind, const AxisVector& target);  // m: kind, ends, feed, time set
  void arc(const AxisVector& target, bool clockwise);
  void emit(Move& m);  // the block's move or event into the path stages (path_corner_ first)
  // what the path stages read of the control (their interfaces), and their alarms and warnings
  OffsetOfMove offset_of_move(const PlaneAxes& plane) const override;  // for path_comp_
  double rapid_seconds(const AxisVector& from, const AxisVector& to) const override;
  static CompensationSettings compensation_settings(const MachineProfile& p);
  AxisVector machine_shift() const override;  // for path_stroke_: origin and tool shift
  V2 nose_tip_now() const override;  // for path_nose_: the tip's offset, none in G12.1/G07.1
  static void path_alarm(const Move& at, const std::string& code, const std::string& message);
  void path_warning(const Move& at, const std::string& code, const std::string& message);
  bool compensating() const { return path_comp_.active(); }
  void end_of_block_compensation(bool g40, bool g41);
  V2 nose_tip() const;
  double nose_radius() const;
  void emit_event(MoveKind kind, int code);
  void m_code_event(int m);  // spindle, coolant, M06, M00/M01 and other M codes of the block
  void set_origin();
  void warn_mixed_decimal_points(const nc::Program& p);
  void start_file_checks(const nc::Program& main);
  void finish_file_checks(const nc::Program& main);
  double css_top_speed() const;
  double minutes_per_rev(double r0, double r1) const;
  void warn_spindle_limit(double rpm, std::uint16_t column);  // NC2090 (feed_time.cpp)
  void check_css_spindle_limit(const Move& m);
  void check_centre_line(const Move& m);  // NC2077: a lathe's feed beyond X0 (centre_line.cpp)
  bool beyond_centre_ = false;            // the last feed went beyond X0: warned already
  double feed_seconds(double length, double r0, double r1) const;
  double arc_feed_seconds(const Move& m, double planar) const;
  void clamp_cutting_feed(Move& m, double fed) {  // NC2073: over the maximum cutting feed (feed_time.cpp)
    const double max = profile_.max_cutting_feed;
    if (max > 0 && m.seconds > 0 && fed * 60.0 > max * (1 + 1e-9) * m.seconds) [[unlikely]]
      clamp_to_max_feed(m, fed);
  }
  void clamp_to_max_feed(Move& m, double fed);

  // drilling canned cycles (canned_cycles.cpp, tapping_cycles.cpp, lathe_drilling.cpp): the block's
  // data and alarms; the holes' motions are the expanders' of hole_cycles.hpp, through HoleOutput
  struct CycleMoves;  // CycleOutput: the expanders' moves made here (cycle_moves.hpp)
  struct HoleOutput;
  void select_canned_cycle(int g, std::uint16_t column);
  void cancel_canned_cycle();
  bool canned_cycle_block();  // a block in cycle mode: stores the data, drills when it has axis words
  void cycle_m_codes();  // the cycle block's M codes, at its first hole's positioning
  bool cycle_m_done_ = false;  // they were: the block's M codes make no event after it
  int cycle_repeat_count();  // the block's K (or L), 1 without it; PS0045 beyond 0..9999
  void rigid_tapping_words();        // M29 and what may stand between it and G84/G74
  void rigid_tapping_check(std::uint16_t column) const;
  bool lathe_drilling_block();  // a lathe's G83..G85, G87..G89 (lathe_drilling.cpp)
  // NC2076: a peck drilling hole from point R to Z in cuts of q whose d (No.5114/No.5115) is 0
  void check_peck_d(int code, double r, double z, double q, std::uint16_t column);

  // tool position offset G45..G48 (position_offset.cpp)
  int position_offset_ = 0;  // 45..48 given in the block (one-shot), else 0
  void check_position_offset(const std::vector<int>& one_shot);
  void apply_position_offset(AxisVector& target);

  // AI contour control / look-ahead modes (high_speed.cpp)
  void high_speed_mode(int g, std::uint16_t column);
  // chamfering and corner R (chamfer.cpp): the block's move waits for the next one
  void arm_corner(const AxisVector& target);  // the block's ,C ,R (lathe: C, I, K, R), before its move
  void corner_block_end(bool program_end = false);  // after an NC block: what it left undone is an alarm
  CornerContext corner_context() const override;  // for path_corner_
  void set_offset_numbers(int d, int lathe_offset) override;
  void move_held() override;
  std::vector<Cmd> comma_cmds_;  // the block's ,C ,R ,A words (letters c, r, a)
  bool corner_words_read_ = false;  // this block's ,C ,R words were acted on
  bool corner_on_ = false;       // comma words read, a request armed or a move held

  // rotary axes (rotary.cpp)
  void init_rotary();
  double angle(const Cmd& c) const;  // a rotary axis word, degrees
  void roll_over(AxisVector& target) const;  // absolute commands of roll-over axes: the turn they make
  void wrap_rotary();                        // positions of roll-over axes back within one turn
  double combined_length(const AxisVector& from, const AxisVector& to, double linear) const;

  // ---- coordinate transforms of a mill (transform_modes.cpp): G15/G16 polar coordinate command,
  // G50.1/G51.1 programmable mirror image, G50/G51 scaling, G68/G69 coordinate system rotation ----
  void check_code_in_transform(int g, std::uint16_t column) const;  // codes the modes forbid
  void transform_codes(std::vector<int>& one_shot);  // the block's transform codes, after its other G codes
  bool transformed_axis_target(AxisVector& target);  // axis_target in G16 or a transform mode
  bool transform_arc_words();  // R or I J K of an arc under a transform; true when G02 and G03 swap
  void transformed_cycle_levels(int axis, double& r_level, double& z_level) const;  // canned cycle R and Z
  V2 transformed_plane_vector(V2 v) const;  // G40 I J
  AxisVector program_position() const;  // #5001..: the end point before the transforms
  Transforms xf_;
  bool xf_on_ = false;         // G16 or a transform is active
  bool xf_hook_ = false;       // xf_on_, or the first move after a cancel is still to be checked
  bool xf_cancelled_ = false;  // G69, G50 or G50.1 given: the next move should be absolute
  int xf_rotation_plane_ = 17;
  double xf_rotation_deg_ = 0;  // the G68 angle as programmed (RIN: an incremental R adds to it)
  bool xf_arc_ = false;         // the arc in hand takes xf_arc_r_ / xf_arc_offset_
  double xf_arc_r_ = 0;
  V2 xf_arc_offset_{};
  // ---- end of coordinate transforms ----

  // ---- polar coordinate interpolation G12.1/G13.1 and cylindrical interpolation G07.1
  // (polar_cylindrical.cpp): moves are made in the programmed plane, path_developed_ turns them into
  // the linear and rotary axes' moves ----
  struct Developed : DevelopedMode {  // the mode's axes (path_developed_ has them too)
    int saved_plane = 17;
  };
  bool developed_code(int g, std::uint16_t column);  // false: g is not a code of this machine
  void polar_start(std::uint16_t column);
  void cylinder_code(std::uint16_t column);
  void end_developed();
  void check_code_in_developed(int g, std::uint16_t column) const;  // codes the modes forbid
  bool developed_axis_target(AxisVector& target);  // axis_target in the modes
  std::optional<Developed> dev_;
  bool developed_ = false;       // dev_ has a value
  bool developed_hook_ = false;  // axis words go to developed_axis_target
  // ---- end of polar and cylindrical interpolation ----

  // ---- lathe multiple repetitive cycles G70..G75 (lathe_repetitive.cpp) ----
  struct ShapeRange {
    std::int32_t first = 0, last = 0;  // block indexes of N(ns) and N(nf) in prog_
    int ns = 0, nf = 0;
  };
  int repetitive_code(int g) const;  // the cycle a lathe G code names (x10, as in system A), else 0
  bool repetitive_cycle_path(int g); // its body; a path too long for memory is NC9000 above
  ShapeRange shape_range(int g);
  std::vector<Move> walk_shape(const ShapeRange& r, int g, bool keep);
  std::vector<Move> nose_compensated(const std::vector<Move>& shape);  // G71..G73 under G41/G42
  RadiusCompensation radius_compensation(CompensationSettings settings, RadiusCompensation::Deliver deliver);
  void check_shape_block(const nc::Block& b, bool first, int g);
  void finishing_cycle(const ShapeRange& r);
  bool stock_removal_cycle(int g);
  bool pattern_repeating_cycle();
  bool peck_cycle(int g);
  void emit_cycle_path(const std::vector<mrc::Step>& path, bool transposed);
  double increments(const Cmd& c) const;  // P/Q of G74/G75: least input increments, in mm
  // ---- end of the multiple repetitive cycles ----

  // ---- lathe single cutting cycles and threading (lathe_cycles.cpp, threading.cpp) ----
  // G32 G90 G92 G94 G76 (G33 G77 G78 G79 G76 on systems B/C): group 01 keeps the code as written
  bool select_lathe_motion(int g, std::vector<int>& one_shot);  // handle_g_codes: false if g is none of them
  void lathe_motion(const AxisVector& target);  // a block with axis words in G32/G90/G92/G94 mode
  void end_lathe_cycle_data() { lathe_cycle_ = {}; }  // one-shot codes but G04 clear X, Z, R
  void single_cycle(const AxisVector& target);      // G90/G92/G94: the data; the moves are turning.hpp's
  void thread_block(const AxisVector& target);     // G32
  void thread_cut(const AxisVector& to, double lead, double angle);
  double thread_start_angle();                     // Q in 0.001 deg, degrees
  double increments(const Cmd& c, const char* what) const;  // a length written in least increments, mm
  // ---- end of lathe cycles ----

  // ---- reference position moves, single direction positioning, skip and stored stroke checks
  // (codes/: reference_moves.cpp, single_direction.cpp, skip.cpp, stroke_area.cpp) ----
  unsigned block_axes() const;  // a bit per axis the block names (U, V, W too on system A)
  bool names_plane_axis() const;  // of the offset plane
  void remember_intermediate(const AxisVector& mid);  // G28/G30/G30.1: the point G29 goes through
  // NC2074: a reference return (g x10, point 0..3 or -1 floating) whose moves from `from` through
  // `mid` to `ref` take the tool towards the part
  void check_return_direction(int g, int point, const AxisVector& from, const AxisVector& mid, const AxisVector& ref);
  void single_direction(const AxisVector& target);
  AxisVector intermediate_{};
  unsigned intermediate_axes_ = 0;        // axes G28/G30/G30.1 have given an intermediate point
  std::optional<AxisVector> skip_position_;  // #5061..: where the last G31 ended
  void init_stroke_check();               // the profile's limits at power-on
  void stroke_area_switch(bool on);       // G22 / G23
  bool area_check_on() const override { return modal_.stroke2_on; }  // for path_stroke_
  StrokeLimits stroke_;                   // stored stroke limits (path_stroke_ checks the moves)
  // ---- end of reference position moves ----

  // variables (variables.cpp)
 public:
  nc::Value read_var(int n, std::uint16_t column);
 private:
  void write_var(int n, nc::Value v, std::uint16_t column);
  nc::Value read_system(int n, std::uint16_t column);  // system_variables.cpp
  int axis_of_order(int k) const;  // the k-th axis of the profile (0-based) as an axis index, or -1
  int modal_code(int group) const;  // #4001..#4022 (variables.cpp)
  void write_system(int n, nc::Value v, std::uint16_t column);
  double program_units(int axis, double mm_value) const override;  // for position variables

  void warn_once(std::string code, std::string message, std::uint16_t column = 0);  // once per block and code
  nc::Span span(std::uint16_t column = 0, std::uint32_t length = 1) const;

  struct Frame {
    const nc::Program* prog = nullptr;
    std::int32_t pc = 0;
    std::int32_t entry = 0;  // where a repeat starts again (M98 Q: the called block)
    std::int32_t level = 0;  // local variable level
    enum Kind : std::uint8_t { main, subprogram, macro } kind = main;
    bool custom = false;     // called by a custom G/M code (such codes are ordinary inside)
    bool modal = false;      // called by G66
    // the G66 calls a move here may make: those below this index of modal_calls_ (a macro called by
    // the n-th G66 calls the (n-1)-th after its moves; the main program, the latest)
    std::size_t modal_limit = SIZE_MAX;
    int repeat = 0;          // calls still to come (L)
    std::array<nc::Value, 33> initial{};  // locals on entry, for repeated macro calls
    const nc::Program* caller = nullptr;    // the calling block, for the call stack of an alarm
    std::uint32_t call_line = 0;
    std::uint16_t call_column = 0;
  };
  void add_call_stack(nc::Diagnostic& d) const;
  // the observer's side (observe.cpp): only called when there is one
  ExecutionObserver* observer_ = nullptr;
  ModalReadout observed_modal_{};  // the modal state the observer was last given
  bool modal_stale_ = true;      // an NC block ran since it was read
  bool shape_read_ = false;      // G71..G73 reading their shape: its blocks are the cycle block's
  void observe_block(const nc::Block& b);
  ToolInForce tool_in_force() const;
  void observe_call(const Frame& f);
  void observe_repeat(const Frame& f);  // a repeated macro call's locals back to its arguments
  void observed_write(int n, nc::Value v, std::uint16_t column);
  nc::Value observed_read(int n, std::uint16_t column);  // a system variable the program reads
  std::uint64_t moves_delivered() const;
  ModalReadout modal_readout();
  std::vector<const nc::Program*> reached_;  // programs of other files entered so far (their warnings given)

  MachineProfile profile_;  // G10 L52 may change its parameters
  std::array<bool, kAxes> has_axis_{};  // the profile's axes, by axis_index
  double per_unit_mm_ = 1000, per_unit_inch_ = 10000;  // least input increments per mm and per inch
  int on_grid_mm_ = 3, on_grid_inch_ = 4;  // decimals a literal may have to be on that grid already (-1: none)
  const ProgramLibrary& library_;
  RunOptions options_;
  nc::EvalOptions eval_options_;
  RunResult result_;

  std::vector<Frame> frames_;
  std::vector<std::array<nc::Value, 33>> locals_;
  std::vector<nc::Value> common_;  // #100..#999
  int common_high_ = 199;          // last of the first common range
  const nc::Program* prog_ = nullptr;
  const nc::Block* block_ = nullptr;
  std::int32_t block_index_ = -1;  // block_'s index in prog_
  // The compiled piece holding block_ (its words, code, errors, comments and prints): prog_ itself, or
  // a piece of a streamed program, kept in memory by unit_hold_; it holds prog_'s blocks [first, end).
  const nc::Program* unit_ = nullptr;
  const nc::Program* unit_prog_ = nullptr;
  std::int32_t unit_first_ = 0, unit_end_ = 0;
  // Makes block i of p the block in hand; false past p's end.
  bool select_block(const nc::Program* p, std::int32_t i) {
    prog_ = p;
    if (p != unit_prog_ || i < unit_first_ || i >= unit_end_) [[unlikely]]
      if (!select_piece(p, i)) return false;
    block_ = &unit_->blocks[i - unit_first_];
    block_index_ = i;
    return true;
  }
  [[gnu::noinline]] bool select_piece(const nc::Program* p, std::int32_t i);
  [[gnu::noinline, gnu::cold]] void past_the_end();  // the program ran out of blocks
  void settle_loop(const nc::Block& b);
  std::uint32_t line_of(const nc::Program* p, std::int32_t i);
  // A streamed program's whole-file checks (NC2001, NC2030, NC2031) as its pieces are read.
  struct FileChecks;
  bool finished_ = false;
  int macro_depth_ = 0;
  int sub_depth_ = 0;
  std::unordered_map<const nc::Program*, std::vector<std::int32_t>> loop_of_;  // innermost DO per block
  std::int32_t last_back_jump_ = -1;  // the block index of the last jump back, in last_back_jump_prog_
  const nc::Program* last_back_jump_prog_ = nullptr;

  // current block words
  std::vector<Cmd> cmds_;
  std::array<bool, 26> have_{};
  std::array<std::uint8_t, 26> slot_{};
  std::vector<int> g_codes_;  // x10: 541 for G54.1
  std::vector<int> m_codes_;
  bool word_check_ = false;  // the block repeats an address or signs one that takes no sign
  double digit_limit_ = 1e8;  // 10^number_digits: a word's value in units or increments stays below
  std::set<std::tuple<const nc::Program*, std::int32_t, std::string>> warned_once_;  // warn_once: given already
  std::set<std::pair<const nc::Program*, std::int32_t>> repeat_warned_;  // blocks warned of a repeated address
  std::uint64_t operations_ = 0;  // expression operations evaluated, counted with blocks as steps
  std::uint64_t block_moves_ = 0;  // moves past the first of their block, counted as steps too
  std::uint64_t moving_block_ = 0;  // the count of blocks when the last move was made
  std::uint64_t moves_in_block_ = 0;  // that block's moves past its first
  std::chrono::steady_clock::time_point started_;

  ModalState modal_;  // modal.hpp
  bool exact_stop_once_ = false;  // G09 in the current block
  std::uint32_t statements_since_ = 0, nc_blocks_since_ = 0;  // since the previous event
  double feed_ = 0, speed_ = 0;
  double max_spindle_ = 0;  // G50 S on a lathe
  int tool_ = 0, h_ = 0, d_ = 0, last_m_ = -1;
  bool tool_changed_ = false;  // a mill's M06 with no cutting move since (NC2075)
  std::int32_t last_sequence_ = -1;
  // G66 modal calls in force, the latest last: a second G66 nests inside the first, and G67 cancels
  // the latest (the manual's nesting of modal calls).
  struct ModalCall {
    int program = 0;
    int repeat = 1;
    std::vector<Arg> args;
  };
  std::vector<ModalCall> modal_calls_;
  std::size_t modal_limit_next_ = SIZE_MAX;  // the modal_limit of the frame call_program makes next
  // drilling canned cycle (group 09): 0 = G80, else 73, 74, 76, 81..89; data kept while it is active
  AxisVector cycle_initial_{};        // where the cycle mode started: the initial level along the drilling axis
  int cycle_axis_ = -1;               // the drilling axis of the cycle mode, -1 before its first hole
  std::optional<double> cycle_r_, cycle_z_;  // mm as written (G91: R from the initial level, Z from R)
  double cycle_q_ = 0, cycle_p_ = 0;  // peck depth or shift (mm), dwell (s)
  bool cycle_has_q_ = false;
  bool cycle_z_incremental_ = false;  // lathe: the bottom was written as a distance from R (W, U, or under G91)
  int cycle_clamp_m_ = -1;            // lathe: the C-axis clamp M code the cycle gave out in this block
  bool rigid_tapping_ = false;        // rigid mode: M29 (or No.5200#0) with G84/G74, until the cycle ends
  bool rigid_pending_ = false;        // M29 given, its G84/G74 not yet
  // rotary axes with roll-over (No.1008#0): absolute words of this block and their values
  bool rolls_ = false;                // the profile has a roll-over axis
  bool extra_axes_ = false;           // the profile has an A, B or C axis
  std::array<bool, kAxes> rotary_{};
  std::array<bool, kAxes> roll_word_{};
  AxisVector roll_value_{};
  void select_lathe_offset(int number, std::uint16_t column);
  // an offset as the program reads it and writes it: a length in inches under G20
  double offset_units(double mm, bool length = true) const;
  double offset_mm(double value, bool length = true) const;
  static bool is_tip_variable(int n);     // #2301..#2364: a lathe's tool nose tip (a number)
  double* lathe_offset_field(int n);
  void lathe_offset_setting();
  int lathe_offset_ = 0;     // active lathe offset number (T code's last two digits)

  // cutter / tool-nose radius compensation
  RadiusCompensation* comp_ = nullptr;  // path_comp_'s
  bool comp_suspended_ = false;        // G28/G30/G53 in offset mode: moves without the vector
  bool comp_drop_ = false;             // and the vector goes even where the move stays put in the plane
  bool macro_call_block_ = false;      // the block called a macro (G65, G66, custom G/M code)
  std::optional<V2> cancel_direction_;  // I J K of a G40 block

  Coordinates coords_;  // coordinates.hpp
  std::map<int, MillOffset> tool_offsets_;
  double* mill_offset_field(int n);
  double length_offset(int n) const;  // H: geometry + wear
  double radius_offset(int n) const;  // D: geometry + wear (memory C: the D values)
  std::map<int, LatheOffset> lathe_offsets_;
  std::map<int, nc::Value> system_store_;  // writable system variables without other meaning
  double clock_base_ms_ = 0;
  double parts_done_ = 0, parts_required_ = 0;

  // lathe multiple repetitive cycles: modal data (after profile_, which sets them)
  std::vector<Move>* shape_moves_ = nullptr;  // reading a shape: emit() keeps its motions here
  double mrc_depth_ = profile_.mrc_depth;      // Δd of G71/G72 (No.5132), modal
  double mrc_escape_ = profile_.mrc_escape;    // e of G71/G72 (No.5133)
  double mrc_relief_x_ = profile_.mrc_relief_x, mrc_relief_z_ = profile_.mrc_relief_z;  // G73 Δi Δk (No.5135/5136)
  double mrc_divisions_ = profile_.mrc_divisions;  // G73 d (No.5137)
  double mrc_return_ = profile_.mrc_return;    // e of G74/G75 (No.5139)
  // ---- lathe cycles' state (after profile_, which initialises it) ----
  struct LatheCycle {             // X(U), Z(W), R: modal while G90/G92/G94 lasts
    std::optional<double> x, z;   // cutting end point, work coordinates (X a radius)
    double r = 0;                 // taper: X radius (G90/G92) or Z (G94) at the cut's start less its end
  };
  LatheCycle lathe_cycle_;
  bool g76_reads_a_ = false;  // the one-block G76 reads its end point: A is its tool angle
  std::uint64_t thread_block_ = 0;  // RunStats::blocks at the last G32 cut: the next block continues it
  bool g01_macro_ = g01_calls_macro();  // kept as G10 L52 changes the profile
  int thread_chamfer_ = profile_.thread_chamfer;  // G76 P(m)(r)(a), Q(dmin), R(d) rewrite these
  int g76_finish_count_ = profile_.g76_finish_count;
  int g76_tool_angle_ = profile_.g76_tool_angle;
  double g76_min_depth_ = profile_.g76_min_depth;
  double g76_allowance_ = profile_.g76_allowance;

  // ---- the path stages (path/stage.hpp), linked in the constructor; run() links the last to its sink ----
  CornerStage path_corner_{profile_.lathe(), *this,
                            [](const nc::Span& where, const std::string& code, const std::string& message) {
                              throw nc::Alarm(nc::Diagnostic{nc::Severity::error, code, message, where});
                            }};
  CompensationStage path_comp_{compensation_settings(profile_),
                                OffsetModes{&modal_.comp_side, &comp_suspended_, &comp_drop_, &modal_.plane, &cancel_direction_},
                                *this, path_alarm,
                                [this](const Move& at, const std::string& code, const std::string& message) {
                                  path_warning(at, code, message);
                                }};
  DevelopedConversion path_developed_{options_.path_tolerance, profile_.max_cutting_feed,
                                      [this](const Move& at, const std::string& code, const std::string& message) {
                                        path_warning(at, code, message);
                                      }};
  StrokeCheck path_stroke_{stroke_, *this, path_alarm};
  NoseCentre path_nose_{*this};  // linked in with --nose-centre on a lathe
  Statistics path_stats_{result_.stats, SetupView{&modal_.work_index, &coords_.origin, &modal_.length_comp, &h_}};

  // ---- the checks of silent mistakes (cold: kept at the end, away from the hot state) ----
  struct VacantWord {  // the block's first dimension or F word that read a vacant variable
    int variable = 0;  // 0: none
    char letter = 0;
    bool ignored = false;  // the word's value was vacant: the control ignores the word
    double value = 0;      // else the value the vacant variable (as 0) gave it
    std::uint16_t column = 0;
  };
  VacantWord vacant_word_;
  int radius_checked_ = -1;  // the D number checked since the last G40 (-1: none)
  int changed_tool_ = 0;               // the T of the last M06, the line it was made at and the
  std::uint32_t tool_change_line_ = 0;  // Z the tool stood at then (NC2075)
  double tool_change_z_ = 0;
  bool peck_d_checked_ = false;  // NC2076 warned in this cycle mode

  // (cold, kept after the members a block uses)
  std::shared_ptr<const nc::Program> unit_hold_;  // keeps unit_ in memory when it is a streamed piece
  std::unique_ptr<FileChecks> file_checks_;
};

}  // namespace ncurve::machine
