// Texts made from the command line's own definitions, so they never drift from it: the bash
// completion script, the man page, and the nearest command to a mistyped one.
#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace ncurve::app {

std::string bash_completion(const CLI::App& app);
std::string man_page(const CLI::App& app, const std::string& version);
// The candidate nearest to `word` by edit distance, or "" when none is near enough to be meant.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace ncurve::app
