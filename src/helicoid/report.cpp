#include "helicoid/report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "report/svg_plot.hpp"

namespace ncurve::helicoid {

namespace {

const char* kColumns =
    "psi_deg,A_mm,u_deg,r_mm,x_mm,y_mm,z_mm,cutter_x_mm,cutter_y_mm,cutter_z_mm,cutter_alpha_deg,cutter_s_mm,"
    "cutter_region,normal_angle_deg,evaluations,plane_A_mm,plane_error_mm,cusp_mm,Z_mm";

double plane_error(const Contact& c) { return c.plane_A - c.A; }

}  // namespace

std::string contacts_csv(const Job& job) {
  std::string s = std::string(kColumns) + "\n";
  for (std::size_t i = 0; i < job.contacts.size(); ++i) {
    const auto& c = job.contacts[i];
    s += fmt::format("{:.6f},{:.7f},{:.6f},{:.7f},{:.7f},{:.7f},{:.7f},{:.7f},{:.7f},{:.7f},{:.6f},{:.6f},{},{:.3e},{},{:.7f},{:.7f},",
                     c.psi, c.A, c.u, c.r, c.work_point[0], c.work_point[1], c.work_point[2], c.cutter_point[0],
                     c.cutter_point[1], c.cutter_point[2], c.alpha, c.s, c.region, c.normal_angle, c.evaluations,
                     c.plane_A, plane_error(c));
    s += i < job.cusps.size() ? fmt::format("{:.7f},", job.cusps[i]) : ",";
    s += fmt::format("{:.7f}\n", c.z);
  }
  return s;
}

namespace {

struct Summary {
  double a_min = 1e300, a_max = -1e300, plane_worst = 0, plane_worst_psi = 0, normal_worst = 0, mean_evaluations = 0;
  double cusp_worst = 0, cusp_worst_psi = 0;
  std::int64_t evaluations = 0;
};

Summary summarize(const Job& job) {
  Summary s;
  for (const auto& c : job.contacts) {
    s.a_min = std::min(s.a_min, c.A);
    s.a_max = std::max(s.a_max, c.A);
    if (std::abs(plane_error(c)) > std::abs(s.plane_worst)) s.plane_worst = plane_error(c), s.plane_worst_psi = c.psi;
    s.normal_worst = std::max(s.normal_worst, c.normal_angle);
    s.evaluations += c.evaluations;
  }
  for (std::size_t i = 0; i < job.cusps.size(); ++i)
    if (job.cusps[i] > s.cusp_worst) s.cusp_worst = job.cusps[i], s.cusp_worst_psi = job.contacts[i].psi;
  if (!job.contacts.empty()) s.mean_evaluations = static_cast<double>(s.evaluations) / job.contacts.size();
  return s;
}

}  // namespace

std::string contacts_json(const Job& job, const ContactSearch& search) {
  nlohmann::ordered_json j;
  Summary sum = summarize(job);
  j["title"] = job.title;
  j["method"] = method_name(job.method);
  j["step_deg"] = job.step;
  j["final_motion"] = job.final_motion;
  j["swing_deg"] = search.setting().swing;
  j["crossing_angle_deg"] = 90 - search.setting().swing;
  j["start_distance_mm"] = search.setting().start_distance;
  j["lattice"] = {{"alpha_step_deg", search.lattice().alpha_step},
                  {"s_step_mm", search.lattice().s_step},
                  {"alpha_max_deg", search.lattice().alpha_max},
                  {"points", search.lattice().size(search.cutter().length())}};
  j["summary"] = {{"A_min_mm", sum.a_min},         {"A_max_mm", sum.a_max},
                  {"evaluations", sum.evaluations}, {"mean_evaluations", sum.mean_evaluations},
                  {"normal_angle_max_deg", sum.normal_worst}, {"plane_error_max_mm", sum.plane_worst},
                  {"plane_error_max_psi_deg", sum.plane_worst_psi},
                  {"cusp_max_mm", sum.cusp_worst}, {"cusp_max_psi_deg", sum.cusp_worst_psi}};
  if (job.pass_tolerance > 0) {
    auto psis = nlohmann::ordered_json::array();
    for (std::size_t k : job.passes) psis.push_back(job.contacts[k].psi);
    j["program"] = {{"tolerance_mm", job.pass_tolerance}, {"passes", job.passes.size()}, {"psi_deg", psis}};
  }
  auto& steps = j["steps"] = nlohmann::ordered_json::array();
  for (const auto& c : job.contacts) {
    steps.push_back({{"psi_deg", c.psi},
                     {"A_mm", c.A},
                     {"u_deg", c.u},
                     {"r_mm", c.r},
                     {"x_mm", c.work_point[0]},
                     {"y_mm", c.work_point[1]},
                     {"z_mm", c.work_point[2]},
                     {"cutter_x_mm", c.cutter_point[0]},
                     {"cutter_y_mm", c.cutter_point[1]},
                     {"cutter_z_mm", c.cutter_point[2]},
                     {"cutter_alpha_deg", c.alpha},
                     {"cutter_s_mm", c.s},
                     {"cutter_region", c.region},
                     {"normal_angle_deg", c.normal_angle},
                     {"evaluations", c.evaluations},
                     {"plane_A_mm", c.plane_A},
                     {"plane_error_mm", plane_error(c)},
                     {"Z_mm", c.z}});
    if (steps.size() <= job.cusps.size()) steps.back()["cusp_mm"] = job.cusps[steps.size() - 1];
  }
  return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";  // a name that is not UTF-8 gets U+FFFD
}

std::string contacts_text(const Job& job, const ContactSearch& search) {
  Summary sum = summarize(job);
  std::string s = fmt::format("{}\n", job.title);
  s += fmt::format("cutter axis crosses the workpiece axis at {:.4f} deg (disc swung {:.4f} deg); search from A = {:.4f} mm\n",
                   90 - search.setting().swing, search.setting().swing, search.setting().start_distance);
  s += fmt::format("method {}: {} steps, {} distance evaluations ({:.1f} per step) on a lattice of {} points per step\n",
                   method_name(job.method), job.contacts.size(), sum.evaluations, sum.mean_evaluations,
                   search.lattice().size(search.cutter().length()));
  s += fmt::format("A from {:.6f} to {:.6f} mm; surfaces' normals parallel within {:.2e} deg\n", sum.a_min, sum.a_max,
                   sum.normal_worst);
  s += fmt::format("plane programming (profile offset by the corner radius) is off by up to {:+.4f} mm (psi = {:g} deg)\n",
                   sum.plane_worst, sum.plane_worst_psi);
  if (!job.cusps.empty())
    s += fmt::format("one pass per step leaves cusps up to {:.4f} mm (after psi = {:g} deg)\n", sum.cusp_worst,
                     sum.cusp_worst_psi);
  if (job.pass_tolerance > 0)
    s += fmt::format("program: {} passes of the {} steps leave cusps within {:g} mm\n", job.passes.size(),
                     job.contacts.size(), job.pass_tolerance);
  s += "\n";
  s += fmt::format("{:>8} {:>12} {:>9} {:>9} {:>8} {:>8} {:>12} {:>10}\n", "psi deg", "A mm", "u deg", "r mm", "cutter",
                   "evals", "plane A mm", "error mm");
  const bool axial = job.final_motion != "x";
  if (axial) s += fmt::format("final motion along Z ({}): Z mm is where the cutter touches\n", job.final_motion);
  for (const auto& c : job.contacts) {
    s += fmt::format("{:8.3f} {:12.6f} {:9.3f} {:9.4f} {:>8} {:8} {:12.6f} {:+10.6f}", c.psi, c.A, c.u, c.r, c.region,
                     c.evaluations, c.plane_A, plane_error(c));
    s += axial ? fmt::format(" Z {:12.6f}\n", c.z) : "\n";
  }
  return s;
}

std::string pass_program(const Job& job, const ContactSearch& search, const PassOptions& o) {
  const double twist = search.workpiece().twist();
  double a_max = 0;
  for (const auto& c : job.contacts) a_max = std::max(a_max, c.A);
  const double retract = a_max + o.clearance;
  std::string s = "%\n";
  s += fmt::format("O{:04d} (NCURVE HELICOID)\n", o.program_number);
  std::string title = job.title;
  std::transform(title.begin(), title.end(), title.begin(), [](unsigned char ch) {
    return ch == '(' || ch == ')' ? ' ' : static_cast<char>(std::toupper(ch));
  });
  s += fmt::format("({})\n", title);
  s += fmt::format("(X = CENTRE DISTANCE A-PSI, A = WORKPIECE TURN, Z ALONG THE AXIS: A = PSI - {:.6f} * Z)\n", twist);
  if (job.pass_tolerance > 0)
    s += fmt::format("({} PASSES OF {} STEPS, CUSPS WITHIN {:g} MM)\n", job.passes.size(), job.contacts.size(),
                     job.pass_tolerance);
  s += "G21 G90 G94\n";
  s += fmt::format("G00 X{:.3f}\n", retract);
  std::vector<std::size_t> passes = job.passes;
  if (passes.empty())
    for (std::size_t i = 0; i < job.contacts.size(); ++i) passes.push_back(i);
  bool forward = true;
  for (std::size_t k : passes) {
    const auto& c = job.contacts[k];
    double z0 = forward ? o.z_start : o.z_end, z1 = forward ? o.z_end : o.z_start;
    s += fmt::format("G00 Z{:.3f} A{:.3f}\n", z0, c.phase - twist * z0);
    s += fmt::format("G01 X{:.4f} F{:g}\n", c.A, o.feed);
    s += fmt::format("G01 Z{:.3f} A{:.3f}\n", z1, c.phase - twist * z1);
    s += fmt::format("G00 X{:.3f}\n", retract);
    forward = !forward;
  }
  s += "M30\n%\n";
  return s;
}

std::string contacts_svg(const Job& job, const ContactSearch& search) {
  namespace plot = report::plot;
  const auto& profile = search.workpiece().profile;
  constexpr double W = 1000, H = 520;
  plot::Page page(W, H);
  const double top = page.heading(job.title);
  // Left: the end profile (phase 0) with each contact turned back to it, equal scales.
  std::vector<V2> outline;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (int i = 0; i <= 720; ++i) {
    V2 p = profile.point(profile.u0() + profile.period() * i / 720);
    outline.push_back(p);
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  plot::Panel end;
  end.x = 8, end.y = top, end.w = 440, end.h = H - top - 30;
  end.title = "end profile with the contacts";
  end.u = {x0, x1, "x, mm", 1, 6};
  end.v = {y0, y1, "y, mm", 1, 6};
  end.equal = true;
  const plot::Frame f = plot::draw_panel(page, end);
  std::string path;
  for (std::size_t i = 0; i < outline.size(); ++i)
    path += fmt::format("{}{:.2f},{:.2f} ", i ? "L" : "M", f.x(outline[i].x), f.y(outline[i].y));
  std::string s = fmt::format("<path d=\"{}Z\" fill=\"#eef\" stroke=\"#336\"/>\n", path);
  for (const auto& c : job.contacts) {
    V2 p = profile.point(c.u);
    s += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"2\" fill=\"{}\"/>\n", f.x(p.x), f.y(p.y),
                     c.region == "corner" ? "#c00" : "#080");
  }
  page.add(s);
  plot::draw_legend(page, 16, H - 26, 430,
                    {{"contact on the corner", "#c00", "", 1.5, false, true}, {"on the flank", "#080", "", 1.5, false, true}});
  // Right: A(psi) and the plane method's error.
  if (job.contacts.size() >= 2) {
    const double p0 = job.contacts.front().psi, p1 = job.contacts.back().psi;
    double a_lo = 1e300, a_hi = -1e300, e_lo = 0, e_hi = 0;
    for (const auto& c : job.contacts) {
      a_lo = std::min(a_lo, c.A), a_hi = std::max(a_hi, c.A);
      e_lo = std::min(e_lo, plane_error(c) * 1000), e_hi = std::max(e_hi, plane_error(c) * 1000);
    }
    const double half = (H - top - 10) / 2;
    plot::Panel a;
    a.x = 460, a.y = top, a.w = W - 468, a.h = half;
    a.title = "centre distance A(psi)";
    a.u = {p0, p1, "psi, degrees", 1, 8};
    a.v = {a_lo, a_hi, "A, mm", 1, 5};
    const plot::Frame fa = plot::draw_panel(page, a);
    plot::Panel e = a;
    e.y = top + half + 6;
    e.title = "plane method A minus true A";
    e.v = {e_lo, e_hi, "error, µm", 1, 5};
    const plot::Frame fe = plot::draw_panel(page, e);
    std::string a_path, e_path;
    for (std::size_t i = 0; i < job.contacts.size(); ++i) {
      const auto& c = job.contacts[i];
      a_path += fmt::format("{}{:.2f},{:.2f} ", i ? "L" : "M", fa.x(c.psi), fa.y(c.A));
      e_path += fmt::format("{}{:.2f},{:.2f} ", i ? "L" : "M", fe.x(c.psi), fe.y(plane_error(c) * 1000));
    }
    page.add(fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#c00\"/>\n", a_path));
    page.add(fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#999\"/>\n", fe.left,
                         fe.y(0), fe.left + fe.width));
    page.add(fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#06c\"/>\n", e_path));
  }
  return page.str();
}

}  // namespace ncurve::helicoid
