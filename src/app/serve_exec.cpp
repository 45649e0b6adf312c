#include "app/serve_exec.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>

namespace ncurve::app {

int exec_serve(char** argv) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::string server = (ec ? std::filesystem::path(argv[0]) : self).parent_path() / "ncurve-serve";
  ::execv(server.c_str(), argv);
  std::cerr << "ncurve serve: error: cannot start " << server << " (" << std::strerror(errno)
            << "): the workbench server is the program ncurve-serve, installed beside ncurve\n";
  return 2;
}

}  // namespace ncurve::app
