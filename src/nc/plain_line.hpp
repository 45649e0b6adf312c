// The fast path for the plain blocks of expanded programs (X1.234 Y-5. F100., N120 G01 X3.).
#pragma once
#include <cstdint>

#include "nc/program.hpp"

namespace ncurve::nc::text {

// Compiles the line from `begin`, of nothing but plain address words, straight from the raw text and
// returns where it ends (its '\n', which must follow); anything else (macros, comments, an N not first, '/', errors) returns null, leaving prog as it
// was, for the general scanner and compile_block, which give the same result for plain lines.
const char* plain_nc_line(const char* begin, std::uint32_t line, Program& prog, int max_digits);

}  // namespace ncurve::nc::text
