// `ncurve analyze PROGRAM --curve ...`: the shape error of the program's contour against the
// curve, seed 000's models beside it, and its CSV, plot, JSON and text.
#pragma once
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "gen/generate.hpp"
#include "gen/shape_models.hpp"
#include "report/motion_plots.hpp"
#include "report/shape_check.hpp"
#include "report/writers.hpp"

namespace ncurve::app::shape {

// The path measured: no radius compensation in the program (tool path and program are one),
// the compensated tool path, or the contour as programmed (--programmed).
enum class Path { plain, tool, programmed };
inline const char* to_string(Path p) { return p == Path::tool ? "tool" : "programmed"; }

struct Report {
  Path path = Path::plain;
  gen::Options o;
  std::vector<machine::Move> contour;  // the contour proper
  std::size_t approach = 0, departure = 0;  // feed moves set aside before and after it
  gen::Stats stats;
  gen::ShapeModels models;
  double rms = 0;              // of the blocks' largest deviations
  std::uint32_t line = 0;      // the block where the deviation peaks
  std::size_t beyond_tol = 0;
  double size = 0;             // the contour's extent (diagonal of its bounding box), mm
};

inline std::string where(const machine::Move& m) {
  return m.file ? fmt::format("line {} of {}", m.line, m.file->name()) : fmt::format("line {}", m.line);
}

// "X 1.0000 Y 2.0000 Z 3.0000", or on a lathe "X(dia) 2.0000 Z 3.0000" (X as `ncurve run` writes it).
inline std::string position(const machine::MachineProfile& p, const geom::Vec3& v) {
  const report::OutputFrame frame(p);
  std::string s;
  for (char axis : p.axes) {
    const int k = machine::axis_index(axis);
    if (k < 0 || k > 2) continue;
    s += fmt::format("{}{}{} {:.4f}", s.empty() ? "" : " ", axis, k == 0 && frame.x_diameter ? "(dia)" : "",
                     k == 0 ? frame.x(v[0]) : v[static_cast<std::size_t>(k)]);
  }
  return s;
}

// [X, Y, Z] with X as a diameter on a lathe programmed in diameters.
inline nlohmann::json position_json(const machine::MachineProfile& p, const geom::Vec3& v) {
  return {report::OutputFrame(p).x(v[0]), v[1], v[2]};
}

// Measures `contour` (feed moves) against the curve; the reason it cannot, if it cannot: the
// contour does not follow the curve (message for the user), or the measurement failed.
inline std::optional<std::string> measure(std::vector<machine::Move> contour, const geom::Curve& curve,
                                          const machine::MachineProfile& profile, double tol, Report& r) {
  r.o.profile = profile;
  r.o.tol = tol > 0 ? tol : 0.01;
  if (!contour.empty()) r.o.depth = -contour.front().start[2];
  if (contour.empty()) return fmt::format("the program has no feed moves to compare with the curve {}", curve.name());
  const report::CurveNearest nearest(curve, gen::axis_map(curve, r.o));
  if (auto t = nearest.undefined_at())
    return fmt::format("the curve {} is undefined at t = {:g}; check --curve and its parameters", curve.name(), *t);
  const double floor = std::max(r.o.tol, 10 * profile.increment);
  auto lost = [&](double distance, const machine::Move& m) {
    return fmt::format("the path does not follow the curve {}: it is {:.4g} mm away at {}; check --curve and its "
                       "parameters",
                       curve.name(), distance, where(m));
  };
  // the measurement takes the contour to start within this of the curve's start
  const double near = std::max(floor, 1e-3 + 10 * r.o.tol);
  const report::ContourSpan span = report::contour_span(contour, curve, nearest.map(), near);
  r.approach = span.first;
  r.departure = contour.size() - span.last;
  r.contour.assign(contour.begin() + static_cast<std::ptrdiff_t>(span.first),
                   contour.begin() + static_cast<std::ptrdiff_t>(span.last));
  try {
    r.stats = gen::measure(r.contour, curve, r.o, false);
  } catch (const std::exception& e) {
    return fmt::format("--curve: {}", e.what());
  }
  std::vector<double> end_t;
  for (const auto& d : r.stats.deviation) end_t.push_back(d.first);
  if (auto off = report::farthest_off_curve(r.contour, nearest, r.stats.start_t, end_t, floor)) {
    const machine::Move* m = &r.contour[off->move];
    const double anywhere = nearest.distance(off->at);
    if (report::off_curve(anywhere, off->longer, floor)) return lost(anywhere, *m);
    // near the curve, but not where the curve runs in order from its start to its end
    return fmt::format("the path does not follow the curve {} in order of t from {:g} to {:g}: at {} it is {:.4g} mm "
                       "from where the curve runs by then (it skips part of the curve or runs backwards); check "
                       "--curve, --from and --to",
                       curve.name(), curve.t0(), curve.t1(), where(*m), off->distance);
  }
  try {
    r.models = gen::shape_models(r.contour, curve, r.o, r.stats);
  } catch (const std::exception& e) {
    return fmt::format("--curve: {}", e.what());
  }
  double sq = 0, lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  std::size_t worst = 0;
  for (std::size_t i = 0; i < r.stats.deviation.size(); ++i) {
    const double d = r.stats.deviation[i].second;
    sq += d * d;
    r.beyond_tol += tol > 0 && d > tol;
    if (d > r.stats.deviation[worst].second) worst = i;
  }
  for (const auto& p : r.stats.path)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  r.size = r.stats.path.empty() ? 0 : std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  r.rms = r.stats.deviation.empty() ? 0 : std::sqrt(sq / static_cast<double>(r.stats.deviation.size()));
  if (worst < r.contour.size()) r.line = r.contour[worst].line;
  return std::nullopt;
}

// A model whose error on one block exceeds the whole contour's extent does not describe it (a ray
// from the centre that runs along a block, a block that turns a full circle about the centre).
inline bool applies(const gen::ModelError& e, const Report& r) { return std::isfinite(e.max_error) && e.max_error <= r.size; }

inline std::string csv(const gen::ShapeModels& m) {
  auto number = [](double v) { return std::isfinite(v) ? fmt::format("{:.9g}", v) : std::string(); };
  std::string out = "line,kind,t0,t1,deviation_mm,chord_mm,arc_mm,radius_mm,yang_mm,joshi_mm,narayan_arc_mm,khan_arc_mm\n";
  for (const auto& b : m.blocks)
    out += fmt::format("{},{},{:.12g},{:.12g},{:.9g},{},{:.9g},{},{},{},{},{}\n", b.line, b.arc_move ? "arc" : "line",
                       b.t0, b.t1, b.deviation, number(b.chord), b.arc, number(b.radius), number(b.yang),
                       number(b.joshi), number(b.narayan), number(b.khan));
  return out;
}

// The path coloured by deviation over the curve, in the machine's plane (Z across and X up, as a
// radius, on a lathe: equal scales keep the shape).
inline std::string plot(const geom::Curve& curve, const Report& r, double tol, const std::string& program) {
  const gen::Stats& s = r.stats;
  const geom::Plane plane = gen::plane_of(r.o.profile);
  const int u = plane.u_axis, v = plane.v_axis;
  std::vector<report::DeviationSegment> path;
  for (std::size_t i = 0; i + 1 < s.path.size() && i < s.path_block.size(); ++i) {
    const std::size_t block = s.path_block[i];
    path.push_back({s.path[i][u], s.path[i][v], s.path[i + 1][u], s.path[i + 1][v], s.deviation[block].second, block});
  }
  const gen::AxisMap map = gen::axis_map(curve, r.o);
  std::vector<std::array<double, 2>> nominal;
  const int samples = 2000;
  for (int k = 0; k <= samples; ++k) {
    geom::Vec3 p = map(curve.point(curve.t0() + (curve.t1() - curve.t0()) * k / samples));
    nominal.push_back({p[u], p[v]});
  }
  auto name = [&](int axis) {
    std::string n(1, "XYZ"[axis]);
    return axis == 0 && r.o.profile.lathe() ? n + " (radius)" : n;
  };
  return report::deviation_svg(path, nominal, tol, fmt::format("{}: shape error against {}", program, curve.name()),
                               fmt::format("largest {:.2f} µm at t = {:.6g} · {} contour blocks, {:.3f} mm",
                                           s.max_deviation * 1000, s.worst_t, s.deviation.size(), s.path_length),
                               name(u), name(v));
}

inline void add_json(nlohmann::json& j, const geom::Curve& curve, const Report& r, double tol) {
  const gen::Stats& s = r.stats;
  const gen::ShapeModels& m = r.models;
  j["shape_error"] = {{"curve", curve.name()},
                      {"max_mm", s.max_deviation},
                      {"t", s.worst_t},
                      {"at", position_json(r.o.profile, s.worst_point)},
                      {"line", r.line},
                      {"blocks", s.deviation.size()},
                      {"rms_block_max_mm", r.rms},
                      {"path_length_mm", s.path_length},
                      {"moves_set_aside", {r.approach, r.departure}},
                      {"path", to_string(r.path)}};
  if (tol > 0) j["shape_error"]["tolerance_mm"] = tol, j["shape_error"]["blocks_beyond_tolerance"] = r.beyond_tol;
  auto model = [&](const gen::ModelError& e) {
    return nlohmann::json{{"max_mm", e.max},   {"max_error_mm", e.max_error}, {"max_relative_error", e.max_relative},
                          {"line", e.line},    {"block", e.block},            {"applies", applies(e, r)}};
  };
  j["shape_models"] = {{"line_blocks", m.lines},
                       {"centre", position_json(r.o.profile, m.centre)},
                       {"yang_chord_height", model(m.yang)},
                       {"joshi_radial", model(m.joshi)},
                       {"arc_length_mm", m.arc_length},
                       {"narayan_arc", model(m.narayan)},
                       {"khan_arc", model(m.khan)},
                       {"narayan_length_mm", m.narayan_length},
                       {"khan_length_mm", m.khan_length}};
}

inline std::string text(const geom::Curve& curve, const Report& r, double tol) {
  const gen::Stats& s = r.stats;
  const gen::ShapeModels& m = r.models;
  const auto& profile = r.o.profile;
  std::string out = fmt::format(
      "  shape error       max {:.6f} mm from {} at t = {:.6g} ({}), block at line {}; {} contour blocks, {:.3f} mm\n",
      s.max_deviation, curve.name(), s.worst_t, position(profile, s.worst_point), r.line, s.deviation.size(),
      s.path_length);
  if (r.path == Path::tool)
    out += "  path measured     the tool's (cutter centre, or the imaginary tip on a lathe), radius compensation "
           "applied; --programmed measures the contour as programmed\n";
  else if (r.path == Path::programmed)
    out += "  path measured     the contour as programmed (the compensated moves' programmed ends, corners left out)\n";
  if (r.approach + r.departure > 0)
    out += fmt::format("                    set aside: {} feed move(s) approaching the curve, {} leaving it\n",
                       r.approach, r.departure);
  if (tol > 0) out += fmt::format("  tolerance         {} mm: {} blocks beyond it\n", tol, r.beyond_tol);
  if (m.lines == 0) return out;
  const double um = 1000;
  auto figure = [&](const gen::ModelError& e, const std::string& text) {
    if (applies(e, r)) return text;
    return fmt::format("does not apply here: off by {:.4g} mm on the block at line {}, more than the contour's extent "
                       "({:.4g} mm)",
                       e.max_error, e.line, r.size);
  };
  out += fmt::format("  the spiral paper's chord models over {} line blocks (centre {} for the radial ones):\n", m.lines,
                     position(profile, m.centre));
  out += "    chord height, Yang a = sqrt(8Rh - 4h^2)  " +
         figure(m.yang, fmt::format("max {:.3f} um, off the measured by up to {:.3f} um ({:.1f} %)", m.yang.max * um,
                                    m.yang.max_error * um, 100 * m.yang.max_relative)) +
         "\n";
  out += "    radial shape error, Joshi eqs 8-11      " +
         figure(m.joshi, fmt::format("max {:.3f} um, off the measured by up to {:.3f} um ({:.1f} %)", m.joshi.max * um,
                                     m.joshi.max_error * um, 100 * m.joshi.max_relative)) +
         "\n";
  out += fmt::format("    arc length {:.4f} mm: Narayan {}, Khan pi/(2 sqrt 2) chord {}\n", m.arc_length,
                     figure(m.narayan, fmt::format("{:.4f} mm (blocks off by up to {:.3f} %)", m.narayan_length,
                                                   100 * m.narayan.max_relative)),
                     figure(m.khan, fmt::format("{:.4f} mm (up to {:.3f} %)", m.khan_length, 100 * m.khan.max_relative)));
  return out;
}

}  // namespace ncurve::app::shape
