#include "app/shipped.hpp"
#include "app/cli_docs.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace ncurve::app {
namespace fs = std::filesystem;
namespace {

bool holds_shipped_files(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "profiles", ec) && fs::is_directory(dir / "macros", ec);
}

std::string& chosen_dir() {
  static std::string dir;
  return dir;
}

}  // namespace

void set_shipped_dir(std::string dir) { chosen_dir() = std::move(dir); }

std::optional<std::string> shipped_dir() {
  std::error_code ec;
  if (const std::string& dir = chosen_dir(); !dir.empty())
    return holds_shipped_files(dir) ? std::optional(fs::weakly_canonical(dir, ec).string()) : std::nullopt;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  fs::path bin = exe.parent_path();
  for (const fs::path& dir : {bin.parent_path() / "share" / "ncurve", bin.parent_path()})
    if (holds_shipped_files(dir)) return fs::weakly_canonical(dir, ec).string();
  return std::nullopt;
}

std::vector<std::string> shipped_profiles() {
  std::vector<std::string> names;
  if (auto dir = shipped_dir()) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(fs::path(*dir) / "profiles", ec))
      if (e.path().extension() == ".toml") names.push_back(e.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string find_profile(const std::string& name) {
  std::error_code ec;
  if (fs::is_regular_file(name, ec)) return name;
  auto dir = shipped_dir();
  if (dir && name.find('/') == std::string::npos) {
    for (const std::string& file : {name, name + ".toml"}) {
      fs::path p = fs::path(*dir) / "profiles" / file;
      if (fs::is_regular_file(p, ec)) return p.string();
    }
  }
  std::vector<std::string> names = shipped_profiles();
  if (names.empty()) throw std::runtime_error(fmt::format("no profile file '{}'", name));
  std::string near = nearest(name, names);
  throw std::runtime_error(fmt::format("no profile file '{}' and no shipped profile of that name{} (shipped: {})",
                                       name, near.empty() ? "" : fmt::format("; did you mean {}?", near),
                                       fmt::join(names, ", ")));
}

std::string find_folder(const std::string& name) {
  std::error_code ec;
  if (fs::is_directory(name, ec)) return name;
  auto dir = shipped_dir();
  if (dir && name.find('/') == std::string::npos && fs::is_directory(fs::path(*dir) / name, ec))
    return (fs::path(*dir) / name).string();
  throw std::runtime_error(fmt::format("no folder '{}'", name));
}

namespace {
// A transform that replaces the value by what `find` makes of it, or fails with find's message.
CLI::Validator resolving(std::string (*find)(const std::string&), const char* type, const char* name) {
  return CLI::Validator(
      [find](std::string& value) -> std::string {
        try {
          value = find(value);
          return {};
        } catch (const std::runtime_error& e) {
          return e.what();
        }
      },
      type, name);
}
}  // namespace

CLI::Validator profile_path() { return resolving(find_profile, "PROFILE", "profile"); }
CLI::Validator folder_path() { return resolving(find_folder, "DIR", "folder"); }

CLI::Validator input_file() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        std::error_code ec;
        if (value == "-" || fs::is_regular_file(value, ec)) return {};
        if (fs::exists(value, ec)) return fmt::format("'{}' is not a file", value);
        return fmt::format("no file '{}'", value);
      },
      "FILE", "input file");
}

}  // namespace ncurve::app
