// Rows of numbers from a text file (CSV or spaces): cutter profiles and point lists.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace ncurve::io {

struct NumberRow {
  std::uint32_t line = 0;  // 1-based
  std::vector<double> values;
  std::vector<std::uint32_t> columns;  // 1-based column where each value starts
};

// Numbers separated by commas, semicolons or blanks, one row per line; '#' starts a comment; a
// first row that does not start with a number is a header. Each row must have min..max values.
// Throws std::runtime_error "origin:line:column: ..." quoting the row.
std::vector<NumberRow> read_number_rows(const std::string& text, const std::string& origin, std::size_t min_values,
                                        std::size_t max_values);
std::vector<NumberRow> read_number_file(const std::string& path, std::size_t min_values, std::size_t max_values);

}  // namespace ncurve::io
