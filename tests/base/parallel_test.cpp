// The pool behind for_each_on_cores: every item once, errors in item order, and calls made while
// it is busy (nested, or from another thread) still done.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "base/parallel.hpp"

using namespace ncurve;

TEST(Parallel, EveryItemRunsOnce) {
  for (std::size_t n : {0u, 1u, 2u, 7u, 1000u}) {
    std::vector<std::atomic<int>> runs(n);
    base::for_each_on_cores(n, [&](std::size_t k) { ++runs[k]; });
    for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(runs[k].load(), 1) << k << " of " << n;
  }
}

TEST(Parallel, TheLowestItemsErrorIsRethrown) {
  for (int round = 0; round < 20; ++round) {
    try {
      base::for_each_on_cores(64, [](std::size_t k) {
        if (k % 10 == 3) throw std::runtime_error("item " + std::to_string(k));
      });
      FAIL() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "item 3");
    }
  }
}

TEST(Parallel, CallsWhileBusyAreDone) {
  // nested: each outer item runs an inner loop; two threads at once, each with nested loops
  auto nested = [] {
    std::atomic<long> sum{0};
    base::for_each_on_cores(16, [&](std::size_t i) {
      base::for_each_on_cores(16, [&](std::size_t j) { sum += static_cast<long>(i * 16 + j); });
    });
    return sum.load();
  };
  const long expected = 255 * 256 / 2;
  long a = 0, b = 0;
  std::thread other([&] { a = nested(); });
  b = nested();
  other.join();
  EXPECT_EQ(a, expected);
  EXPECT_EQ(b, expected);
}

// Work beside the caller: every item once, its results there after wait(), the lowest item's
// error rethrown there; work the caller shares meanwhile is still done (on its own thread); work
// left unwaited is finished when the Beside goes.
TEST(Parallel, WorkBesideTheCaller) {
  for (int round = 0; round < 50; ++round) {
    std::vector<std::atomic<int>> runs(5);
    std::vector<long> sums(5, 0);
    auto work = [&](std::size_t k) {
      ++runs[k];
      for (long i = 1; i <= 1000; ++i) sums[k] += i * static_cast<long>(k + 1);
    };
    base::Beside b(5, work);
    std::atomic<long> shared{0};
    base::for_each_on_cores(8, [&](std::size_t k) { shared += static_cast<long>(k); });
    b.wait();
    b.wait();  // once is enough
    for (std::size_t k = 0; k < 5; ++k) {
      EXPECT_EQ(runs[k].load(), 1) << k;
      EXPECT_EQ(sums[k], 500500 * static_cast<long>(k + 1)) << k;
    }
    EXPECT_EQ(shared.load(), 28);
  }
  auto fails = [](std::size_t k) {
    if (k >= 2) throw std::runtime_error("item " + std::to_string(k));
  };
  base::Beside failing(6, fails);
  try {
    failing.wait();
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "item 2");
  }
  std::atomic<int> runs{0};
  auto count = [&](std::size_t) { ++runs; };
  { base::Beside unwaited(3, count); }
  EXPECT_EQ(runs.load(), 3);
  // beside a busy pool: at once, on the caller's thread
  base::for_each_on_cores(2, [&](std::size_t) {
    std::atomic<int> inner{0};
    auto add = [&](std::size_t) { ++inner; };
    base::Beside nested(4, add);
    EXPECT_EQ(inner.load(), 4);
    nested.wait();
  });
}
