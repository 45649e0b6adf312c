#include "report/background_sink.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <span>
#include <type_traits>
#include <utility>

namespace ncurve::report {

BackgroundSink::BackgroundSink(machine::MoveSink& writer) : writer_(writer) {
  filling_.moves.resize(kBatch);
  handed_.moves.resize(kBatch);
  thread_ = std::thread([this] { work(); });
}

BackgroundSink::~BackgroundSink() {
  try {
    finish();
  } catch (...) {
  }
}

// The move is written past this core's cache, to memory (streaming stores), where the writer's
// core reads it: the run's own stores then never wait for that core to give a batch's lines back.
// (A vector's elements are at operator new's 16-byte alignment, a Move a multiple of 16 bytes.)
static void put_move(machine::Move& to, const machine::Move& m) {
#if defined(__SSE2__)
  if constexpr (sizeof(machine::Move) % 16 == 0 && __STDCPP_DEFAULT_NEW_ALIGNMENT__ >= 16 &&
                std::is_trivially_copyable_v<machine::Move>) {
    auto* d = reinterpret_cast<__m128i*>(&to);
    const auto* s = reinterpret_cast<const __m128i*>(&m);
    for (std::size_t i = 0; i < sizeof(machine::Move) / 16; ++i) _mm_stream_si128(d + i, _mm_loadu_si128(s + i));
    return;
  }
#endif
  to = m;
}

void BackgroundSink::on_move(const machine::Move& m) {
  put_move(filling_.moves[filling_.count], m);
  if (++filling_.count == kBatch) hand_over();
}

void BackgroundSink::on_setup(const machine::Setup& s) { filling_.setups.emplace_back(filling_.count, s); }

void BackgroundSink::stopped(const nc::Diagnostic& alarm) {
  finish();
  writer_.stopped(alarm);
}

// The batch filled goes to the writer once it has written the one before.
void BackgroundSink::hand_over() {
#if defined(__SSE2__)
  _mm_sfence();  // the streamed moves before the hand-over
#endif
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return !waiting_ || failed_; });
  if (failed_) {
    filling_.count = 0;
    filling_.setups.clear();
    return;
  }
  std::swap(filling_, handed_);
  waiting_ = true;
  changed_.notify_all();
}

void BackgroundSink::work() {
  Batch batch;
  batch.moves.resize(kBatch);
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return waiting_ || done_; });
      if (!waiting_) return;
      std::swap(batch, handed_);
      waiting_ = false;
      changed_.notify_all();
    }
    try {
      // the moves between two setups at once
      const std::span<const machine::Move> moves(batch.moves.data(), batch.count);
      std::size_t from = 0;
      for (const auto& [before, setup] : batch.setups) {
        if (before > from) writer_.on_moves(moves.subspan(from, before - from));
        writer_.on_setup(setup);
        from = before;
      }
      if (moves.size() > from) writer_.on_moves(moves.subspan(from));
    } catch (...) {
      std::lock_guard lock(mutex_);
      failed_ = std::current_exception();
      changed_.notify_all();
      return;
    }
    batch.count = 0;
    batch.setups.clear();
  }
}

void BackgroundSink::finish() {
  if (!thread_.joinable()) {
    if (failed_) std::rethrow_exception(std::exchange(failed_, nullptr));
    return;
  }
  if (filling_.count || !filling_.setups.empty()) hand_over();
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !waiting_ || failed_; });
    done_ = true;
    changed_.notify_all();
  }
  thread_.join();
  if (failed_) std::rethrow_exception(std::exchange(failed_, nullptr));
}

}  // namespace ncurve::report
