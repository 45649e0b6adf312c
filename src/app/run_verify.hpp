// `ncurve run --setup FILE --verify --resolution MM --part FILE.stl`: the program's moves cut into the
// stock of its setup (or the default box), the findings added to the run's warnings.
#pragma once
#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/curve_args.hpp"
#include "machine/interpreter.hpp"
#include "machine/library.hpp"
#include "report/verify_report.hpp"
#include "sim/design_check.hpp"
#include "sim/curve_walls.hpp"
#include "sim/section_walls.hpp"
#include "sim/lathe_section_sink.hpp"

namespace ncurve::app {

struct VerifyArgs {
  std::string setup;        // --setup FILE (or the name of setup_text)
  std::optional<std::string> setup_text;  // the setup's TOML, not read from a file
  bool verify = false;      // --verify
  double resolution = 0;    // --resolution MM: the Z-map's cell; 0: the stock's shorter side in 1000 cells
  std::string part;         // --part FILE.stl
  std::string design;       // --design FILE.stl: the gouge and stock left against it (a mill)
  double most_cells = 1e8;  // the largest Z-map
  int cells = 0;            // the stock's shorter side in so many cells (0: 1000), unless resolution
  std::uint64_t cut_moves = UINT64_MAX;  // cut only the first so many motions
  CurveArgs curve;                  // --curve: the design's curve, its walls measured
  std::vector<std::string> curve_extras;  // its parameters (--NAME VALUE)
  double tol = 0.01;                // --tol: --curve's and --design's tolerance, mm
  std::string wall = "auto";        // --wall: groove, edge or auto (edge when the program compensates)
  std::size_t max_moves = 1000000;  // --max-moves: the cuts kept to measure the walls
  bool on() const {
    return verify || !setup.empty() || setup_text || !part.empty() || resolution > 0 || !curve.name.empty() ||
           !design.empty();
  }
};

void add_verify_options(CLI::App* run, VerifyArgs& a);
// --wall groove|edge|auto of run and analyze.
void add_wall_option(CLI::App* cmd, std::string& wall);

class RunVerification {
public:
  // Reads the setup and, without a stock in it, runs the program once to find the default box (a
  // lathe's bar).
  // Throws std::runtime_error with a message for the user (a bad setup file, a part that cannot be made).
  RunVerification(const VerifyArgs& args, const machine::MachineProfile& profile, const machine::ProgramLibrary& lib,
                  const machine::RunOptions& options);
  ~RunVerification();
  // The sink the run's moves go to as well; null when nothing is verified (the report says why).
  machine::MoveSink* sink();
  // After the run: the findings join the run's warnings.
  void finish(machine::RunResult& result);
  // Writes --part; throws io::OutputError.
  void write_part(const std::vector<std::string>& inputs);
  const report::VerifyReport& report() const { return report_; }
  // The STL files read: the setup's stock and fixtures, --design.
  std::vector<std::string> stl_files() const;
  // The cut stock of a mill; null when nothing was verified or on a lathe.
  const sim::ZMap* map() const { return verifier_ ? &verifier_->map() : nullptr; }
  // The walls measured against --curve; null without one.
  const sim::WallReport* walls() const { return walls_ ? &*walls_ : nullptr; }
  // The cut section of a lathe; null when nothing was verified or on a mill.
  const sim::LatheSection* section() const { return section_.get(); }

private:
  void measure_walls(machine::RunResult& result);
  void lathe(const machine::MachineProfile& profile, const machine::ProgramLibrary& lib,
             const machine::RunOptions& options, const std::function<void(const std::string&)>& refuse);

  VerifyArgs args_;
  sim::SetupFile setup_;
  std::unique_ptr<sim::MillTools> tools_;
  std::unique_ptr<sim::Verifier> verifier_;
  std::unique_ptr<sim::LatheSection> section_;  // a lathe's
  std::unique_ptr<sim::LatheSectionSink> section_sink_;
  std::vector<double> design_top_;  // --design's top on the map's grid
  std::optional<sim::DesignResult> design_;
  report::VerifyReport report_;
  std::optional<geom::Curve> curve_;
  geom::Placement place_;  // a lathe's: the curve on the machine's Z and X
  std::unique_ptr<sim::ProfileMoves> profile_moves_;
  std::unique_ptr<machine::MoveSink> lathe_tee_;
  std::unique_ptr<sim::CutLog> cuts_;
  bool compensated_ = false;  // a cutting move under G41/G42
  std::optional<sim::WallReport> walls_;
};

}  // namespace ncurve::app
