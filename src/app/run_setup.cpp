#include "app/run_setup.hpp"

#include <fmt/format.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "app/cli_checks.hpp"
#include "base/bounds.hpp"
#include "app/shipped.hpp"

namespace ncurve::app {
namespace {

std::pair<int, double> parse_set(const std::string& s) {
  auto eq = s.find('=');
  auto bad = [&] { return std::runtime_error(fmt::format("--set: '{}' is not of the form #100=5", s)); };
  if (s.empty() || s[0] != '#' || eq == std::string::npos) throw bad();
  try {
    std::size_t used = 0;
    int n = std::stoi(s.substr(1, eq - 1), &used);
    if (used != eq - 1) throw bad();
    std::string value = s.substr(eq + 1);
    double v = std::stod(value, &used);
    if (used != value.size()) throw bad();
    return {n, v};
  } catch (const std::logic_error&) {
    throw bad();
  }
}

// All of standard input, or an error: never a program cut short where memory ran out.
std::string read_standard_input() {
  std::string text;
  std::size_t size = 0;
  try {
    struct stat st{};  // a file redirected in: read at its size, not by doubling
    if (::fstat(STDIN_FILENO, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0)
      text.resize(static_cast<std::size_t>(st.st_size) + (1u << 16));
    for (;;) {
      if (text.size() - size < (1u << 16)) text.resize(std::max<std::size_t>(text.size() * 2, 1u << 20));
      const ssize_t got = ::read(STDIN_FILENO, text.data() + size, text.size() - size);
      if (got == 0) break;
      if (got < 0) {
        if (errno == EINTR) continue;
        throw std::runtime_error(fmt::format("cannot read the program from standard input: {}", std::strerror(errno)));
      }
      size += static_cast<std::size_t>(got);
    }
    text.resize(size);
  } catch (const std::bad_alloc&) {
    throw std::runtime_error(fmt::format("out of memory reading standard input ({} MB read): the program was not run; "
                                         "give it as a file",
                                         size >> 20));
  }
  return text;
}

}  // namespace

void apply_parameters(machine::MachineProfile& profile, const std::vector<std::string>& params) {
  for (const auto& p : params) {
    auto eq = p.find('=');
    std::size_t used = 0;
    double v = 0;
    try {
      if (eq == std::string::npos) throw std::invalid_argument(p);
      v = std::stod(p.substr(eq + 1), &used);
      if (used != p.size() - eq - 1) throw std::invalid_argument(p);
    } catch (const std::logic_error&) {
      throw std::runtime_error(fmt::format("--param: '{}' is not of the form 6050=102", p));
    }
    try {
      machine::set_parameter(profile, p.substr(0, eq), v);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(fmt::format("--param: {}", e.what()));
    }
  }
}

void add_run_inputs(CLI::App* cmd, RunInputs& in, bool program_required, bool folder_ok) {
  auto* program = cmd->add_option("program", in.program,
                                  folder_ok ? "part program (.nc); - reads it from standard input; more programs, or a "
                                              "folder of them: each run on its own, a table of the results"
                                            : "part program (.nc); - reads it from standard input")
                      ->check(folder_ok ? input_file() | CLI::ExistingDirectory : input_file());
  if (program_required) program->required();
  cmd->add_option("--machine", in.machine,
                  "machine profile (TOML file, or a shipped one by name: fanuc-mill, fanuc-lathe, ...); default: "
                  "FANUC 3-axis mill, factory parameters")
      ->transform(profile_path());
  cmd->add_option("--lib", in.libs,
                  "folder of macro programs (O9010.nc, ...), or `macros` for the shipped custom cycles; may be "
                  "repeated")
      ->transform(folder_path())
      ->allow_extra_args(false);
  cmd->add_option("--param", in.params,
                  "set a control parameter over the profile's, e.g. --param 6050=102 (G102 calls O9010); may be "
                  "repeated")
      ->allow_extra_args(false);
  cmd->add_option("--set", in.sets, "preset a variable before the run, e.g. --set \"#100=5\"; may be repeated")
      ->allow_extra_args(false);
  cmd->add_flag("--nose-centre", in.nose_centre,
               "lathe: write the tool-nose centre's path, not the imaginary tip's that the control commands");
  cmd->add_option("--max-steps", in.max_steps,
                  "stop a program that has not ended after this many steps (a block is one, an expression one "
                  "an operation; default 200000000)")
      ->check(whole(1, 1'000'000'000'000'000L));
  cmd->add_option("--max-seconds", in.max_seconds,
                  "stop a program that has not ended after this many seconds of running (default 60; 0: no limit)")
      ->check(non_negative("a time", "s"));
  cmd->add_option("--max-memory", in.max_memory_mb,
                  "refuse a program file that would take more than this many MB of memory once read whole (default: "
                  "ten times its size, at least 256); run reads such a file as a stream instead")
      ->check(CLI::Range(1.0, 1e9));
}

RunSetup prepare_run(const RunInputs& in) {
  RunSetup s;
  s.options.max_steps = in.max_steps;
  s.options.max_seconds = in.max_seconds;
  s.options.nose_centre = in.nose_centre;
  for (const auto& v : in.sets) s.options.presets.push_back(parse_set(v));
  if (in.machine_text) s.profile = machine::parse_profile(*in.machine_text, in.machine);
  else if (!in.machine.empty()) s.profile = machine::load_profile(in.machine);
  apply_parameters(s.profile, in.params);
  nc::ParseOptions parse_options = s.profile.parse_options();
  parse_options.max_memory = static_cast<std::size_t>(in.max_memory_mb * 1e6);
  s.lib = std::make_unique<machine::ProgramLibrary>(parse_options);
  if (in.text) {
    s.problems = s.lib->add_text(in.program, *in.text, true);
  } else if (in.stream) {
    std::size_t chunk = nc::ProgramStream::kChunkBytes;
    if (const char* bytes = std::getenv("NCURVE_STREAM_CHUNK"))  // tests read in tiny pieces
      chunk = std::max<std::size_t>(std::strtoull(bytes, nullptr, 10), 1);
    s.lib->add_streamed(in.program, in.program == "-" ? "<stdin>" : in.program, chunk);
  } else if (in.program == "-") {
    s.problems = s.lib->add_text("<stdin>", read_standard_input(), true);
  } else {
    s.problems = s.lib->add_file(in.program, true);
  }
  for (const auto& dir : in.libs) {
    auto more = s.lib->add_folder(dir);
    s.problems.insert(s.problems.end(), more.begin(), more.end());
  }
  for (const auto& f : s.lib->files()) s.inputs.push_back(f->name());
  if (!in.machine_text && !in.machine.empty()) s.inputs.push_back(in.machine);
  if (!s.lib->streamed()) complete_problems(s);
  return s;
}

RunSetup prepare_run_of_any_size(RunInputs in) {
  std::error_code ec;
  if (!in.text && in.program != "-" && std::filesystem::is_regular_file(in.program, ec) &&
      std::filesystem::file_size(in.program, ec) >= kStreamFrom)
    in.stream = true;
  try {
    return prepare_run(in);
  } catch (const base::BoundExceeded&) {  // too large to hold read whole
    if (in.stream || in.text || in.program == "-") throw;
    in.stream = true;
    return prepare_run(in);
  }
}

void complete_problems(RunSetup& s) {
  if (s.lib->streamed()) s.problems = s.lib->streamed_problems();
  s.problems_left_out = s.lib->problems_left_out();
  s.unchecked_lines = s.lib->unchecked_lines();
  if (s.problems.size() > nc::kMaxDiagnostics) {  // the first hundred of all files together
    s.problems_left_out += s.problems.size() - nc::kMaxDiagnostics;
    s.problems.resize(nc::kMaxDiagnostics);
  }
}

report::RunReport run_report(const RunSetup& s, std::string source, const machine::RunResult& result,
                             const report::VerifyReport* verify) {
  report::RunReport rep;
  rep.source = std::move(source);
  rep.profile = &s.profile;
  rep.result = &result;
  rep.stats = report::source_stats(*s.lib, s.lib->main()->file.get());
  rep.text_problems = s.problems;
  rep.text_problems_left_out = s.problems_left_out;
  rep.unchecked_lines = s.unchecked_lines;
  rep.verify = verify;
  return rep;
}

}  // namespace ncurve::app
