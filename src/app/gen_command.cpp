// ncurve gen: a program for a curve, proven by running it back through the interpreter.
#include "app/gen_command.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <fstream>
#include <iostream>
#include <new>
#include <set>

#include "app/analyze_command.hpp"
#include "app/cli_checks.hpp"
#include "app/curve_args.hpp"
#include "app/save.hpp"
#include "app/shipped.hpp"
#include "base/bounds.hpp"
#include "gen/generate.hpp"
#include "machine/profile.hpp"

namespace ncurve::app {
namespace {

std::string list_curves() {
  std::string s = "Curves (ncurve gen NAME --PARAM VALUE ... --from T0 --to T1):\n";
  for (const auto& c : geom::catalogue()) {
    s += fmt::format("\n  {:<10} {}\n", c.name, c.doc);
    s += fmt::format("  {:<10} x = {}\n  {:<10} y = {}\n  {:<10} z = {}\n", "", c.x, "", c.y, "", c.z);
    s += fmt::format("  {:<10} --from {} --to {}  ({})\n", "", c.from, c.to, c.t_doc);
    if (c.lathe) s += fmt::format("  {:<10} a lathe curve: --machine profiles/fanuc-lathe.toml\n", "");
    for (const auto& p : c.params) s += fmt::format("  {:<10} --{} {:.10g}  ({})\n", "", p.name, p.value, p.doc);
  }
  s += "\n  expr       any curve: ncurve gen expr --x \"..\" --y \"..\" [--z \"..\"] --t 0:360 [--NAME VALUE ...]\n"
       "             (macro expression language: SIN COS TAN ATAN ... in degrees, [ ] or ( ), names for parameters)\n";
  return s;
}

// The cycle time `ncurve analyze` estimates for the program on its machine, the cycle's
// parameters set; none if it does not run.
std::optional<motion::PlanTotals> time_of(const gen::Options& o, const gen::Result& r) {
  machine::MachineProfile p = o.profile;
  try {
    for (const auto& [key, value] : r.parameters) machine::set_parameter(p, key, value);
    return program_time("<generated>", r.text, p);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

bool is_macro_form(gen::Form f) {
  return f == gen::Form::macro || f == gen::Form::adaptive_macro || f == gen::Form::cycle;
}

}  // namespace

GenTimes gen_times(const GenJob& job, const gen::Result& r) {
  GenTimes t;
  t.form = time_of(job.options, r);
  if (!t.form || !is_macro_form(job.options.form)) return t;
  gen::Options e = job.options;
  e.form = gen::Form::expanded;
  e.cycle_program = 0;
  try {
    const gen::Result lines = gen::generate(job.curve, e);
    if (lines.within_tolerance) t.expanded = time_of(e, lines);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
  }
  return t;
}

namespace {
// A macro form this many times slower than the G01 lines is warned of.
constexpr double kSlowerThanExpanded = 1.5;
}  // namespace

std::string slower_warning(const GenJob& job, const GenTimes& t) {
  if (!t.form || !t.expanded || t.form->seconds <= kSlowerThanExpanded * t.expanded->seconds) return {};
  return fmt::format(
      "the {} form takes {:.1f} s on {} ({} full stops, {} macro statements of {} ms), {:.1f} times the {:.1f} s of "
      "--form expanded ({} full stops): the control computes the points while the tool waits",
      gen::to_string(job.options.form), t.form->seconds, job.options.profile.name, t.form->stops,
      t.form->macro_statements, job.options.profile.motion.macro_time * 1000, t.form->seconds / t.expanded->seconds,
      t.expanded->seconds, t.expanded->stops);
}

void add_gen_times(nlohmann::json& j, const GenTimes& times, const std::string& program_text) {
  if (times.form) j["cycle_time_s"] = times.form->seconds;
  if (times.expanded) j["expanded_cycle_time_s"] = times.expanded->seconds;
  j["common_variables"] = common_variables_set(program_text);
}

std::vector<int> common_variables_set(const std::string& text) {
  std::string code;  // the text without comments
  int depth = 0;
  for (char c : text) {
    if (c == '(') ++depth;
    else if (c == ')' && depth > 0) --depth;
    else if (depth == 0) code += c;
  }
  std::set<int> set;  // each "#N =" (spaces allowed)
  auto space = [&](std::size_t i) {
    while (i < code.size() && (code[i] == ' ' || code[i] == '\t')) ++i;
    return i;
  };
  for (std::size_t i = code.find('#'); i != std::string::npos; i = code.find('#', i + 1)) {
    std::size_t k = space(i + 1);
    long n = 0;
    const std::size_t digits = k;
    while (k < code.size() && std::isdigit(static_cast<unsigned char>(code[k])) && n < 100000) n = n * 10 + (code[k++] - '0');
    if (k == digits || (k = space(k)) >= code.size() || code[k] != '=') continue;
    if ((n >= 100 && n <= 199) || (n >= 500 && n <= 999)) set.insert(static_cast<int>(n));
  }
  return {set.begin(), set.end()};
}

std::string variable_ranges(const std::vector<int>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size();) {
    std::size_t j = i;
    while (j + 1 < v.size() && v[j + 1] == v[j] + 1) ++j;
    s += fmt::format("{}#{}", s.empty() ? "" : ", ", v[i]);
    if (j > i) s += fmt::format("{}#{}", j == i + 1 ? ", " : "..", v[j]);
    i = j + 1;
  }
  return s;
}

void add_gen_command(CLI::App& app, GenArgs& a) {
  CLI::App* gen = app.add_subcommand("gen", "write a program for a curve within a guaranteed shape tolerance");
  gen->allow_extras();
  gen->add_option("curve", a.curve, "curve name (see --list) or expr");
  gen->add_flag("--list", a.list, "list the curves and their parameters");
  gen->add_option("--tol", a.tol, "shape tolerance, mm (default 0.005)")->check(positive_mm());
  gen->add_option("--form", a.form, "expanded, arcs, macro, adaptive-macro or cycle")
      ->check(one_of("a form", {"expanded", "arcs", "macro", "adaptive-macro", "cycle"}));
  gen->add_option("--lines", a.lines,
                  "expanded: equal-error (default: fewest lines, tolerance band), equal-error-chord, equal-step, "
                  "equal-chord or radial-error (the spiral paper's shape error along the ray from the centre)")
      ->check(one_of("a line method", {"equal-error", "equal-error-chord", "equal-step", "equal-chord", "radial-error"}));
  gen->add_option("--machine", a.machine,
                  "machine profile (TOML file, or a shipped one by name: fanuc-mill, fanuc-lathe, ...); default: "
                  "FANUC 3-axis mill")
      ->transform(profile_path());
  gen->add_option("--from", a.from, "start of the curve parameter t")->check(finite("a value of the curve parameter t"));
  gen->add_option("--to", a.to, "end of the curve parameter t")->check(finite("a value of the curve parameter t"));
  gen->add_option("--x", a.x, "expr: x(t)");
  gen->add_option("--y", a.y, "expr: y(t)");
  gen->add_option("--z", a.z, "expr: z(t)");
  gen->add_option("--t", a.t_range, "expr: range of t as FROM:TO");
  gen->add_option("--feed", a.feed, "feed, mm/min (mill) or mm/rev (lathe)")
      ->check(positive("a feed", "mm/min (mill) or mm/rev (lathe)"));
  gen->add_option("--depth", a.depth, "mill: depth of a plane contour below Z0, mm")->check(non_negative_mm());
  gen->add_option("--step-down", a.step_down, "mill: depth per pass for a plane contour, mm (default: one pass)")
      ->check(non_negative_mm());
  gen->add_option("--clearance", a.clearance, "mill: rapid plane above Z0; lathe: retract, mm")->check(positive_mm());
  gen->add_option("--program-number", a.program_number, "O number of the program")->check(whole(1, 9999));
  gen->add_option("--tool-radius", a.tool_radius,
                  "program the cutter centre (mill) or tool-nose centre (lathe) for this radius, mm")
      ->check(non_negative_mm());
  gen->add_option("--tip", a.tip,
                  "lathe: imaginary tool nose direction 0..9 (FANUC: 3 = outside turning towards the chuck); the "
                  "program follows that tip, 0 the nose centre")
      ->check(whole(0, 9));
  gen->add_option("--side", a.side, "left or right of the curve looking along it (G41 / G42 side); default left")
      ->check(one_of("a side", {"left", "right"}));
  gen->add_option("--cycle-program", a.cycle_program,
                  "cycle: the macro's program O9010..O9019 (G102..G111, No.6050..6059); default: the curve's own "
                  "(spiral 9010, ellipse 9011, parabola 9012, hyperbola 9013, involute 9014, sine 9015, cycloid 9016, "
                  "trochoid 9017, helix 9018, rotor and expr 9019)")
      ->check(whole(9010, 9019));
  gen->add_flag("--macro-only", a.macro_only,
                "cycle: write only the cycle's macro program (for the control's memory), not the calling program");
  gen->add_option("--tool", a.tool,
                  "call this tool before the contour: mill T_ M06 and G43 H_ at the clearance; lathe T_ with the "
                  "offset of the same number (T0101)")
      ->check(whole(1, 9999));
  gen->add_option("--spindle", a.spindle, "start the spindle at this speed, rev/min: S_ M03 (lathe: G97 S_ M03)")
      ->check(whole(1, 999999));
  gen->add_flag("--spindle-ccw", a.spindle_ccw, "turn the spindle counter-clockwise (M04 for M03)");
  gen->add_option("--css", a.css,
                  "lathe: constant surface speed, m/min (G96 S_ M03; ft/min in an inch program); clamp it with "
                  "--max-rpm")
      ->check(whole(1, 99999));
  gen->add_option("--max-rpm", a.max_rpm, "lathe with --css: the spindle clamp, rev/min (G50 S_; G92 S_ on G-code "
                                          "systems B and C)")
      ->check(whole(1, 999999));
  gen->add_flag("--coolant", a.coolant, "coolant on before the contour (M08), off at the end (M09)");
  gen->add_flag("--inch", a.inch,
                "write the program in inches (G20; coordinates and feeds in inches on the inch increment); the curve, "
                "--tol and the other lengths stay in mm, --feed in mm/min or mm/rev, --css in m/min");
  gen->add_option("--max-moves", a.max_moves,
                  "the most lines and arcs the program may make (all depth passes), default 200000; more is refused")
      ->check(whole(1, 100000000));
  gen->add_option("--plot", a.plot, "SVG plot of the curve, the path and the deviation along it");
  gen->add_option("-o,--output", a.output, "write the program here (statistics go to the terminal)");
  gen->add_flag("--json", a.json, "statistics as JSON");
  a.command = gen;
}

GenJob gen_job(const GenArgs& a, const std::vector<std::string>& extras, const std::string& command,
               const std::vector<std::string>& options) {
  gen::Options o;
  if (a.curve.empty()) throw std::runtime_error("name a curve (ncurve gen --list shows them) or expr");
  if (a.machine_text) o.profile = machine::parse_profile(*a.machine_text, a.machine);
  else if (!a.machine.empty()) o.profile = machine::load_profile(a.machine);
  gen::parse_form(a.form, o.form);
  if (a.lines == "equal-step") o.lines = geom::LineMethod::equal_step;
  else if (a.lines == "equal-chord") o.lines = geom::LineMethod::equal_chord;
  else if (a.lines == "equal-error-chord") o.lines = geom::LineMethod::equal_error_on_curve;
  else if (a.lines == "radial-error") o.lines = geom::LineMethod::radial_error;
  o.tol = a.tol;
  o.feed = a.feed;
  o.depth = a.depth;
  o.step_down = a.step_down;
  o.clearance = a.clearance;
  o.program_number = a.program_number;
  o.tool_radius = a.tool_radius;
  o.side = a.side == "right" ? gen::Side::right : gen::Side::left;
  o.tip = a.tip;
  o.cycle_program = a.cycle_program;
  o.tool = a.tool;
  o.spindle = a.spindle;
  o.spindle_ccw = a.spindle_ccw;
  o.css = a.css;
  o.max_rpm = a.max_rpm;
  o.coolant = a.coolant;
  o.inch = a.inch;
  o.max_moves = static_cast<std::size_t>(a.max_moves);
  gen::check_options(o);
  if (a.macro_only && o.form != gen::Form::cycle) throw std::runtime_error("--macro-only is for --form cycle");
  geom::Curve curve = build_curve({a.curve, a.x, a.y, a.z, a.t_range, a.from, a.to, command, options}, extras, o.profile);
  return GenJob{std::move(o), std::move(curve)};
}

nlohmann::json gen_json(const GenJob& job, const gen::Result& r, const std::string* program) {
  const auto& s = r.stats;
  const gen::Options& o = job.options;
  nlohmann::json j;
  j["curve"] = job.curve.name();
  j["form"] = gen::to_string(o.form);
  j["tolerance"] = o.tol;
  j["words"] = s.words;
  j["bytes"] = s.bytes;
  j["blocks"] = s.blocks;
  j["points"] = s.points;
  j["path_length"] = s.path_length;
  j["max_deviation"] = s.max_deviation;
  j["worst_t"] = s.worst_t;
  j["worst_point"] = s.worst_point;
  j["within_tolerance"] = r.within_tolerance;
  j["tool_radius"] = o.tool_radius;
  j["passes"] = s.passes;
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [key, value] : r.parameters) params[key] = value;
  j["parameters"] = params;
  if (program) j["program"] = *program;
  if (!r.macro.empty()) j["macro"] = r.macro;
  return j;
}

std::vector<std::string> gen_warnings(const GenJob& job) {
  std::vector<std::string> out;
  const gen::Options& o = job.options;
  if (const geom::CurveSpec* spec = geom::find_curve(job.curve.name()); spec && spec->lathe && !o.profile.lathe())
    out.push_back(fmt::format(
        "{} is a lathe curve; without a lathe profile this is a mill program (its X and Z on the mill's X and Z, X as "
        "a radius). For the lathe program (G18, X as a diameter, feed per revolution) give --machine "
        "profiles/fanuc-lathe.toml",
        spec->name));
  if (o.css > 0 && o.max_rpm == 0 && o.profile.lathe())
    out.push_back("--css without --max-rpm: no spindle clamp, the spindle speeds up without limit as X nears 0");
  return out;
}

int gen_command(const GenArgs& a) {
  if (a.list) {
    std::cout << list_curves();
    return 0;
  }
  std::optional<GenJob> job;
  try {
    job.emplace(gen_job(a, a.command->remaining(), "ncurve gen", long_options(*a.command)));
  } catch (const std::bad_alloc&) {
    throw;  // main() says what ran out
  } catch (const std::exception& e) {
    std::cerr << "ncurve gen: " << e.what() << "\n";
    return 2;
  }
  const gen::Options& o = job->options;
  const geom::Curve* curve = &job->curve;

  for (const std::string& w : gen_warnings(*job)) std::cerr << "ncurve gen: warning: " << w << "\n";
  gen::Result r;
  try {
    r = gen::generate(*curve, o);
  } catch (const base::BoundExceeded& e) {
    std::cerr << "ncurve gen: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    throw;  // main() says what ran out
  } catch (const std::exception& e) {
    std::cerr << "ncurve gen: " << e.what() << "\n";
    return 1;
  }
  const std::string& program = a.macro_only ? r.macro : r.text;
  // "-o -" is the default: the program to standard output, the statistics to the terminal
  const std::string output = a.output == "-" ? std::string() : a.output;
  const std::vector<std::string> inputs{a.machine_text ? std::string() : a.machine};
  if (!output.empty() && !save(output, program, inputs)) return 2;
  const auto& s = r.stats;
  if (!a.plot.empty() && !save(a.plot, gen::plot_svg(r.cutter_centre ? *r.cutter_centre : *curve, o, s), inputs)) return 2;
  const GenTimes times = gen_times(*job, r);
  const std::vector<int> commons = common_variables_set(r.text);
  if (a.json) {
    nlohmann::json j = gen_json(*job, r, output.empty() ? &program : nullptr);
    add_gen_times(j, times, r.text);
    std::cout << j.dump(2) << "\n";
  } else {
    if (output.empty()) std::cout << program;
    std::ostream& out = output.empty() ? std::cerr : std::cout;
    out << fmt::format(
        "curve {} (t {:.6g}..{:.6g}), form {}, tolerance {} mm\n"
        "  words {}, bytes {}, blocks {}, cutter-location points {}\n"
        "  path length {:.4f} mm, max deviation {:.6f} mm at t = {:.6g} (round trip through the interpreter)\n",
        curve->name(), curve->t0(), curve->t1(), gen::to_string(o.form), o.tol, s.words, s.bytes, s.blocks, s.points,
        s.path_length, s.max_deviation, s.worst_t);
    if (s.passes > 1)
      out << fmt::format("  {} depth passes of at most {} mm to Z-{}, each measured (the figures above are the last)\n",
                         s.passes, o.step_down, o.depth);
    if (times.form)
      out << fmt::format("  cycle time {:.1f} s on {} ({} full stops, {} macro statements; ncurve analyze's estimate)"
                         "{}\n",
                         times.form->seconds, o.profile.name, times.form->stops, times.form->macro_statements,
                         times.expanded ? fmt::format(", {:.1f} s as --form expanded", times.expanded->seconds) : "");
    if (!commons.empty())
      out << fmt::format("  common variables it sets: {} (what they held before the program is lost)\n",
                         variable_ranges(commons));
    for (const auto& [key, value] : r.parameters)
      out << fmt::format("  set parameter No.{} = {} on the control (ncurve run ... --param {}={})\n", key, value, key,
                         value);
  }
  if (const std::string w = slower_warning(*job, times); !w.empty()) std::cerr << "ncurve gen: warning: " << w << "\n";
  if (!r.within_tolerance) {
    std::cerr << fmt::format(
        "ncurve gen: error: the program deviates {:.6f} mm from the curve at t = {:.6g} (X {:.4f} Y {:.4f} Z {:.4f}), "
        "more than the tolerance {} mm\n",
        s.max_deviation, s.worst_t, s.worst_point[0], s.worst_point[1], s.worst_point[2], o.tol);
    return 1;
  }
  return 0;
}

}  // namespace ncurve::app
