// Move sinks that write the tool path: JSON Lines, CSV points, expanded G-code.
#pragma once
#include <fmt/format.h>
#include <nlohmann/json_fwd.hpp>
#include <array>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "machine/arc_points.hpp"
#include "machine/move.hpp"
#include "nc/diagnostic.hpp"
#include "machine/profile.hpp"
#include "report/csv_numbers.hpp"

namespace ncurve::report {

// Work coordinates as the user reads them: X as a diameter on a lathe in diameter mode.
struct OutputFrame {
  bool x_diameter = false;
  explicit OutputFrame(const machine::MachineProfile& p) : x_diameter(p.lathe() && p.diameter_x) {}
  double x(double radius_or_x) const { return x_diameter ? 2 * radius_or_x : radius_or_x; }
};

// An alarm's calling blocks, innermost first: [{"file", "line", "block"}, ...].
nlohmann::json called_from_json(const nc::Diagnostic& d);

class JsonlWriter final : public machine::MoveSink {
public:
  JsonlWriter(std::ostream& out, const machine::MachineProfile& profile) : out_(out), frame_(profile) {}
  void on_move(const machine::Move& m) override;
  // The run stopped on an alarm: a last record {"kind":"alarm", ...} says so.
  void stopped(const nc::Diagnostic& alarm) override;

private:
  std::ostream& out_;
  OutputFrame frame_;
  const nc::SourceFile* last_file_ = nullptr;
  std::string file_json_;
  fmt::memory_buffer buffer_;  // one record, formatted with compile-time format strings
};

// One row per point; arcs become points whose chord error stays within arc_tolerance.
class CsvWriter final : public machine::MoveSink {
public:
  CsvWriter(std::ostream& out, const machine::MachineProfile& profile, double arc_tolerance);
  void on_move(const machine::Move& m) override;
  void on_moves(std::span<const machine::Move> moves) override;  // their rows in one write
  // The run stopped on an alarm: a last row of kind "alarm:CODE" at the alarm's line.
  void stopped(const nc::Diagnostic& alarm) override;

private:
  void rows(const machine::Move& m);
  void row(std::string_view line, std::string_view kind, const machine::AxisVector& p, double f);
  void write();
  std::ostream& out_;
  OutputFrame frame_;
  double arc_tolerance_;
  bool started_ = false;
  std::vector<int> extra_;  // A, B, C of the profile: columns a, b, c after f
  fmt::memory_buffer text_;  // rows not yet written to out_
  std::array<RecentNumbers<fixed6>, machine::kAxes> axis_;  // the columns x, y, z, a, b, c
  RecentNumbers<shortest> feed_;
};

// The program the macro stands for: every move as a plain G00/G01/G02/G03 block, absolute, in mm,
// after the modal setup the run had (plane, units, G40, G90, feed mode, work coordinate system,
// G52 for what the run's origin adds to the profile's work offset, G43 H). A block writes only the
// axes whose position changes.
class GcodeWriter final : public machine::MoveSink {
public:
  GcodeWriter(std::ostream& out, const machine::MachineProfile& profile, const std::string& source_name);
  void on_move(const machine::Move& m) override;
  void on_setup(const machine::Setup& s) override;
  // The run stopped on an alarm: a comment naming it ends the program, without M30.
  void stopped(const nc::Diagnostic& alarm) override;
  void finish();

private:
  std::string num(double v) const;
  void write_setup();
  std::ostream& out_;
  const machine::MachineProfile& profile_;
  OutputFrame frame_;
  int decimals_;
  int motion_ = -1;
  double feed_ = -1;
  bool per_rev_ = false;
  bool per_rev_known_ = false;
  bool ended_ = false;
  bool stopped_ = false;
  bool header_ = false;          // the modal setup line is out
  machine::Setup setup_;         // the run's, for the next move
  machine::Setup written_;       // the one the program has set up
  std::vector<std::string> local_;  // the G52 offsets written, per axis of the profile
  machine::AxisVector turns_{};    // added to A, B, C: roll-over axes written as continuous angles
  machine::AxisVector last_end_{};
  bool moved_ = false;
  std::array<std::string, machine::kAxes> at_;  // each axis's position as the program last left it
  std::array<bool, machine::kAxes> at_known_{};  // false: at the move's start (no block yet, or a new origin)
};

}  // namespace ncurve::report
