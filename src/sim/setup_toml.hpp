// Reading a setup file's TOML values (private to src/sim/setup*, tool_library*): every error
// "file:line:column: error: ..." names the key by its dotted path and what is wrong with it.
#pragma once
#include <initializer_list>
#include <string>
#include <string_view>
#include <toml++/toml.h>

#include "sim/setup.hpp"

namespace ncurve::sim::setup_toml {

enum class Range { any, positive, non_negative };

class Reader {
public:
  Reader(std::string origin, double scale) : origin_(std::move(origin)), scale_(scale) {}

  [[noreturn]] void fail(const toml::source_region& at, const std::string& what) const;
  [[noreturn]] void fail(const toml::node& node, const std::string& what) const { fail(node.source(), what); }

  double number(const toml::node& node, const std::string& key, Range range = Range::any) const;
  // A number in mm (or inches, scaled to mm).
  double length(const toml::node& node, const std::string& key, Range range = Range::any) const {
    return number(node, key, range) * scale_;
  }
  // Degrees, more than `low` and less than `high`.
  double angle(const toml::node& node, const std::string& key, double low, double high) const;
  int whole(const toml::node& node, const std::string& key, int low, int high) const;
  bool flag(const toml::node& node, const std::string& key) const;
  std::string text(const toml::node& node, const std::string& key) const;
  Point3 point(const toml::node& node, const std::string& key) const;  // [x, y, z], scaled
  const toml::table& table(const toml::node& node, const std::string& key) const;

  // An error at the first key of t not in `known`: "unknown key 'k' in [where] (a, b, c)".
  void only_keys(const toml::table& t, const std::string& where, std::initializer_list<std::string_view> known) const;
  // The value of a key that must be there; else an error at the table.
  const toml::node& required(const toml::table& t, std::string_view key, const std::string& where,
                             const std::string& why) const;

  double scale() const { return scale_; }
  const std::string& origin() const { return origin_; }

private:
  std::string origin_;
  double scale_;
};

// "where.key", or "key" at the top level.
inline std::string dotted(const std::string& where, std::string_view key) {
  return where.empty() ? std::string(key) : where + "." + std::string(key);
}

// The tool library from [tools] (tool_library.cpp); notes the defaults it applies.
ToolLibrary read_tools(const Reader& r, const toml::table& tools, std::vector<std::string>& defaulted);

}  // namespace ncurve::sim::setup_toml
