#include "app/run_verify.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "io/output_file.hpp"
#include "sim/part_stl.hpp"

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
}

RunVerification::RunVerification(const VerifyArgs& args, const machine::MachineProfile& profile,
                                 const machine::ProgramLibrary& lib, const machine::RunOptions& options)
    : args_(args) {
  if (!args.setup.empty()) {
    setup_ = sim::read_setup(args.setup);
    report_.setup_file = args.setup;
  }
  const sim::SetupFile* given = args.setup.empty() ? nullptr : &setup_;
  report_.defaults = sim::setup_defaults(given);
  if (profile.lathe()) {
    report_.refused = "a lathe's material removal is not simulated yet";
    if (!args.part.empty()) throw std::runtime_error("--part: " + report_.refused);
    return;
  }
  tools_ = std::make_unique<sim::MillTools>(setup_.tools, profile);
  std::optional<sim::Stock> stock = setup_.stock;
  if (!stock) {  // a first run finds the box around the cutting moves
    sim::DefaultStockBox finder([this](int t, int d) { return tools_->radius(t, d); }, setup_.tool_in_spindle.value_or(0));
    machine::Interpreter first(profile, lib, options);
    first.run(finder);
    if (const auto box = finder.box(); box && box->max[0] > box->min[0] && box->max[1] > box->min[1]) stock = *box;
    report_.stock_default = true;
  }
  if (!stock) {
    report_.refused = "no default stock: the program makes no cutting move with a tool of known size (give the "
                      "stock and the tools in a setup file, --setup)";
    if (!args.part.empty()) throw std::runtime_error("--part: " + report_.refused);
    return;
  }
  report_.stock = stock;
  if (std::holds_alternative<sim::StlFile>(*stock)) {
    report_.refused = "an STL stock is not simulated yet: give a box or a cylinder";
    if (!args.part.empty()) throw std::runtime_error("--part: " + report_.refused);
    return;
  }
  sim::VerifyOptions vo;
  vo.cell = args.resolution;
  try {
    verifier_ = std::make_unique<sim::Verifier>(*stock, *tools_, setup_.tool_in_spindle, vo, setup_.fixtures);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(fmt::format("--verify: {} (--resolution {:g} mm)", e.what(), args.resolution));
  }
  report_.verifier = verifier_.get();
}

RunVerification::~RunVerification() = default;

machine::MoveSink* RunVerification::sink() { return verifier_.get(); }

void RunVerification::finish(machine::RunResult& result) {
  if (tools_)
    for (const auto& [number, tool] : tools_->used())
      report_.tools.push_back(tool ? sim::describe(number, tool->tool) +
                                         (tool->from_library ? "" : " (default: the D offset in force)")
                                   : fmt::format("T{}: not in the library and no D offset in force when it cut: not cut",
                                                 number));
  if (!verifier_) return;
  report_.fixtures = verifier_->fixtures_checked();
  for (const sim::Finding& f : verifier_->findings()) result.warnings.push_back(f.diagnostic);
}

void RunVerification::write_part(const std::vector<std::string>& inputs) {
  if (args_.part.empty() || !verifier_) return;
  io::OutputFile file(args_.part, inputs);
  sim::write_part_stl(verifier_->map(), file.stream());
  file.commit();
  report_.part_file = args_.part;
}

}  // namespace ncurve::app
