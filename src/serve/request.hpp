// Reading a request body: JSON, its keys checked, and the run inputs it names.
#pragma once
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

#include "app/run_setup.hpp"
#include "serve/api.hpp"

namespace ncurve::serve {

// The body as a JSON object; ApiError 400 saying where it is not.
nlohmann::json parse_body(const std::string& body);
// Fails with ApiError 400 on a key the endpoint does not know (a misspelt option is not ignored).
void check_keys(const nlohmann::json& j, std::initializer_list<const char*> known, const char* endpoint);
std::optional<std::string> get_string(const nlohmann::json& j, const char* key, bool required = false);
std::optional<double> get_number(const nlohmann::json& j, const char* key);
bool get_bool(const nlohmann::json& j, const char* key, bool otherwise);
// "set" or "param" as the command line's values ("#100=5", "6050=102"): an object {"#100": 5} or a
// list of --set / --param values; ApiError 400 on a bad shape (a bad value is the command's error).
std::vector<std::string> option_values(const nlohmann::json& j, const char* key);
// program, name, machine, set, param, max_steps, max_seconds, nose_centre of a run or analyze request.
app::RunInputs run_inputs(const ServeConfig& config, const nlohmann::json& j);
// The profile read and the program parsed; a bad one is ApiError 400 (running out of memory is not).
app::RunSetup prepare(const app::RunInputs& in);
// The profile a request names: a shipped one by name, or TOML text (a file path is not taken).
void choose_profile(const ServeConfig& config, const nlohmann::json& j, app::RunInputs& in);
// What the page needs of a profile: title, lathe, diameter, axes, offset_memory.
nlohmann::json profile_json(const machine::MachineProfile& profile);

}  // namespace ncurve::serve
