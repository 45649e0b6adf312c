// Work items 0..n-1 on all cores. Results must not depend on which thread ran an item; the
// exception of the lowest item that threw is rethrown, as a loop in order would.
#pragma once
#include <cstddef>
#include <memory>

namespace ncurve::base {

// The cores this process may use (asked once: the library reads it from /sys each time).
std::size_t cores();

// Items are shared between the calling thread and a pool of workers, one a core besides it,
// started on first use and kept (starting a thread costs tens of microseconds). A call made while
// the pool is busy (from a worker, or from another thread) runs its items on its own thread.
void for_each_on_cores(std::size_t n, void (*work)(void* context, std::size_t item), void* context);

template <class Work>
void for_each_on_cores(std::size_t n, Work work) {
  for_each_on_cores(n, [](void* context, std::size_t item) { (*static_cast<Work*>(context))(item); }, &work);
}

// Items 0..n-1 of work shared with the pool's workers while the caller goes on; wait() (or the
// destructor) runs on the caller's thread the items no worker has taken, waits for the rest and
// rethrows the lowest item's error, as for_each_on_cores does. Where the pool is busy (or there is
// one core) the items run at once, on the caller's thread. Until wait() the pool is busy: work
// shared meanwhile runs on its own thread. The work must outlive the Beside.
class Beside {
public:
  Beside(std::size_t n, void (*work)(void* context, std::size_t item), void* context);
  template <class Work>
  Beside(std::size_t n, Work& work)
      : Beside(n, [](void* context, std::size_t item) { (*static_cast<Work*>(context))(item); }, &work) {}
  Beside(const Beside&) = delete;
  Beside& operator=(const Beside&) = delete;
  ~Beside();
  void wait();

private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ncurve::base
