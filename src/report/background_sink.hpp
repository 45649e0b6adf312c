// A writer run on a second core beside the run: the moves go to it in batches, in order, so its
// output is byte for byte what it writes on the run's own thread.
#pragma once
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "machine/move.hpp"

namespace ncurve::report {

class BackgroundSink final : public machine::MoveSink {
public:
  explicit BackgroundSink(machine::MoveSink& writer);
  ~BackgroundSink() override;
  BackgroundSink(const BackgroundSink&) = delete;
  BackgroundSink& operator=(const BackgroundSink&) = delete;

  void on_move(const machine::Move& m) override;
  void on_setup(const machine::Setup& s) override;
  // After all moves are written (on this thread).
  void stopped(const nc::Diagnostic& alarm) override;
  // Waits until every move is written; rethrows what the writer threw.
  void finish();

private:
  struct Batch {
    std::vector<machine::Move> moves;  // kBatch of them, the first `count` filled
    std::size_t count = 0;
    std::vector<std::pair<std::size_t, machine::Setup>> setups;  // before moves[first]
  };
  static constexpr std::size_t kBatch = 2048;
  void hand_over();
  void work();

  machine::MoveSink& writer_;
  Batch filling_, handed_;
  bool waiting_ = false;  // handed_ holds a batch for the writer
  bool done_ = false;
  std::exception_ptr failed_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::thread thread_;
};

}  // namespace ncurve::report
