// The macro folders a request reads (its "lib", among the server's --lib) and GET /api/libs; the
// tool offsets a request sets over its profile's ("tool_offsets") and the profile's as JSON.
#include "serve/run_settings.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "machine/library.hpp"
#include "serve/request.hpp"

namespace ncurve::serve {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {
std::string server_libs(const ServeConfig& config) {
  return config.libs.empty() ? "the server was started with no --lib folder"
                             : fmt::format("its --lib folders: {}", fmt::join(config.libs, ", "));
}

// a value of "tool_offsets" as the profile file takes it (machine::offset_field_error)
double offset_number(const std::string& where, const json& v, const std::string& field) {
  if (!v.is_number())
    throw ApiError(400, fmt::format("\"tool_offsets\": offset {}: '{}' must be a number (mm)", where, field));
  const double x = v.get<double>();
  if (const std::string why = machine::offset_field_error(field, x); !why.empty())
    throw ApiError(400, fmt::format("\"tool_offsets\": offset {}: {}", where, why));
  return x;
}
}  // namespace

std::vector<std::string> chosen_libs(const ServeConfig& config, const json& j) {
  auto it = j.find("lib");
  if (it == j.end() || it->is_null()) return config.libs;
  if (!it->is_array())
    throw ApiError(400, fmt::format("\"lib\" must be a list of the server's macro folders, e.g. [\"macros\"] ({})",
                                    server_libs(config)));
  std::vector<std::string> out;
  for (const json& v : *it) {
    if (!v.is_string())
      throw ApiError(400, fmt::format("\"lib\": each folder is named by a string, as `serve --lib` gave it ({})",
                                      server_libs(config)));
    const std::string name = v.get<std::string>();
    if (std::find(config.libs.begin(), config.libs.end(), name) == config.libs.end())
      throw ApiError(400, fmt::format("\"lib\": \"{}\" is not a macro folder of this server ({}); a folder is read "
                                      "only when `ncurve serve --lib DIR` names it",
                                      name, server_libs(config)));
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  }
  return out;
}

Answer api_libs(const ServeConfig& config) {
  json list = json::array();
  for (const std::string& dir : config.libs) {
    json l{{"name", dir}};
    std::error_code ec;
    const fs::path abs = fs::absolute(dir, ec);
    l["path"] = ec ? dir : abs.string();
    json programs = json::array();
    std::vector<std::string> names;
    if (fs::is_directory(dir, ec)) {
      for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file(ec) && machine::program_file_name(e.path().string()))
          names.push_back(e.path().filename().string());
      std::sort(names.begin(), names.end());
    } else {
      l["error"] = "not a folder";
    }
    constexpr std::size_t kMostNamed = 200;
    for (std::size_t i = 0; i < names.size() && i < kMostNamed; ++i) programs.push_back(names[i]);
    l["programs"] = programs;
    l["program_count"] = names.size();
    list.push_back(l);
  }
  return Answer{200, json{{"libs", list}}.dump(-1, ' ', false, json::error_handler_t::replace) + "\n"};
}

void apply_tool_offsets(const json& j, machine::MachineProfile& profile) {
  auto it = j.find("tool_offsets");
  if (it == j.end() || it->is_null()) return;
  if (!it->is_object())
    throw ApiError(400, profile.lathe() ? "\"tool_offsets\" must be an object, e.g. {\"1\": {\"r\": 0.8}}"
                                        : "\"tool_offsets\" must be an object, e.g. {\"1\": {\"radius\": 5}}");
  for (const auto& [key, value] : it->items()) {
    int n = 0;
    std::size_t used = 0;
    try {
      n = std::stoi(key, &used);
    } catch (...) {
    }
    if (key.empty() || used != key.size())
      throw ApiError(400, fmt::format("\"tool_offsets\": '{}' is not a whole offset number", key));
    if (profile.lathe()) {
      if (n < 1 || n > 64) throw ApiError(400, "\"tool_offsets\": lathe offset numbers are 1 .. 64");
      if (!value.is_object())
        throw ApiError(400, fmt::format("\"tool_offsets\": offset {}: a lathe offset is an object: {{\"x\": .., \"z\": "
                                        "..,  \"r\": .., \"tip\": .., \"x_wear\": ..}}",
                                        key));
      machine::LatheOffset o = profile.lathe_offsets.count(n) ? profile.lathe_offsets[n] : machine::LatheOffset{};
      for (const auto& [f, v] : value.items()) {
        if (!machine::set_lathe_offset_field(o, f, offset_number(key, v, f)))
          throw ApiError(400, fmt::format("\"tool_offsets\": offset {}: unknown lathe offset field '{}' (x, z, r, tip, "
                                          "x_wear, z_wear, r_wear)",
                                          key, f));
      }
      profile.lathe_offsets[n] = o;
      continue;
    }
    if (n < 1 || n > 999) throw ApiError(400, "\"tool_offsets\": tool offset numbers are 1 .. 999");
    machine::MillOffset o = profile.tool_offsets.count(n) ? profile.tool_offsets[n] : machine::MillOffset{};
    if (value.is_number()) {  // one value: the geometry of H and D alike
      o.geometry = o.d_geometry = offset_number(key, value, "length");
      profile.tool_offsets[n] = o;
      continue;
    }
    if (!value.is_object())
      throw ApiError(400, fmt::format("\"tool_offsets\": offset {} is a number (H and D) or an object: {{\"length\": "
                                      "..,  \"length_wear\": .., \"radius\": .., \"radius_wear\": ..}}",
                                      key));
    if (value.contains("x") || value.contains("z"))
      throw ApiError(400, fmt::format("\"tool_offsets\": offset {}: x and z are a lathe offset's; this profile is a "
                                      "mill's (length, length_wear, radius, radius_wear)",
                                      key));
    const bool c = profile.offset_memory == machine::OffsetMemory::C;
    std::optional<double> length, length_wear, radius, radius_wear;
    for (const auto& [f, v] : value.items()) {
      const double x = offset_number(key, v, f);
      if (f == "length") length = x;
      else if (f == "length_wear") length_wear = x;
      else if (f == "radius") radius = x;
      else if (f == "radius_wear") radius_wear = x;
      else
        throw ApiError(400, fmt::format("\"tool_offsets\": offset {}: unknown mill offset field '{}' (length, "
                                        "length_wear, radius, radius_wear)",
                                        key, f));
    }
    if (!c && ((length && radius && *length != *radius) || (length_wear && radius_wear && *length_wear != *radius_wear)))
      throw ApiError(400, fmt::format("\"tool_offsets\": offset {}: offset memory {} holds one value for H and D: give "
                                      "length or radius, not both (offset_memory = \"C\" separates them)",
                                      key, profile.offset_memory == machine::OffsetMemory::A ? 'A' : 'B'));
    if (c) {
      if (length) o.geometry = *length;
      if (length_wear) o.wear = *length_wear;
      if (radius) o.d_geometry = *radius;
      if (radius_wear) o.d_wear = *radius_wear;
    } else {
      if (auto g = length ? length : radius) o.geometry = o.d_geometry = *g;
      if (auto w = length_wear ? length_wear : radius_wear) o.wear = o.d_wear = *w;
      if (profile.offset_memory == machine::OffsetMemory::A && o.wear != 0)
        throw ApiError(400, fmt::format("\"tool_offsets\": offset {}: offset memory A has no wear values "
                                        "(offset_memory = \"B\" or \"C\")",
                                        key));
    }
    profile.tool_offsets[n] = o;
  }
}

json tool_offsets_json(const machine::MachineProfile& profile) {
  json out = json::object();
  if (profile.lathe()) {
    for (const auto& [n, o] : profile.lathe_offsets)
      out[std::to_string(n)] = {{"x", o.x}, {"z", o.z}, {"r", o.r}, {"tip", o.tip},
                                {"x_wear", o.x_wear}, {"z_wear", o.z_wear}, {"r_wear", o.r_wear}};
    return out;
  }
  const bool c = profile.offset_memory == machine::OffsetMemory::C;
  for (const auto& [n, o] : profile.tool_offsets)
    out[std::to_string(n)] = {{"length", o.geometry}, {"length_wear", o.wear}, {"radius", c ? o.d_geometry : o.geometry},
                              {"radius_wear", c ? o.d_wear : o.wear}};
  return out;
}

}  // namespace ncurve::serve
