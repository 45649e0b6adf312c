// The command line's run settings a request may carry beyond set and param: the macro folders
// (--lib, among the server's) and the tool offsets over the profile's ([tool_offsets]).
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "machine/profile.hpp"
#include "serve/api.hpp"

namespace ncurve::serve {

// "lib": the server's --lib folders a run reads, named as `serve --lib` gave them; without the key
// all of them, [] none. ApiError 400 naming a folder the server was not given.
std::vector<std::string> chosen_libs(const ServeConfig& config, const nlohmann::json& j);
// "tool_offsets": {"1": {"radius": 5}, "2": 10.5} over the profile's, in the profile's [tool_offsets]
// words (mill: length, length_wear, radius, radius_wear, or a number for H and D; lathe: x, z, r,
// tip, x_wear, z_wear, r_wear). ApiError 400 saying what is wrong, in the profile file's words.
void apply_tool_offsets(const nlohmann::json& j, machine::MachineProfile& profile);
// The profile's offsets as "tool_offsets" takes them: mill {"N": {length, length_wear, radius,
// radius_wear}} (radius is length on memory A and B, which hold one value), lathe {"N": {x, z, r,
// tip, x_wear, z_wear, r_wear}}.
nlohmann::json tool_offsets_json(const machine::MachineProfile& profile);

}  // namespace ncurve::serve
