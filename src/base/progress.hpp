// Progress of long work on the terminal: "ncurve helicoid: 1200 of 7200 steps (16 %)" on one line
// of standard error, redrawn at most five times a second and cleared when the work ends; nothing
// at all when standard error is not a terminal (a pipe, a file, a test).
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

namespace ncurve::base {

class Progress {
public:
  // what: "ncurve helicoid"; unit: "steps"; total 0: a count without an end.
  Progress(std::string what, std::string unit, std::uint64_t total = 0);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  // `done` units of work so far; cheap when nothing is drawn.
  void at(std::uint64_t done) {
    if (shown_) draw(done);
  }
  // Where standard error is a terminal (the only place progress is drawn).
  static bool terminal();

private:
  void draw(std::uint64_t done);
  std::string what_, unit_;
  std::uint64_t total_;
  bool shown_, drawn_ = false;
  std::chrono::steady_clock::time_point start_, next_;
};

}  // namespace ncurve::base
