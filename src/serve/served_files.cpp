#include "serve/served_files.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string_view>

namespace ncurve::serve {

namespace {
namespace fs = std::filesystem;

// a file the page's Open would take as a part program (workbench.html's accept list)
bool program_name(const fs::path& p) {
  static constexpr std::array<std::string_view, 10> kExtensions{".nc",  ".cnc", ".tap", ".txt", ".ncc",
                                                                ".iso", ".eia", ".ptp", ".prg", ".gcode"};
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return p.filename().string().front() != '.' && std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end();
}

// a folder's programs by name; none is an error (a folder given is meant to offer some)
std::vector<std::string> folder_programs(const std::string& folder) {
  std::vector<std::string> found;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec))
    if (e.is_regular_file(ec) && program_name(e.path())) found.push_back(e.path().string());
  if (ec) throw std::runtime_error(folder + " cannot be read (" + ec.message() + ")");
  if (found.empty())
    throw std::runtime_error(folder + " holds no part program (.nc .cnc .tap .txt .ncc .iso .eia .ptp .prg .gcode)");
  std::sort(found.begin(), found.end(),
            [](const std::string& a, const std::string& b) { return fs::path(a).filename() < fs::path(b).filename(); });
  return found;
}
}  // namespace

std::vector<std::string> served_files(const std::vector<std::string>& given) {
  std::vector<std::string> files;
  for (const std::string& f : given) {
    struct stat st {};
    const bool exists = ::stat(f.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) {
      for (std::string& p : folder_programs(f)) files.push_back(std::move(p));
      continue;
    }
    if (!exists || !S_ISREG(st.st_mode))  // a FIFO or device would block its reader
      throw std::runtime_error(f + " is not a regular file (a FIFO, a device or a socket cannot be served)");
    files.push_back(f);
  }
  std::set<std::string> names;
  for (const std::string& f : files)
    if (!names.insert(fs::path(f).filename().string()).second)
      throw std::runtime_error("two files named " + fs::path(f).filename().string() + ": the page opens files by name");
  for (std::size_t i = 0, n = files.size(); i < n; ++i) {
    const fs::path p(files[i]);
    if (p.extension() != ".nc") continue;
    const fs::path setup = p.parent_path() / (p.stem().string() + ".setup.toml");
    std::error_code ec;
    if (fs::is_regular_file(setup, ec) && names.insert(setup.filename().string()).second) files.push_back(setup.string());
  }
  return files;
}

}  // namespace ncurve::serve
