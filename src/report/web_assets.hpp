// The web page files compiled into the binary (from web/ and Debian's libjs-three; the table is
// generated at build time by cmake/embed_files.cmake).
#pragma once
#include <string_view>

namespace ncurve::web {

// The file of that name ("backplot.js", "backplot.css", "run.js", "run.html", "three.min.js",
// "OrbitControls.js"); empty for any other name.
std::string_view asset(std::string_view name);

}  // namespace ncurve::web
