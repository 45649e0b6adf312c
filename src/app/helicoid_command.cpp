// ncurve helicoid: disc-cutter locations for a helical surface by minimum directed distance.
#include "app/helicoid_command.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <new>
#include <memory>
#include <numbers>

#include "geom/curve.hpp"
#include "helicoid/report.hpp"
#include "io/number_rows.hpp"
#include "app/cli_units.hpp"
#include "app/save.hpp"
#include "base/progress.hpp"

namespace ncurve::app {
namespace {
// Bounds on one command's work (docs/helicoid.md): rows of the table (psi steps, or centre
// distances; a robust step takes about 7 ms) and lattice points evaluated by --method brute
// (about 0.2 us each).
constexpr double kMostSteps = 20000;
constexpr double kMostBrutePoints = 1e9;
}  // namespace

void add_helicoid_command(CLI::App& app, HelicoidArgs& a) {
  CLI::App* h = app.add_subcommand("helicoid", "disc-cutter locations for a helical surface (the helicoid paper's method)");
  h->add_option("--example", a.example, "seed004: the screw-drill rotor of the helicoid paper with its cutter")
      ->check(CLI::IsMember({"seed004"}));
  h->add_option("--profile", a.profile, "end profile: rotor (the helicoid paper's) or a closed curve of `ncurve gen --list`");
  h->add_option("--profile-x", a.profile_x, "end profile x(u), macro expression in u (degrees)");
  h->add_option("--profile-y", a.profile_y, "end profile y(u)");
  h->add_option("--profile-csv", a.profile_csv,
                 "end profile as a closed list of points x,y (mm) in order around the axis: a periodic cubic spline "
                 "runs through them, the first point turned to face +X")
      ->check(CLI::ExistingFile);
  h->add_option("--u", a.u_range, "range of u closing the profile once, FROM:TO (default 0:360)");
  h->add_option("--lead", a.lead, "lead, mm per turn (0: straight, no twist)")->check(units::length_mm(units::at_least(0)));
  h->add_option("--hand", a.hand, "right or left")->check(CLI::IsMember({"right", "left"}));
  h->add_option("--lobes", a.lobes, "number of lobes (A repeats every 360/lobes degrees)")->check(units::whole_number(1));
  h->add_option("--cutter-diameter", a.cutter_diameter, "disc cutter outside diameter, mm")
      ->check(units::length_mm(units::above(0)));
  h->add_option("--corner-radius", a.corner_radius, "insert corner radius, mm")->check(units::length_mm(units::at_least(0)));
  h->add_option("--included-angle", a.included_angle, "insert included angle, degrees (symmetric V)")
      ->check(units::angle_deg(units::above(0), units::below(180)));
  h->add_option("--cutter-profile", a.cutter_profile,
                 "general cutter axial profile: vertices rho,w[,radius] (mm) from the -w side over the rim to the +w "
                 "side; a radius makes the piece to the next vertex an arc (> 0 convex, < 0 concave)")
      ->check(CLI::ExistingFile);
  h->add_option("--flank-depth", a.flank_depth, "radial depth of the insert's flanks, mm (default: profile depth + 3)")
      ->check(units::length_mm(units::above(0)));
  h->add_option("--ref-radius", a.ref_radius, "radius at which the cutter follows the helix, mm (default: mean radius)")
      ->check(units::length_mm(units::above(0)));
  h->add_option("--crossing-angle", a.crossing_angle, "angle between cutter and workpiece axes, degrees (overrides --ref-radius)")
      ->check(units::angle_deg(units::above(0), units::below(180)));
  h->add_option("--start-distance", a.start_distance, "centre distance the search starts from, mm (must be clear)")
      ->check(units::length_mm(units::above(0)));
  h->add_option("--final-motion", a.final_motion,
                 "x: the cutter comes in along -X (as in the helicoid paper); z- or z+: at --centre-distance it travels along Z")
      ->check(CLI::IsMember({"x", "z-", "z+"}));
  h->add_option("--centre-distance", a.centre_distance,
                 "final motion along Z: the fixed centre distance, mm, or FROM:TO:STEP for one row per distance at psi "
                 "= --from");
  h->add_option("--start-z", a.start_z, "final motion along Z: where the cutter starts, clear of the workpiece, mm")
      ->check(units::length_mm());
  h->add_option("--step", a.step, "psi step, degrees")->check(units::angle_deg(units::above(0)));
  h->add_option("--from", a.from, "first psi, degrees (default 0)")->check(units::angle_deg());
  h->add_option("--to", a.to, "last psi, degrees (default 360/lobes)")->check(units::angle_deg());
  h->add_option("--method", a.method, "robust (default), nine-point or brute")
      ->check(CLI::IsMember({"robust", "nine-point", "brute"}));
  h->add_option("--alpha-step", a.alpha_step, "lattice step around the cutter axis, degrees")
      ->check(units::angle_deg(units::above(0)));
  h->add_option("--s-step", a.s_step, "lattice step along the cutter profile, mm")->check(units::length_mm(units::above(0)));
  h->add_option("--alpha-range", a.alpha_range, "lattice half range around the cutter axis, degrees")
      ->check(units::angle_deg(units::above(0), units::below(90)));
  h->add_flag("--csv", a.csv, "contacts as CSV");
  h->add_flag("--json", a.json, "contacts as JSON");
  h->add_flag("--no-check", a.no_check, "skip the interference check over the whole cutter");
  h->add_option("-o,--output", a.output, "write the table to this file");
  h->add_option("--program", a.program, "write a 4-axis FANUC program (X, Z, A): one helical pass per step (or see --program-tol)");
  h->add_option("--program-tol", a.program_tol,
                 "program: the fewest of the steps' passes whose cusps stay within this, mm")
      ->check(units::length_mm(units::above(0)));
  // the program's Z (3 decimals) and F (6 figures) as words a FANUC control reads
  h->add_option("--length", a.length, "program: pass length along Z, mm")
      ->check(units::length_mm(units::above(0), units::at_most(99999)));
  h->add_option("--feed", a.feed, "program: feed along the pass, mm/min")
      ->check(units::feed_mm_min(units::at_least(0.001), units::at_most(99999)));
  h->add_option("--plot", a.plot, "SVG: end profile with contacts, A(psi), plane-method error");
  a.command = h;
}

void helicoid_job(const HelicoidArgs& a, std::optional<helicoid::ContactSearch>& search, helicoid::Job& job,
                  bool progress_shown) {
  using namespace helicoid;
  std::vector<double> psis, centre_distances;
  // refused before the search, which can take long: no output over an input
  const std::vector<std::string> inputs{a.profile_csv, a.cutter_profile};
  for (const std::string* out : {&a.output, &a.program, &a.plot})
    if (io::same_file(*out, inputs))
      throw HelicoidRefused(fmt::format("error: {}: refusing to write over an input file", *out));
  try {
    const bool seed = a.example == "seed004";
    std::optional<EndProfile> profile;
    std::string profile_name;
    if (!a.profile_csv.empty() + !a.profile_x.empty() + !a.profile.empty() > 1)
      throw std::runtime_error("give one end profile: --profile, --profile-x/--profile-y or --profile-csv");
    if (!a.profile_csv.empty()) {
      std::vector<V2> points;
      for (const auto& row : io::read_number_file(a.profile_csv, 2, 2)) points.push_back({row.values[0], row.values[1]});
      try {
        profile = EndProfile::from_points("points " + a.profile_csv, points);
      } catch (const std::bad_alloc&) {
    throw;  // main() says what ran out
  } catch (const std::exception& e) {
        throw std::runtime_error(a.profile_csv + ": " + e.what());
      }
      profile_name = "points " + a.profile_csv;
    } else if (!a.profile_x.empty() || !a.profile_y.empty()) {
      if (a.profile_x.empty() || a.profile_y.empty()) throw std::runtime_error("--profile-x needs --profile-y and back");
      geom::CurveSpec spec;
      spec.name = "profile";
      spec.x = a.profile_x;
      spec.y = a.profile_y;
      spec.z = "0";
      spec.from = 0, spec.to = 360;
      if (!a.u_range.empty()) {
        auto colon = a.u_range.find(':');
        auto from = units::finite_number(a.u_range.substr(0, colon));
        auto to = colon == std::string::npos ? std::nullopt : units::finite_number(a.u_range.substr(colon + 1));
        if (!from || !to) throw std::runtime_error(fmt::format("--u '{}': give FROM:TO in degrees", a.u_range));
        spec.from = *from, spec.to = *to;
      }
      // The expression language names the parameter t; accept u for the profile.
      auto rename = [](std::string e) {
        std::string out;
        for (std::size_t i = 0; i < e.size(); ++i) {
          bool word = (i == 0 || !std::isalnum(static_cast<unsigned char>(e[i - 1]))) &&
                      (i + 1 == e.size() || !std::isalnum(static_cast<unsigned char>(e[i + 1])));
          out += (word && (e[i] == 'u' || e[i] == 'U')) ? 't' : e[i];
        }
        return out;
      };
      spec.x = rename(spec.x);
      spec.y = rename(spec.y);
      profile = EndProfile::from_curve(std::make_shared<geom::Curve>(spec, std::map<std::string, double>{}));
      profile_name = "profile x = " + a.profile_x + ", y = " + a.profile_y;
    } else if (seed || a.profile == "rotor") {
      profile = EndProfile::seed004_rotor();
      profile_name = "seed004 rotor";
    } else if (!a.profile.empty()) {
      const geom::CurveSpec* spec = geom::find_curve(a.profile);
      if (!spec) throw std::runtime_error(fmt::format("no curve named '{}' (ncurve gen --list)", a.profile));
      profile = EndProfile::from_curve(std::make_shared<geom::Curve>(*spec, std::map<std::string, double>{}));
      profile_name = a.profile;
    } else {
      throw std::runtime_error("give --example seed004, --profile NAME or --profile-x/--profile-y");
    }
    auto need = [&](const std::optional<double>& v, double seed_value, const char* name) {
      if (v) return *v;
      if (seed) return seed_value;
      throw std::runtime_error(fmt::format("{} is needed (or --example seed004)", name));
    };
    Workpiece work{*profile, need(a.lead, 860, "--lead"), a.hand == "left" ? -1 : 1, a.lobes.value_or(seed ? 5 : 1)};
    if (work.lead < 0) throw std::runtime_error("--lead must be >= 0 (give the hand with --hand)");
    double depth = work.profile.r_max() - work.profile.r_min();
    std::optional<DiscCutter> general;
    std::string cutter_name;
    if (!a.cutter_profile.empty()) {
      if (a.cutter_diameter || a.corner_radius || a.included_angle || a.flank_depth)
        throw std::runtime_error("--cutter-profile gives the whole cutter: leave out --cutter-diameter, --corner-radius, "
                                 "--included-angle and --flank-depth");
      general = DiscCutter::from_file(a.cutter_profile);
    }
    double diameter = general ? 2 * general->outer_radius() : need(a.cutter_diameter, 252, "--cutter-diameter");
    double corner = general ? 0 : need(a.corner_radius, 1.2, "--corner-radius");
    double angle = general ? 0 : need(a.included_angle, 35, "--included-angle");
    double flank = a.flank_depth.value_or(depth + 3);
    if (general) {
      double inner = general->outer_radius();
      for (const auto& e : general->elements()) inner = std::min({inner, e.start.x, e.end.x});
      flank = general->outer_radius() - inner;
    }
    DiscCutter cutter = general ? *general : DiscCutter::v_insert(diameter, corner, angle, flank);
    double ref = a.ref_radius.value_or((work.profile.r_min() + work.profile.r_max()) / 2);
    Setting setting;
    setting.swing = a.crossing_angle ? 90 - *a.crossing_angle : helix_angle(work.lead, ref);
    setting.start_distance = a.start_distance.value_or(seed ? 177.7 : 0);
    Lattice lattice;
    lattice.alpha_step = a.alpha_step;
    lattice.s_step = a.s_step;
    double reach = std::acos(std::max(-1.0, (diameter / 2 - depth - flank) / (diameter / 2))) * 180 / std::numbers::pi;
    lattice.alpha_max = a.alpha_range.value_or(std::min(89.0, reach + 2));
    if (const std::int64_t points = lattice.size(cutter.length()); points > kMostLatticePoints)
      throw std::runtime_error(fmt::format(
          "the search lattice (+-{:g} deg by {:g} deg around the cutter, {:g} mm of profile by {:g} mm) has {:.3g} "
          "points, more than {:.3g}: raise --alpha-step or --s-step (or lower --alpha-range)",
          lattice.alpha_max, lattice.alpha_step, cutter.length(), lattice.s_step, static_cast<double>(points),
          static_cast<double>(kMostLatticePoints)));
    search.emplace(work, cutter, setting, lattice);
    if (search->setting().start_distance < work.profile.r_max() + cutter.outer_radius() - 1e-9 &&
        search->deepest_penetration(0, search->setting().start_distance) > 1e-6)
      throw std::runtime_error(fmt::format("the start centre distance {} mm cuts into the workpiece",
                                           search->setting().start_distance));
    double from = a.from.value_or(0), to = a.to.value_or(360.0 / work.lobes);
    if (to < from) throw std::runtime_error(fmt::format("--to ({:g} deg) is before --from ({:g} deg)", to, from));
    const double steps = std::floor((to - from) / a.step + 1e-9);
    if (steps + 1 > kMostSteps)
      throw std::runtime_error(fmt::format("psi from {:g} to {:g} deg in steps of {:g} deg is {:.3g} steps, more than {:.0f}: "
                                           "raise --step", from, to, a.step, steps + 1, kMostSteps));
    const int n = static_cast<int>(steps);
    for (int i = 0; i <= n; ++i) psis.push_back(from + i * a.step);
    if ((a.final_motion != "x") == a.centre_distance.empty() || (a.final_motion == "x" && a.start_z))
      throw std::runtime_error("--centre-distance and --start-z go with --final-motion z- or z+, and z- and z+ need "
                               "--centre-distance");
    if (!a.centre_distance.empty()) {
      std::vector<double> v;
      std::size_t at = 0;
      for (;;) {
        std::size_t colon = a.centre_distance.find(':', at);
        std::string part = a.centre_distance.substr(at, colon == std::string::npos ? std::string::npos : colon - at);
        std::size_t used = 0;
        double x = 0;
        try {
          x = std::stod(part, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != part.size() || !std::isfinite(x))
          throw std::runtime_error(fmt::format("--centre-distance '{}': give A or FROM:TO:STEP in mm", a.centre_distance));
        v.push_back(x);
        if (colon == std::string::npos) break;
        at = colon + 1;
      }
      if (v.size() != 1 && (v.size() != 3 || !(v[2] > 0) || v[1] < v[0]))
        throw std::runtime_error(fmt::format("--centre-distance '{}': give A or FROM:TO:STEP (STEP > 0, TO >= FROM)",
                                             a.centre_distance));
      if (v.size() == 1) {
        centre_distances.push_back(v[0]);
      } else {
        const double count = std::floor((v[1] - v[0]) / v[2] + 1e-9);
        if (count + 1 > kMostSteps)
          throw std::runtime_error(fmt::format("--centre-distance '{}' is {:.3g} distances, more than {:.0f}: a larger STEP",
                                               a.centre_distance, count + 1, kMostSteps));
        for (int i = 0; i <= static_cast<int>(count); ++i) centre_distances.push_back(v[0] + i * v[2]);
        psis = {psis.front()};
      }
    }
    job.method = method_from_name(a.method);
    // brute force evaluates every lattice point at every step (about 0.2 us each)
    const double rows = static_cast<double>(psis.size() * std::max<std::size_t>(1, centre_distances.size()));
    const double evaluations = rows * static_cast<double>(lattice.size(cutter.length()));
    if (job.method == Method::brute && evaluations > kMostBrutePoints)
      throw std::runtime_error(fmt::format(
          "--method brute over {:.0f} steps of {:.3g} lattice points is {:.3g} evaluations, more than {:.3g}: raise "
          "--step, --alpha-step or --s-step, or use --method robust",
          rows, static_cast<double>(lattice.size(cutter.length())), evaluations, kMostBrutePoints));
    job.step = a.step;
    const std::string cutter_text = general ? fmt::format("cutter {} (D{:g})", a.cutter_profile, diameter)
                                            : fmt::format("cutter D{:g} r{:g} {:g} deg", diameter, corner, angle);
    job.title = fmt::format("{}, lead {:g} mm {} hand, {}, crossing {:.4f} deg", profile_name, work.lead, a.hand,
                            cutter_text, 90 - setting.swing);
  } catch (const std::bad_alloc&) {
    throw;  // main() says what ran out
  } catch (const std::exception& e) {
    throw HelicoidRefused(e.what());
  }
  {
    std::optional<base::Progress> shown;
    if (progress_shown)
      shown.emplace("ncurve helicoid", "contacts",
                    a.final_motion != "x" ? psis.size() * centre_distances.size() : psis.size());
    auto progress = [&](std::size_t n) {
      if (shown) shown->at(n);
    };
    if (a.final_motion != "x") {
      for (double distance : centre_distances) {
        AxialMotion motion{distance, a.start_z, a.final_motion == "z+" ? 1 : -1};
        const std::size_t before = job.contacts.size();
        for (auto& c : search->run_axial(psis, job.method, motion, [&](std::size_t n) { progress(before + n); }))
          job.contacts.push_back(c);
      }
      job.final_motion = a.final_motion;
    } else {
      job.contacts = search->run(psis, job.method, [&](std::size_t n) { progress(n); });
    }
    for (const auto& c : job.contacts) {
      if (c.normal_angle > 1e-3)
        throw std::runtime_error(fmt::format(
            "psi = {:g} deg: the surfaces' normals differ by {:.4f} deg at the contact (cutter {} at alpha {:.3f} deg, "
            "s {:.3f} mm): the contact is at an edge of the searched cutter region, widen --alpha-range or "
            "--flank-depth", c.psi, c.normal_angle, c.region, c.alpha, c.s));
      if (!a.no_check) {
        double p = search->deepest_penetration(c.phase, c.A);
        if (p > 1e-6)
          throw std::runtime_error(fmt::format("psi = {:g} deg: at A = {:.6f} mm the cutter cuts {:.6f} mm into the "
                                               "workpiece elsewhere (interference)", c.psi, c.A, p));
      }
    }
    for (std::size_t i = 0; i + 1 < job.contacts.size(); ++i)
      job.cusps.push_back(search->cusp(job.contacts[i], job.contacts[i + 1]).height);
    if (a.program_tol) {
      auto plan = search->fewest_passes(job.contacts, *a.program_tol);
      job.passes = plan.passes;
      job.pass_tolerance = *a.program_tol;
    }
  }
}

int helicoid_command(const HelicoidArgs& a) {
  std::optional<helicoid::ContactSearch> search;
  helicoid::Job job;
  try {
    helicoid_job(a, search, job, true);
  } catch (const std::bad_alloc&) {
    throw;  // main() says what ran out
  } catch (const HelicoidRefused& e) {
    std::cerr << "ncurve helicoid: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ncurve helicoid: " << e.what() << "\n";
    return 1;
  }
  using namespace helicoid;
  std::string table = a.json ? contacts_json(job, *search) : a.csv ? contacts_csv(job) : contacts_text(job, *search);
  if (a.output.empty()) std::cout << table;
  else if (!save(a.output, table)) return 2;
  if (!a.program.empty()) {
    PassOptions o;
    o.z_end = -a.length;
    o.feed = a.feed;
    if (!save(a.program, pass_program(job, *search, o))) return 2;
  }
  if (!a.plot.empty() && !save(a.plot, contacts_svg(job, *search))) return 2;
  return 0;
}

}  // namespace ncurve::app
