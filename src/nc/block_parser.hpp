// Compiles one block's characters (spaces and comments stripped, upper case) into a Block: its
// address words, macro statement and expression code.
#pragma once
#include <span>

#include "nc/program.hpp"
#include "nc/text.hpp"

namespace ncurve::nc::text {

// Fills b (and prog's words and code); throws SyntaxError at the first fault.
void compile_block(std::span<const Ch> s, Program& prog, Block& b, int max_digits);
// One expression alone into prog's code, significant digits counted (leading zeros are not).
void compile_standalone(std::span<const Ch> s, Program& prog);

}  // namespace ncurve::nc::text
