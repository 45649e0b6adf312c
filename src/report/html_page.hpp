// ncurve run --html: one self-contained HTML page with the 3D backplot of a run. The page's files
// (web/run.html, web/backplot.js, web/run.js, web/backplot.css and three.js) are compiled into the
// binary (web_assets.hpp): the page needs nothing else, offline.
#pragma once
#include <string>
#include <string_view>

namespace ncurve::report {

struct HtmlPageInput {
  std::string title;         // the program's name
  std::string summary_json;  // report::summary_json of the run
  std::string data_json;     // BackplotData::json
};

std::string backplot_html(const HtmlPageInput& in);

// JSON text made safe inside an HTML <script> element: < > & and U+2028, U+2029 as \u escapes
// (only inside strings do they occur, where the escapes mean the same), so no text of the
// program can close the script.
std::string script_json(std::string_view json);

}  // namespace ncurve::report
