// The moves of a run as fixed-size records in one growing buffer, which NumPy then takes as a
// structured array without a copy (no Python object a move). Plain C++: the layout is described
// here and turned into a dtype by the binding.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "machine/move.hpp"
#include "machine/profile.hpp"
#include "report/writers.hpp"

namespace ncurve::python {

// A field of the record: its name (the CSV's column where the CSV has it), NumPy's type code and
// its byte offset.
struct RecordField {
  std::string name;
  std::string format;  // "<f8", "<u4", "<i4", "u1", "?"
  std::size_t offset;
};

// Bytes from malloc, grown by realloc (a large block is moved by remapping its pages, not copied,
// and pages not yet written take no memory) and freed by free(): what the array's capsule frees.
class RecordBuffer {
public:
  explicit RecordBuffer(std::size_t record_size) : record_(record_size) {}
  ~RecordBuffer();
  RecordBuffer(const RecordBuffer&) = delete;
  RecordBuffer& operator=(const RecordBuffer&) = delete;
  // Room for one more record (for the caller to fill whole); throws std::bad_alloc.
  unsigned char* append();
  std::size_t count() const { return count_; }
  // The buffer cut to its records, given up by this object (free() it); never null.
  unsigned char* release();

private:
  std::size_t record_;
  unsigned char* data_ = nullptr;
  std::size_t count_ = 0, capacity_ = 0;
};

// A MoveSink writing each move (motions, dwells and events alike) as one record: kind, line, file
// (index into files()), program, code, plane and flags, then start x0 y0 z0, end x y z, the A B C
// the profile has (a0 .. and a ..), arc centre cx cy cz, f, length, seconds. Coordinates as the
// CLI writes them: work coordinates in mm, X as a diameter on a lathe in diameter mode.
class MoveRecords final : public machine::MoveSink {
public:
  explicit MoveRecords(const machine::MachineProfile& profile);
  void on_move(const machine::Move& m) override;
  void on_moves(std::span<const machine::Move> moves) override;

  const std::vector<RecordField>& fields() const { return fields_; }
  std::size_t record_size() const { return size_; }
  std::size_t count() const { return buffer_->count(); }
  // The records, given up by this sink (the run is over).
  std::unique_ptr<RecordBuffer> take() { return std::move(buffer_); }
  // The names of the files the moves' `file` indexes, in order of first use.
  const std::vector<std::string>& files() const { return files_; }

private:
  std::int32_t file_index(const nc::SourceFile* f);
  report::OutputFrame frame_;
  std::vector<int> rotary_;  // axis indexes of A, B, C the profile has
  std::vector<RecordField> fields_;
  std::size_t size_ = 0;  // bytes a record
  std::unique_ptr<RecordBuffer> buffer_;
  std::vector<std::string> files_;
  std::unordered_map<const nc::SourceFile*, std::int32_t> file_index_;
  const nc::SourceFile* last_file_ = nullptr;
  std::int32_t last_index_ = -1;
};

}  // namespace ncurve::python
