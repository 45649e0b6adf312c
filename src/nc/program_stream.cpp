#include "nc/program_stream.hpp"

#include <algorithm>

#include "nc/line_reader.hpp"

namespace ncurve::nc {

using text::Problems;
using text::ReadState;

struct ProgramStream::Chunk {
  ReadState start;
  std::size_t end = 0;  // offset after its last line
  std::vector<PieceRecord> pieces;
};

struct ProgramStream::Loaded {
  std::vector<std::unique_ptr<Program>> pieces;  // as Chunk::pieces
};

struct ProgramStream::ProgramInfo {
  Program* program = nullptr;         // owned by the listener once begun
  std::unique_ptr<Program> pending;   // before
  std::vector<std::pair<std::size_t, std::size_t>> pieces;  // (chunk, piece) of its pieces with blocks
  std::vector<std::int32_t> firsts;   // their first blocks
  std::int32_t blocks = 0;            // read so far
  bool closed = false, content = false;
  text::LoopMatcher loops;
  std::unordered_map<std::int32_t, std::int32_t> match;      // DO <-> END
  std::unordered_map<std::int32_t, Diagnostic> loop_error;  // a block's loop problem
  std::vector<Loop> pairs;
  SourceCount count;
  std::size_t piece_holding(std::int32_t i) const;
};

Program::Piece Program::piece_of(std::int32_t i) const {
  if (stream) return stream->piece_of(stream_index, i);
  if (i < 0 || i >= static_cast<std::int32_t>(blocks.size())) return {};
  return Piece{this, 0, static_cast<std::int32_t>(blocks.size()), {}};
}

std::int32_t Program::find_sequence(std::int32_t n) const {
  if (stream) return stream->find_sequence(stream_index, n);
  auto it = sequence_index.find(n);
  return it == sequence_index.end() ? -1 : it->second;
}

void SourceCount::add(const Program& p) {
  for (const Block& b : p.blocks) {
    if (b.kind != Statement::empty || b.sequence >= 0) ++blocks;
    if (b.sequence >= 0) ++words;
    if (b.kind == Statement::nc) words += b.words_end - b.words_begin;
    else if (b.kind != Statement::empty) ++words;
  }
}

ProgramStream::ProgramStream(std::shared_ptr<const SourceFile> file, ParseOptions options, Listener& listener,
                             std::size_t chunk_bytes)
    : file_(std::move(file)),
      options_(options),
      listener_(listener),
      chunk_bytes_(std::max<std::size_t>(chunk_bytes, 1)),
      frontier_(std::make_unique<ReadState>()),
      syntax_(std::make_unique<Problems>()),
      loops_(std::make_unique<Problems>()) {}

ProgramStream::~ProgramStream() = default;

bool ProgramStream::advance() {
  if (finished_) return false;
  if (frontier_->done || frontier_->offset >= file_->size()) {
    if (!programs_.empty() && !programs_.back().closed) close_program(static_cast<std::int32_t>(programs_.size() - 1), true);
    finished_ = true;
    return false;
  }
  const std::size_t k = chunks_.size();
  chunks_.push_back(Chunk{*frontier_, 0, {}});
  chunks_[k].start.syntax_kept = syntax_->kept;
  std::shared_ptr<Loaded> loaded = read_chunk(k, true);
  const bool ended = frontier_->done || frontier_->offset >= file_->size();
  after_first_read(k, loaded, ended);
  if (ended) {
    if (frontier_->done) read_after_end();
    finished_ = true;
  }
  return true;
}

namespace {
// The '\n' in text, counted 64 bytes at a time in a form the compiler makes vector instructions of.
std::size_t line_ends(std::string_view text) {
  std::size_t n = 0, at = 0;
  for (; at + 64 <= text.size(); at += 64) {
    std::uint8_t in_block = 0;  // at most 64
    for (std::size_t i = 0; i < 64; ++i) in_block = static_cast<std::uint8_t>(in_block + (text[at + i] == '\n'));
    n += in_block;
  }
  for (; at < text.size(); ++at) n += text[at] == '\n';
  return n;
}
}  // namespace

std::shared_ptr<ProgramStream::Loaded> ProgramStream::read_chunk(std::size_t k, bool first) {
  const ReadState start = chunks_[k].start;
  std::string window;
  if (first) {
    read_lines(start.offset, window);
    if (line_ends(window) > kChunkLines) {
      std::size_t at = 0;
      for (std::size_t lines = 0; lines < kChunkLines; ++lines) at = window.find('\n', at) + 1;
      window.resize(at);
    }
  } else {
    file_->read(start.offset, chunks_[k].end - start.offset, window);
  }

  auto loaded = std::make_shared<Loaded>();
  ReadState st = start;
  Problems again;
  again.kept = start.syntax_kept;
  again.keep = false;
  std::size_t unchecked_again = 0;
  auto new_piece = [&](int number) {
    auto piece = std::make_unique<Program>();
    piece->file = file_;
    piece->number = number;
    Program* raw = piece.get();
    loaded->pieces.push_back(std::move(piece));
    if (first) chunks_[k].pieces.push_back(PieceRecord{st.program, st.blocks, 0, 0, -1});
    return raw;
  };
  text::LineReader::Hooks hooks;
  hooks.new_program = [&](int number, std::uint32_t) {
    if (first) {
      ProgramInfo& info = programs_.emplace_back();
      info.pending = std::make_unique<Program>();
      info.program = info.pending.get();
      info.program->file = file_;
      info.program->number = number;
      info.program->stream = this;
      info.program->stream_index = st.program;
    }
    return new_piece(number);
  };
  hooks.sequence_before = [&](std::int32_t n) { return sequence_before(st.program, n, k); };
  text::LineReader reader(*file_, std::clamp(options_.max_digits, 1, kMostDigits), std::move(hooks));
  Program* current = st.program >= 0 ? new_piece(programs_[st.program].program->number) : nullptr;
  if (current) {
    current->blocks.reserve(blocks_hint_);
    current->words.reserve(words_hint_);
  }
  reader.read(window, st, current, first ? *syntax_ : again, first ? unchecked_ : unchecked_again);
  if (current) {
    blocks_hint_ = current->blocks.size() + current->blocks.size() / 8;
    words_hint_ = current->words.size() + current->words.size() / 8;
    st.last_alarms = reader.last_alarms(current, st);
    st.blocks += static_cast<std::int32_t>(current->blocks.size());
  }
  if (first) {
    chunks_[k].end = st.offset;
    *frontier_ = st;
    for (std::size_t j = 0; j < loaded->pieces.size(); ++j) {
      PieceRecord& r = chunks_[k].pieces[j];
      const Program& piece = *loaded->pieces[j];
      r.count = static_cast<std::int32_t>(piece.blocks.size());
      for (const auto& [n, at] : piece.sequence_index) {
        if (r.n_max < r.n_min) r.n_min = r.n_max = n;
        r.n_min = std::min(r.n_min, n);
        r.n_max = std::max(r.n_max, n);
      }
    }
  } else {
    for (std::size_t j = 0; j < loaded->pieces.size(); ++j)
      patch(chunks_[k].pieces[j].program, *loaded->pieces[j], chunks_[k].pieces[j].first);
  }
  alive_[k] = loaded;
  keep(k, loaded);
  return loaded;
}

void ProgramStream::keep(std::size_t chunk, std::shared_ptr<Loaded> loaded) {
  kept_.emplace_front(chunk, std::move(loaded));
  if (kept_.size() > kPiecesKept) kept_.pop_back();
}

void ProgramStream::after_first_read(std::size_t k, const std::shared_ptr<Loaded>& held, bool ended) {
  Loaded& loaded = *held;
  const std::size_t n = loaded.pieces.size();
  for (std::size_t j = 0; j < n; ++j) {
    const PieceRecord r = chunks_[k].pieces[j];
    Program& piece = *loaded.pieces[j];
    if (programs_[r.program].pending) {  // its first piece
      ProgramInfo& info = programs_[r.program];
      info.program->line = piece.line;
      info.program->name = piece.name;
      listener_.program_begun(std::move(info.pending));
    }
    if (r.count > 0) {
      ProgramInfo& info = programs_[r.program];
      info.pieces.emplace_back(k, j);
      info.firsts.push_back(r.first);
      info.blocks = r.first + r.count;
    }
    auto pair = [&](std::int32_t d, std::int32_t e, std::uint8_t id, std::uint32_t line) {
      ProgramInfo& info = programs_[r.program];
      info.match[d] = e;
      info.match[e] = d;
      info.pairs.push_back(Loop{d, e, id, line});
      patch_alive(r.program, d);
    };
    auto fault = [&](std::int32_t index, std::uint32_t line, std::uint16_t column, const char* code,
                     std::string message, std::uint32_t length) {
      loop_fault(r.program, index, Span{file_.get(), line, column, length}, code, std::move(message));
    };
    ProgramInfo& info = programs_[r.program];  // (nothing below adds a program)
    static_assert(static_cast<int>(Statement::do_loop) == static_cast<int>(Statement::while_do) + 1 &&
                  static_cast<int>(Statement::end_loop) == static_cast<int>(Statement::while_do) + 2);
    for (std::size_t i = 0; i < piece.blocks.size(); ++i) {
      const Block& b = piece.blocks[i];
      if (static_cast<unsigned>(b.kind) - static_cast<unsigned>(Statement::while_do) <= 2u) [[unlikely]]
        info.loops.see(r.first + static_cast<std::int32_t>(i), b, pair, fault);
      if (!info.content && (b.kind != Statement::empty || b.sequence >= 0 || b.error >= 0)) [[unlikely]] {
        info.content = true;
        listener_.program_content(*info.program);
      }
    }
    programs_[r.program].count.add(piece);
    if (j + 1 < n || ended) close_program(r.program, ended && j + 1 == n);
  }
  for (std::size_t j = 0; j < n; ++j) patch(chunks_[k].pieces[j].program, *loaded.pieces[j], chunks_[k].pieces[j].first);
  for (const Visitor& v : visitors_)
    for (std::size_t j = 0; j < n; ++j) v(*programs_[chunks_[k].pieces[j].program].program, *loaded.pieces[j], held);
}

void ProgramStream::close_program(std::int32_t program, bool last) {
  ProgramInfo& info = programs_[program];
  if (info.closed) return;
  info.loops.close([&](std::int32_t index, std::uint32_t line, std::uint16_t column, const char* code,
                       std::string message, std::uint32_t length) {
    loop_fault(program, index, Span{file_.get(), line, column, length}, code, std::move(message));
  });
  info.closed = true;
  listener_.program_ended(*info.program, info.content, last);
}

// A loop's problem at block `index`: listed, and raised when the block runs.
void ProgramStream::loop_fault(std::int32_t program, std::int32_t index, Span at, const char* code,
                               std::string message) {
  Diagnostic d{Severity::error, code, std::move(message), at};
  programs_[program].loop_error.try_emplace(index, d);
  loops_->add(std::move(d));
  patch_alive(program, index);
}

// Which of the program's pieces holds block i (i read already, 0 <= i < blocks).
std::size_t ProgramStream::ProgramInfo::piece_holding(std::int32_t i) const {
  return static_cast<std::size_t>(std::upper_bound(firsts.begin(), firsts.end(), i) - firsts.begin() - 1);
}

namespace {
void patch_block(const std::unordered_map<std::int32_t, std::int32_t>& match,
                 const std::unordered_map<std::int32_t, Diagnostic>& loop_error, Program& piece, Block& b,
                 std::int32_t index) {
  if (b.kind != Statement::while_do && b.kind != Statement::do_loop && b.kind != Statement::end_loop) return;
  if (auto m = match.find(index); m != match.end()) b.match = m->second;
  if (auto e = loop_error.find(index); e != loop_error.end() && b.error < 0) {
    b.error = static_cast<std::int32_t>(piece.errors.size());
    piece.errors.push_back(e->second);
  }
}
}  // namespace

void ProgramStream::patch(std::int32_t program, Program& piece, std::int32_t first) const {
  const ProgramInfo& info = programs_[program];
  if (info.match.empty() && info.loop_error.empty()) return;
  for (std::size_t i = 0; i < piece.blocks.size(); ++i)
    patch_block(info.match, info.loop_error, piece, piece.blocks[i], first + static_cast<std::int32_t>(i));
}

void ProgramStream::patch_alive(std::int32_t program, std::int32_t index) {
  const ProgramInfo& info = programs_[program];
  if (info.firsts.empty() || index < info.firsts.front()) return;
  const auto [chunk, j] = info.pieces[info.piece_holding(index)];
  auto alive = alive_.find(chunk);
  if (alive == alive_.end()) return;
  std::shared_ptr<Loaded> loaded = alive->second.lock();
  if (!loaded || j >= loaded->pieces.size()) return;
  const PieceRecord& r = chunks_[chunk].pieces[j];
  if (index < r.first || index >= r.first + static_cast<std::int32_t>(loaded->pieces[j]->blocks.size())) return;
  Program& piece = *loaded->pieces[j];
  patch_block(info.match, info.loop_error, piece, piece.blocks[index - r.first], index);
}

std::shared_ptr<ProgramStream::Loaded> ProgramStream::load(std::size_t chunk) {
  for (auto it = kept_.begin(); it != kept_.end(); ++it)
    if (it->first == chunk) {
      kept_.splice(kept_.begin(), kept_, it);
      return kept_.front().second;
    }
  if (auto alive = alive_.find(chunk); alive != alive_.end())
    if (std::shared_ptr<Loaded> loaded = alive->second.lock()) {
      keep(chunk, loaded);
      return loaded;
    }
  return read_chunk(chunk, false);
}

bool ProgramStream::sequence_before(std::int32_t program, std::int32_t n, std::size_t chunk) {
  if (program < 0 || static_cast<std::size_t>(program) >= programs_.size()) return false;
  for (std::size_t p = 0; p < programs_[program].pieces.size(); ++p) {
    const auto [c, j] = programs_[program].pieces[p];
    if (c >= chunk) break;
    const PieceRecord& r = chunks_[c].pieces[j];
    if (n < r.n_min || n > r.n_max) continue;
    if (load(c)->pieces[j]->sequence_index.contains(n)) return true;
  }
  return false;
}

Program::Piece ProgramStream::piece_of(std::int32_t program, std::int32_t i) {
  while (i >= programs_[program].blocks && !programs_[program].closed && advance()) {
  }
  const ProgramInfo& info = programs_[program];
  if (i < 0 || i >= info.blocks) return {};
  const auto [chunk, j] = info.pieces[info.piece_holding(i)];
  std::shared_ptr<Loaded> loaded = load(chunk);
  const PieceRecord& r = chunks_[chunk].pieces[j];
  const Program* piece = loaded->pieces[j].get();
  return Program::Piece{piece, r.first, r.first + r.count, std::shared_ptr<const Program>(loaded, piece)};
}

std::int32_t ProgramStream::find_sequence(std::int32_t program, std::int32_t n) {
  const std::int64_t key = (static_cast<std::int64_t>(program) << 32) | static_cast<std::uint32_t>(n);
  if (auto it = sequences_.find(key); it != sequences_.end()) return it->second;
  std::int32_t found = -1;
  for (std::size_t checked = 0; found < 0;) {
    for (; checked < programs_[program].pieces.size() && found < 0; ++checked) {
      const auto [chunk, j] = programs_[program].pieces[checked];
      const PieceRecord& r = chunks_[chunk].pieces[j];
      if (n < r.n_min || n > r.n_max) continue;
      const std::shared_ptr<Loaded> loaded = load(chunk);
      const auto& index = loaded->pieces[j]->sequence_index;
      if (auto it = index.find(n); it != index.end()) found = r.first + it->second;
    }
    if (found >= 0 || programs_[program].closed || !advance()) break;
  }
  if (found < 0 && !programs_[program].closed) return found;
  if (sequences_.size() >= (std::size_t{1} << 16)) sequences_.clear();
  sequences_.emplace(key, found);
  return found;
}

void ProgramStream::settle_loop(std::int32_t program, std::int32_t i) {
  while (!programs_[program].closed && !programs_[program].match.contains(i) &&
         !programs_[program].loop_error.contains(i) && advance()) {
  }
}

ProgramStream::Loop ProgramStream::loop_around(std::int32_t program, std::int32_t i) {
  for (;;) {
    const std::int32_t open = programs_[program].loops.first_open();
    if (programs_[program].closed || open < 0 || open >= i || !advance()) break;
  }
  Loop best;
  for (const Loop& l : programs_[program].pairs)
    if (l.begin < i && i <= l.end && l.begin > best.begin) best = l;
  return best;
}

void ProgramStream::visit(Visitor v) {
  for (std::size_t k = 0; k < chunks_.size(); ++k) {
    const std::shared_ptr<Loaded> loaded = load(k);
    for (std::size_t j = 0; j < loaded->pieces.size(); ++j)
      v(*programs_[chunks_[k].pieces[j].program].program, *loaded->pieces[j], loaded);
  }
  visitors_.push_back(std::move(v));
}

// About chunk_bytes_ of text from `offset`, whole lines only (a longer line whole).
void ProgramStream::read_lines(std::size_t offset, std::string& window) const {
  window.clear();
  file_->read(offset, chunk_bytes_, window);
  if (offset + window.size() >= file_->size()) return;
  const std::size_t nl = window.rfind('\n');
  if (nl != std::string::npos) {
    window.resize(nl + 1);
    return;
  }
  for (;;) {  // a line longer than a piece: on to its end
    const std::size_t at = window.size();
    if (file_->read(offset + at, std::size_t{1} << 16, window) == 0) return;
    const std::size_t end = window.find('\n', at);
    if (end != std::string::npos) {
      window.resize(end + 1);
      return;
    }
  }
}

void ProgramStream::read_after_end() {
  std::uint32_t line = frontier_->line;
  const std::uint32_t end_line = frontier_->line;
  std::size_t offset = frontier_->offset;
  std::string window;
  while (offset < file_->size()) {
    read_lines(offset, window);
    if (window.empty()) break;
    text::programs_after_end(window, line, end_line, after_end_);
    offset += window.size();
  }
}

ParseResult ProgramStream::problems() const {
  ParseResult r;
  Problems syntax = *syntax_, loops = *loops_;
  text::merge_problems(syntax, loops, r);
  r.unchecked_lines = unchecked_;
  r.after_end = after_end_;
  return r;
}

const SourceCount& ProgramStream::count(std::int32_t program) const { return programs_[program].count; }

}  // namespace ncurve::nc
