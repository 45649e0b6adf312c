#include "base/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace ncurve::base {

std::size_t cores() {
  static const std::size_t n = std::max(1u, std::thread::hardware_concurrency());
  return n;
}

namespace {

void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}

// Looks for done() for up to a millisecond, giving way to other threads now and then (waking a
// sleeping thread takes tens of microseconds); whether it came.
template <class Done>
bool look_for(Done done) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(1);
  for (int spin = 1; !done(); ++spin) {
    relax();
    if (spin % 256 == 0) {
      if (std::chrono::steady_clock::now() > until) return false;
      std::this_thread::yield();
    }
  }
  return true;
}

struct Job {
  void (*work)(void*, std::size_t);
  void* context;
  std::size_t n;
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors;
  int joined = 0;                    // workers, under the pool's lock
  std::atomic<int> finished{0};      // of those, done with it (the last use of the job)

  void run() {
    for (std::size_t k; (k = next++) < n;) {
      try {
        work(context, k);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  }
};

class Pool {
public:
  Pool() {
    for (std::size_t i = 1; i < cores(); ++i) workers_.emplace_back([this, i] { serve(i <= kLooking); });
  }
  ~Pool() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
      ++generation_;
    }
    wake_.notify_all();
    for (auto& t : workers_) t.join();
  }

  // false if the pool is busy with another job
  bool run(Job& job) {
    if (!start(job)) return false;
    finish(job);
    return true;
  }

  // The job offered to the workers, the caller free to go on (false if the pool is busy); the
  // pool stays busy until finish().
  bool start(Job& job) {
    if (busy_.exchange(true)) return false;
    {
      std::lock_guard lock(mutex_);
      job_ = &job;
      ++generation_;
    }
    wake_.notify_all();
    return true;
  }

  // The caller takes the items no worker has, then waits for the workers' last.
  void finish(Job& job) {
    job.run();
    int joined = 0;
    {
      // no worker joins from now on; those that did finish before the job goes out of scope
      std::lock_guard lock(mutex_);
      job_ = nullptr;
      joined = job.joined;
    }
    // they are on their last item: look for a while, as the workers do, then sleep
    auto all_done = [&] { return job.finished.load(std::memory_order_acquire) == joined; };
    if (!look_for(all_done)) {
      std::unique_lock lock(mutex_);
      done_.wait(lock, all_done);
    }
    busy_ = false;
  }

  static Pool& shared() {
    static Pool pool;
    return pool;
  }

private:
  // Jobs come in bursts (the phases of one generated program): the first kLooking workers look
  // for the next before sleeping; the others, on a machine with many cores, sleep at once.
  static constexpr std::size_t kLooking = 3;

  void serve(bool looking) {
    std::uint64_t seen = 0;
    for (;;) {
      if (looking) look_for([&] { return generation_.load(std::memory_order_acquire) != seen; });
      Job* job = nullptr;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return generation_.load() != seen; });
        seen = generation_;
        if (stopping_) return;
        job = job_;
        if (!job) continue;  // woke after the job was done
        ++job->joined;
      }
      job->run();
      {
        std::lock_guard lock(mutex_);
        const int joined = job->joined;
        if (job->finished.fetch_add(1, std::memory_order_release) + 1 == joined) done_.notify_one();
      }
    }
  }

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::atomic<std::uint64_t> generation_{0};
  Job* job_ = nullptr;
  bool stopping_ = false;
  std::atomic<bool> busy_{false};
};

}  // namespace

void for_each_on_cores(std::size_t n, void (*work)(void*, std::size_t), void* context) {
  Job job{work, context, n, {}, {}};
  job.errors.resize(n);
  if (n > 1 && cores() > 1) {
    if (!Pool::shared().run(job)) job.run();
  } else {
    job.run();
  }
  for (auto& e : job.errors)
    if (e) std::rethrow_exception(e);
}

struct Beside::State {
  State(std::size_t n, void (*work)(void*, std::size_t), void* context) : job{work, context, n, {}, {}} {}
  Job job;
  bool started = false;  // offered to the pool (else run at once)
  bool waited = false;
};

Beside::Beside(std::size_t n, void (*work)(void*, std::size_t), void* context)
    : state_(std::make_unique<State>(n, work, context)) {
  State& s = *state_;
  s.job.errors.resize(n);
  s.started = n > 0 && cores() > 1 && Pool::shared().start(s.job);
  if (!s.started) s.job.run();
}

Beside::~Beside() {
  if (state_->started && !state_->waited) Pool::shared().finish(state_->job);
}

void Beside::wait() {
  State& s = *state_;
  if (s.waited) return;
  s.waited = true;
  if (s.started) Pool::shared().finish(s.job);
  for (auto& e : s.job.errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace ncurve::base
