// ncurve run --plot: the tool path as an SVG drawing, collected from the move stream in bounded
// memory: collinear moves merged; when the elements reach their limit, runs of short moves are
// simplified within a fraction of a pixel of the drawing; past what that can save, the rest is
// counted, not drawn.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "machine/move.hpp"
#include "geom/plane.hpp"
#include "sim/part_stl.hpp"
#include "nc/diagnostic.hpp"
#include "report/other_axes.hpp"

namespace ncurve::report {

enum class PlotView : std::uint8_t { xy, xz, yz, iso };
// "xy", "xz" (or "zx"), "yz" or "iso"; nullopt for anything else.
std::optional<PlotView> plot_view(const std::string& name);
// Whether the view shows something on this machine: a lathe without a Y axis moves in one plane,
// ZX, and has that view only (the others would draw its Y, always 0).
bool view_fits(const machine::MachineProfile& profile, PlotView view);

struct PathPlotOptions {
  std::vector<PlotView> views;  // empty: the machine plane, the two other projections and iso (lathe: ZX);
                                // views that do not fit the machine are left out
  std::string title;
  bool inch = false;            // axes in inches (the program ended under G20)
};

class PathPlot final : public machine::MoveSink {
public:
  static constexpr std::size_t kDefaultLimit = 50'000;
  explicit PathPlot(const machine::MachineProfile& profile, std::size_t max_elements = kDefaultLimit);
  void on_move(const machine::Move& m) override;
  void stopped(const nc::Diagnostic& alarm) override;
  std::string svg(const PathPlotOptions& options) const;
  // The cut part (a mill's, run --verify), drawn under the path in the XY, XZ and YZ views.
  void set_part(sim::PartGrid part) { part_ = std::move(part); }
  // A lathe's cut part: its half-section (Z, X as a radius), drawn under the path in the ZX plane.
  void set_section(std::vector<std::vector<geom::V2>> polygons) { section_ = std::move(polygons); }

  struct Element {
    machine::MoveKind kind;       // rapid, line or arc
    std::uint8_t plane = 17;
    std::array<double, 3> a{}, b{}, c{};  // start, end, arc centre (X Y Z, X as a radius)
    double sweep = 0;
  };
  const std::vector<Element>& elements() const { return elements_; }
  // How far the simplification may have moved the drawn path, mm (0: not simplified).
  double simplified_within() const { return tol_; }

private:
  void add(const machine::Move& m);  // one straight piece or arc
  void compact();
  void simplify(double tol, std::size_t from);
  bool lathe_, x_diameter_, lathe_y_;  // lathe_y_: a lathe with a Y axis
  machine::AxisVector rapid_rate_;     // rapids drawn as the machine moves them (No.1401#1)
  bool linear_rapid_;
  int machine_plane_;
  std::size_t limit_;
  std::vector<Element> elements_;
  std::uint64_t motions_ = 0, left_out_ = 0;
  std::array<std::uint64_t, 3> moves_by_kind_{};  // rapid, line, arc: the moves, not the elements drawn
  double tol_ = 0;       // the bound of the simplification's error so far
  double last_tol_ = 0;  // the highest level a pass has simplified at
  std::size_t fresh_ = 0;  // elements from here on were added since the last pass
  bool given_up_ = false;  // simplifying no longer saves enough: further moves are counted only
  std::array<double, 3> lo_{INFINITY, INFINITY, INFINITY}, hi_{-INFINITY, -INFINITY, -INFINITY};
  // what the views frame: each axis from its first move on, a cut from where it starts (svg())
  std::array<double, 3> frame_lo_{INFINITY, INFINITY, INFINITY}, frame_hi_{-INFINITY, -INFINITY, -INFINITY};
  std::array<bool, 3> axis_moved_{};
  std::array<double, 3> cut_lo_{INFINITY, INFINITY, INFINITY}, cut_hi_{-INFINITY, -INFINITY, -INFINITY};  // lines, arcs
  bool moved_ = false;
  std::array<double, 3> last_{};
  std::optional<nc::Diagnostic> alarm_;
  std::array<double, 3> alarm_at_{};
  OtherAxes other_;  // the A, B and C axes, not drawn
  std::optional<sim::PartGrid> part_;
  std::vector<std::vector<geom::V2>> section_;
};

}  // namespace ncurve::report

namespace ncurve::report {

// Passes every move and the alarm to two sinks.
class TeeSink final : public machine::MoveSink {
public:
  TeeSink(machine::MoveSink& first, machine::MoveSink& second) : first_(first), second_(second) {}
  void on_move(const machine::Move& m) override {
    first_.on_move(m);
    second_.on_move(m);
  }
  void on_setup(const machine::Setup& s) override {
    first_.on_setup(s);
    second_.on_setup(s);
  }
  void stopped(const nc::Diagnostic& alarm) override {
    first_.stopped(alarm);
    second_.stopped(alarm);
  }

private:
  machine::MoveSink& first_;
  machine::MoveSink& second_;
};

}  // namespace ncurve::report
