#include "app/run_verify.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "gen/generate.hpp"
#include "io/output_file.hpp"
#include "report/path_plot.hpp"
#include "sim/mesh_top.hpp"
#include "sim/stl_read.hpp"
#include "sim/part_stl.hpp"
#include "sim/stl.hpp"

namespace ncurve::app {

void add_verify_options(CLI::App* run, VerifyArgs& a) {
  run->add_option("--setup", a.setup, "the stock, fixtures and tool library (TOML, docs/setup.md); turns on --verify")
      ->check(CLI::ExistingFile);
  run->add_flag("--verify", a.verify,
                "cut the stock with the moves and report what goes wrong (a rapid through material, a cut deeper "
                "than the flutes, ...); without --setup the stock is the box around the cutting moves");
  run->add_option("--resolution", a.resolution, "the Z-map's cell size, mm (default: the stock's shorter side in 1000 cells)")
      ->check(CLI::Range(1e-4, 1e4));
  run->add_option("--part", a.part, "write the cut part as a binary STL file (turns on --verify)");
  add_curve_options(run, a.curve,
                    "measure the cut part's walls against this curve, a name of `ncurve gen --list` (its parameters "
                    "as --NAME VALUE) or expr; turns on --verify");
  run->add_option("--tol", a.tol,
                  "--curve, --design: a wall or surface beyond the design or short of it by more is a finding, mm "
                  "(default 0.01)")
      ->check(CLI::Range(1e-6, 1e3));
  run->add_option("--design", a.design,
                  "a mill: the design solid (STL, mm); warn where the cut gouges it or leaves stock on it beyond "
                  "--tol (turns on --verify)")
      ->check(CLI::ExistingFile);
  add_wall_option(run, a.wall);
  run->add_option("--max-moves", a.max_moves, "--curve: the most cuts kept for measuring the walls (about 150 bytes each), default 1000000")
      ->check(CLI::Range(1.0, 1e9));
}

void add_wall_option(CLI::App* cmd, std::string& wall) {
  cmd->add_option("--wall", wall,
                  "--curve: the design's walls: groove (the tool's axis was to follow the curve), edge (the curve is "
                  "the part's edge, a G41/G42 contour) or auto (edge when the program compensates; the default)")
      ->check(CLI::IsMember({"auto", "groove", "edge"}));
}

namespace {

// The run before the one that cuts: the default stock box, and the first move that turns a rotary
// axis (the Z-map is of 3 axes).
class FirstPass final : public machine::MoveSink {
public:
  explicit FirstPass(sim::DefaultStockBox& box) : box_(box) {}
  void on_move(const machine::Move& m) override {
    box_.on_move(m);
    if (rotary_line_ || !m.is_motion()) return;
    for (int a = 3; a < machine::kAxes; ++a)
      if (m.start[a] != m.end[a]) {
        rotary_axis_ = "ABC"[a - 3];
        rotary_line_ = m.line;
        rotary_file_ = m.file;
        return;
      }
  }
  std::string rotary() const {
    if (!rotary_line_) return {};
    return fmt::format("the program turns the {} axis ({}:{} first): the material removal is of 3 axes, a "
                       "rotary-axis program is not simulated yet",
                       rotary_axis_, rotary_file_ ? rotary_file_->name() : "", rotary_line_);
  }

private:
  sim::DefaultStockBox& box_;
  char rotary_axis_ = 0;
  std::uint32_t rotary_line_ = 0;
  const nc::SourceFile* rotary_file_ = nullptr;
};

// A lathe's default bar: about the spindle axis, out to the largest radius a cutting move starts
// from, its face at the largest Z one starts from, as long as the cuts go towards the chuck.
class DefaultBar final : public machine::MoveSink {
public:
  void on_move(const machine::Move& m) override {
    if (m.kind != machine::MoveKind::line && m.kind != machine::MoveKind::arc) return;
    radius_ = std::max(radius_, m.start[0]);
    face_ = std::max(face_, m.start[2]);
    low_ = std::min({low_, m.start[2], m.end[2]});
    any_ = true;
  }
  std::optional<sim::Cylinder> bar() const {
    if (!any_ || !(radius_ > 0) || !(face_ > low_)) return std::nullopt;
    sim::Cylinder c;
    c.diameter = 2 * radius_;
    c.face = face_;
    c.length = face_ - low_;
    return c;
  }

private:
  double radius_ = 0, face_ = -1e300, low_ = 1e300;
  bool any_ = false;
};

}  // namespace

RunVerification::RunVerification(const VerifyArgs& args, const machine::MachineProfile& profile,
                                 const machine::ProgramLibrary& lib, const machine::RunOptions& options)
    : args_(args) {
  if (args.setup_text) {
    setup_ = sim::parse_setup(*args.setup_text, args.setup.empty() ? "<setup>" : args.setup);
    report_.setup_file = args.setup.empty() ? "<setup>" : args.setup;
    // a setup sent as text (the server's) may name no file to be read
    bool stl = setup_.stock && std::holds_alternative<sim::StlFile>(*setup_.stock);
    for (const sim::Fixture& f : setup_.fixtures) stl = stl || std::holds_alternative<sim::StlFile>(f.shape);
    if (stl)
      throw std::runtime_error(fmt::format("{}: error: an STL stock or fixture names a file, and a setup sent as text "
                                           "reads none (give a box)",
                                           report_.setup_file));
  } else if (!args.setup.empty()) {
    setup_ = sim::read_setup(args.setup);
    report_.setup_file = args.setup;
  }
  const sim::SetupFile* given = report_.setup_file.empty() ? nullptr : &setup_;
  report_.defaults = sim::setup_defaults(given, profile.lathe());
  // nothing verified, and why; --part cannot be made then
  auto refuse = [&](const std::string& why) {
    report_.refused = why;
    if (!args.part.empty()) throw std::runtime_error("--part: " + why);
    if (!args.design.empty()) throw std::runtime_error("--design: " + why);
  };
  if (!args.curve.name.empty()) {
    try {
      curve_.emplace(build_curve(args.curve, args.curve_extras, profile));
      if (profile.lathe()) {  // as `gen` and `analyze` place a profile on a lathe
        gen::Options go;
        go.profile = profile;
        place_ = gen::axis_map(*curve_, go);
      }
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("--curve: ") + e.what());
    }
  }
  if (!args.design.empty() && profile.lathe())
    throw std::runtime_error("--design: the check against a design is a mill's (on its Z-map), not a lathe's yet");
  std::optional<sim::Mesh> design;  // read before the runs: its errors first
  if (!args.design.empty()) design = sim::read_stl(args.design);
  if (profile.lathe()) {
    lathe(profile, lib, options, refuse);
    return;
  }
  tools_ = std::make_unique<sim::MillTools>(setup_.tools, profile);
  std::optional<sim::Stock> stock = setup_.stock;
  const bool rotary_axes = profile.axes.find_first_of("ABC") != std::string::npos;
  if (!stock || rotary_axes) {  // a first run finds the box around the cutting moves, and a rotary axis turned
    sim::DefaultStockBox finder([this](int t, int d) { return tools_->radius(t, d); }, setup_.tool_in_spindle.value_or(0));
    FirstPass pass(finder);
    machine::Interpreter first(profile, lib, options);
    first.run(pass);
    if (const std::string why = pass.rotary(); !why.empty()) {
      refuse(why);
      return;
    }
    if (const auto box = finder.box(); !stock && box && box->max[0] > box->min[0] && box->max[1] > box->min[1]) {
      stock = *box;
      report_.stock_default = true;
    }
  }
  if (!stock) {
    refuse("no default stock: the program makes no cutting move with a tool of known size (give the stock and the "
           "tools in a setup file, --setup)");
    return;
  }
  report_.stock = stock;
  sim::VerifyOptions vo;
  vo.cell = args.resolution;
  vo.most_cells = args.most_cells;
  if (args.cells > 0) vo.min_cells = args.cells;
  vo.cut_moves = args.cut_moves;
  vo.profile = &profile;
  vo.mark_cells = design.has_value();
  vo.check_reference = !report_.stock_default;
  try {
    verifier_ = std::make_unique<sim::Verifier>(*stock, *tools_, setup_.tool_in_spindle, vo, setup_.fixtures);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(fmt::format("--verify: {}: a coarser --resolution (it is {})", e.what(),
                                         args.resolution > 0 ? fmt::format("{:g} mm", args.resolution)
                                                             : std::string("the stock's shorter side in 1000 cells")));
  }
  report_.verifier = verifier_.get();
  if (curve_) {
    cuts_ = std::make_unique<sim::CutLog>(args.max_moves);
    verifier_->log_cuts(cuts_.get());
  }
  if (design) design_top_ = sim::mesh_top(*design, verifier_->map());
}

RunVerification::~RunVerification() = default;

std::vector<std::string> RunVerification::stl_files() const {
  std::vector<std::string> out;
  if (setup_.stock)
    if (const auto* s = std::get_if<sim::StlFile>(&*setup_.stock)) out.push_back(s->path);
  for (const sim::Fixture& f : setup_.fixtures)
    if (const auto* s = std::get_if<sim::StlFile>(&f.shape)) out.push_back(s->path);
  if (!args_.design.empty()) out.push_back(args_.design);
  return out;
}

void RunVerification::lathe(const machine::MachineProfile& profile, const machine::ProgramLibrary& lib,
                            const machine::RunOptions& options, const std::function<void(const std::string&)>& refuse) {
  std::optional<sim::Stock> stock = setup_.stock;
  if (!stock) {  // a first run finds the bar round the cutting moves
    DefaultBar bar;
    machine::Interpreter first(profile, lib, options);
    first.run(bar);
    if (const auto c = bar.bar()) {
      stock = *c;
      report_.stock_default = true;
    }
  }
  if (!stock) {
    refuse("no default stock: the program makes no cutting move (give the stock in a setup file, --setup)");
    return;
  }
  report_.stock = stock;
  const auto* bar = std::get_if<sim::Cylinder>(&*stock);
  if (!bar) {
    refuse("a lathe's stock is a cylinder or a tube (shape = \"cylinder\" or \"tube\")");
    return;
  }
  section_ = std::make_unique<sim::LatheSection>(*bar);
  sim::LatheSinkOptions so;
  so.profile = &profile;
  so.fixtures = setup_.fixtures;
  so.cut_moves = args_.cut_moves;
  section_sink_ = std::make_unique<sim::LatheSectionSink>(*section_, setup_.tools, profile.lathe_offsets,
                                                          setup_.tool_in_spindle, so);
  report_.section = section_.get();
  report_.section_sink = section_sink_.get();
  if (curve_) {  // the feed moves kept to name the block of a wall
    profile_moves_ = std::make_unique<sim::ProfileMoves>();
    lathe_tee_ = std::make_unique<report::TeeSink>(*section_sink_, *profile_moves_);
  }
  report_.fixtures = section_sink_->fixtures_checked();
}

machine::MoveSink* RunVerification::sink() {
  if (lathe_tee_) return lathe_tee_.get();
  if (section_sink_) return section_sink_.get();
  return verifier_.get();
}

void RunVerification::finish(machine::RunResult& result) {
  if (tools_)
    for (const auto& [number, tool] : tools_->used())
      report_.tools.push_back(tool ? sim::describe(number, tool->tool) +
                                         (tool->from_library ? "" : " (default: the D offset in force)")
                                   : fmt::format("T{}: not in the library and no D offset in force when it cut: not cut",
                                                 number));
  if (section_sink_)  // a lathe's turret: the tools that cut
    for (const auto& [number, volume] : section_sink_->volume_by_tool()) {
      const auto it = setup_.tools.tools.find(number);
      report_.tools.push_back(it != setup_.tools.tools.end()
                                  ? sim::describe(number, it->second)
                                  : fmt::format("T{}: not in the library: the insert of its offset's nose radius and tip",
                                                number));
    }
  if (section_sink_)
    for (const sim::Finding& f : section_sink_->findings()) result.warnings.push_back(f.diagnostic);
  if (section_sink_ && curve_) measure_walls(result);
  if (!verifier_) return;
  report_.fixtures = verifier_->fixtures_checked();
  for (const sim::Finding& f : verifier_->findings()) result.warnings.push_back(f.diagnostic);
  if (!args_.design.empty()) {
    const sim::ZMap& map = verifier_->map();
    design_ = sim::check_design({&map, design_top_, map.cut_by(), verifier_->cut_blocks(), verifier_->last_block(),
                                 args_.design, args_.tol});
    for (const sim::Finding& f : design_->findings) result.warnings.push_back(f.diagnostic);
    report_.design = &*design_;
    report_.design_file = args_.design;
  }
  if (curve_) measure_walls(result);
}

// The part's walls against the curve: a mill's from the cuts kept, a lathe's turned surface from its
// section.
void RunVerification::measure_walls(machine::RunResult& result) {
  report::CurveCheck& check = report_.curve.emplace();
  check.curve = curve_->name();
  check.tol = args_.tol;
  check.block = section_ ? profile_moves_->block() : sim::block_of(*cuts_);
  sim::WallOptions o;
  o.tol = args_.tol;
  o.design = section_ || args_.wall == "edge" || (args_.wall == "auto" && cuts_->any_compensated())
                 ? sim::WallDesign::edge
                 : sim::WallDesign::groove;
  if (verifier_) {
    o.top = verifier_->map().stock().max[2];
    if (verifier_->counts().cut == 0) {
      check.refused = "no move was cut: no tool in the spindle, or none of known size (tool_in_spindle and "
                      "[tools.N] in a setup file, --setup)";
      return;
    }
  }
  try {
    walls_ = section_ ? sim::measure_section_walls(*section_, *profile_moves_, *curve_, place_, o)
                      : sim::measure_walls(*cuts_, *curve_, o);
  } catch (const std::runtime_error& e) {
    check.refused = e.what();
    return;
  }
  check.walls = &*walls_;
  check.findings = sim::wall_findings(check.block, *walls_, args_.tol);
  for (const sim::Finding& f : check.findings) result.warnings.push_back(f.diagnostic);
}

void RunVerification::write_part(const std::vector<std::string>& inputs) {
  if (args_.part.empty() || (!verifier_ && !section_)) return;
  io::OutputFile file(args_.part, inputs);
  if (verifier_) sim::write_part_stl(verifier_->map(), file.stream());
  else sim::write_stl(file.stream(), section_->mesh(), "ncurve part: the bar's half-section cut and revolved");
  file.commit();
  report_.part_file = args_.part;
}

}  // namespace ncurve::app
