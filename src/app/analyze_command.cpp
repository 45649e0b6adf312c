// ncurve analyze: how long a program runs and how far the machine strays from it.
#include "app/analyze_command.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>
#include <new>

#include "gen/generate.hpp"
#include "gen/shape_models.hpp"
#include "motion/circle.hpp"
#include "motion/planner.hpp"
#include "motion/servo.hpp"
#include "base/bounds.hpp"
#include "base/progress.hpp"
#include "report/feed_trace.hpp"
#include "report/motion_plots.hpp"
#include "report/verify_report.hpp"
#include "app/analyze_contour.hpp"
#include "app/analyze_shape.hpp"
#include "app/run_verify.hpp"
#include "app/cli_units.hpp"
#include "app/save.hpp"
#include "app/shipped.hpp"

namespace ncurve::app {
namespace {

// The cut part: the material removed and the walls against the curve.
std::string part_text(const report::VerifyReport& r) {
  std::string out;
  if (!r.verifier && !r.section) return fmt::format("  cut part          not made: {}\n", r.refused);
  out += fmt::format("  cut part          {} removed from the {}{}\n", report::removed_text(r),
                     r.stock_default ? (r.section ? "bar round the cutting moves" : "box around the cutting moves")
                                     : "stock of ",
                     r.stock_default ? "" : r.setup_file);
  if (r.curve) out += report::curve_text(*r.curve, 18);
  return out;
}


std::string where(const machine::Move& m) {
  return m.file ? fmt::format("{}:{}", m.file->name(), m.line) : fmt::format("line {}", m.line);
}

// "Kv X 30 Y 30 /s" over the profile's first two axes.
std::string gains(const machine::MachineProfile& p) {
  std::string s = "Kv";
  for (std::size_t i = 0; i < 2 && i < p.axes.size(); ++i)
    s += fmt::format(" {} {:g}", p.axes[i], p.servo.kv[static_cast<std::size_t>(machine::axis_index(p.axes[i]))]);
  return s + " /s";
}

int circle_command(const AnalyzeArgs& a) {
  machine::MachineProfile profile = machine::default_mill();
  motion::CircleTest test;
  try {
    if (!a.in.machine.empty()) profile = machine::load_profile(a.in.machine);
    apply_servo_options(profile, a);
  } catch (const std::bad_alloc&) {
    throw;  // main() says what ran out
  } catch (const std::exception& e) {
    std::cerr << "ncurve analyze circle: " << e.what() << "\n";
    return 2;
  }
  test.radius = a.radius;
  test.feed = a.feed;
  test.clockwise = a.clockwise;
  motion::CircleResult r;
  try {
    r = motion::circle_test(profile, test);
  } catch (const std::bad_alloc&) {
    throw;  // main() says what ran out
  } catch (const std::exception& e) {
    std::cerr << "ncurve analyze circle: " << e.what() << "\n";
    return 2;
  }
  const motion::CirclePlane plane = motion::circle_plane(profile);
  const auto& sv = profile.servo;
  const auto& mo = profile.motion;
  const std::string filter =
      mo.acc_dec == machine::AccDec::after
          ? fmt::format("{} acc/dec after interpolation T {} {:g} {} {:g} s",
                        mo.filter == machine::Filter::linear ? "linear" : "exponential", plane.p_name,
                        mo.time_constant[plane.p], plane.q_name, mo.time_constant[plane.q])
          : "acc/dec before interpolation";
  const std::string subtitle =
      fmt::format("{}: {}, feed-forward {}, {}", profile.name, gains(profile), sv.feed_forward, filter);
  const std::string held = r.feed_reached < test.feed
                               ? fmt::format(" (held to {:.6g} mm/min on this arc: figures at that feed)", r.feed_reached)
                               : "";
  if (!a.plot.empty() && !save(a.plot, report::polar_svg(r, test, plane, subtitle), {a.in.machine})) return 2;
  if (a.json) {
    const nlohmann::json j = circle_json(profile, test, r);
    std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";  // a name that is not UTF-8 gets U+FFFD
    return 0;
  }
  const char P = plane.p_name, Q = plane.q_name;
  const std::string angle =
      r.angle_meaningful
          ? fmt::format("  smallest radius at  {:.1f} deg from +{} towards +{}  (linear model: {:.1f} deg)\n",
                        r.max_deviation_angle, P, Q, r.harmonic_angle)
          : fmt::format("  smallest radius at  no particular angle: {} and {} respond alike (equal gains{}), so the "
                        "circle only shrinks\n",
                        P, Q, mo.acc_dec == machine::AccDec::after ? " and filters" : "");
  std::cout << fmt::format(
      "circular test: R {} mm, F {} mm/min{}, {} in the {}{} plane\n  {}\n"
      "  radius reduction    {:.6f} mm   (FANUC closed form V^2/2R (T terms + (1-a^2)/Kv^2): {:.6f}; linear model: {:.6f})\n"
      "  roundness           {:.6f} mm   (first order V |tau_{} - tau_{}|: {:.6f}; linear model: {:.6f})\n"
      "{}"
      "  contour error, whole run (start and stop included): {:.6f} mm\n"
      "  circular-interpolation paper's formula  e = V^2/2 cos a sin a (cos a/a_{} + sin a/a_{}): {:.6f} mm at {:.1f} deg from +{} "
      "(a_{} {} a_{} {} mm/s^2)\n",
      test.radius, test.feed, held, test.clockwise ? "clockwise" : "counter-clockwise", P, Q, subtitle,
      r.radius_reduction, r.fanuc_radius_reduction, r.harmonic_radius_reduction, r.roundness, P, Q,
      r.first_order_roundness, r.harmonic_roundness, angle, r.max_contour_error, Q, P, r.seed002_error,
      r.seed002_angle, P, P, mo.acceleration[plane.p], Q, mo.acceleration[plane.q]);
  return 0;
}

int program_command(const AnalyzeArgs& a) {
  RunSetup setup;
  try {
    setup = prepare_run(a.in);
    apply_servo_options(setup.profile, a);
  } catch (const std::bad_alloc&) {
    throw;  // main() says what ran out
  } catch (const std::exception& e) {
    std::cerr << "ncurve analyze: " << nc::escape_controls(e.what()) << "\n";
    return 2;
  }
  for (const auto& d : setup.problems) std::cerr << nc::format(d) << "\n";
  if (setup.problems_left_out) std::cerr << "... and " << setup.problems_left_out << " more text problems not shown\n";
  if (setup.unchecked_lines)
    std::cerr << "... and " << setup.unchecked_lines << " lines after them that can never run, not checked\n";
  const machine::MachineProfile& profile = setup.profile;
  std::optional<geom::Curve> curve;
  if (a.curve.name.empty() && (!a.shape_csv.empty() || !a.shape_plot.empty() || a.tol > 0)) {
    std::cerr << "ncurve analyze: --shape-csv, --shape-plot and --tol need a nominal curve (--curve NAME ...)\n";
    return 2;
  }
  if (!a.curve.name.empty()) {
    try {
      curve.emplace(build_curve(a.curve, a.command->remaining(), profile));
    } catch (const std::bad_alloc&) {
    throw;  // main() says what ran out
  } catch (const std::exception& e) {
      std::cerr << "ncurve analyze: --curve: " << e.what() << "\n";
      return 2;
    }
  } else if (!a.command->remaining().empty()) {
    std::cerr << "ncurve analyze: unexpected argument '" << a.command->remaining().front() << "'\n";
    return 2;
  }

  std::optional<io::OutputFile> blocks_file;
  if (!a.blocks.empty()) {
    try {
      blocks_file.emplace(a.blocks, setup.inputs);
    } catch (const io::OutputError& e) {
      std::cerr << "ncurve analyze: error: " << e.what() << "\n";
      return 2;
    }
  }
  std::ostream* csv = blocks_file ? &blocks_file->stream() : nullptr;
  if (csv) {
    *csv << "file,line,kind,length_mm,programmed_mm_min,cap_mm_min,limit,v_in_mm_min,v_peak_mm_min,v_out_mm_min,"
           "start_s,seconds,wait_s,settle_s,starved\n";
  }
  std::optional<motion::ServoSim> sim;
  if (a.servo) sim.emplace(profile);
  report::FeedTrace trace;
  motion::BlockTime slowest_wait{};
  motion::Planner planner(profile, [&](const motion::BlockTime& b) {
    if (csv)
      *csv << fmt::format("{},{},{},{:.6f},{:.3f},{:.3f},{},{:.3f},{:.3f},{:.3f},{:.6f},{:.6f},{:.6f},{:.6f},{}\n",
                         b.move.file ? b.move.file->name() : "", b.move.line, machine::to_string(b.move.kind), b.length,
                         b.programmed, b.cap, motion::to_string(b.limit), b.v_in, b.v_peak, b.v_out, b.start, b.seconds,
                         b.wait, b.settle, b.starved ? 1 : 0);
    if (sim) {
      check_servo_ticks(b, profile, a.max_ticks);
      sim->on_block(b);
    }
    if (b.wait > slowest_wait.wait) slowest_wait = b;
    if (!a.plot.empty() && b.move.kind != machine::MoveKind::rapid)
      trace.add({b.length, b.programmed, b.v_in, b.v_peak, b.v_out, b.profile.up.distance(b.profile.up.duration()),
                 b.profile.down.distance(b.profile.down.duration()), b.starved});
  });
  ContourTee tee;
  base::Progress progress{"ncurve analyze", "moves"};
  tee.progress = &progress;
  tee.max_moves = a.max_moves;
  tee.profile = &profile;
  tee.programmed = a.programmed;
  std::vector<machine::Move> contour;
  tee.planner = &planner;
  if (curve) {
    tee.contour = &contour;
    tee.plane_only = !profile.lathe() && curve->planar_z();
  }
  // the part cut: its walls against the curve and the material each tool removed (a mill's)
  std::optional<RunVerification> part;
  if (curve) {
    const VerifyArgs va = analyze_part(a);
    try {
      part.emplace(va, profile, *setup.lib, setup.options);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      std::cerr << "ncurve analyze: " << nc::escape_controls(e.what()) << "\n";
      return 2;
    }
    tee.part = part->sink();
  }
  machine::Interpreter interp(profile, *setup.lib, setup.options);
  machine::RunResult result;
  try {
    result = interp.run(tee);
    planner.finish();
  } catch (const base::BoundExceeded& e) {  // (the --blocks file is not written)
    std::cerr << "ncurve analyze: " << e.what() << "\n";
    return 2;
  }
  if (blocks_file) {
    try {
      blocks_file->commit();
    } catch (const io::OutputError& e) {
      std::cerr << "ncurve analyze: error: " << e.what() << "\n";
      return 2;
    }
  }
  if (sim) settle(*sim, profile);
  if (part) part->finish(result);
  if (!result.ok()) {
    std::cerr << nc::format(*result.alarm) << "\n";
    return 1;
  }
  std::optional<shape::Report> shape;
  if (curve) {
    shape.emplace();
    shape->path = !tee.compensated ? shape::Path::plain : a.programmed ? shape::Path::programmed : shape::Path::tool;
    if (auto why = shape::measure(std::move(contour), *curve, profile, a.tol, *shape)) {
      std::cerr << "ncurve analyze: " << *why;
      if (shape->path == shape::Path::tool)
        std::cerr << "; the path measured is the tool's, radius compensation applied (G41/G42): --programmed measures "
                     "the contour as programmed";
      std::cerr << "\n";
      return 1;
    }
    if (!a.shape_csv.empty() && !save(a.shape_csv, shape::csv(shape->models), setup.inputs)) return 2;
    if (!a.shape_plot.empty() && !save(a.shape_plot, shape::plot(*curve, *shape, a.tol, a.in.program), setup.inputs))
      return 2;
  }
  const motion::PlanTotals& t = planner.totals();
  const double mean_feed = t.feed_motion_seconds > 0 ? t.feed_length / t.feed_motion_seconds * 60 : 0;
  if (!a.plot.empty()) {
    std::string title = fmt::format("{}: feed along the cutting path, cycle time {:.2f} s ({})", a.in.program,
                                    t.seconds, profile.name);
    if (!save(a.plot, report::feed_svg(trace.samples(), title), setup.inputs)) return 2;
  }
  if (a.json) {
    nlohmann::json j = analyze_json(a.in.program, profile, t, sim ? &*sim : nullptr);
    if (shape) shape::add_json(j, *curve, *shape, a.tol);
    if (part) j["part"] = report::verify_json(part->report());
    std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    return 0;
  }
  std::cout << fmt::format(
      "{} on {}\n"
      "  cycle time        {:.3f} s   (moving {:.3f}, waiting for blocks {:.3f}, settling {:.3f}, dwell {:.3f})\n"
      "  at programmed feed {:.3f} s  (length / F, no acceleration or processing time)\n"
      "  motions {}, full stops {}, waits {}, starved blocks {} (block processing {} ms)\n"
      "  cutting length {:.3f} mm, mean feed reached {:.1f} mm/min\n"
      "  macro statements {} ({} ms each), NC blocks {} ({} ms each)\n",
      a.in.program, profile.name, t.seconds, t.motion_seconds, t.wait_seconds, t.settle_seconds, t.dwell_seconds,
      t.programmed_seconds, t.motions, t.stops, t.waits, t.starved, profile.motion.block_time * 1000, t.feed_length,
      mean_feed, t.macro_statements, profile.motion.macro_time * 1000, t.nc_blocks, profile.motion.block_time * 1000);
  if (t.without_lookahead > 0)
    std::cout << fmt::format("  look-ahead off    {} motions (G05.1 Q0, G08 P0, G05 P0): each slows to a stop at its end\n",
                             t.without_lookahead);
  if (slowest_wait.wait > 0)
    std::cout << fmt::format("  longest wait      {:.4f} s before {} (the control was still reading or computing)\n",
                             slowest_wait.wait, where(slowest_wait.move));
  if (shape) std::cout << shape::text(*curve, *shape, a.tol);
  if (part) std::cout << part_text(part->report());
  if (sim) {
    auto contour = [&](const char* label, const motion::ContourStats& s, const char* none) {
      if (s.ticks == 0) return fmt::format("  {} none ({})\n", label, none);
      return fmt::format("  {} max {:.6f} mm at t = {:.3f} s ({}), at {}; rms {:.6f} mm\n", label, s.max_error, s.max_t,
                         s.max_file ? fmt::format("{}:{}", s.max_file->name(), s.max_line) : "at rest",
                         shape::position(profile, s.max_actual), s.rms);
    };
    std::cout << contour("contour error, cutting", sim->cutting(), "no feed moves")
              << contour("contour error, rapids ", sim->rapids(), "no rapid moves")
              << fmt::format("  servo             {}, feed-forward {}\n", gains(profile), profile.servo.feed_forward);
  }
  return 0;
}

}  // namespace

// --kv 30 or --kv 30,25 over the profile's servo settings: the gains of its first two axes (X and
// Y on a mill, X and Z on a lathe), one value for both; and --feed-forward.
void apply_servo_options(machine::MachineProfile& p, const AnalyzeArgs& a) {
  if (a.feed_forward) p.servo.feed_forward = *a.feed_forward;
  const std::vector<std::string>& kv = a.kv;
  if (kv.empty()) return;
  if (kv.size() > 2 || kv.size() > p.axes.size())
    throw std::runtime_error(fmt::format("--kv takes one gain per axis of {}, at most two", p.axes));
  for (std::size_t i = 0; i < 2 && i < p.axes.size(); ++i) {
    const std::string& text = kv[std::min(i, kv.size() - 1)];
    const std::optional<double> v = units::finite_number(text);
    if (!v || !(*v > 0)) throw std::runtime_error(fmt::format("--kv: '{}' is not a gain in 1/s", text));
    p.servo.kv[static_cast<std::size_t>(machine::axis_index(p.axes[i]))] = *v;
  }
}

VerifyArgs analyze_part(const AnalyzeArgs& a) {
  VerifyArgs va;
  va.verify = true;
  va.setup = a.setup;
  va.curve = a.curve;
  va.curve_extras = a.command->remaining();
  va.tol = a.tol > 0 ? a.tol : 0.01;
  va.wall = a.wall;
  va.max_moves = a.max_moves;
  return va;
}

void check_servo_ticks(const motion::BlockTime& b, const machine::MachineProfile& profile, double max_ticks) {
  if ((b.start + b.seconds) / profile.servo.period > max_ticks)
    throw base::BoundExceeded(fmt::format(
        "--servo: the program runs longer than {:.3g} servo periods of {:g} ms ({:.4g} s of machine time), at {}: "
        "raise --max-ticks",
        max_ticks, profile.servo.period * 1000, max_ticks * profile.servo.period, where(b.move)));
}

motion::PlanTotals program_time(const std::string& name, const std::string& text,
                                const machine::MachineProfile& profile) {
  machine::ProgramLibrary lib(profile.parse_options());
  lib.add_text(name, text, true);
  motion::Planner planner(profile);
  machine::Interpreter interp(profile, lib);
  const machine::RunResult r = interp.run(planner);
  if (!r.ok()) throw std::runtime_error(nc::format(*r.alarm));
  planner.finish();
  return planner.totals();
}

nlohmann::json analyze_json(const std::string& program, const machine::MachineProfile& profile,
                            const motion::PlanTotals& t, const motion::ServoSim* sim) {
  const double mean_feed = t.feed_motion_seconds > 0 ? t.feed_length / t.feed_motion_seconds * 60 : 0;
  nlohmann::json j;
  j["program"] = program;
  j["machine"] = profile.name;
  j["cycle_time_s"] = t.seconds;
  j["motion_s"] = t.motion_seconds;
  j["wait_s"] = t.wait_seconds;
  j["settle_s"] = t.settle_seconds;
  j["dwell_s"] = t.dwell_seconds;
  j["programmed_time_s"] = t.programmed_seconds;
  j["motions"] = t.motions;
  j["stops"] = t.stops;
  j["waits"] = t.waits;
  j["starved_blocks"] = t.starved;
  j["motions_without_lookahead"] = t.without_lookahead;
  j["feed_length_mm"] = t.feed_length;
  j["mean_feed_mm_min"] = mean_feed;
  j["macro_statements"] = t.macro_statements;
  j["nc_blocks"] = t.nc_blocks;
  j["axes"] = nlohmann::json::array();
  for (char axis : profile.axes) j["axes"].push_back(std::string(1, axis));
  j["x_diameter"] = report::OutputFrame(profile).x_diameter;
  if (sim) {
    auto contour_json = [&](const motion::ContourStats& s) {
      return nlohmann::json{{"max_mm", s.max_error},
                            {"rms_mm", s.rms},
                            {"t_s", s.max_t},
                            {"line", s.max_line},
                            {"file", s.max_file ? s.max_file->name() : ""},
                            {"at", shape::position_json(profile, s.max_actual)},
                            {"samples", s.ticks}};
    };
    j["contour_error"] = contour_json(sim->cutting());
    j["rapid_contour_error"] = contour_json(sim->rapids());
  }
  return j;
}

nlohmann::json circle_json(const machine::MachineProfile& profile, const motion::CircleTest& test,
                           const motion::CircleResult& r) {
  const motion::CirclePlane plane = motion::circle_plane(profile);
  const auto& sv = profile.servo;
  nlohmann::json j;
  j["radius"] = test.radius;
  j["feed"] = test.feed;
  j["feed_reached"] = r.feed_reached;
  j["direction"] = test.clockwise ? "cw" : "ccw";
  j["plane"] = std::string{plane.p_name, plane.q_name};
  j["axes"] = nlohmann::json::array();
  for (std::size_t i = 0; i < 2 && i < profile.axes.size(); ++i) j["axes"].push_back(std::string(1, profile.axes[i]));
  j["kv"] = nlohmann::json::array();
  for (std::size_t i = 0; i < 2 && i < profile.axes.size(); ++i)
    j["kv"].push_back(sv.kv[static_cast<std::size_t>(machine::axis_index(profile.axes[i]))]);
  j["feed_forward"] = sv.feed_forward;
  j["radius_reduction"] = r.radius_reduction;
  j["roundness"] = r.roundness;
  j["max_deviation_angle"] = r.max_deviation_angle;
  j["angle_meaningful"] = r.angle_meaningful;
  j["max_contour_error"] = r.max_contour_error;
  j["closed_form"] = {{"fanuc_radius_reduction", r.fanuc_radius_reduction},
                      {"first_order_roundness", r.first_order_roundness},
                      {"harmonic_radius_reduction", r.harmonic_radius_reduction},
                      {"harmonic_roundness", r.harmonic_roundness},
                      {"harmonic_angle", r.harmonic_angle},
                      {"seed002_error", r.seed002_error},
                      {"seed002_angle", r.seed002_angle}};
  return j;
}

void settle(motion::ServoSim& sim, const machine::MachineProfile& profile) {
  double slowest = INFINITY;  // five time constants of the slowest loop
  for (char axis : profile.axes)
    if (int k = machine::axis_index(axis); k >= 0 && k < 3)
      slowest = std::min(slowest, profile.servo.kv[static_cast<std::size_t>(k)]);
  sim.finish(std::max(0.2, 5.0 / slowest));
}

void add_analyze_command(CLI::App& app, AnalyzeArgs& a) {
  CLI::App* cmd = app.add_subcommand(
      "analyze", "cycle time (feed planning, block and macro processing), servo contour error of a program");
  add_run_inputs(cmd, a.in, false);
  cmd->add_flag("--json", a.json, "results as JSON");
  cmd->add_flag("--servo", a.servo, "simulate the servo loops and report the contour error");
  cmd->add_option("--blocks", a.blocks, "write each motion's timing and feed to this CSV file");
  cmd->add_option("--plot", a.plot, "SVG: feed reached against programmed along the path");
  cmd->add_option("--kv", a.kv, "position loop gain KX[,KY] in 1/s over the profile's (KX[,KZ] on a lathe)")
      ->delimiter(',')
      ->check(units::gain_per_s());
  cmd->add_option("--feed-forward", a.feed_forward, "velocity feed-forward coefficient 0..1 over the profile's")
      ->check(units::ratio(units::at_least(0), units::at_most(1)));
  cmd->add_option("--max-moves", a.max_moves,
                  "--curve: the most contour moves kept for measuring (about 250 bytes each), default 500000; more is "
                  "refused")
      ->check(units::number("a count", "", units::at_least(1), units::at_most(1e9), true));
  cmd->add_option("--max-ticks", a.max_ticks,
                  "--servo: the most servo periods simulated (about 60 ns each), default 50000000; a longer program "
                  "is refused")
      ->check(units::number("a count", "", units::at_least(1), units::at_most(1e12), true));
  add_curve_options(cmd, a.curve,
                    "nominal curve for the shape error: a name of `ncurve gen --list` (its parameters as --NAME VALUE) "
                    "or expr");
  cmd->add_option("--setup", a.setup,
                  "--curve: the stock and tools the part is cut with (TOML, docs/setup.md); default: the box around "
                  "the cutting moves, each tool a flat end mill of its D offset")
      ->check(CLI::ExistingFile);
  add_wall_option(cmd, a.wall);
  cmd->add_option("--shape-csv", a.shape_csv,
                  "--curve: write each contour block's deviation and the spiral paper's chord models to this CSV file");
  cmd->add_option("--shape-plot", a.shape_plot, "--curve: SVG of the path coloured by its deviation from the curve");
  cmd->add_flag("--programmed", a.programmed,
                "--curve: measure the contour as programmed (the programmed ends of the moves under cutter or "
                "tool-nose radius compensation), not the tool centre path");
  cmd->add_option("--tol", a.tol, "--curve: shape tolerance, mm; blocks beyond it are counted and marked")
      ->check(units::length_mm(units::above(0)));
  CLI::App* circle = cmd->add_subcommand("circle", "ISO 230-4 circular test on the machine model");
  circle->add_option("--radius", a.radius, "radius, mm")->required()->check(units::length_mm(units::above(0)));
  circle->add_option("--feed", a.feed, "feed, mm/min")->required()->check(units::feed_mm_min());
  circle->add_option("--kv", a.kv, "position loop gain KX[,KY] in 1/s over the profile's (KX[,KZ] on a lathe)")
      ->delimiter(',')
      ->check(units::gain_per_s());
  circle->add_option("--feed-forward", a.feed_forward, "velocity feed-forward coefficient 0..1")
      ->check(units::ratio(units::at_least(0), units::at_most(1)));
  circle->add_option("--machine", a.in.machine, "machine profile (TOML file, or a shipped one by name)")
      ->transform(profile_path());
  circle->add_flag("--cw", a.clockwise, "clockwise (G02); default counter-clockwise");
  circle->add_flag("--json", a.json, "results as JSON");
  circle->add_option("--plot", a.plot, "SVG: polar deviation diagram");
  a.command = cmd;
  a.circle = circle;
}

int analyze_command(const AnalyzeArgs& a) {
  if (a.circle->parsed()) return circle_command(a);
  if (a.in.program.empty()) {
    std::cerr << "ncurve analyze: name a program (ncurve analyze prog.nc --machine profile.toml) or use "
                 "`ncurve analyze circle`\n";
    return 2;
  }
  return program_command(a);
}

}  // namespace ncurve::app
