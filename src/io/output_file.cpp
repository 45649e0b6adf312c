#include "io/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <mutex>

#include <fmt/format.h>

namespace ncurve::io {
namespace fs = std::filesystem;
namespace {

std::string reason(int err) { return err ? std::strerror(err) : "write error"; }

// The temporaries being written, removed by a SIGINT, SIGTERM or SIGHUP that ends the process
// before they are renamed (unlink is safe in a signal handler; the names outlive their slot).
std::array<std::atomic<const char*>, 16> live_temporaries{};

extern "C" void remove_temporaries_and_die(int sig) {
  for (auto& slot : live_temporaries)
    if (const char* name = slot.load()) ::unlink(name);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// Installs the handler for the signals whose action is still the default (a server's own stays).
void catch_stop_signals() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction old{};
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
      struct sigaction act{};
      act.sa_handler = remove_temporaries_and_die;
      sigemptyset(&act.sa_mask);
      ::sigaction(sig, &act, nullptr);
    }
  });
}

void track(const std::string& temporary) {
  catch_stop_signals();
  for (auto& slot : live_temporaries) {
    const char* expected = nullptr;
    if (slot.compare_exchange_strong(expected, temporary.c_str())) return;
  }
}

void untrack(const std::string& temporary) {
  for (auto& slot : live_temporaries) {
    const char* expected = temporary.c_str();
    if (slot.compare_exchange_strong(expected, nullptr)) return;
  }
}

// Creates an empty file beside `path` that no other process has; returns its name.
std::string make_temporary(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  fs::path target(path);
  for (int attempt = 0; attempt < 100; ++attempt) {
    fs::path tmp = target.parent_path() /
                   fmt::format(".{}.{}-{}.tmp", target.filename().string(), ::getpid(), counter++);
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return tmp.string();
    }
    if (errno != EEXIST) throw OutputError(fmt::format("{}: cannot write: {}", path, reason(errno)));
  }
  throw OutputError(fmt::format("{}: cannot write: no free temporary name beside it", path));
}

}  // namespace

bool same_file(const std::string& path, const std::vector<std::string>& inputs) {
  if (path == "-") return false;
  std::error_code ec;
  for (const auto& in : inputs) {
    if (in.empty() || in == "-") continue;
    if (fs::equivalent(path, in, ec)) return true;
  }
  return false;
}

OutputFile::OutputFile(std::string path, const std::vector<std::string>& inputs) : path_(std::move(path)) {
  if (path_.empty()) throw OutputError("an output file name is empty");
  if (is_stdout()) {
    out_ = &std::cout;
    return;
  }
  if (same_file(path_, inputs))
    throw OutputError(fmt::format("{}: refusing to write over an input file", path_));
  struct stat st{};
  bool in_place = ::stat(path_.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
  if (in_place && S_ISDIR(st.st_mode)) throw OutputError(fmt::format("{}: cannot write: it is a folder", path_));
  if (!in_place) {
    temporary_ = make_temporary(path_);
    track(temporary_);
  }
  constexpr std::size_t kBuffer = 1 << 20;
  buffer_ = std::make_unique_for_overwrite<char[]>(kBuffer);
  file_.rdbuf()->pubsetbuf(buffer_.get(), kBuffer);  // before open, as libstdc++ requires
  errno = 0;
  file_.open(in_place ? path_ : temporary_, std::ios::binary | std::ios::trunc);
  if (!file_) {
    int err = errno;
    if (!temporary_.empty()) {
      untrack(temporary_);
      std::remove(temporary_.c_str());
    }
    temporary_.clear();
    throw OutputError(fmt::format("{}: cannot write: {}", path_, reason(err)));
  }
  out_ = &file_;
}

OutputFile::~OutputFile() {
  if (!committed_ && !temporary_.empty()) {
    file_.close();
    std::remove(temporary_.c_str());
    untrack(temporary_);
  }
}

void OutputFile::commit() {
  if (committed_) return;
  if (is_stdout()) {
    committed_ = true;
    check_stdout();
    return;
  }
  errno = 0;
  file_.flush();
  bool ok = static_cast<bool>(file_);
  int err = errno;
  file_.close();
  if (ok && file_.fail()) {
    ok = false;
    err = errno;
  }
  if (!ok) throw OutputError(fmt::format("{}: cannot write: {}", path_, reason(err)));
  if (!temporary_.empty()) {
    // Only a complete file gets the requested name; mode as a new file would have.
    mode_t mask = ::umask(0);
    ::umask(mask);
    ::chmod(temporary_.c_str(), 0666 & ~mask);
    if (std::rename(temporary_.c_str(), path_.c_str()) != 0)
      throw OutputError(fmt::format("{}: cannot write: {}", path_, reason(errno)));
    untrack(temporary_);
    temporary_.clear();
  }
  committed_ = true;
}

void write_file(const std::string& path, const std::string& text, const std::vector<std::string>& inputs) {
  OutputFile f(path, inputs);
  f.stream() << text;
  f.commit();
}

void check_stdout() {
  errno = 0;
  std::cout.flush();
  bool ok = static_cast<bool>(std::cout);
  int err = errno;
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    ok = false;
    err = errno;
  }
  if (!ok) throw OutputError(fmt::format("standard output: cannot write: {}", reason(err)));
}

}  // namespace ncurve::io
