#include "report/verify_report.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "report/backplot_data.hpp"
#include "report/summary.hpp"

namespace ncurve::report {

namespace {

std::string stock_words(const sim::Stock& s) {
  if (const auto* b = std::get_if<sim::AxisBox>(&s))
    return fmt::format("box X{:g}..{:g} Y{:g}..{:g} Z{:g}..{:g}", b->min[0], b->max[0], b->min[1], b->max[1], b->min[2],
                       b->max[2]);
  if (const auto* c = std::get_if<sim::Cylinder>(&s))
    return c->inner_diameter > 0
               ? fmt::format("tube D{:g} bore {:g}, {:g} long from Z{:g}", c->diameter, c->inner_diameter, c->length,
                             c->face)
               : fmt::format("cylinder D{:g}, {:g} long from Z{:g}", c->diameter, c->length, c->face);
  return "STL " + std::get<sim::StlFile>(s).path;
}

nlohmann::json stock_json(const sim::Stock& s) {
  nlohmann::json j;
  if (const auto* b = std::get_if<sim::AxisBox>(&s)) {
    j["shape"] = "box";
    j["min"] = b->min;
    j["max"] = b->max;
  } else if (const auto* c = std::get_if<sim::Cylinder>(&s)) {
    j["shape"] = c->inner_diameter > 0 ? "tube" : "cylinder";
    j["diameter"] = c->diameter;
    if (c->inner_diameter > 0) j["inner_diameter"] = c->inner_diameter;
    j["length"] = c->length;
    j["face"] = c->face;
  } else {
    j["shape"] = "stl";
    j["file"] = std::get<sim::StlFile>(s).path;
  }
  return j;
}

// "T1 12.3, T2 4.5": the material each tool removed, mm^3.
std::string by_tool_text(const std::map<int, double>& by_tool) {
  std::string out;
  for (const auto& [t, volume] : by_tool) out += fmt::format("{}T{} {:.1f}", out.empty() ? "" : ", ", t, volume);
  return out;
}

nlohmann::json by_tool_json(const std::map<int, double>& by_tool) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [t, volume] : by_tool) j[std::to_string(t)] = volume;
  return j;
}

// Each finding as a diagnostic with where (`at`) and how much (`amount`).
nlohmann::json findings_json(const std::vector<sim::Finding>& findings) {
  nlohmann::json j = nlohmann::json::array();
  for (const sim::Finding& f : findings) {
    nlohmann::json d = diagnostic_json(f.diagnostic);
    d["at"] = f.at;
    d["amount"] = f.amount;
    j.push_back(d);
  }
  return j;
}

std::string extreme_text(const sim::DesignExtreme& e) {
  if (e.cells == 0) return "none beyond the tolerance";
  return fmt::format("{:.3f} mm at X{:.3f} Y{:.3f} Z{:.3f} ({} cells beyond the tolerance)", e.amount, e.at[0], e.at[1],
                     e.at[2], e.cells);
}

nlohmann::json extreme_json(const sim::DesignExtreme& e) {
  return {{"amount_mm", e.amount}, {"at", e.cells ? nlohmann::json(e.at) : nlohmann::json(nullptr)}, {"cells", e.cells}};
}

const char* design_words(sim::WallDesign d) {
  return d == sim::WallDesign::groove ? "groove: the tool's axis on the curve" : "edge: the part's wall on the curve";
}

// "t = 12.3 of the curve (X1.0000 Y2.0000), the wall of line 24 of spiral.nc"
std::string wall_point_text(const CurveCheck& c, std::int64_t k) {
  const sim::WallPoint& p = c.walls->points[static_cast<std::size_t>(k)];
  std::string s = c.walls->turned ? fmt::format("t = {:.6g} of the curve (Z{:.4f}, radius {:.4f})", p.t, p.x, p.y)
                                   : fmt::format("t = {:.6g} of the curve (X{:.4f} Y{:.4f})", p.t, p.x, p.y);
  if (c.block && p.cut >= 0) {
    const auto [file, line] = c.block(p.cut);
    s += fmt::format(", the wall of line {}{}", line, file ? " of " + file->name() : std::string());
  }
  return s;
}

}  // namespace

std::string curve_text(const CurveCheck& c, int width) {
  auto line = [&](const char* label, const std::string& text) { return fmt::format("  {:<{}}{}\n", label, width, text); };
  if (!c.walls) return line("curve", fmt::format("{}: not measured: {}", c.curve, c.refused));
  const sim::WallReport& w = *c.walls;
  std::string out = line("curve", fmt::format("{} ({}), walls measured at {} points, tolerance {:g} mm", c.curve,
                                              design_words(w.design), w.points.size(), c.tol));
  if (w.gouge_at >= 0) out += line("beyond design", fmt::format("{:.4f} mm at {}", w.largest_gouge, wall_point_text(c, w.gouge_at)));
  if (w.left_at >= 0) out += line("short of it", fmt::format("{:.4f} mm at {}", w.largest_left, wall_point_text(c, w.left_at)));
  out += line("walls rms",
              fmt::format("{:.4f} mm; {} points beyond the tolerance{}{}; findings {}", w.rms, w.beyond(c.tol),
                          w.not_cut ? fmt::format("; {} curve points not cut", w.not_cut) : "",
                          w.no_design ? fmt::format("; {} sides where the curve turns tighter than the tool", w.no_design)
                                      : "",
                          c.findings.size()));
  return out;
}

nlohmann::json curve_json(const CurveCheck& c) {
  nlohmann::json j;
  j["curve"] = c.curve;
  j["tol_mm"] = c.tol;
  if (!c.walls) {
    j["refused"] = c.refused;
    return j;
  }
  const sim::WallReport& w = *c.walls;
  auto point = [&](std::int64_t k) -> nlohmann::json {
    if (k < 0) return nullptr;
    const sim::WallPoint& p = w.points[static_cast<std::size_t>(k)];
    nlohmann::json at = {{"t", p.t}, {"curve_point", {p.x, p.y}}, {"normal", {p.nx, p.ny}}, {"z", p.level}};
    if (c.block && p.cut >= 0) at["line"] = c.block(p.cut).second;
    return at;
  };
  j["design"] = w.design == sim::WallDesign::groove ? "groove" : "edge";
  j["points"] = w.points.size();
  j["largest_gouge_mm"] = w.largest_gouge;
  j["gouge_at"] = point(w.gouge_at);
  j["largest_left_mm"] = w.largest_left;
  j["left_at"] = point(w.left_at);
  j["rms_mm"] = w.rms;
  j["beyond_tol"] = w.beyond(c.tol);
  j["not_cut"] = w.not_cut;
  j["no_design"] = w.no_design;
  return j;
}

nlohmann::json deviation_json(const CurveCheck& c) {
  std::vector<float> points;
  if (c.walls)
    for (const sim::WallPoint& p : c.walls->points) {
      const double s = p.design_offset + p.error;
      points.insert(points.end(), {static_cast<float>(p.x + s * p.nx), static_cast<float>(p.y + s * p.ny),
                                   static_cast<float>(p.error)});
    }
  return {{"tol", c.tol}, {"points", base64(points.data(), points.size() * sizeof(float))}};
}

std::string removed_text(const VerifyReport& r) {
  if (r.section) {
    const std::string by_tool = by_tool_text(r.section_sink->volume_by_tool());
    return fmt::format("{:.1f} mm^3{}", r.section->volume_removed(), by_tool.empty() ? "" : " (" + by_tool + ")");
  }
  if (!r.verifier) return {};
  const std::string by_tool = by_tool_text(r.verifier->volume_by_tool());
  return fmt::format("{:.1f} mm^3{}", r.verifier->map().volume_removed(), by_tool.empty() ? "" : " (" + by_tool + ")");
}

std::string verify_text(const VerifyReport& r) {
  std::string out;
  out += fmt::format("  setup          {}\n", r.setup_file.empty() ? "none (the defaults below)" : r.setup_file);
  if (r.stock)
    out += fmt::format("  stock          {}{}\n", stock_words(*r.stock),
                       !r.stock_default                             ? ""
                       : std::holds_alternative<sim::Cylinder>(*r.stock) ? " (the bar round the cutting moves)"
                                                                          : " (the box around the cutting moves)");
  for (const std::string& t : r.tools) out += fmt::format("  tool           {}\n", t);
  for (const std::string& f : r.fixtures) out += fmt::format("  fixture        {}\n", f);
  for (const std::string& d : r.defaults) out += fmt::format("  default        {}\n", d);
  if (r.section) {  // a lathe: the half-section
    out += fmt::format("  section        the bar's half-section on a {:g} mm grid, within {:g} mm of the exact cut\n",
                       sim::kSectionUnit, sim::kSectionResolution);
    out += fmt::format("  removed        {}\n", removed_text(r));
    const auto& c = r.section_sink->counts();
    if (c.no_tool) out += fmt::format("  not cut        {} moves with no tool (before the first T code, or T0)\n", c.no_tool);
    if (c.not_zx_arc) out += fmt::format("  not cut        {} arcs outside G18\n", c.not_zx_arc);
    if (c.after) out += fmt::format("  not cut        {} motions after the ones asked for\n", c.after);
    const std::size_t found = r.section_sink->findings().size() + (r.curve ? r.curve->findings.size() : 0);
    out += fmt::format("  findings       {}{} (a lathe's: a rapid through material, the holder in the bar, the tool in a "
                       "fixture, the surface against a curve)\n",
                       found + r.section_sink->findings_left_out(),
                       r.section_sink->findings_left_out() ? fmt::format(" ({} listed)", found) : std::string());
    if (r.curve) out += curve_text(*r.curve, 15);
    if (!r.part_file.empty()) out += fmt::format("  part           {}\n", r.part_file);
    return out;
  }
  if (!r.verifier) {
    out += fmt::format("  verified       no: {}\n", r.refused);
    return out;
  }
  const sim::Verifier& v = *r.verifier;
  const sim::ZMap& map = v.map();
  out += fmt::format("  Z-map          {} x {} cells of {:.4f} mm\n", map.nx(), map.ny(), map.cell());
  out += fmt::format("  removed        {}\n", removed_text(r));
  const auto& c = v.counts();
  if (c.no_tool)
    out += fmt::format("  not cut        {} moves with no tool in the spindle or a tool of no size (tool_in_spindle, "
                       "[tools.N] in the setup)\n",
                       c.no_tool);
  if (c.not_xy_arc) out += fmt::format("  not cut        {} arcs in G18/G19 (not simulated yet)\n", c.not_xy_arc);
  if (c.rotary)
    out += fmt::format("  not cut        {} moves turning a rotary axis (3 axes are simulated)\n", c.rotary);
  if (c.after) out += fmt::format("  not cut        {} motions after the ones asked for\n", c.after);
  // the walls' and the design's findings are listed with the verifier's
  const std::size_t more = (r.curve ? r.curve->findings.size() : 0) + (r.design ? r.design->findings.size() : 0);
  const std::size_t left_out = v.findings_left_out() + (r.design ? r.design->left_out : 0);
  out += fmt::format("  findings       {}{}\n", v.findings().size() + more + left_out,
                     left_out ? fmt::format(" ({} listed)", v.findings().size() + more) : std::string());
  if (r.curve) out += curve_text(*r.curve, 15);
  if (r.design) {
    out += fmt::format("  design         {}, tol {:g} mm, exact to the cell ({:.4f} mm); findings {}\n", r.design_file,
                       r.design->tol, map.cell(), r.design->findings.size() + r.design->left_out);
    out += fmt::format("  gouge          {}\n", extreme_text(r.design->gouge));
    out += fmt::format("  stock left     {}\n", extreme_text(r.design->stock_left));
  }
  if (!r.part_file.empty()) out += fmt::format("  part           {}\n", r.part_file);
  return out;
}

nlohmann::json verify_json(const VerifyReport& r) {
  nlohmann::json j;
  j["setup"] = r.setup_file.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.setup_file);
  j["stock"] = r.stock ? stock_json(*r.stock) : nlohmann::json(nullptr);
  j["stock_default"] = r.stock_default;
  j["tools"] = r.tools;
  j["fixtures"] = r.fixtures;
  j["defaults"] = r.defaults;
  j["verified"] = r.verifier != nullptr || r.section != nullptr;
  if (r.section) {
    j["section"] = {{"grid_mm", sim::kSectionUnit}, {"resolution_mm", sim::kSectionResolution}};
    j["volume_removed_mm3"] = r.section->volume_removed();
    j["volume_by_tool_mm3"] = by_tool_json(r.section_sink->volume_by_tool());
    const auto& c = r.section_sink->counts();
    j["moves_cut"] = c.cut;
    j["moves_not_cut"] = {{"no_tool", c.no_tool}, {"not_zx_arc", c.not_zx_arc}, {"after", c.after}};
    j["findings"] = findings_json(r.section_sink->findings());
    if (r.curve)
      for (const nlohmann::json& f : findings_json(r.curve->findings)) j["findings"].push_back(f);
    j["findings_left_out"] = r.section_sink->findings_left_out();
    if (r.curve) j["curve"] = curve_json(*r.curve);
    j["part"] = r.part_file.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.part_file);
    return j;
  }
  if (!r.verifier) {
    j["refused"] = r.refused;
    return j;
  }
  const sim::Verifier& v = *r.verifier;
  const sim::ZMap& map = v.map();
  j["zmap"] = {{"cells", {map.nx(), map.ny()}}, {"cell_mm", map.cell()}};
  j["volume_removed_mm3"] = map.volume_removed();
  j["volume_by_tool_mm3"] = by_tool_json(v.volume_by_tool());
  const auto& c = v.counts();
  j["moves_cut"] = c.cut;
  j["moves_not_cut"] = {{"no_tool", c.no_tool}, {"not_xy_arc", c.not_xy_arc}, {"rotary", c.rotary}, {"after", c.after}};
  j["findings"] = findings_json(v.findings());
  if (r.curve)
    for (const nlohmann::json& f : findings_json(r.curve->findings)) j["findings"].push_back(f);
  if (r.design)
    for (const nlohmann::json& f : findings_json(r.design->findings)) j["findings"].push_back(f);
  j["findings_left_out"] = v.findings_left_out() + (r.design ? r.design->left_out : 0);
  j["part"] = r.part_file.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.part_file);
  if (r.curve) j["curve"] = curve_json(*r.curve);
  if (r.design)
    j["design"] = {{"file", r.design_file},
                   {"tol_mm", r.design->tol},
                   {"cell_mm", map.cell()},
                   {"gouge", extreme_json(r.design->gouge)},
                   {"stock_left", extreme_json(r.design->stock_left)},
                   {"findings", r.design->findings.size() + r.design->left_out}};
  return j;
}

}  // namespace ncurve::report
