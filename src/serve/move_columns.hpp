// The moves of a run as columns (one array per field) for `POST /api/run`: a third of the size of
// JSON Lines, and what a backplot uploads as it is.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "machine/move.hpp"
#include "machine/profile.hpp"
#include "report/programmed_contour.hpp"
#include "report/writers.hpp"
#include "serve/json_out.hpp"

namespace ncurve::serve {

class MoveColumns final : public machine::MoveSink {
public:
  // Keeps at most `limit` moves (about 60 bytes each); the run's summary counts them all.
  MoveColumns(const machine::MachineProfile& profile, FileTable& files, std::size_t limit);
  // On a lathe: the imaginary tip's offset from the nose centre (Z, X radius) for the move in hand
  // (machine::Interpreter::nose_tip_now), which a compensated arc's centre carries; none given, or
  // moves of the nose centre (nose_centre), the arc's centre is the programmed one.
  void follow_nose_tip(std::function<std::array<double, 2>()> tip) { nose_tip_ = std::move(tip); }
  void on_move(const machine::Move& m) override;
  std::size_t count() const { return kind_.size(); }
  bool complete() const { return dropped_ == 0; }
  // {"count": ..., "kinds": [...], "kind": [...], "file": [...], ...} (docs/serve.md)
  void write_json(Columns& out) const;

private:
  report::OutputFrame frame_;
  std::vector<int> rotary_;  // axis indexes of A, B, C the profile has
  FileTable& files_;
  std::size_t limit_;
  std::uint64_t dropped_ = 0;
  machine::AxisVector last_end_{};
  std::vector<std::uint8_t> kind_;
  std::vector<std::uint32_t> file_, line_;
  std::vector<double> x_, y_, z_, f_;
  std::vector<std::vector<double>> abc_;
  // sparse: moves that start away from the previous end, arcs, event codes
  std::vector<std::uint32_t> start_at_;
  std::vector<double> sx_, sy_, sz_;
  std::vector<std::vector<double>> sabc_;
  std::vector<std::uint32_t> arc_at_;
  std::vector<double> cx_, cy_, cz_, sweep_;
  std::vector<std::uint8_t> plane_, cw_;
  std::vector<std::uint32_t> code_at_;
  std::vector<int> code_;
  // the programmed contour under cutter / tool-nose radius compensation (report::ProgrammedContour)
  void note_programmed(const machine::Move& m, std::uint32_t index);
  std::function<std::array<double, 2>()> nose_tip_;
  report::ProgrammedContour contour_;
  std::vector<std::uint32_t> programmed_at_;
  std::vector<double> px_, py_, pz_, psx_, psy_, psz_;
  std::vector<std::uint32_t> programmed_arc_at_;
  std::vector<double> pcx_, pcy_, pcz_, psweep_;
  // a dog-leg rapid's corners (non-linear positioning), in order
  const machine::MachineProfile& profile_;
  std::vector<std::uint32_t> corner_at_;
  std::vector<double> kx_, ky_, kz_;
};

}  // namespace ncurve::serve
