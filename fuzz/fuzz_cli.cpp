// libFuzzer target: any bytes as a command line (arguments separated by NUL bytes, the first the
// command), parsed by the CLI11 set-up of `ncurve` (src/app/cli.cpp) with every option's checks;
// nothing is run but the manual page and the completion script, which read the set-up alone.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/cli_docs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncurve;
  std::vector<std::string> args{"ncurve"};
  std::string arg;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0) {
      args.push_back(arg);
      arg.clear();
    } else {
      arg += static_cast<char>(data[i]);
    }
  }
  args.push_back(arg);
  if (args.size() > 64) return 0;
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  const int argc = static_cast<int>(args.size());

  CLI::App app{app::kDescription};
  app::Commands c;
  app::add_commands(app, c);
  if (!app::not_a_command(app, argc, argv.data()).empty()) return 0;
  try {
    app.parse(argc, argv.data());
  } catch (const CLI::ParseError& e) {
    std::ostringstream out, err;
    (void)app.exit(e, out, err);  // the message as a user sees it
    return 0;
  }
  if (c.completion->parsed()) (void)app::bash_completion(app);
  if (c.man->parsed()) (void)app::man_page(app, "fuzz");
  return 0;
}
