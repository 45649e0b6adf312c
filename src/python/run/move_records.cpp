#include "python/run/move_records.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>

namespace ncurve::python {
namespace {

// The record's first 24 bytes: the integers and flags; the doubles follow at kDoublesAt.
struct Head {
  std::uint32_t line;
  std::int32_t file;
  std::int32_t program;
  std::int32_t code;
  std::uint8_t kind;
  std::uint8_t plane;
  bool clockwise, feed_per_rev, compensated, corner, threading, lookahead;
};
static_assert(sizeof(Head) == 24);
constexpr std::size_t kDoublesAt = sizeof(Head);

double clean(double v) { return v == 0 ? 0.0 : v; }  // no -0, as the CLI writes none

}  // namespace

RecordBuffer::~RecordBuffer() { std::free(data_); }

unsigned char* RecordBuffer::append() {
  if (count_ == capacity_) {
    const std::size_t grown = std::max<std::size_t>(capacity_ * 2, 1024);
    void* more = std::realloc(data_, grown * record_);
    if (!more) throw std::bad_alloc();
    data_ = static_cast<unsigned char*>(more);
    capacity_ = grown;
  }
  return data_ + count_++ * record_;
}

unsigned char* RecordBuffer::release() {
  // cut to size (a large block's spare pages are unmapped); a failed shrink keeps the larger block
  if (count_ > 0 && count_ < capacity_)
    if (void* cut = std::realloc(data_, count_ * record_)) data_ = static_cast<unsigned char*>(cut);
  if (!data_) data_ = static_cast<unsigned char*>(std::malloc(record_));  // NumPy wants a pointer
  if (!data_) throw std::bad_alloc();
  unsigned char* out = data_;
  data_ = nullptr;
  count_ = capacity_ = 0;
  return out;
}

MoveRecords::MoveRecords(const machine::MachineProfile& profile) : frame_(profile) {
  for (char a : std::string_view("ABC"))
    if (profile.axes.find(a) != std::string::npos) rotary_.push_back(machine::axis_index(a));
  // the names in the order NumPy shows them; the offsets as Head and the doubles lay them out
  fields_ = {{"kind", "u1", offsetof(Head, kind)},
             {"line", "<u4", offsetof(Head, line)},
             {"file", "<i4", offsetof(Head, file)},
             {"program", "<i4", offsetof(Head, program)}};
  std::size_t at = kDoublesAt;
  auto real = [&](std::string name) {
    fields_.push_back({std::move(name), "<f8", at});
    at += sizeof(double);
  };
  static constexpr const char* kLetters = "xyzabc";
  for (const char* suffix : {"0", ""}) {  // start, then end (the CSV's x, y, z, a, b, c)
    for (int k = 0; k < 3; ++k) real(std::string(1, kLetters[k]) + suffix);
    for (int k : rotary_) real(std::string(1, kLetters[k]) + suffix);
  }
  for (const char* name : {"cx", "cy", "cz", "f", "length", "seconds"}) real(name);
  size_ = at;
  fields_.insert(fields_.end(), {{"code", "<i4", offsetof(Head, code)},
                                 {"plane", "u1", offsetof(Head, plane)},
                                 {"clockwise", "?", offsetof(Head, clockwise)},
                                 {"feed_per_rev", "?", offsetof(Head, feed_per_rev)},
                                 {"compensated", "?", offsetof(Head, compensated)},
                                 {"corner", "?", offsetof(Head, corner)},
                                 {"threading", "?", offsetof(Head, threading)},
                                 {"lookahead", "?", offsetof(Head, lookahead)}});
  buffer_ = std::make_unique<RecordBuffer>(size_);
}

std::int32_t MoveRecords::file_index(const nc::SourceFile* f) {
  if (f == last_file_) return last_index_;
  std::int32_t index = -1;
  if (f) {
    auto [it, added] = file_index_.try_emplace(f, static_cast<std::int32_t>(files_.size()));
    if (added) files_.push_back(f->name());
    index = it->second;
  }
  last_file_ = f;
  last_index_ = index;
  return index;
}

void MoveRecords::on_move(const machine::Move& m) {
  unsigned char* r = buffer_->append();
  Head h{};
  h.line = m.line;
  h.file = file_index(m.file);
  h.program = m.program;
  h.code = m.is_motion() || m.kind == machine::MoveKind::dwell ? 0 : m.code;
  h.kind = static_cast<std::uint8_t>(m.kind);
  h.plane = m.plane;
  h.clockwise = m.kind == machine::MoveKind::arc && m.clockwise;
  h.feed_per_rev = m.feed_per_rev;
  h.compensated = m.compensated;
  h.corner = m.corner;
  h.threading = m.threading;
  h.lookahead = m.lookahead;
  std::memcpy(r, &h, sizeof h);
  double v[2 * machine::kAxes + 6];
  std::size_t n = 0;
  for (const machine::AxisVector* p : {&m.start, &m.end}) {
    v[n++] = clean(frame_.x((*p)[0]));
    v[n++] = clean((*p)[1]);
    v[n++] = clean((*p)[2]);
    for (int k : rotary_) v[n++] = clean((*p)[k]);
  }
  const bool arc = m.kind == machine::MoveKind::arc;
  v[n++] = arc ? clean(frame_.x(m.center[0])) : 0.0;
  v[n++] = arc ? clean(m.center[1]) : 0.0;
  v[n++] = arc ? clean(m.center[2]) : 0.0;
  v[n++] = m.feed;
  v[n++] = m.length;
  v[n++] = m.seconds;
  std::memcpy(r + kDoublesAt, v, n * sizeof(double));
}

void MoveRecords::on_moves(std::span<const machine::Move> moves) {
  for (const machine::Move& m : moves) on_move(m);
}

}  // namespace ncurve::python
