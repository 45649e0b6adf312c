// The fast path for the plain blocks of expanded programs (X1.234 Y-5. F100., N120 G01 X3.).
#pragma once
#include <cstdint>
#include <string_view>

#include "nc/program.hpp"

namespace ncurve::nc::text {

// Compiles a line of nothing but plain address words straight from the raw text and returns true;
// anything else (macros, comments, an N not first, '/', errors) returns false, leaving prog as it was, for the
// general scanner and compile_block, which give the same result for plain lines. The line's text
// must be followed by '\n' (raw.data()[raw.size()]), where its scanning stops.
bool plain_nc_line(std::string_view raw, std::uint32_t line, Program& prog, int max_digits);

}  // namespace ncurve::nc::text
