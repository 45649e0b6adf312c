// The moves of a run in the compact form the 3D backplot (web/backplot.js) draws: typed arrays
// (kind, end point, feed, block per motion; centre, sweep and plane per arc) sent as base64, the
// blocks as (file, line) pairs and the source files' text once, so that a million moves make a
// page of tens of megabytes that a browser decodes in a fraction of a second. The keys are
// documented in docs/html.md.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "machine/move.hpp"
#include "nc/diagnostic.hpp"
#include "report/lathe_part.hpp"
#include "report/programmed_contour.hpp"
#include "report/other_axes.hpp"
#include "sim/part_stl.hpp"

namespace ncurve::report {

class BackplotData final : public machine::MoveSink {
public:
  // The most motions kept (about 30 bytes each in the page); past that they are counted only.
  static constexpr std::size_t kDefaultLimit = 2'000'000;
  // Source text beyond this many bytes in all is left out of the page (hover then shows the line number only).
  static constexpr std::size_t kMostSourceBytes = 32u << 20;

  explicit BackplotData(const machine::MachineProfile& profile, std::size_t limit = kDefaultLimit);
  // On a lathe: the imaginary tip's offset from the nose centre for the move in hand
  // (machine::Interpreter::nose_tip_now), which a compensated arc's centre carries; none given (or
  // moves of the nose centre), the arc's centre is the programmed one.
  void follow_nose_tip(std::function<std::array<double, 2>()> tip) { nose_tip_ = std::move(tip); }
  void on_move(const machine::Move& m) override;
  void stopped(const nc::Diagnostic& alarm) override;

  std::size_t motions() const { return kind_.size(); }
  std::uint64_t left_out() const { return left_out_; }
  // The data as one JSON object (UTF-8; a byte of a name or text that is not UTF-8 becomes U+FFFD).
  // `inch`: the program ended under G20 (the axes are labelled in inches).
  std::string json(bool inch) const;
  // The cut part, drawn shaded under the path (run --verify).
  void set_part(sim::PartGrid part) { part_ = std::move(part); }
  void set_part(LathePart part) { lathe_part_ = std::move(part); }  // a lathe's, revolved by the page
  // The part's walls against the design, coloured on it (report::deviation_json).
  void set_deviation(nlohmann::json deviation) { deviation_ = std::move(deviation); }

private:
  std::uint32_t block_of(const machine::Move& m);

  bool lathe_, x_diameter_;
  int machine_plane_;
  std::size_t limit_;
  std::uint64_t left_out_ = 0;
  std::vector<std::uint8_t> kind_;    // 0 rapid, 1 feed (G01), 2 arc
  std::vector<float> end_;            // X Y Z of each motion's end (X as a radius)
  std::vector<float> feed_;           // mm/min, or mm/rev
  std::vector<std::uint32_t> block_;  // index in the blocks
  std::vector<float> arcs_;           // per arc: centre X Y Z, sweep (rad, counter-clockwise +), plane
  const machine::MachineProfile& profile_;   // its rapid rates and No.1401#1
  std::vector<std::array<double, 4>> corners_;  // a dog-leg rapid's corners in order: motion, X Y Z
  std::vector<std::uint32_t> jump_at_;       // motions that do not start where the one before ended
  std::vector<std::array<double, 3>> jump_;  // and where they start
  std::array<double, 3> last_{};
  std::vector<std::uint16_t> block_file_;
  std::vector<std::uint32_t> block_line_;
  std::unordered_map<std::uint64_t, std::uint32_t> block_index_;
  std::vector<const nc::SourceFile*> files_;
  const nc::SourceFile* last_file_ = nullptr;
  std::uint32_t last_line_ = 0, last_block_ = 0;
  bool have_last_block_ = false;
  std::optional<nc::Diagnostic> alarm_;
  std::array<double, 3> alarm_at_{};
  // the A, B and C axes (the drawing is of X Y Z), and each one's end for each motion kept
  OtherAxes other_;
  std::array<std::vector<double>, 3> other_end_;
  // the programmed contour beside a compensated path: per piece its motion, start and end X Y Z; per
  // arc among them its motion, centre X Y Z, sweep (radians) and plane
  ProgrammedContour contour_;
  std::function<std::array<double, 2>()> nose_tip_;
  std::vector<std::array<double, 7>> programmed_;
  std::vector<std::array<double, 6>> programmed_arcs_;
  std::optional<sim::PartGrid> part_;
  std::optional<LathePart> lathe_part_;
  nlohmann::json deviation_;
};

// The cut part's grid as the pages take it: {nx, ny, x0, y0, dx, dy, bottom, top, heights (base64 of
// float32)} (docs/html.md).
nlohmann::json part_json(const sim::PartGrid& grid);

// `text` as base64 (RFC 4648, with padding).
std::string base64(const void* data, std::size_t bytes);

}  // namespace ncurve::report
