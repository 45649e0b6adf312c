// ncurve analyze: how long a program runs and how far the machine strays from it.
#include "app/analyze_command.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>

#include "gen/generate.hpp"
#include "gen/shape_models.hpp"
#include "motion/circle.hpp"
#include "motion/planner.hpp"
#include "motion/servo.hpp"
#include "report/motion_plots.hpp"
#include "app/cli_units.hpp"
#include "app/save.hpp"

namespace ncurve::app {
namespace {

std::string where(const machine::Move& m) {
  return m.file ? fmt::format("{}:{}", m.file->name(), m.line) : fmt::format("line {}", m.line);
}

// --kv 30 or --kv 30,25 (X, Y), and --feed-forward, over the profile's servo settings.
void apply_servo_options(machine::MachineProfile& p, const AnalyzeArgs& a) {
  if (a.feed_forward) p.servo.feed_forward = *a.feed_forward;
  const std::vector<std::string>& kv = a.kv;
  if (kv.empty()) return;
  if (kv.size() > 2) throw std::runtime_error("--kv takes KX or KX,KY");
  for (std::size_t i = 0; i < kv.size(); ++i) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(kv[i], &used);
    } catch (const std::logic_error&) {
      used = 0;
    }
    if (used != kv[i].size() || !(v > 0)) throw std::runtime_error(fmt::format("--kv: '{}' is not a gain in 1/s", kv[i]));
    p.servo.kv[i] = v;
    if (kv.size() == 1) p.servo.kv[1] = v;
  }
}

int circle_command(const AnalyzeArgs& a) {
  machine::MachineProfile profile = machine::default_mill();
  motion::CircleTest test;
  try {
    if (!a.in.machine.empty()) profile = machine::load_profile(a.in.machine);
    apply_servo_options(profile, a);
  } catch (const std::exception& e) {
    std::cerr << "ncurve analyze circle: " << e.what() << "\n";
    return 2;
  }
  test.radius = a.radius;
  test.feed = a.feed;
  test.clockwise = a.clockwise;
  motion::CircleResult r = motion::circle_test(profile, test);
  const auto& sv = profile.servo;
  const auto& mo = profile.motion;
  std::string filter = mo.acc_dec == machine::AccDec::after
                           ? fmt::format("{} acc/dec after interpolation T {} / {} s",
                                         mo.filter == machine::Filter::linear ? "linear" : "exponential",
                                         mo.time_constant[0], mo.time_constant[1])
                           : "acc/dec before interpolation";
  std::string subtitle = fmt::format("Kv X {} Y {} /s, feed-forward {}, {}", sv.kv[0], sv.kv[1], sv.feed_forward, filter);
  if (!a.plot.empty() && !save(a.plot, report::polar_svg(r, test, subtitle), {a.in.program})) return 2;
  if (a.json) {
    nlohmann::json j;
    j["radius"] = test.radius;
    j["feed"] = test.feed;
    j["direction"] = test.clockwise ? "cw" : "ccw";
    j["kv"] = {sv.kv[0], sv.kv[1]};
    j["feed_forward"] = sv.feed_forward;
    j["radius_reduction"] = r.radius_reduction;
    j["roundness"] = r.roundness;
    j["max_deviation_angle"] = r.max_deviation_angle;
    j["max_contour_error"] = r.max_contour_error;
    j["closed_form"] = {{"fanuc_radius_reduction", r.fanuc_radius_reduction},
                        {"first_order_roundness", r.first_order_roundness},
                        {"harmonic_radius_reduction", r.harmonic_radius_reduction},
                        {"harmonic_roundness", r.harmonic_roundness},
                        {"harmonic_angle", r.harmonic_angle},
                        {"seed002_error", r.seed002_error},
                        {"seed002_angle", r.seed002_angle}};
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << fmt::format(
      "circular test: R {} mm, F {} mm/min, {}\n  {}\n"
      "  radius reduction    {:.6f} mm   (FANUC closed form V^2/2R (T terms + (1-a^2)/Kv^2): {:.6f}; linear model: {:.6f})\n"
      "  roundness           {:.6f} mm   (first order V |tau_x - tau_y|: {:.6f}; linear model: {:.6f})\n"
      "  smallest radius at  {:.1f} deg  (linear model: {:.1f} deg)\n"
      "  contour error, whole run (start and stop included): {:.6f} mm\n"
      "  seed 002's formula  e = V^2/2 cos a sin a (cos a/a_y + sin a/a_x): {:.6f} mm at {:.1f} deg "
      "(a_x {} a_y {} mm/s^2)\n",
      test.radius, test.feed, test.clockwise ? "clockwise" : "counter-clockwise", subtitle, r.radius_reduction,
      r.fanuc_radius_reduction, r.harmonic_radius_reduction, r.roundness, r.first_order_roundness, r.harmonic_roundness,
      r.max_deviation_angle, r.harmonic_angle, r.max_contour_error, r.seed002_error, r.seed002_angle,
      mo.acceleration[0], mo.acceleration[1]);
  return 0;
}

struct BlockRecord {
  double s0, length, programmed, v_in, v_peak, v_out, up, down;
  bool starved;
};

std::vector<report::FeedSample> feed_samples(const std::vector<BlockRecord>& blocks) {
  std::vector<report::FeedSample> out;
  if (blocks.empty()) return out;
  const double total = blocks.back().s0 + blocks.back().length;
  const std::size_t bins = 3000;
  if (blocks.size() * 4 <= bins) {
    for (const auto& b : blocks) {
      out.push_back({b.s0, b.programmed, b.v_in, b.starved});
      out.push_back({b.s0 + b.up, b.programmed, b.v_peak, b.starved});
      out.push_back({b.s0 + b.length - b.down, b.programmed, b.v_peak, b.starved});
      out.push_back({b.s0 + b.length, b.programmed, b.v_out, b.starved});
    }
    return out;
  }
  // many blocks: per bin of path length, the lowest feed reached (dips stay visible)
  std::vector<report::FeedSample> bin(bins + 1);
  std::vector<bool> used(bins + 1, false);
  for (const auto& b : blocks) {
    std::size_t k = static_cast<std::size_t>(b.s0 / std::max(total, 1e-12) * bins);
    k = std::min(k, bins);
    double low = std::min({b.v_in, b.v_peak, b.v_out});
    if (!used[k]) bin[k] = {total * k / bins, b.programmed, low, b.starved};
    else {
      bin[k].reached = std::min(bin[k].reached, low);
      bin[k].programmed = std::max(bin[k].programmed, b.programmed);
      bin[k].starved = bin[k].starved || b.starved;
    }
    used[k] = true;
  }
  for (std::size_t k = 0; k <= bins; ++k)
    if (used[k]) out.push_back(bin[k]);
  return out;
}

std::string shape_csv(const gen::ShapeModels& m) {
  auto number = [](double v) { return std::isfinite(v) ? fmt::format("{:.9g}", v) : std::string(); };
  std::string out = "line,kind,t0,t1,deviation_mm,chord_mm,arc_mm,radius_mm,yang_mm,joshi_mm,narayan_arc_mm,khan_arc_mm\n";
  for (const auto& b : m.blocks)
    out += fmt::format("{},{},{:.12g},{:.12g},{:.9g},{},{:.9g},{},{},{},{},{}\n", b.line, b.arc_move ? "arc" : "line",
                       b.t0, b.t1, b.deviation, number(b.chord), b.arc, number(b.radius), number(b.yang),
                       number(b.joshi), number(b.narayan), number(b.khan));
  return out;
}

std::string shape_plot(const geom::Curve& curve, const gen::Options& o, const gen::Stats& s, double tol,
                       const std::string& program) {
  const geom::Plane plane = gen::plane_of(o.profile);
  const int u = plane.u_axis, v = plane.v_axis;
  std::vector<report::DeviationSegment> path;
  for (std::size_t i = 0; i + 1 < s.path.size() && i < s.path_block.size(); ++i) {
    const std::size_t block = s.path_block[i];
    path.push_back({s.path[i][u], s.path[i][v], s.path[i + 1][u], s.path[i + 1][v], s.deviation[block].second, block});
  }
  const gen::AxisMap map = gen::axis_map(curve, o);
  std::vector<std::array<double, 2>> nominal;
  const int samples = 2000;
  for (int k = 0; k <= samples; ++k) {
    geom::Vec3 p = map(curve.point(curve.t0() + (curve.t1() - curve.t0()) * k / samples));
    nominal.push_back({p[u], p[v]});
  }
  const std::string axes = o.profile.axes;
  auto name = [&](int axis) { return axis < static_cast<int>(axes.size()) ? axes[static_cast<std::size_t>(axis)] : '?'; };
  return report::deviation_svg(path, nominal, tol,
                               fmt::format("{}: shape error against {}", program, curve.name()),
                               fmt::format("largest {:.2f} µm at t = {:.6g} · {} contour blocks, {:.3f} mm",
                                           s.max_deviation * 1000, s.worst_t, s.deviation.size(), s.path_length),
                               name(u), name(v));
}

int program_command(const AnalyzeArgs& a) {
  RunSetup setup;
  try {
    setup = prepare_run(a.in);
    apply_servo_options(setup.profile, a);
  } catch (const std::exception& e) {
    std::cerr << "ncurve analyze: " << e.what() << "\n";
    return 2;
  }
  for (const auto& d : setup.problems) std::cerr << nc::format(d) << "\n";
  const machine::MachineProfile& profile = setup.profile;
  std::optional<geom::Curve> curve;
  if (a.curve.name.empty() && (!a.shape_csv.empty() || !a.shape_plot.empty() || a.tol > 0)) {
    std::cerr << "ncurve analyze: --shape-csv, --shape-plot and --tol need a nominal curve (--curve NAME ...)\n";
    return 2;
  }
  if (!a.curve.name.empty()) {
    try {
      curve.emplace(build_curve(a.curve, a.command->remaining(), profile));
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
      blocks_file.emplace(a.blocks, std::vector<std::string>{a.in.program});
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
  std::vector<BlockRecord> records;
  double cut_length = 0;
  motion::BlockTime slowest_wait{};
  motion::Planner planner(profile, [&](const motion::BlockTime& b) {
    if (csv)
      *csv << fmt::format("{},{},{},{:.6f},{:.3f},{:.3f},{},{:.3f},{:.3f},{:.3f},{:.6f},{:.6f},{:.6f},{:.6f},{}\n",
                         b.move.file ? b.move.file->name() : "", b.move.line, machine::to_string(b.move.kind), b.length,
                         b.programmed, b.cap, motion::to_string(b.limit), b.v_in, b.v_peak, b.v_out, b.start, b.seconds,
                         b.wait, b.settle, b.starved ? 1 : 0);
    if (sim) sim->on_block(b);
    if (b.wait > slowest_wait.wait) slowest_wait = b;
    if (!a.plot.empty() && b.move.kind != machine::MoveKind::rapid) {
      records.push_back({cut_length, b.length, b.programmed, b.v_in, b.v_peak, b.v_out,
                         b.profile.up.distance(b.profile.up.duration()),
                         b.profile.down.distance(b.profile.down.duration()), b.starved});
      cut_length += b.length;
    }
  });
  // The contour measured against the curve: feed moves (lines and arcs), and for a plane curve on a
  // mill only those that stay at one Z (plunges and retracts are not part of the contour).
  struct Tee final : machine::MoveSink {
    machine::MoveSink* planner = nullptr;
    std::vector<machine::Move>* contour = nullptr;
    bool plane_only = false;
    void on_move(const machine::Move& m) override {
      planner->on_move(m);
      if (!contour || (m.kind != machine::MoveKind::line && m.kind != machine::MoveKind::arc)) return;
      if (plane_only && m.end[2] != m.start[2]) return;
      contour->push_back(m);
    }
  } tee;
  std::vector<machine::Move> contour;
  tee.planner = &planner;
  if (curve) {
    tee.contour = &contour;
    tee.plane_only = !profile.lathe() && curve->planar_z();
  }
  machine::Interpreter interp(profile, *setup.lib, setup.options);
  machine::RunResult result = interp.run(tee);
  planner.finish();
  if (blocks_file) {
    try {
      blocks_file->commit();
    } catch (const io::OutputError& e) {
      std::cerr << "ncurve analyze: error: " << e.what() << "\n";
      return 2;
    }
  }
  if (sim) sim->finish(std::max(0.2, 5.0 / profile.servo.kv[0]));
  if (!result.ok()) {
    std::cerr << nc::format(*result.alarm) << "\n";
    return 1;
  }
  std::optional<gen::Stats> shape;
  gen::ShapeModels models;
  double shape_rms = 0;        // of the blocks' largest deviations
  std::uint32_t shape_line = 0;  // the block where the deviation peaks
  std::size_t beyond_tol = 0;
  if (curve) {
    gen::Options o;
    o.profile = profile;
    o.tol = a.tol > 0 ? a.tol : 0.01;
    if (!contour.empty()) o.depth = -contour.front().start[2];
    try {
      shape = gen::measure(contour, *curve, o, false);
      models = gen::shape_models(contour, *curve, o, *shape);
    } catch (const std::exception& e) {
      std::cerr << "ncurve analyze: --curve: " << e.what() << "\n";
      return 1;
    }
    if (!a.shape_csv.empty() && !save(a.shape_csv, shape_csv(models), {a.in.program})) return 2;
    if (!a.shape_plot.empty() &&
        !save(a.shape_plot, shape_plot(*curve, o, *shape, a.tol, a.in.program), {a.in.program}))
      return 2;
    double sq = 0;
    std::size_t worst = 0;
    for (std::size_t i = 0; i < shape->deviation.size(); ++i) {
      sq += shape->deviation[i].second * shape->deviation[i].second;
      beyond_tol += a.tol > 0 && shape->deviation[i].second > a.tol;
      if (shape->deviation[i].second > shape->deviation[worst].second) worst = i;
    }
    shape_rms = shape->deviation.empty() ? 0 : std::sqrt(sq / shape->deviation.size());
    if (worst < contour.size()) shape_line = contour[worst].line;
  }
  const motion::PlanTotals& t = planner.totals();
  const double mean_feed = t.feed_motion_seconds > 0 ? t.feed_length / t.feed_motion_seconds * 60 : 0;
  if (!a.plot.empty()) {
    std::string title = fmt::format("{}: feed along the cutting path, cycle time {:.2f} s ({})", a.in.program,
                                    t.seconds, profile.name);
    if (!save(a.plot, report::feed_svg(feed_samples(records), title), {a.in.program})) return 2;
  }
  if (a.json) {
    nlohmann::json j;
    j["program"] = a.in.program;
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
    j["feed_length_mm"] = t.feed_length;
    j["mean_feed_mm_min"] = mean_feed;
    j["macro_statements"] = t.macro_statements;
    j["nc_blocks"] = t.nc_blocks;
    if (sim) {
      const auto& s = sim->stats();
      j["contour_error"] = {{"max_mm", s.max_error}, {"rms_mm", s.rms}, {"t_s", s.max_t}, {"line", s.max_line},
                            {"at", {s.max_actual[0], s.max_actual[1], s.max_actual[2]}}};
    }
    if (shape) {
      j["shape_error"] = {{"curve", curve->name()},
                          {"max_mm", shape->max_deviation},
                          {"t", shape->worst_t},
                          {"at", shape->worst_point},
                          {"line", shape_line},
                          {"blocks", shape->deviation.size()},
                          {"rms_block_max_mm", shape_rms},
                          {"path_length_mm", shape->path_length}};
      if (a.tol > 0) j["shape_error"]["tolerance_mm"] = a.tol, j["shape_error"]["blocks_beyond_tolerance"] = beyond_tol;
      auto model = [](const gen::ModelError& e) {
        return nlohmann::json{{"max_mm", e.max}, {"max_error_mm", e.max_error}, {"max_relative_error", e.max_relative},
                              {"line", e.line}, {"block", e.block}};
      };
      j["shape_models"] = {{"line_blocks", models.lines},
                           {"centre", models.centre},
                           {"yang_chord_height", model(models.yang)},
                           {"joshi_radial", model(models.joshi)},
                           {"arc_length_mm", models.arc_length},
                           {"narayan_arc", model(models.narayan)},
                           {"khan_arc", model(models.khan)},
                           {"narayan_length_mm", models.narayan_length},
                           {"khan_length_mm", models.khan_length}};
    }
    std::cout << j.dump(2) << "\n";
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
  if (slowest_wait.wait > 0)
    std::cout << fmt::format("  longest wait      {:.4f} s before {} (the control was still reading or computing)\n",
                             slowest_wait.wait, where(slowest_wait.move));
  if (shape) {
    std::cout << fmt::format(
        "  shape error       max {:.6f} mm from {} at t = {:.6g} (X {:.4f} Y {:.4f} Z {:.4f}), block at line {}; {} "
        "contour blocks, {:.3f} mm\n",
        shape->max_deviation, curve->name(), shape->worst_t, shape->worst_point[0], shape->worst_point[1],
        shape->worst_point[2], shape_line, shape->deviation.size(),
        shape->path_length);
    if (a.tol > 0)
      std::cout << fmt::format("  tolerance         {} mm: {} blocks beyond it\n", a.tol, beyond_tol);
    if (models.lines > 0) {
      const double um = 1000;
      std::cout << fmt::format(
          "  seed 000's models over {} line blocks (centre X {:.4f} Y {:.4f} for the radial ones):\n"
          "    chord height, Yang a = sqrt(8Rh - 4h^2)  max {:.3f} um, off the measured by up to {:.3f} um "
          "({:.1f} %)\n"
          "    radial shape error, Joshi eqs 8-11      max {:.3f} um, off the measured by up to {:.3f} um "
          "({:.1f} %)\n"
          "    arc length {:.4f} mm: Narayan {:.4f} mm (blocks off by up to {:.3f} %), Khan pi/(2 sqrt 2) chord "
          "{:.4f} mm (up to {:.3f} %)\n",
          models.lines, models.centre[0], models.centre[1], models.yang.max * um, models.yang.max_error * um,
          100 * models.yang.max_relative, models.joshi.max * um, models.joshi.max_error * um,
          100 * models.joshi.max_relative, models.arc_length, models.narayan_length, 100 * models.narayan.max_relative,
          models.khan_length, 100 * models.khan.max_relative);
    }
  }
  if (sim) {
    const auto& s = sim->stats();
    std::cout << fmt::format(
        "  contour error     max {:.6f} mm at t = {:.3f} s ({}), rms {:.6f} mm (servo Kv X {} Y {} /s, feed-forward "
        "{})\n",
        s.max_error, s.max_t, s.max_file ? fmt::format("{}:{}", s.max_file->name(), s.max_line) : "at rest", s.rms,
        profile.servo.kv[0], profile.servo.kv[1], profile.servo.feed_forward);
  }
  return 0;
}

}  // namespace

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
  cmd->allow_extras();
  cmd->add_option("--curve", a.curve.name,
                  "nominal curve for the shape error: a name of `ncurve gen --list` (its parameters as --NAME VALUE) "
                  "or expr");
  cmd->add_option("--shape-csv", a.shape_csv,
                  "--curve: write each contour block's deviation and seed 000's models to this CSV file");
  cmd->add_option("--shape-plot", a.shape_plot, "--curve: SVG of the path coloured by its deviation from the curve");
  cmd->add_option("--tol", a.tol, "--curve: shape tolerance, mm; blocks beyond it are counted and marked")
      ->check(units::length_mm(units::above(0)));
  cmd->add_option("--x", a.curve.x, "--curve expr: x(t)");
  cmd->add_option("--y", a.curve.y, "--curve expr: y(t)");
  cmd->add_option("--z", a.curve.z, "--curve expr: z(t)");
  cmd->add_option("--t", a.curve.t_range, "--curve expr: range of t as FROM:TO");
  cmd->add_option("--from", a.curve.from, "start of the curve parameter t")->check(units::number("a number", ""));
  cmd->add_option("--to", a.curve.to, "end of the curve parameter t")->check(units::number("a number", ""));
  CLI::App* circle = cmd->add_subcommand("circle", "ISO 230-4 circular test on the machine model");
  circle->add_option("--radius", a.radius, "radius, mm")->required()->check(units::length_mm(units::above(0)));
  circle->add_option("--feed", a.feed, "feed, mm/min")->required()->check(units::feed_mm_min());
  circle->add_option("--kv", a.kv, "position loop gain KX[,KY] in 1/s over the profile's (KX[,KZ] on a lathe)")
      ->delimiter(',')
      ->check(units::gain_per_s());
  circle->add_option("--feed-forward", a.feed_forward, "velocity feed-forward coefficient 0..1")
      ->check(units::ratio(units::at_least(0), units::at_most(1)));
  circle->add_option("--machine", a.in.machine, "machine profile (TOML)")->check(CLI::ExistingFile);
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
