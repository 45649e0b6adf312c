// Reading a setup file's TOML values with errors at their file:line:column (see the header).
#include "sim/setup_toml.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ncurve::sim::setup_toml {

void Reader::fail(const toml::source_region& at, const std::string& what) const {
  throw std::runtime_error(fmt::format("{}:{}:{}: error: {}", origin_, at.begin.line, at.begin.column, what));
}

double Reader::number(const toml::node& node, const std::string& key, Range range) const {
  const auto v = node.value<double>();
  if (!v || node.is_boolean()) fail(node, fmt::format("'{}' must be a number", key));
  if (!std::isfinite(*v)) fail(node, fmt::format("'{}' must be a finite number, not {}", key, *v));
  if (range == Range::positive && !(*v > 0)) fail(node, fmt::format("'{}' must be more than zero, not {}", key, *v));
  if (range == Range::non_negative && !(*v >= 0))
    fail(node, fmt::format("'{}' must be zero or more, not {}", key, *v));
  return *v;
}

double Reader::angle(const toml::node& node, const std::string& key, double low, double high) const {
  const double v = number(node, key);
  if (!(v > low && v < high))
    fail(node, fmt::format("'{}' is an angle in degrees more than {} and less than {}, not {}", key, low, high, v));
  return v;
}

int Reader::whole(const toml::node& node, const std::string& key, int low, int high) const {
  const double v = number(node, key);
  if (v != std::floor(v) || v < low || v > high)
    fail(node, fmt::format("'{}' must be a whole number from {} to {}, not {}", key, low, high, v));
  return static_cast<int>(v);
}

bool Reader::flag(const toml::node& node, const std::string& key) const {
  if (auto v = node.value_exact<bool>()) return *v;
  fail(node, fmt::format("'{}' must be true or false", key));
}

std::string Reader::text(const toml::node& node, const std::string& key) const {
  if (auto v = node.value_exact<std::string>()) return *v;
  fail(node, fmt::format("'{}' must be a string", key));
}

Point3 Reader::point(const toml::node& node, const std::string& key) const {
  const toml::array* a = node.as_array();
  if (!a || a->size() != 3) fail(node, fmt::format("'{}' must be an array of 3 numbers [x, y, z]", key));
  Point3 p{};
  for (std::size_t i = 0; i < 3; ++i) p[i] = length(*a->get(i), key);
  return p;
}

const toml::table& Reader::table(const toml::node& node, const std::string& key) const {
  if (const toml::table* t = node.as_table()) return *t;
  fail(node, fmt::format("'{}' must be a table", key));
}

void Reader::only_keys(const toml::table& t, const std::string& where,
                       std::initializer_list<std::string_view> known) const {
  for (const auto& [k, node] : t) {
    bool found = false;
    for (std::string_view name : known) found = found || k.str() == name;
    if (found) continue;
    std::string list;
    for (std::string_view name : known) list += (list.empty() ? "" : ", ") + std::string(name);
    const std::string in = where.empty() ? "at the top level" : fmt::format("in [{}]", where);
    fail(k.source().begin.line ? k.source() : node.source(), fmt::format("unknown key '{}' {} ({})", k.str(), in, list));
  }
}

const toml::node& Reader::required(const toml::table& t, std::string_view key, const std::string& where,
                                   const std::string& why) const {
  if (const toml::node* n = t.get(key)) return *n;
  fail(t, fmt::format("'{}' is missing: {}", dotted(where, key), why));
}

}  // namespace ncurve::sim::setup_toml
