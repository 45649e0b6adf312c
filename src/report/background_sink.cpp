#include "report/background_sink.hpp"

#include <utility>

namespace ncurve::report {

BackgroundSink::BackgroundSink(machine::MoveSink& writer) : writer_(writer) {
  filling_.moves.reserve(kBatch);
  handed_.moves.reserve(kBatch);
  thread_ = std::thread([this] { work(); });
}

BackgroundSink::~BackgroundSink() {
  try {
    finish();
  } catch (...) {
  }
}

void BackgroundSink::on_move(const machine::Move& m) {
  filling_.moves.push_back(m);
  if (filling_.moves.size() >= kBatch) hand_over();
}

void BackgroundSink::on_setup(const machine::Setup& s) { filling_.setups.emplace_back(filling_.moves.size(), s); }

void BackgroundSink::stopped(const nc::Diagnostic& alarm) {
  finish();
  writer_.stopped(alarm);
}

// The batch filled goes to the writer once it has written the one before.
void BackgroundSink::hand_over() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return !waiting_ || failed_; });
  if (failed_) {
    filling_.moves.clear();
    filling_.setups.clear();
    return;
  }
  std::swap(filling_, handed_);
  waiting_ = true;
  changed_.notify_all();
}

void BackgroundSink::work() {
  Batch batch;
  batch.moves.reserve(kBatch);
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
      std::size_t s = 0;
      for (std::size_t i = 0; i < batch.moves.size(); ++i) {
        for (; s < batch.setups.size() && batch.setups[s].first == i; ++s) writer_.on_setup(batch.setups[s].second);
        writer_.on_move(batch.moves[i]);
      }
      for (; s < batch.setups.size(); ++s) writer_.on_setup(batch.setups[s].second);
    } catch (...) {
      std::lock_guard lock(mutex_);
      failed_ = std::current_exception();
      changed_.notify_all();
      return;
    }
    batch.moves.clear();
    batch.setups.clear();
  }
}

void BackgroundSink::finish() {
  if (!thread_.joinable()) {
    if (failed_) std::rethrow_exception(std::exchange(failed_, nullptr));
    return;
  }
  if (!filling_.moves.empty() || !filling_.setups.empty()) hand_over();
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
