#include "base/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace ncurve::base {

namespace {
// Work shorter than this shows nothing.
constexpr auto kQuiet = std::chrono::milliseconds(500);
constexpr auto kRedraw = std::chrono::milliseconds(200);
}  // namespace

bool Progress::terminal() { return isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string what, std::string unit, std::uint64_t total)
    : what_(std::move(what)), unit_(std::move(unit)), total_(total), shown_(terminal()),
      start_(std::chrono::steady_clock::now()), next_(start_ + kQuiet) {}

Progress::~Progress() {
  if (drawn_) std::fputs("\r\033[K", stderr);  // the line cleared for what follows
}

void Progress::draw(std::uint64_t done) {
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) return;
  next_ = now + kRedraw;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  std::string line = total_ > 0 ? fmt::format("{}: {} of {} {} ({:.0f} %), {:.0f} s", what_, done, total_, unit_,
                                              100.0 * static_cast<double>(done) / static_cast<double>(total_), seconds)
                                : fmt::format("{}: {} {}, {:.0f} s", what_, done, unit_, seconds);
  std::fputs(("\r\033[K" + line).c_str(), stderr);
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace ncurve::base
