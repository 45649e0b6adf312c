// Writing a command's output files: whole or not at all (io::OutputFile), errors to the terminal.
#pragma once
#include <iostream>
#include <string>
#include <vector>

#include "io/output_file.hpp"

namespace ncurve::app {

// Writes `text` to `path` ("-": standard output); false, with the reason printed, if it failed.
inline bool save(const std::string& path, const std::string& text, const std::vector<std::string>& inputs = {}) {
  try {
    io::write_file(path, text, inputs);
    return true;
  } catch (const io::OutputError& e) {
    std::cerr << "ncurve: error: " << e.what() << "\n";
    return false;
  }
}

}  // namespace ncurve::app
