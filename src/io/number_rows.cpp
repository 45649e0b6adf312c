#include "io/number_rows.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ncurve::io {

std::vector<NumberRow> read_number_rows(const std::string& text, const std::string& origin, std::size_t min_values,
                                        std::size_t max_values) {
  std::vector<NumberRow> rows;
  std::istringstream in(text);
  std::string line;
  std::uint32_t number = 0;
  bool first = true;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::string body = line.substr(0, line.find('#'));
    NumberRow row;
    row.line = number;
    std::size_t i = 0;
    bool header = false;
    while (i < body.size()) {
      while (i < body.size() && (std::isspace(static_cast<unsigned char>(body[i])) || body[i] == ',' || body[i] == ';')) ++i;
      if (i >= body.size()) break;
      std::size_t end = i;
      while (end < body.size() && !std::isspace(static_cast<unsigned char>(body[end])) && body[end] != ',' && body[end] != ';')
        ++end;
      double v = 0;
      const char* b = body.data() + i;
      const char* e = body.data() + end;
      if (*b == '+') ++b;
      auto [ptr, ec] = std::from_chars(b, e, v);
      if (ec != std::errc() || ptr != e || !std::isfinite(v)) {
        if (first && row.values.empty()) {
          header = true;
          break;
        }
        throw std::runtime_error(fmt::format("{}:{}:{}: '{}' is not a number in \"{}\"", origin, number, i + 1,
                                             body.substr(i, end - i), line));
      }
      row.values.push_back(v);
      row.columns.push_back(static_cast<std::uint32_t>(i + 1));
      i = end;
    }
    if (header) {
      first = false;
      continue;
    }
    if (row.values.empty()) continue;
    first = false;
    if (row.values.size() < min_values || row.values.size() > max_values)
      throw std::runtime_error(fmt::format("{}:{}:1: {} numbers where {} are expected in \"{}\"", origin, number,
                                           row.values.size(),
                                           min_values == max_values ? fmt::format("{}", min_values)
                                                                    : fmt::format("{} to {}", min_values, max_values),
                                           line));
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<NumberRow> read_number_file(const std::string& path, std::size_t min_values, std::size_t max_values) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error(fmt::format("{}: cannot open", path));
  std::ostringstream text;
  text << f.rdbuf();
  return read_number_rows(text.str(), path, min_values, max_values);
}

}  // namespace ncurve::io
