// The move stream of a lathe cut into its half-section: each rapid, line, thread cut and ZX arc with
// the tool the turret holds (rapids cut too; telling that apart is the checks' work).
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "machine/move.hpp"
#include "machine/profile.hpp"
#include "sim/finding.hpp"
#include "sim/insert_shape.hpp"
#include "sim/lathe_holder.hpp"
#include "sim/lathe_section.hpp"
#include "sim/tool_library.hpp"

namespace ncurve::sim {

// What the sink needs beyond the tools: how the machine moves a rapid, the fixtures, and the insert's
// size. A box fixture on a lathe stands for the ring it sweeps as the spindle turns: Z over the box's
// Z range, the radius from the nearest point of its XY rectangle to the axis to its farthest corner.
struct LatheSinkOptions {
  const machine::MachineProfile* profile = nullptr;  // its rapid positioning (No.1401#1); none: straight
  std::vector<Fixture> fixtures;
  InsertSize size;
  std::uint64_t cut_moves = UINT64_MAX;  // only the first so many motions are cut (a debugger's step)
};

// The ring a box fixture sweeps about the Z axis, as a tube (a bar where the box holds the axis).
Cylinder fixture_ring(const AxisBox& box);

class LatheSectionSink final : public machine::MoveSink {
public:
  // The tool changes on each tool change event, a lathe's T code (T0203: tool 2, offset 3). Its shape
  // is the library's entry for the tool number (lathe_tool_number), else the default insert of the
  // offset set's nose radius (geometry plus wear) and tip (an offset the machine does not hold: a
  // sharp point of tip 0); tool number 0 is no tool. `t_code` is the T code in force before the first
  // tool change. A rapid is cut along the path the profile's positioning gives it (non-linear: the
  // dog-leg of each axis at its own rate), straight without a profile.
  LatheSectionSink(LatheSection& section, ToolLibrary tools, std::map<int, machine::LatheOffset> offsets = {},
                   std::optional<int> t_code = std::nullopt, LatheSinkOptions options = {});

  void on_move(const machine::Move& m) override;

  struct Counts {
    std::uint64_t cut = 0;         // moves cut into the section
    std::uint64_t no_tool = 0;     // motion before the first T code, or with tool number 0
    std::uint64_t not_zx_arc = 0;  // arcs in G17/G19, not simulated
    std::uint64_t not_finite = 0;  // a coordinate that is not a finite number
    std::uint64_t after = 0;       // motions past LatheSinkOptions::cut_moves
  };
  const Counts& counts() const { return counts_; }

  // The volume each tool number removed, mm^3 (the rapids with it included).
  std::map<int, double> volume_by_tool() const;

  // The findings, once a block and code, the first 200:
  // - NC2080: a rapid that removed material (more than 1 um times the length of its path of section
  //   area);
  // - NC2085: the holder (lathe_holder.hpp) swept into material at the move, after its cut (more than
  //   1 um times the move's length, at least 1 mm, of area), said at the move that makes the contact;
  // - NC2086: the insert or its holder swept into a fixture's ring (the same measure), likewise;
  // - NC2083: a feed move removed material with the spindle stopped (the NC2080 measure);
  // - NC2081: a mill tool on the spindle axis (a drill) goes into material past its flutes: its
  //   cutting diameter from the flutes' end up sweeps uncut material (the NC2085 measure);
  // - NC2082: a mill tool that does not cut at its centre, on the spindle axis, fed towards the chuck
  //   with less travel across than its radius into material (the same measure).
  const std::vector<Finding>& findings() const { return findings_; }
  std::size_t findings_left_out() const { return left_out_; }

  // The fixtures checked (boxes, as rings), and those not (STL), in words.
  std::vector<std::string> fixtures_checked() const;

private:
  struct TurretTool {
    ToolOutline cutting;
    ToolOutline past_flutes;  // a mill tool's: its cutting diameter from the flutes' end up (NC2081)
    double flute_length = 0;
    double no_centre = 0;     // a mill tool that does not cut at its centre: its radius (NC2082)
    std::vector<LatheBody> bodies;
    const char* what = "insert";  // the cutting part, in words
  };
  void change_tool(int t_code);
  void check_bodies(const machine::Move& m, const machine::Move& piece);
  void check_fixtures(const machine::Move& m, const machine::Move& piece);
  struct FixtureRing {
    std::string name;
    Cylinder ring;
    LatheSection section;  // never cut
    bool was = false, in = false;  // touched by the move before, by this one
  };
  void rapid(const machine::Move& m);
  void find(const machine::Move& m, const char* code, std::string message, const std::array<double, 3>& at,
            double amount);

  LatheSection& section_;
  ToolLibrary tools_;
  std::map<int, machine::LatheOffset> offsets_;
  LatheSinkOptions options_;
  std::map<int, TurretTool> outlines_;  // by T code
  const TurretTool* tool_ = nullptr;
  std::uint64_t motions_ = 0;
  bool holder_was_ = false, holder_in_ = false;  // in material after the move before, after this one
  bool spindle_on_ = false;  // M03/M04 since the start, not M05/M19 after
  int tool_number_ = 0;
  double volume_at_change_ = 0;
  std::map<int, double> volume_by_tool_;
  std::vector<FixtureRing> fixtures_;
  std::vector<std::string> unchecked_fixtures_;
  Counts counts_;
  std::vector<Finding> findings_;
  std::size_t left_out_ = 0;
  std::set<std::tuple<std::string, const nc::SourceFile*, std::uint32_t>> found_at_;  // code, block
};

}  // namespace ncurve::sim
