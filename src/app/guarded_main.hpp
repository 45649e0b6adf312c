// What ncurve and ncurve-serve make of an error that reaches main(): a message and an exit status.
#pragma once
#include <iostream>
#include <new>
#include <stdexcept>

#include "io/output_file.hpp"

namespace ncurve::app {

// body's exit status after standard output is flushed; 2 for a failed write or no memory, 3 for
// any other exception (an internal error).
template <class Body>
int guarded_main(Body&& body) {
  try {
    const int status = body();
    io::check_stdout();
    return status;
  } catch (const io::OutputError& e) {
    std::cerr << "ncurve: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "ncurve: error: out of memory (the machine ran out of memory for this job; try a smaller one)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ncurve: internal error: " << e.what() << "\n";
    return 3;
  }
}

}  // namespace ncurve::app
