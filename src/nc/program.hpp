// The compiled form of a part program: blocks, address words and expression code.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "nc/diagnostic.hpp"
#include "nc/expr.hpp"

namespace ncurve::nc {

struct Word {
  char letter = 0;
  bool literal = true;         // value known at parse time
  bool decimal_point = false;  // a literal written with '.'
  std::uint8_t decimals = 0;   // its digits after the point (255: that many or more)
  std::uint16_t column = 0;
  double value = 0;  // literal value
  Expr expr;         // otherwise
};

enum class Statement : std::uint8_t {
  empty,     // nothing but N, comments or '/'
  nc,        // address words
  assign,    // #i = expr
  go_to,     // GOTO n
  if_goto,   // IF [cond] GOTO n
  if_then,   // IF [cond] THEN #i = expr
  while_do,  // WHILE [cond] DO m
  do_loop,   // DO m (no WHILE: endless)
  end_loop,  // END m
  popen,     // POPEN: external output open (macro_output.cpp)
  pclos,     // PCLOS: external output close
  dprnt,     // DPRNT[...]: words_begin..words_end index Program::prints
  bprnt,     // BPRNT[...]: likewise
};

// One item of DPRNT[...] or BPRNT[...]: characters as written ('*' kept), or a variable and its
// format: DPRNT [c d] integer and decimal digits, BPRNT [c] decimal places (in decimals).
struct PrintItem {
  std::string text;
  Expr var;  // #b (or #[expr]); empty for characters
  std::uint8_t integers = 0, decimals = 0;
  std::uint16_t column = 0;
};

// A block of nothing but literal X, Y, Z, F (not negative) and G00 or G01, each once: the lane of
// plain motion (machine/plain_motion.cpp). `modal`: no G word, the motion in force.
enum class PlainMotion : std::uint8_t { no, modal, coded };

struct Block {
  Statement kind = Statement::empty;
  bool block_skip = false;
  std::uint8_t loop_id = 0;      // m of DO m / END m
  PlainMotion plain_motion = PlainMotion::no;
  std::uint16_t column = 1;      // first column of the statement
  std::uint32_t line = 0;
  std::int32_t sequence = -1;    // N number
  std::int32_t match = -1;       // WHILE/DO: index of its END; END: index of its DO
  std::int32_t error = -1;       // index into Program::errors: the alarm raised when this block runs
  std::int32_t comment = -1;     // index into Program::comments: first comment of the block
  std::uint32_t words_begin = 0, words_end = 0;
  std::int32_t target_var = -1;  // assignment to a fixed variable number, else target expr
  Expr target, value, cond;
};

class ProgramStream;

struct Program {
  int number = -1;  // O number; -1 when the file has none
  std::uint32_t line = 0;  // line of the O word (0: none)
  std::string name;  // comment on the O line
  std::shared_ptr<const SourceFile> file;
  std::vector<Block> blocks;
  std::vector<Word> words;
  std::vector<Instr> code;
  std::vector<Diagnostic> errors;
  std::vector<std::string> comments;
  std::vector<PrintItem> prints;  // items of DPRNT/BPRNT blocks
  std::unordered_map<std::int32_t, std::int32_t> sequence_index;  // N -> first block with it

  // A program read block by block from its file (program_stream.hpp): its blocks, words and code are
  // in pieces that the stream reads, and reads again after a jump back; these vectors stay empty.
  ProgramStream* stream = nullptr;
  std::int32_t stream_index = -1;  // its index among the file's programs

  Span span_of(const Block& b, std::uint16_t column = 0, std::uint32_t length = 1) const {
    return Span{file.get(), b.line, column ? column : b.column, length};
  }

  // The compiled piece holding block i with its words and code: this program, or a piece of a streamed
  // one (kept in memory while `hold` lives); no piece past the program's end.
  struct Piece {
    const Program* piece = nullptr;
    std::int32_t first = 0, end = 0;  // the program's blocks [first, end) are piece->blocks
    std::shared_ptr<const Program> hold;
  };
  Piece piece_of(std::int32_t i) const;
  // The first block with sequence number n, or -1.
  std::int32_t find_sequence(std::int32_t n) const;
};

// A program's blocks with content and words, as the summary counts its source.
struct SourceCount {
  std::size_t blocks = 0, words = 0;
  void add(const Program& piece);
};

// A program number line after the '%' that ends the file: the control never reads it.
struct UnreadProgram {
  int number = -1;
  std::uint32_t line = 0;      // its O (or :) line
  std::uint32_t end_line = 0;  // the closing '%'
};

// Problems of a text kept to be shown; the rest are counted (a file of junk has one a line).
constexpr std::size_t kMaxDiagnostics = 100;

struct ParseResult {
  std::vector<std::unique_ptr<Program>> programs;
  std::vector<Diagnostic> diagnostics;  // the first kMaxDiagnostics problems found in the text, by line
  std::size_t more_diagnostics = 0;     // problems found beyond those
  std::vector<UnreadProgram> after_end;  // programs after the closing '%'
  // Lines not parsed: past kMaxDiagnostics problems, lines after a block that alarms which no jump
  // can reach (no new N, DO, WHILE, END, '/' or '%', no O first): they can never run.
  std::size_t unchecked_lines = 0;
};

// Digits in one number, NC word or macro constant, every digit typed counted (0.00000001 has nine,
// .00000001 eight): FANUC 0i takes 8 (alarm PS0003 beyond), so every control takes programs written
// with 8; double precision holds 15.
constexpr int kPortableDigits = 8;
constexpr int kMostDigits = 15;

// What the control accepts that differs between models.
struct ParseOptions {
  int max_digits = kPortableDigits;
  // Bytes a file may take once compiled (its text, line index, blocks and words); 0: ten times its
  // size or 256 MB, the larger. Past it parse() throws base::BoundExceeded before compiling.
  std::size_t max_memory = 0;
};

// What a file's compiled form takes at least: text, a line index, a block and a word a line.
std::size_t compiled_size(std::size_t text_bytes, std::size_t lines);
std::size_t memory_bound(std::size_t text_bytes, const ParseOptions& options);

// Splits a file into programs (one per O number, or ':' number, its ISO form) and compiles each
// block, up to the '%' that ends the file.
// Problems are reported and also attached to their block, to be raised when it runs, as FANUC does.
ParseResult parse(std::shared_ptr<const SourceFile> file, ParseOptions options = {});

// Compiles one stand-alone expression (for curves given as text); throws Alarm on error.
struct CompiledExpr {
  std::vector<Instr> code;
};
CompiledExpr compile_expression(const std::string& text, const std::string& origin = "<expression>");

}  // namespace ncurve::nc
