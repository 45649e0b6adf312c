#include "serve/request.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "app/shipped.hpp"
#include "nc/program.hpp"
#include "serve/run_settings.hpp"

namespace ncurve::serve {

using nlohmann::json;

json parse_body(const std::string& body) {
  json j;
  try {
    j = json::parse(body);
  } catch (const json::parse_error& e) {
    throw ApiError(400, fmt::format("the request body is not JSON: {}", e.what()));
  } catch (const json::out_of_range& e) {  // a number past the range of a double: 1e400
    throw ApiError(400, fmt::format("the request body holds a number too large: {}", e.what()));
  }
  if (!j.is_object()) throw ApiError(400, "the request body must be a JSON object ({\"program\": ...})");
  return j;
}

void check_keys(const json& j, std::initializer_list<const char*> known, const char* endpoint) {
  for (const auto& item : j.items()) {
    const std::string& key = item.key();
    if (std::none_of(known.begin(), known.end(), [&](const char* k) { return key == k; }))
      throw ApiError(400, fmt::format("{} has no key \"{}\" (its keys: {})", endpoint, key, fmt::join(known, ", ")));
  }
}

std::optional<std::string> get_string(const json& j, const char* key, bool required) {
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) {
    if (required) throw ApiError(400, fmt::format("the request needs \"{}\" (a string)", key));
    return std::nullopt;
  }
  if (!it->is_string()) throw ApiError(400, fmt::format("\"{}\" must be a string", key));
  return it->get<std::string>();
}

std::optional<double> get_number(const json& j, const char* key) {
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) return std::nullopt;
  if (!it->is_number()) throw ApiError(400, fmt::format("\"{}\" must be a number", key));
  return it->get<double>();
}

bool get_bool(const json& j, const char* key, bool otherwise) {
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) return otherwise;
  if (!it->is_boolean()) throw ApiError(400, fmt::format("\"{}\" must be true or false", key));
  return it->get<bool>();
}

void choose_profile(const ServeConfig& config, const json& j, app::RunInputs& in) {
  const std::optional<std::string> machine = get_string(j, "machine");
  if (!machine) {
    in.machine = config.machine;
    return;
  }
  if (machine->find_first_of("\n=") != std::string::npos) {  // TOML text
    in.machine = "<request>";
    in.machine_text = *machine;
    return;
  }
  std::string name = *machine;
  if (name.size() > 5 && name.ends_with(".toml")) name.resize(name.size() - 5);
  const std::vector<std::string> shipped = app::shipped_profiles();
  if (name.find('/') != std::string::npos || std::find(shipped.begin(), shipped.end(), name) == shipped.end())
    throw ApiError(400, fmt::format("unknown profile \"{}\": \"machine\" is a shipped profile ({}) or a profile's TOML "
                                    "text",
                                    *machine, shipped.empty() ? "none found" : fmt::format("{}", fmt::join(shipped, ", "))));
  in.machine = app::find_profile(name);
}

app::RunSetup prepare(const app::RunInputs& in) {
  try {
    return app::prepare_run(in);
  } catch (const std::bad_alloc&) {
    throw;  // 507
  } catch (const std::exception& e) {
    throw ApiError(400, e.what());
  }
}

std::size_t program_lines(std::string_view program) {
  return static_cast<std::size_t>(std::count(program.begin(), program.end(), '\n')) + 1;
}

std::size_t program_memory(std::string_view program) {
  return nc::compiled_size(program.size(), program_lines(program));
}

std::vector<std::string> option_values(const json& j, const char* key) {
  std::vector<std::string> out;
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) return out;
  const bool set = std::string_view(key) == "set";
  if (it->is_array()) {
    for (const auto& v : *it) {
      if (!v.is_string())
        throw ApiError(400, fmt::format("\"{}\": each entry is a string as --{} takes it, e.g. \"{}\"", key, key,
                                        set ? "#100=5" : "6050=102"));
      out.push_back(v.get<std::string>());
    }
    return out;
  }
  if (!it->is_object())
    throw ApiError(400, fmt::format("\"{}\" must be an object, e.g. {{\"{}\": {}}}, or a list of --{} values, e.g. "
                                    "[\"{}\"]",
                                    key, set ? "#100" : "6050", set ? 5 : 102, key, set ? "#100=5" : "6050=102"));
  for (const auto& [k, v] : it->items()) {
    if (!v.is_number()) throw ApiError(400, fmt::format("\"{}\": the value of \"{}\" must be a number", key, k));
    const double x = v.get<double>();
    if (set) out.push_back(fmt::format("{}{}={}", k.starts_with('#') ? "" : "#", k, x));
    else out.push_back(fmt::format("{}={}", k, x));
  }
  return out;
}

app::RunInputs run_inputs(const ServeConfig& config, const json& j) {
  app::RunInputs in;
  in.text = get_string(j, "program", true);
  const std::size_t budget = config.max_body * kProgramMemoryPerBodyByte;
  if (program_memory(*in.text) > budget)
    throw ApiError(413, fmt::format("the program is too large to run here: its {} lines would take at least {} MB of "
                                    "memory once read, over the {} MB the server allows a program ({} times "
                                    "--max-body); raise --max-body, or run it with ncurve run",
                                    program_lines(*in.text), program_memory(*in.text) >> 20, budget >> 20,
                                    kProgramMemoryPerBodyByte));
  in.program = get_string(j, "name").value_or("program.nc");
  if (in.program.empty() || in.program == "-") throw ApiError(400, "\"name\" names the program's file, e.g. prog.nc");
  choose_profile(config, j, in);
  in.libs = chosen_libs(config, j);
  in.max_steps = config.max_steps;
  in.max_seconds = config.max_seconds;
  if (auto steps = get_number(j, "max_steps")) {
    if (!(*steps >= 1) || *steps > static_cast<double>(config.max_steps))
      throw ApiError(400, fmt::format("\"max_steps\" is 1 to {} (the server's --max-steps)", config.max_steps));
    in.max_steps = static_cast<std::uint64_t>(*steps);
  }
  if (auto seconds = get_number(j, "max_seconds")) {
    const bool over = config.max_seconds > 0 && (*seconds == 0 || *seconds > config.max_seconds);
    if (!(*seconds >= 0) || over)
      throw ApiError(400, fmt::format("\"max_seconds\" is at most {} (the server's --max-seconds)", config.max_seconds));
    in.max_seconds = *seconds;
  }
  in.nose_centre = get_bool(j, "nose_centre", false);
  in.sets = option_values(j, "set");
  in.params = option_values(j, "param");
  return in;
}

}  // namespace ncurve::serve
