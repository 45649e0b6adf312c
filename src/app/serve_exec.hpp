// `ncurve serve` is the program ncurve-serve beside ncurve: the other commands do not load the HTTP
// library (cpp-httplib with OpenSSL and Brotli, milliseconds at every start).
#pragma once

namespace ncurve::app {

// Replaces this process by ncurve-serve with the same arguments; returns 2, having said why, when
// it cannot.
int exec_serve(char** argv);

}  // namespace ncurve::app
