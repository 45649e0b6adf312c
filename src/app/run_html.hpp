// ncurve run --html: the option and the writing of the page.
#pragma once
#include <CLI/CLI.hpp>

#include <string>

#include "app/save.hpp"
#include "machine/library.hpp"
#include "report/backplot_data.hpp"
#include "report/html_page.hpp"

namespace ncurve::app {

inline void add_html_option(CLI::App* run, std::string& html) {
  run->add_option("--html", html,
                  "write an interactive 3D backplot of the run as one self-contained HTML page to this file (- for "
                  "standard output)");
}

// Writes the page; false, with the reason printed, if it failed.
inline bool save_html(const std::string& path, const report::BackplotData& data, bool inch, const std::string& source,
                      const std::string& summary_json, const std::vector<std::string>& inputs) {
  return save(path, report::backplot_html({source, summary_json, data.json(inch)}), inputs);
}

}  // namespace ncurve::app
