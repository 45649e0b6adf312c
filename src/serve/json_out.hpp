// Writing large JSON answers fast: numbers rounded to a micrometre (or 1e-6 degree) and printed
// in their shortest form, file names through one table shared by the parts of an answer.
#pragma once
#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
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

// Where an answer's arrays go: into the JSON text, or (a binary answer, docs/serve.md) into a blob
// of little-endian arrays that the JSON names as {"type": "f64", "offset": bytes, "count": n}.
struct Columns {
  fmt::memory_buffer& json;
  std::string* blob = nullptr;
};

static_assert(std::endian::native == std::endian::little, "binary answers are little-endian");

template <class T, class Put>
void put_array(Columns& out, std::string_view name, const std::vector<T>& values, Put put) {
  if (!out.blob) return put_array(out.json, name, values, put);
  std::string& blob = *out.blob;
  blob.resize((blob.size() + 7) / 8 * 8, '\0');
  const std::size_t offset = blob.size();
  const char* type;
  if constexpr (std::is_same_v<T, double>) type = "f64";
  else if constexpr (std::is_same_v<T, std::uint8_t>) type = "u8";
  else if constexpr (std::is_same_v<T, std::uint32_t>) type = "u32";
  else if constexpr (std::is_same_v<T, std::int32_t>) type = "i32";
  else type = "f64";  // 64-bit integers as doubles: exact to 2^53, and what JavaScript reads
  if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::uint8_t> || std::is_same_v<T, std::uint32_t> ||
                std::is_same_v<T, std::int32_t>) {
    blob.resize(offset + values.size() * sizeof(T));
    if (!values.empty()) std::memcpy(blob.data() + offset, values.data(), values.size() * sizeof(T));
  } else {
    static_assert(std::is_integral_v<T> && sizeof(T) == 8, "an array type binary answers do not have");
    blob.resize(offset + values.size() * sizeof(double));
    for (std::size_t i = 0; i < values.size(); ++i) {
      const auto d = static_cast<double>(values[i]);
      std::memcpy(blob.data() + offset + i * sizeof(double), &d, sizeof d);
    }
  }
  fmt::format_to(fmt::appender(out.json), "\"{}\":{{\"type\":\"{}\",\"offset\":{},\"count\":{}}}", name, type, offset,
                 values.size());
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
