#include "serve/connections.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <deque>
#include <functional>
#include <vector>

namespace ncurve::serve {

namespace {

using Clock = std::chrono::steady_clock;

thread_local Connection* serving = nullptr;

// Waits until sock is ready for events or the time is up; true when ready.
bool wait(socket_t sock, short events, Clock::duration time) {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(time).count();
  if (ms <= 0) return false;
  pollfd p{sock, events, 0};
  int n;
  do n = ::poll(&p, 1, static_cast<int>(std::min<long long>(ms, 1 << 30)));
  while (n < 0 && errno == EINTR);
  return n > 0;
}

std::chrono::microseconds timeout(time_t sec, time_t usec) {
  return std::chrono::seconds(sec) + std::chrono::microseconds(usec);
}

void address(const sockaddr_storage& a, std::string& ip, int& port) {
  char text[INET6_ADDRSTRLEN] = "";
  if (a.ss_family == AF_INET) {
    const auto& v4 = reinterpret_cast<const sockaddr_in&>(a);
    ::inet_ntop(AF_INET, &v4.sin_addr, text, sizeof text);
    port = ntohs(v4.sin_port);
  } else if (a.ss_family == AF_INET6) {
    const auto& v6 = reinterpret_cast<const sockaddr_in6&>(a);
    ::inet_ntop(AF_INET6, &v6.sin6_addr, text, sizeof text);
    port = ntohs(v6.sin6_port);
  }
  ip = text;
}

// A socket read and written within a deadline: one for reading a request (its line, headers and
// body, at most `budget` bytes), then one for writing its answer, from the answer's first byte.
class DeadlineStream final : public httplib::Stream {
public:
  DeadlineStream(socket_t sock, const ConnectionLimits& limits, Clock::duration read_timeout,
                 Clock::duration write_timeout)
      : sock_(sock), limits_(limits), read_timeout_(read_timeout), write_timeout_(write_timeout) {}

  void begin_request() {
    deadline_ = Clock::now() + limits_.request_time;
    budget_ = limits_.request_bytes;
    writing_ = false;
  }
  // The request was cut (its deadline or byte bound): what follows on the socket is not a request.
  bool cut() const { return cut_; }
  // Bytes of the next request already read from the socket.
  bool buffered() const { return begin_ < end_; }

  bool is_readable() const override { return wait(sock_, POLLIN, window(read_timeout_)); }
  bool is_writable() const override { return wait(sock_, POLLOUT, window(write_timeout_)); }

  ssize_t read(char* ptr, size_t size) override {
    if (begin_ < end_) {
      const size_t n = std::min(size, end_ - begin_);
      std::copy_n(buffer_ + begin_, n, ptr);
      begin_ += n;
      return static_cast<ssize_t>(n);
    }
    if (budget_ == 0 || !is_readable()) {
      cut_ = true;
      return -1;
    }
    const bool buffered = size < sizeof buffer_;
    ssize_t n;
    do n = ::recv(sock_, buffered ? buffer_ : ptr, std::min(buffered ? sizeof buffer_ : size, budget_), 0);
    while (n < 0 && errno == EINTR);
    if (n <= 0) return n;
    budget_ -= static_cast<size_t>(n);
    if (!buffered) return n;
    begin_ = 0;
    end_ = static_cast<size_t>(n);
    return read(ptr, size);
  }

  ssize_t write(const char* ptr, size_t size) override {
    if (!writing_) {
      writing_ = true;
      deadline_ = Clock::now() + limits_.request_time;
    }
    if (!is_writable()) {
      cut_ = true;
      return -1;
    }
    ssize_t n;
    do n = ::send(sock_, ptr, size, MSG_NOSIGNAL);
    while (n < 0 && errno == EINTR);
    return n;
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage a{};
    socklen_t len = sizeof a;
    if (::getpeername(sock_, reinterpret_cast<sockaddr*>(&a), &len) == 0) address(a, ip, port);
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage a{};
    socklen_t len = sizeof a;
    if (::getsockname(sock_, reinterpret_cast<sockaddr*>(&a), &len) == 0) address(a, ip, port);
  }
  socket_t socket() const override { return sock_; }

private:
  // httplib's timeout for one read or write, cut short by the deadline
  Clock::duration window(Clock::duration timeout) const { return std::min(timeout, deadline_ - Clock::now()); }

  socket_t sock_;
  const ConnectionLimits& limits_;
  Clock::duration read_timeout_, write_timeout_;
  Clock::time_point deadline_ = Clock::now();
  size_t budget_ = 0;
  bool writing_ = false;
  bool cut_ = false;
  char buffer_[4096];
  size_t begin_ = 0, end_ = 0;
};

// A thread for each connection, started when none is free, up to `most`; past it a connection
// waits for a free one.
class ConnectionThreads final : public httplib::TaskQueue {
public:
  explicit ConnectionThreads(std::size_t most) : most_(most) {}
  ~ConnectionThreads() override = default;

  void enqueue(std::function<void()> fn) override {
    std::unique_lock lock(mutex_);
    jobs_.push_back(std::move(fn));
    if (jobs_.size() > idle_ && threads_.size() < most_) threads_.emplace_back([this] { work(); });
    else ready_.notify_one();
  }

  void shutdown() override {
    {
      std::unique_lock lock(mutex_);
      ending_ = true;
    }
    ready_.notify_all();
    for (auto& t : threads_) t.join();  // (no enqueue comes once httplib shuts its queue down)
  }

private:
  void work() {
    for (;;) {
      std::function<void()> fn;
      {
        std::unique_lock lock(mutex_);
        ++idle_;
        ready_.wait(lock, [this] { return !jobs_.empty() || ending_; });
        --idle_;
        if (jobs_.empty()) return;
        fn = std::move(jobs_.front());
        jobs_.pop_front();
      }
      fn();
    }
  }

  std::size_t most_;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::function<void()>> jobs_;
  std::vector<std::thread> threads_;
  std::size_t idle_ = 0;
  bool ending_ = false;
};

}  // namespace

HttpServer::HttpServer(ConnectionLimits limits) : limits_(limits) {
  new_task_queue = [this] { return new ConnectionThreads(limits_.connections); };
  watcher_ = std::thread([this] { watch(); });
}

HttpServer::~HttpServer() {
  {
    std::unique_lock lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  watcher_.join();
}

Connection* HttpServer::current() { return serving; }

void HttpServer::widen_backlog() { ::listen(svr_sock_, SOMAXCONN); }

void HttpServer::shut_down() {
  {
    std::unique_lock lock(mutex_);
    stopping_ = true;
    for (Connection* c : connections_) {
      c->cancel = true;
      ::shutdown(c->sock, SHUT_RDWR);  // a read or write under way returns at once
    }
  }
  wake_.notify_all();
  stop();
}

bool HttpServer::wait_for_request(socket_t sock) const {
  // httplib's keep-alive wait, looking at the server stopping every 50 ms
  const auto until = Clock::now() + std::chrono::seconds(keep_alive_timeout_sec_);
  while (!stopping_ && svr_sock_ != INVALID_SOCKET) {
    const auto left = until - Clock::now();
    if (left <= Clock::duration::zero()) return false;
    pollfd p{sock, POLLIN, 0};
    const int n = ::poll(&p, 1, static_cast<int>(std::min<long long>(
                                    50, std::chrono::duration_cast<std::chrono::milliseconds>(left).count() + 1)));
    if (n > 0) return true;
    if (n < 0 && errno != EINTR) return false;
  }
  return false;
}

bool HttpServer::process_and_close_socket(socket_t sock) {
  Connection connection{sock};
  bool ok = false;
  {
    std::unique_lock lock(mutex_);
    if (!stopping_) ok = connections_.insert(&connection).second;
  }
  if (ok) {
    serving = &connection;
    DeadlineStream stream(sock, limits_, timeout(read_timeout_sec_, read_timeout_usec_),
                          timeout(write_timeout_sec_, write_timeout_usec_));
    for (std::size_t left = keep_alive_max_count_; left > 0 && (stream.buffered() || wait_for_request(sock));
         --left) {
      stream.begin_request();
      bool closed = false;
      ok = process_request(stream, left == 1, closed, nullptr);
      if (!ok || closed || connection.close || stream.cut() || connection.cancel) break;
    }
    serving = nullptr;
    std::unique_lock lock(mutex_);
    connections_.erase(&connection);
  }
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
  return ok;
}

void HttpServer::watch() {
  std::vector<pollfd> fds;
  std::vector<Connection*> of;
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    fds.clear();
    of.clear();
    for (Connection* c : connections_) {
      fds.push_back(pollfd{c->sock, POLLRDHUP, 0});
      of.push_back(c);
    }
    // (a connection leaves the set under the lock, so each one polled is still open)
    if (!fds.empty() && ::poll(fds.data(), fds.size(), 0) > 0)
      for (std::size_t i = 0; i < fds.size(); ++i)
        if (fds[i].revents & (POLLRDHUP | POLLHUP | POLLERR)) of[i]->cancel = true;
    wake_.wait_for(lock, std::chrono::milliseconds(50));
  }
}

}  // namespace ncurve::serve
