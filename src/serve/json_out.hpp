// Writing large JSON answers fast: numbers rounded to a micrometre (or 1e-6 degree) and printed
// in their shortest form, file names through one table shared by the parts of an answer.
#pragma once
#include <fmt/format.h>

#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "nc/diagnostic.hpp"

namespace ncurve::serve {

// "12.345", "0", "-3.5e-05"; NaN (a vacant variable) as null.
inline void put_number(fmt::memory_buffer& b, double v, double scale = 1e6) {
  if (std::isnan(v)) {
    b.append(std::string_view("null"));
    return;
  }
  double r = std::round(v * scale) / scale;
  if (!std::isfinite(r)) r = v;  // too large to round at that scale: kept as it is
  if (r == 0) r = 0;             // no "-0"
  fmt::format_to(fmt::appender(b), "{}", r);
}

// A JSON string, escaped (bytes that are not UTF-8 become U+FFFD).
std::string json_string(const std::string& s);

// "name": [v0,v1,...] with put for each element.
template <class T, class Put>
void put_array(fmt::memory_buffer& b, std::string_view name, const std::vector<T>& values, Put put) {
  fmt::format_to(fmt::appender(b), "\"{}\":[", name);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) b.push_back(',');
    put(values[i]);
  }
  b.push_back(']');
}

// File names by index, in the order first met: {"files": [...]} of an answer.
class FileTable {
public:
  std::uint32_t index(const nc::SourceFile* f) {
    auto [it, added] = index_.try_emplace(f, static_cast<std::uint32_t>(names_.size()));
    if (added) names_.push_back(f ? f->name() : std::string());
    return it->second;
  }
  const std::vector<std::string>& names() const { return names_; }

private:
  std::unordered_map<const nc::SourceFile*, std::uint32_t> index_;
  std::vector<std::string> names_;
};

}  // namespace ncurve::serve
