// A program file's text: whole in memory, or on disk and read a piece at a time (programs of any size).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ncurve::nc {

class SourceFile {
public:
  // The whole text in memory.
  SourceFile(std::string name, std::string text);
  // A file read piece by piece as it is parsed, never held whole; a pipe or a terminal is first copied
  // to an unnamed temporary file. A byte-order mark is skipped and a CR alone read as LF, as
  // ProgramLibrary does for a text. Throws std::runtime_error when the file cannot be opened or read.
  static std::shared_ptr<SourceFile> open_streamed(const std::string& path, std::string name);
  ~SourceFile();
  SourceFile(const SourceFile&) = delete;
  SourceFile& operator=(const SourceFile&) = delete;

  const std::string& name() const { return name_; }
  bool whole() const { return fd_ < 0; }
  // All of the text when whole(), else empty.
  std::string_view text() const { return text_; }
  // All of the text, a streamed file's read for it.
  std::string all_text() const;
  std::size_t size() const { return whole() ? text_.size() : size_; }
  // Lines of a whole text; of a streamed file, the lines read so far.
  std::size_t line_count() const { return whole() ? line_starts_.size() : lines_read_; }
  // 1-based line number; the line without its end-of-line characters (a streamed file's: its first MB).
  std::string line(std::uint32_t number) const;

  // A streamed file: appends the text from byte `offset` (at most n bytes) to out; returns the bytes added.
  std::size_t read(std::size_t offset, std::size_t n, std::string& out) const;
  // A streamed file: the parser reports where line `number` starts, as it reads it (a sparse index is kept).
  void line_read(std::uint32_t number, std::size_t offset) const {
    if (number > lines_read_) lines_read_ = number;
    if (number % kLineStride == 1) [[unlikely]] note_line_start(number, offset);
  }

private:
  static constexpr std::uint32_t kLineStride = 256;  // a streamed file's line index keeps one line start in this many
  SourceFile(std::string name, int fd, std::size_t skip, std::size_t size);
  void note_line_start(std::uint32_t number, std::size_t offset) const;
  std::string name_;
  std::string text_;
  std::vector<std::size_t> line_starts_;  // whole: every line's; streamed: every kLineStride-th
  int fd_ = -1;
  std::size_t skip_ = 0;  // bytes of a byte-order mark before the text
  std::size_t size_ = 0;
  mutable std::size_t lines_read_ = 0;
  mutable std::vector<std::size_t> sparse_starts_;  // start of line 1 + k * kLineStride
};

}  // namespace ncurve::nc
