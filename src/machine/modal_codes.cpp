// The block's G codes in FANUC's order: a modal code sets its group in the ModalState (or its
// component's mode), a one-shot code is listed for its action (the G-code table's), and a code the
// control has but ncurve does not simulate, or one it lacks, stops the run.
#include <fmt/format.h>

#include <cmath>

#include "machine/executor.hpp"
#include "machine/g_codes.hpp"

namespace ncurve::machine {

namespace {

// The name of a G code of the control that ncurve does not simulate, or nullptr.
const char* unsupported_name(int g, const MachineProfile& p) {
  const GCode* row = g_code(g, g_machine(p));
  return row && row->status == GStatus::not_simulated ? row->name : nullptr;
}
// PS0010 for a G code the control lacks. A whole number could be made a custom G code: the hint
// names a free parameter No.6050..6059 whose program O9010..O9019 is there (the one ncurve's macros
// give this G code, G102..G111, first), or the mapping when none is.
std::string unknown_g_code(int g, const MachineProfile& p, const ProgramLibrary& lib) {
  std::string code = fmt::format("G{}{}", g / 10, g % 10 ? fmt::format(".{}", g % 10) : "");
  std::string text = fmt::format("{} is not a G code of this control", code);
  const int n = g / 10;
  if (g % 10 != 0 || n < 1 || n > 9999) return text;
  std::vector<int> present;
  int free_slot = -1;
  for (int i = 0; i < static_cast<int>(p.g_code_macros.size()); ++i) {
    if (p.g_code_macros[i] != 0) continue;
    if (free_slot < 0) free_slot = i;
    if (lib.find(9010 + i)) present.push_back(i);
  }
  if (free_slot < 0) return text;
  if (present.empty())
    return text + fmt::format(" (parameters No.6050..6059 make G codes that call O9010..O9019, and none of these "
                              "programs is in the file or a --lib folder: --param {}={} makes {} call O{})",
                              6050 + free_slot, n, code, 9010 + free_slot);
  int i = present.front();
  for (int k : present)
    if (102 + k == n) i = k;
  std::string others;
  for (int k : present)
    if (k != i) others += fmt::format("{}O{}", others.empty() ? "" : ", ", 9010 + k);
  if (!others.empty()) others = fmt::format("; No.6050..6059 call O9010..O9019, and {} are here too", others);
  return text + fmt::format(" (to make it a custom G code calling O{}, set parameter No.{} = {}: --param {}={}{})",
                            9010 + i, 6050 + i, n, 6050 + i, n, others);
}

}  // namespace

void Executor::handle_g_codes(std::vector<int>& one_shot) {
  exact_stop_once_ = false;
  position_offset_ = 0;
  cycle_m_done_ = false;
  // Most blocks: no G code, or one motion code of group 01 outside a transform and developed mode,
  // which sets the motion and ends a drilling canned cycle (as the loop below does, more cheaply).
  if (g_codes_.empty()) return;
  if (g_codes_.size() == 1 && !xf_on_ && !developed_) {
    const int g = g_codes_.front();
    if (g == 0 || g == 10 || g == 20 || g == 30) {
      modal_.motion = g / 10;
      if (modal_.cycle != 0) cancel_canned_cycle();
      return;
    }
  }
  const bool lathe = profile_.lathe();
  const bool system_a = lathe && profile_.gcode_system == 'A';
  bool group01 = false;
  bool transform = false;  // a G15/G16, G50/G51, G50.1/G51.1, G68/G69 of a mill: transform_codes
  struct CancelCycle {  // after the block's codes: G00..G03 with G81 in one block cancel it too
    Executor* self;
    bool& group01;
    ~CancelCycle() {
      if (group01 && self->modal_.cycle != 0) self->cancel_canned_cycle();
    }
  } cancel_cycle{this, group01};
  for (std::size_t i = 0; i < g_codes_.size(); ++i) {
    int g = g_codes_[i];
    std::uint16_t column = 0;  // G00..G03 need it only to check a transform or developed mode
    if ((g != 0 && g != 10 && g != 20 && g != 30) || xf_on_ || developed_)
      for (const Cmd& c : cmds_)
        if (c.letter == 'G' && std::lround(c.value * 10) == g) column = c.column;
    if (xf_on_) check_code_in_transform(g, column);
    if (developed_) [[unlikely]] check_code_in_developed(g, column);  // polar_cylindrical.cpp
    switch (g) {
      case 0: case 10: case 20: case 30:
        modal_.motion = g / 10;
        group01 = true;  // a group 01 code ends a drilling canned cycle
        break;
      case 230: stroke_area_switch(false); break;  // G22 comes with its area (one_shot)
      case 250: case 260: modal_.speed_fluctuation_check = g == 260; break;  // nothing on the path
      case 90: exact_stop_once_ = true; break;  // G09: one-shot exact stop, for the time planner
      case 450: case 460: case 470: case 480:  // tool position offset (position_offset.cpp)
        if (lathe) alarm("PS0010", unknown_g_code(g, profile_, library_), column);
        position_offset_ = g / 10;
        break;
      case 170: case 180: case 190:
        if (g / 10 != modal_.plane && (rigid_tapping_ || rigid_pending_))
          alarm("PS0206", fmt::format("the plane cannot change (G{}) in rigid tapping mode (after M29)", g / 10), column);
        if (g / 10 != modal_.plane && compensating())
          alarm("PS0037", fmt::format("the plane cannot change (G{}) while cutter compensation is active: cancel it "
                                      "with G40 first",
                                      g / 10),
                column);
        modal_.plane = g / 10;
        break;
      case 400:
        radius_checked_ = -1;
        if (modal_.comp_side != 0 || comp_->offset_mode()) {
          modal_.comp_side = 0;
          const PlaneAxes pa = plane_axes(modal_.plane);
          if (has(pa.ip) || has(pa.iq))
            cancel_direction_ = V2{has(pa.ip) ? dimension(word(pa.ip)) : 0.0, has(pa.iq) ? dimension(word(pa.iq)) : 0.0};
          if (cancel_direction_ && xf_on_) cancel_direction_ = transformed_plane_vector(*cancel_direction_);
        }
        break;
      case 410: case 420:
        modal_.comp_side = g == 410 ? 1 : -1;
        break;
      case 200: case 210:
        // The 30i-MA manual (8.2): G20/G21 in a block of its own at the start, before the coordinate
        // system is set, and "must not be switched during a program". ncurve converts at the switch;
        // the control changes the unit of the offsets whose numbers it keeps, so it warns.
        if (modal_.inch != (g == 200) && result_.stats.feed_length + result_.stats.rapid_length > 0)
          warn_once("NC2018", fmt::format("G{} switches the unit after the program has moved: the manual says G20 and "
                                          "G21 must not be switched during a program (the offsets then change unit)",
                                          g / 10));
        modal_.inch = g == 200;
        break;
      case 800: cancel_canned_cycle(); break;
      case 670: break;
      case 150: case 160: case 501: case 510: case 511: case 680: case 690:
        if (!lathe) {
          transform = true;
          break;
        }
        if (g == 150 || g == 690) break;  // cancels: nothing active to cancel
        if (const char* what = unsupported_name(g, profile_))
          alarm("NC9001", fmt::format("{} is not supported yet", what), column);
        alarm("PS0010", unknown_g_code(g, profile_, library_), column);
      case 51: case 50: case 80: case 611: high_speed_mode(g, column); break;  // high_speed.cpp
      case 71: case 121: case 131: case 1070: case 1120: case 1130:  // polar_cylindrical.cpp
        if (developed_code(g, column)) break;
        alarm("PS0010", unknown_g_code(g, profile_, library_), column);
      case 430: case 440:
        if (!has('H') && h_ == 0) alarm("PS0030", fmt::format("G{} needs an H offset number", g / 10), column);
        modal_.length_comp = g / 10;
        h_ = has('H') ? static_cast<int>(std::lround(word('H').value)) : h_;
        coords_.tool_shift[2] = (g == 430 ? 1 : -1) * length_offset(h_);
        break;
      case 490: modal_.length_comp = 49; coords_.tool_shift[2] = 0; break;
      case 540: case 550: case 560: case 570: case 580: case 590:
        modal_.work_index = g / 10 - 53;
        set_origin();
        break;
      case 541: {
        int p = has('P') ? static_cast<int>(std::lround(word('P').value)) : 1;
        if (p < 1 || p > 300) alarm("PS0030", "G54.1 P must be 1 to 300", column);
        modal_.work_index = 6 + p;
        set_origin();
        break;
      }
      case 610: case 620: case 630: modal_.exact_stop = g == 610; modal_.exact_stop_code = g / 10; break;
      case 640: modal_.exact_stop = false; modal_.exact_stop_code = 64; break;
      case 960: modal_.css = true; break;
      case 970: modal_.css = false; break;
      case 500:
        if (system_a) one_shot.push_back(g);  // coordinate system setting / max spindle speed
        else if (!lathe) transform = true;    // scaling cancel
        break;
      default: {
        if (lathe && select_lathe_motion(g, one_shot)) {  // lathe_cycles.cpp
          group01 = group01 || modal_.motion == g / 10;  // G32/G90/G92/G94 end a drilling cycle, G76 does not
          break;
        }
        if (system_a) {
          if (g == 980) { modal_.feed_per_rev = false; break; }
          if (g == 990) { modal_.feed_per_rev = true; break; }
        } else {
          if (g == 900) { modal_.incremental = false; break; }
          if (g == 910) { modal_.incremental = true; break; }
          if (g == 940) { modal_.feed_per_rev = false; break; }
          if (g == 950) { modal_.feed_per_rev = true; break; }
          if (g == 980 || g == 990) {  // canned cycle return level: initial level, point R
            modal_.cycle_return_initial = g == 980;
            break;
          }
        }
        if (lathe) {  // G70..G75 (G72..G77 in system C): lathe_repetitive.cpp
          if (const int r = repetitive_code(g); r >= 700 && r <= 750) { one_shot.push_back(r); break; }
          if (profile_.gcode_system == 'C' && (g == 700 || g == 710)) { modal_.inch = g == 700; break; }
        }
        if (!lathe && g == 330) {  // G33 thread cutting of a machining center (threading.cpp)
          modal_.motion = 33;
          group01 = true;
          break;
        }
        if (!lathe && g == 600) {  // G60: one-shot (group 00), or modal in group 01 with No.5431#0 MDL = 1
          if (!profile_.g60_modal) one_shot.push_back(g);
          else modal_.motion = 60, group01 = true;
          break;
        }
        if (lathe && g >= 700 && g <= 760)
          alarm("NC9001", fmt::format("G{} (multiple repetitive cycle) is not supported yet", g / 10), column);
        if (drilling_cycle_code(g, lathe)) {
          select_canned_cycle(g, column);
          break;
        }
        if (g_action(g, g_machine(profile_))) {  // a one-shot code with an action of its own in the table
          one_shot.push_back(g);
          break;
        }
        if (const char* what = unsupported_name(g, profile_))
          alarm("NC9001", fmt::format("{} is not supported yet", what), column);
        alarm("PS0010", unknown_g_code(g, profile_, library_), column);
      }
    }
  }
  if (transform) transform_codes(one_shot);
}

}  // namespace ncurve::machine
