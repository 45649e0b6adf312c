// Tasks run in order on a thread of their own beside the caller's (a streamed file's checks while
// it runs). At most `backlog` wait at once: post() waits for room, so what the tasks hold stays bounded.
#pragma once
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>

namespace ncurve::base {

class TaskThread {
public:
  explicit TaskThread(std::size_t backlog = 8);
  ~TaskThread();  // finishes the tasks posted
  TaskThread(const TaskThread&) = delete;
  TaskThread& operator=(const TaskThread&) = delete;

  void post(std::function<void()> task);
  // Waits until every task posted has run; rethrows the first one's exception.
  void finish();

private:
  void work();

  std::size_t backlog_;
  std::deque<std::function<void()>> tasks_;
  bool busy_ = false;  // the thread runs a task taken from tasks_
  bool stopping_ = false;
  std::exception_ptr failed_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::thread thread_;
};

}  // namespace ncurve::base
