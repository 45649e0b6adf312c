// The parser's line loop as a reader that can stop at a line and go on later from the state it
// left (parser.cpp reads a whole text at once, program_stream.cpp a file piece by piece).
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include "nc/program.hpp"

namespace ncurve::nc::text {

// The first kMaxDiagnostics problems of a kind (syntax, loops), a count of the rest; a piece read
// again counts them (what it reads depends on the count) without keeping them.
struct Problems {
  std::vector<Diagnostic> list;
  std::size_t kept = 0, more = 0;
  bool keep = true;
  void add(Diagnostic d);
};

// What the lines read so far decide about the next: where reading resumes, the program being read
// and its last block.
struct ReadState {
  std::size_t offset = 0;     // of the next line in the file's text
  std::uint32_t line = 0;     // lines read
  std::int32_t program = -1;  // index of the program being read in the file
  std::int32_t blocks = 0;    // its blocks before the piece being read
  bool started = false;       // a block has been read: a '%' now ends the file
  bool done = false;          // the '%' that ends the file was read
  bool last_alarms = false;   // the program's block before the piece has a syntax error and no '/'
  std::size_t syntax_kept = 0;
};

class LineReader {
public:
  struct Hooks {
    // A program starts (O line, or a block before any): the Program its blocks go to from now on.
    std::function<Program*(int number, std::uint32_t line)> new_program;
    // Whether sequence number n is on a block of the current program before the piece being read.
    std::function<bool(std::int32_t n)> sequence_before;
  };
  LineReader(const SourceFile& file, int max_digits, Hooks hooks);
  ~LineReader();

  // Reads the lines of `text` (the file's text from state.offset on, whole lines), up to a '%' that
  // ends the file; state and current go on from where they were.
  void read(std::string_view text, ReadState& state, Program*& current, Problems& syntax, std::size_t& unchecked);
  // The program's last block alarms when the control reaches it (a syntax error, no '/').
  bool last_alarms(const Program* current, const ReadState& state) const;

private:
  struct Scanner;
  void handle_block(std::uint32_t line, ReadState& state, Program*& current, Problems& syntax);
  void drop_if_unreachable(const Block& b, ReadState& state, Program& current);
  bool cannot_be_a_target(std::string_view raw, const Program& p) const;
  bool first_with_sequence(const Program& p, const Block& b) const;

  const SourceFile& file_;
  int max_digits_;
  Hooks hooks_;
  std::unique_ptr<Scanner> scanner_;
};

// Adds a problem at block b and, when b has none yet, attaches it to b (raised when b runs).
void add_error(Program& p, Block& b, std::string code, std::string message, std::uint16_t column,
               std::uint32_t length, Problems& all);

// The program number lines after the '%' of line end_line that ends the file, in `text` (whole lines
// from line `line` + 1 on); `line` is advanced past them.
void programs_after_end(std::string_view text, std::uint32_t& line, std::uint32_t end_line,
                        std::vector<UnreadProgram>& found);

// The syntax and loop problems in line order, the first kMaxDiagnostics of them, the rest counted.
void merge_problems(Problems& syntax, Problems& loops, ParseResult& result);

// Pairs DO/WHILE with END in a program's blocks in order; FANUC allows three levels of nesting.
class LoopMatcher {
public:
  // `pair(do, end, m, do_line)` joins loop m; `fault(index, code, message, length)` is a problem at that block.
  using Pair = std::function<void(std::int32_t, std::int32_t, std::uint8_t, std::uint32_t)>;
  using Fault = std::function<void(std::int32_t index, std::uint32_t line, std::uint16_t column, const char* code,
                                   std::string message, std::uint32_t length)>;
  void see(std::int32_t index, const Block& b, const Pair& pair, const Fault& fault);
  // The program's end: each DO still open has no END.
  void close(const Fault& fault);
  // Index of the first DO still open (-1: none).
  std::int32_t first_open() const { return open_.empty() ? -1 : open_.front().index; }

private:
  struct Open {
    std::int32_t index;
    std::uint8_t id;
    std::uint32_t line;
    std::uint16_t column;
  };
  std::vector<Open> open_;
};

// The loops' problems and pairs of a whole program, attached to its blocks (parse()).
void match_loops(Program& p, Problems& all);

}  // namespace ncurve::nc::text
