// GET /api/profiles, GET /api/files, GET /api/files/NAME, the page at GET / and its files at GET /assets/NAME.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "app/shipped.hpp"
#include "machine/interpreter.hpp"
#include "machine/profile.hpp"
#include "report/web_assets.hpp"
#include "serve/api.hpp"
#include "serve/request.hpp"
#include "serve/run_settings.hpp"

namespace ncurve::serve {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {
std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace) + "\n"; }

// the profile's rotary axes (No.1006#0), "A" ...: in degrees, where a linear A, B, C is in mm
std::string rotary_axes(const machine::MachineProfile& profile) {
  std::string out;
  for (char a : std::string_view("ABC"))
    if (profile.axes.find(a) != std::string::npos && profile.rotary[machine::axis_index(a)].rotary) out += a;
  return out;
}

}  // namespace

json profile_json(const machine::MachineProfile& profile) {
  return json{{"title", profile.name},
              {"lathe", profile.lathe()},
              {"diameter", profile.lathe() && profile.diameter_x},
              {"axes", profile.axes},
              {"offset_memory", std::string(1, static_cast<char>('A' + static_cast<int>(profile.offset_memory)))},
              {"rotary", rotary_axes(profile)},
              {"tool_offsets", tool_offsets_json(profile)},
              {"modal_groups", machine::modal_groups(profile)}};
}

Answer api_profiles(const ServeConfig& config) {
  auto describe = [](json& p, const std::string& path) {
    try {
      p.update(profile_json(machine::load_profile(path)));
    } catch (const std::exception& e) {
      p["error"] = e.what();
    }
  };
  json list = json::array();
  json fallback = config.machine.empty() ? json(nullptr) : json(config.machine);
  for (const std::string& name : app::shipped_profiles()) {
    json p{{"name", name}};
    std::string path;
    try {
      path = app::find_profile(name);
    } catch (const std::exception&) {  // (described below as an error)
    }
    describe(p, path);
    std::error_code ec;  // --machine arrives as a path: the page selects the shipped profile by name
    if (!config.machine.empty() && fs::equivalent(path, config.machine, ec)) fallback = name;
    list.push_back(p);
  }
  json out{{"profiles", list}, {"default", fallback}};
  // what a request that names no profile runs on: --machine's, else the factory-parameter mill of
  // `ncurve run` without --machine
  json server{{"path", config.machine.empty() ? json(nullptr) : json(config.machine)},
              {"factory", config.machine.empty()}};
  if (config.machine.empty()) server.update(profile_json(machine::default_mill()));
  else describe(server, config.machine);
  out["server"] = server;
  return Answer{200, dump(out)};
}

Answer api_files(const ServeConfig& config) {
  json list = json::array();
  for (const std::string& path : config.files) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    json f{{"name", fs::path(path).filename().string()}, {"path", path}};
    f["bytes"] = ec ? json(nullptr) : json(size);
    list.push_back(f);
  }
  return Answer{200, dump(json{{"files", list}})};
}

Answer api_file(const ServeConfig& config, const std::string& name) {
  for (const std::string& path : config.files) {
    if (fs::path(path).filename().string() != name) continue;
    // opened without waiting and read only as a regular file: a FIFO put in its place blocks no one
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw ApiError(500, fmt::format("cannot read {}: {}", path, std::strerror(errno)));
    struct stat st {};
    std::string text;
    const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    ssize_t n = 0;
    if (regular) {
      char buffer[1 << 16];
      while ((n = ::read(fd, buffer, sizeof buffer)) > 0 || (n < 0 && errno == EINTR))
        if (n > 0) text.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
    if (!regular) throw ApiError(500, fmt::format("cannot read {}: not a regular file", path));
    if (n < 0) throw ApiError(500, fmt::format("cannot read {}", path));
    return Answer{200, std::move(text), "text/plain; charset=utf-8"};
  }
  throw ApiError(404, fmt::format("no file \"{}\" was given to ncurve serve (GET /api/files lists them)", name));
}

Answer page() { return asset("workbench.html"); }

Answer asset(const std::string& name) {
  // the workbench's files and what they need, compiled in (cmake/embed_files.cmake)
  static constexpr std::string_view kServed[] = {"workbench.html", "workbench.css", "workbench.js", "wb-editor.js",
                                                 "wb-debug.js", "wb-colour.js", "wb-answer.js", "wb-dom.js", "wb-part.js", "wb-summary.js", "wb-diags.js", "wb-runline.js", "wb-files.js", "wb-settings.js", "wb-gen.js", "wb-compare.js", "wb-tool.js", "wb-watch.js", "wb-step.js", "backplot-decode.js", "backplot-geometry.js", "backplot-lines.js", "backplot-axes.js", "backplot-holes.js", "backplot-snap.js", "backplot-measure.js", "backplot-part.js", "backplot-programmed.js", "backplot-cutter.js", "backplot.js", "backplot-compare.js", "backplot.css", "three.min.js",
                                                 "OrbitControls.js", "example.nc", "example-lathe.nc", "example.setup.toml"};
  for (std::string_view served : kServed) {
    if (served != name) continue;
    const std::string_view text = web::asset(name);
    const char* type = name.ends_with(".js")    ? "text/javascript; charset=utf-8"
                       : name.ends_with(".css") ? "text/css; charset=utf-8"
                       : name.ends_with(".html") ? "text/html; charset=utf-8"
                                                 : "text/plain; charset=utf-8";
    return Answer{200, std::string(text), type};
  }
  throw ApiError(404, fmt::format("no asset \"{}\"", name));
}

}  // namespace ncurve::serve
