#include "base/task_thread.hpp"

namespace ncurve::base {

TaskThread::TaskThread(std::size_t backlog) : backlog_(backlog == 0 ? 1 : backlog), thread_([this] { work(); }) {}

TaskThread::~TaskThread() {
  {
    std::unique_lock lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void TaskThread::post(std::function<void()> task) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return tasks_.size() < backlog_; });
  tasks_.push_back(std::move(task));
  lock.unlock();
  changed_.notify_all();
}

void TaskThread::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return tasks_.empty() && !busy_; });
  if (failed_) std::rethrow_exception(std::exchange(failed_, nullptr));
}

void TaskThread::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return !tasks_.empty() || stopping_; });
    if (tasks_.empty()) return;  // stopping, and all done
    std::function<void()> task = std::move(tasks_.front());
    tasks_.pop_front();
    busy_ = true;
    lock.unlock();
    changed_.notify_all();  // room for post()
    try {
      if (!failed_) task();  // after a failure the rest are dropped: finish() reports the first
    } catch (...) {
      failed_ = std::current_exception();
    }
    task = nullptr;  // what it held is let go on this thread, before finish() returns
    lock.lock();
    busy_ = false;
    changed_.notify_all();
  }
}

}  // namespace ncurve::base
