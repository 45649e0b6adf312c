// Measuring beside other work: a pass's runs while the interpreter still runs the program (Ahead),
// the fit's path while its program is emitted (Speculation). Included by generate.cpp alone.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "base/memory.hpp"
#include "base/parallel.hpp"
#include "gen/measure.hpp"
#include "machine/interpreter.hpp"

namespace ncurve::gen::detail {

// Measures a pass's runs while the program still runs, on a thread beside the interpreter: run k
// once a move after it has come (the last run is left to Measurer::measure, which knows where the
// contour ends). stop() before the pass outgrows its reserve (its moves would move) and before
// measuring; runs not done then are measured there.
class Ahead {
public:
  Ahead(const Measurer& m, const std::vector<ContourMove>& moves)
      : measurer_(m), moves_(moves), measured_(room(moves.capacity())), arrived_(moves.size()), worker_([this] { work(); }) {}
  Ahead(const Ahead&) = delete;
  Ahead& operator=(const Ahead&) = delete;
  ~Ahead() { stop(); }

  void arrived(std::size_t moves) {  // the pass has this many moves now
    if (moves % Measurer::kRun != 1) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      arrived_ = moves;
    }
    wake_.notify_one();
  }
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopped_ = true;
    }
    wake_.notify_one();
    if (worker_.joinable()) worker_.join();
  }
  // after stop()
  std::vector<Measured>& measured() { return measured_; }
  const std::vector<Place>& starts() const { return starts_; }
  const std::vector<Place>& ends() const { return ends_; }

private:
  static std::vector<Measured> room(std::size_t moves) {
    std::vector<Measured> measured;
    base::reserve_large(measured, moves);
    measured.resize(moves);
    return measured;
  }
  void work() {
    try {
      for (std::size_t k = 0;; ++k) {
        {
          std::unique_lock<std::mutex> lock(mutex_);
          wake_.wait(lock, [&] { return stopped_ || arrived_ > (k + 1) * Measurer::kRun; });
          if (stopped_) return;
        }
        const Place start = measurer_.run_start(moves_, k, k > 0 ? starts_.back() : Place{});
        const Place end = measurer_.measure_run(moves_, k, start, std::numeric_limits<std::size_t>::max(), measured_);
        starts_.push_back(start);
        ends_.push_back(end);
      }
    } catch (...) {  // Measurer::measure measures the run again and reports what went wrong
    }
  }

  const Measurer& measurer_;
  const std::vector<ContourMove>& moves_;
  std::vector<Measured> measured_;
  std::vector<Place> starts_, ends_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::size_t arrived_ = 0;
  bool stopped_ = false;
  std::thread worker_;
};

inline bool bitwise_equal(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(Vec3)) == 0; }


// The fit's path measured while its program is emitted, read and run: each coordinate as the
// control will read the number written for it (machine::round_to_increment), lengths as the
// interpreter takes them. Its runs are measured by the pool's workers meanwhile and, once the
// moves have come, by all cores. The round trip takes them where the interpreter's moves are these
// bit for bit (the same moves in the same runs give the same figures); else it measures its moves
// itself.
class Speculation {
public:
  Speculation(const geom::Curve& curve, const Options& o, const std::vector<geom::Piece>& pieces)
      : measurer_(curve, o, true), moves_(as_read(pieces, machine::increments_per_mm(o.profile))),
        run_(Measurer::run_of(moves_.size())) {
    const std::size_t runs = (moves_.size() + run_ - 1) / run_;
    starts_.resize(runs);
    ends_.resize(runs);
    measured_.resize(moves_.size());
    beside_.emplace(runs, work_);
  }

  // The figures of `moves` if they are the ones measured.
  std::optional<Stats> take(const std::vector<ContourMove>& moves) {
    try {
      beside_->wait();
    } catch (const std::exception&) {
      return std::nullopt;  // the round trip measures the moves again and reports it
    }
    if (moves.size() != moves_.size()) return std::nullopt;
    for (std::size_t i = 0; i < moves.size(); ++i) {
      const ContourMove &m = moves[i], &s = moves_[i];
      if (m.arc || !bitwise_equal(m.start, s.start) || !bitwise_equal(m.end, s.end) ||
          std::memcmp(&m.length, &s.length, sizeof(double)) != 0)
        return std::nullopt;
    }
    Stats s = measurer_.measure(moves, std::move(measured_), starts_, ends_, true);  // the same moves, the same starts
    s.measured_beside = true;
    return s;
  }

private:
  static std::vector<ContourMove> as_read(const std::vector<geom::Piece>& pieces, double per_unit) {
    auto read = [&](const Vec3& p) {
      return Vec3{machine::round_to_increment(p[0], per_unit), machine::round_to_increment(p[1], per_unit),
                  machine::round_to_increment(p[2], per_unit)};
    };
    std::vector<ContourMove> moves(pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      ContourMove& m = moves[i];
      const bool joined = i > 0 && bitwise_equal(pieces[i].start, pieces[i - 1].end);  // read once
      m.start = joined ? moves[i - 1].end : read(pieces[i].start);
      m.end = read(pieces[i].end);
      m.length = machine::line_length(m.start.data(), m.end.data());
    }
    return moves;
  }

  // run k; run 0 first finds where every run starts (in order), which the others wait for
  void measure_run(std::size_t k) {
    if (k == 0) {
      struct Found {  // also where finding them throws: the others then measure from nowhere, in vain
        std::atomic<bool>& flag;
        ~Found() { flag.store(true, std::memory_order_release); }
      } found{starts_found_};
      for (std::size_t r = 0; r < starts_.size(); ++r)
        starts_[r] = measurer_.run_start(moves_, r, r > 0 ? starts_[r - 1] : Place{}, run_);
    } else {
      while (!starts_found_.load(std::memory_order_acquire)) std::this_thread::yield();
    }
    ends_[k] = measurer_.measure_run(moves_, k, starts_[k], moves_.size(), measured_, run_);
  }

  Measurer measurer_;
  std::vector<ContourMove> moves_;
  std::size_t run_;
  std::vector<Place> starts_, ends_;
  std::atomic<bool> starts_found_{false};
  std::vector<Measured> measured_;
  std::function<void(std::size_t)> work_ = [this](std::size_t k) { measure_run(k); };
  std::optional<base::Beside> beside_;  // last: waited for before the rest goes
};

}  // namespace ncurve::gen::detail
