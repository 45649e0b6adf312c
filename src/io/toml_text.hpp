// A TOML text (a machine profile, a setup file) read by toml++, within a bound on how deep it nests:
// toml++'s parser and its tables recurse once a level, so a key of 60,000 dotted parts would overflow
// the stack.
#pragma once
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace ncurve::io {

constexpr int kMaxTomlKeyParts = 32;   // a.b.c = 1: three parts
constexpr int kMaxTomlBrackets = 32;   // [[1, 2], {x = 3}]: two levels

// Throws std::runtime_error ("origin:line:column: error: ...") past either bound.
void check_toml_nesting(std::string_view text, const std::string& origin);

// The text's root table: the nesting checked, a syntax error thrown as std::runtime_error
// "origin:line:column: error: ...".
toml::table parse_toml(std::string_view text, const std::string& origin);

}  // namespace ncurve::io
