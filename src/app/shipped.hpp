// Where the files shipped with ncurve are (profiles, macros, examples, docs): share/ncurve beside
// an installed binary, or the source tree that holds a build folder's binary.
#pragma once
#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace ncurve::app {

// The folder holding profiles/ and macros/, if there is one.
std::optional<std::string> shipped_dir();
// Where shipped_dir() looks when the process is not ncurve's binary (the Python module, which
// knows where it was installed): this folder if it holds profiles/ and macros/.
void set_shipped_dir(std::string dir);
// The names of the shipped profiles (file stems), sorted; none without a shipped folder.
std::vector<std::string> shipped_profiles();
// A profile path as given, or a shipped profile by name ("fanuc-lathe", "fanuc-lathe.toml").
// Throws std::runtime_error naming the shipped profiles when neither exists.
std::string find_profile(const std::string& name);
// A folder as given, or a shipped folder by name ("macros").
std::string find_folder(const std::string& name);

// Option transforms that resolve the names above, with the message of a failed look-up.
CLI::Validator profile_path();
CLI::Validator folder_path();
// An existing file, or "-" for standard input.
CLI::Validator input_file();

}  // namespace ncurve::app
