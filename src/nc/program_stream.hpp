// A program file read piece by piece as the run reaches it (programs of any size): only a piece's
// compiled blocks are in memory, with an index of the pieces, their sequence numbers and the DO/END
// pairs; a jump back reads its piece again. Gives what parse() gives, block for block.
#pragma once
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <unordered_map>
#include <vector>

#include "nc/program.hpp"

namespace ncurve::nc {

namespace text {
struct Problems;
struct ReadState;
class LoopMatcher;
}  // namespace text

class ProgramStream {
public:
  // What the reading finds, in file order, for the owner of the programs.
  struct Listener {
    virtual ~Listener() = default;
    // A program whose first piece was read; the listener owns it from now on.
    virtual void program_begun(std::unique_ptr<Program> p) = 0;
    // Its first block with content (not empty, or an N, or an error).
    virtual void program_content(Program& p) = 0;
    // Its end; `last`: the file's last program.
    virtual void program_ended(Program& p, bool has_content, bool last) = 0;
  };
  // Bytes of text read at once (about 1.5 MB compiled); a piece ends at a line's end.
  static constexpr std::size_t kChunkBytes = std::size_t{1} << 18;
  static constexpr std::size_t kChunkLines = 16384;  // and at most these lines (short lines, many blocks)
  // Pieces kept in memory besides those in use.
  static constexpr std::size_t kPiecesKept = 4;

  ProgramStream(std::shared_ptr<const SourceFile> file, ParseOptions options, Listener& listener,
                std::size_t chunk_bytes = kChunkBytes);
  ~ProgramStream();

  bool finished() const { return finished_; }
  // Reads the next piece of the file; false once all is read.
  bool advance();
  void finish() {
    while (advance()) {
    }
  }

  // A program and one piece of it, in file order; `keep` holds the piece in memory as long as it is held.
  using Visitor = std::function<void(const Program& program, const Program& piece, const std::shared_ptr<const void>& keep)>;
  // Calls v for every piece read so far (reading again those not in memory), then for each piece read.
  void visit(Visitor v);
  void forget_visitors() { visitors_.clear(); }

  Program::Piece piece_of(std::int32_t program, std::int32_t i);
  std::int32_t find_sequence(std::int32_t program, std::int32_t n);
  // Reads on until the DO or WHILE at block i has its END, or is known to have none.
  void settle_loop(std::int32_t program, std::int32_t i);
  // The innermost DO..END around block i (as a GOTO to it sees them); begin -1: none.
  struct Loop {
    std::int32_t begin = -1, end = -1;
    std::uint8_t id = 0;
    std::uint32_t line = 0;
  };
  Loop loop_around(std::int32_t program, std::int32_t i);

  // Once finished: the file's problems and what parse() reports besides (no programs).
  ParseResult problems() const;
  // The blocks and words of a program, for the summary.
  const SourceCount& count(std::int32_t program) const;

private:
  struct PieceRecord {
    std::int32_t program = 0, first = 0, count = 0;
    std::int32_t n_min = 0, n_max = -1;  // its sequence numbers' range (empty: max < min)
  };
  struct Chunk;  // a piece of the file: its start, its end and its programs' pieces
  struct Loaded;  // a chunk's compiled pieces
  struct ProgramInfo;

  std::shared_ptr<Loaded> load(std::size_t chunk);
  std::shared_ptr<Loaded> read_chunk(std::size_t chunk, bool first);
  void after_first_read(std::size_t chunk, const std::shared_ptr<Loaded>& loaded, bool ended);
  void patch(std::int32_t program, Program& piece, std::int32_t first) const;
  void patch_alive(std::int32_t program, std::int32_t index);
  void close_program(std::int32_t program, bool last);
  void loop_fault(std::int32_t program, std::int32_t index, Span at, const char* code, std::string message);
  void keep(std::size_t chunk, std::shared_ptr<Loaded> loaded);
  bool sequence_before(std::int32_t program, std::int32_t n, std::size_t chunk);
  void read_after_end();
  void read_lines(std::size_t offset, std::string& window) const;

  std::shared_ptr<const SourceFile> file_;
  ParseOptions options_;
  Listener& listener_;
  std::size_t chunk_bytes_;
  std::vector<Chunk> chunks_;
  std::vector<ProgramInfo> programs_;
  std::unique_ptr<text::ReadState> frontier_;
  std::unique_ptr<text::Problems> syntax_, loops_;
  std::size_t unchecked_ = 0;
  std::size_t blocks_hint_ = 0, words_hint_ = 0;  // the last piece's, reserved for the next: no regrowth
  std::vector<UnreadProgram> after_end_;
  bool finished_ = false;
  std::list<std::pair<std::size_t, std::shared_ptr<Loaded>>> kept_;  // most recent first
  std::unordered_map<std::size_t, std::weak_ptr<Loaded>> alive_;
  std::unordered_map<std::int64_t, std::int32_t> sequences_;  // find_sequence's answers
  std::vector<Visitor> visitors_;
};

}  // namespace ncurve::nc
