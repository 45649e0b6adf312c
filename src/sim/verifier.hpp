// A mill program verified against its setup: the stock cut on a Z-map by each tool in the spindle,
// and the findings of the cut (a rapid through material, a cut deeper than the flutes, a plunge with
// a tool that does not centre-cut, a cut with the spindle stopped or too fast for the tool).
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "machine/move.hpp"
#include "sim/cut_log.hpp"
#include "sim/finding.hpp"
#include "sim/setup.hpp"
#include "sim/tool_shape.hpp"
#include "sim/zmap.hpp"

namespace ncurve::sim {

// A part of a tool that must not touch the stock: a flat-bottomed body of revolution whose bottom
// is `offset` above the tip (a holder's cone as steps of cylinders inside it).
struct ToolBody {
  ToolShape shape;
  double offset = 0;
  const char* what = "";  // "shank", "holder"
};

// A tool as the verifier uses it: its cutting end, the bodies above it wider than the cut, and
// what it came from.
struct VerifyTool {
  MillTool tool;
  ToolShape shape;
  bool from_library = false;  // else a flat end mill of the D offset in force
  std::vector<ToolBody> bodies;
};
VerifyTool verify_tool(const MillTool& t, bool from_library);

// The mill tools of a run by T number: the library's, and for a number it lacks a flat end mill of
// the radius of the D offset in force when it first cuts (the profile's value); none while D is 0.
class MillTools {
public:
  MillTools(const ToolLibrary& library, const machine::MachineProfile& profile);
  const VerifyTool* get(int number, int d_offset);
  double radius(int number, int d_offset) {
    const VerifyTool* t = get(number, d_offset);
    return t ? t->tool.radius() : 0;
  }
  // The tools asked for so far, by number (none: no tool of that number).
  const std::map<int, std::optional<VerifyTool>>& used() const { return tools_; }

private:
  const ToolLibrary& library_;
  const machine::MachineProfile& profile_;
  std::map<int, std::optional<VerifyTool>> tools_;
};

// Material a finding is about lies deeper than this on some cell's line, mm: less is the rounding
// between the kernels (and no chip).
inline constexpr double kFindingDepth = 1e-3;
// An arc outside the XY plane (G18, G19) is cut as chords at most this far from it, mm.
inline constexpr double kArcChord = 5e-4;

struct VerifyOptions {
  double cell = 0;                        // Z-map cell, mm; 0: from min_cells
  int min_cells = ZMap::kDefaultCells;    // the stock's shorter side in this many cells
  std::size_t max_findings = 200;         // beyond: counted only
  double most_cells = 1e8;                // the largest map (8 bytes a cell)
  std::uint64_t cut_moves = UINT64_MAX;   // only the first so many motions are cut (a debugger's step)
  const machine::MachineProfile* profile = nullptr;  // its rapid positioning (No.1401#1); none: straight
  bool mark_cells = false;  // keep the block that last lowered each cell (a design's check)
  bool check_reference = true;  // NC2089 (with a profile): off where the stock is a guess (the default box)
};

// A block of the program: where a finding found after the run is said.
struct BlockAt {
  const nc::SourceFile* file = nullptr;
  std::uint32_t line = 0;
  bool operator==(const BlockAt&) const = default;
};

// The moves are cut in batches (ZMap::cut_batch, the map's rows shared between the cores) and
// checked, in order, when their batch is: when it is full, at a tool change or spindle event (a
// batch's moves share the tool and the spindle's state), and before a result is read.
class Verifier final : public machine::MoveSink {
public:
  Verifier(const Stock& stock, MillTools& tools, std::optional<int> spindle, VerifyOptions options = {},
           const std::vector<Fixture>& fixtures = {});
  void on_move(const machine::Move& m) override;
  // A new work zero: the reference point is checked against the stock at the next motion.
  void on_setup(const machine::Setup& s) override;
  // Cuts and checks the moves queued (the results below do it first).
  void flush();

  const ZMap& map() const { settle(); return map_; }
  const std::vector<Finding>& findings() const { settle(); return findings_; }
  std::size_t findings_left_out() const { settle(); return left_out_; }
  // Material removed by each T number, mm^3.
  const std::map<int, double>& volume_by_tool() const { settle(); return volume_by_tool_; }
  struct Counts {
    std::uint64_t cut = 0;
    std::uint64_t no_tool = 0;     // motion with no tool in the spindle, or a tool without a size
    std::uint64_t not_xy_arc = 0;  // arcs in G18/G19 not cut (none now: they are cut as chords)
    std::uint64_t rotary = 0;      // moves that turn a rotary axis (3 axes are simulated)
    std::uint64_t after = 0;       // motions past VerifyOptions::cut_moves
  };
  const Counts& counts() const { return counts_; }

  // Keep every cut in `log` as well (for measuring walls afterwards).
  void log_cuts(CutLog* log) { log_ = log; }

  // Each fixture, checked.
  std::vector<std::string> fixtures_checked() const;

  // With VerifyOptions::mark_cells: the blocks of the cuts, map().cut_by()'s ids indexing them,
  // and the last block of the run.
  const std::vector<BlockAt>& cut_blocks() const { return cut_blocks_; }
  const BlockAt& last_block() const { return last_block_; }

private:
  struct FixtureMap {
    std::string name;
    ZMap map;
    bool touched = false;  // by the move before
  };
  // A move queued: its cut in batch_, its bodies' probes from bodies in body_probes_.
  struct Queued {
    machine::Move move;
    std::size_t cut = 0, bodies = 0;
  };
  static constexpr std::size_t kNoProbe = SIZE_MAX;  // a body that cannot meet the stock

  // A result read with moves queued: they are cut and checked first (a Verifier that has taken
  // moves is never const itself, and one that has none queued is left as it is).
  void settle() const { const_cast<Verifier*>(this)->flush(); }
  void cut(const machine::Move& m);
  // What a body (shape at offset above the tip) meets along the move on the map; none when it cannot.
  CutReport probe(ZMap& map, const machine::Move& m, const ToolShape& shape, double offset);
  // body_probes: each body's probe of the map after the move's cut.
  void check_bodies(const machine::Move& m, std::span<const CutReport> body_probes);
  void check_fixtures(const machine::Move& m);
  void check(const machine::Move& m, const CutReport& r);
  void find(const machine::Move& m, const char* code, std::string message, const Point3& at, double amount);
  void check_reference(const machine::Move& m);

  ZMap map_;
  std::vector<FixtureMap> fixtures_;
  MillTools& tools_;
  const VerifyTool* tool_ = nullptr;
  int tool_number_ = 0;
  bool spindle_on_ = false;
  std::uint64_t motions_ = 0;
  bool holder_in_stock_ = false;  // after the move before
  VerifyOptions options_;
  std::vector<Finding> findings_;
  std::size_t left_out_ = 0;
  std::map<int, double> volume_by_tool_;
  Counts counts_;
  std::set<std::tuple<std::string, const nc::SourceFile*, std::uint32_t>> found_at_;  // code, block
  std::map<int, bool> speed_warned_;  // by T number
  std::vector<Queued> queued_;
  std::vector<Sweep> batch_;
  std::vector<std::size_t> body_probes_;  // a sweep of batch_ or kNoProbe, one a body of each queued move
  std::vector<CutReport> reports_;
  std::vector<BlockAt> cut_blocks_;
  BlockAt last_block_;
  CutLog* log_ = nullptr;
  std::optional<machine::AxisVector> origin_;  // the work zero in machine coordinates, to check the reference point
  bool reference_found_ = false;               // NC2089 is said once
};

// The box a Z-map covers for a stock: a box itself, a cylinder's or tube's square about the Z axis.
// None for an STL stock (its mesh's box, once read).
std::optional<Box> zmap_box(const Stock& stock);

}  // namespace ncurve::sim
