// Work items 0..n-1 on all cores. Results must not depend on which thread ran an item; the
// exception of the lowest item that threw is rethrown, as a loop in order would.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace ncurve::base {

// The cores this process may use (asked once: the library reads it from /sys each time).
inline std::size_t cores() {
  static const std::size_t n = std::max(1u, std::thread::hardware_concurrency());
  return n;
}

template <class Work>
void for_each_on_cores(std::size_t n, Work work) {
  std::vector<std::exception_ptr> errors(n);
  std::atomic<std::size_t> next{0};
  auto run = [&] {
    for (std::size_t k; (k = next++) < n;) {
      try {
        work(k);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> helpers;
  for (std::size_t i = 1; i < std::min(n, cores()); ++i) helpers.emplace_back(run);
  run();
  for (auto& t : helpers) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace ncurve::base
