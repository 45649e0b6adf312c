// Puts a variable back to the value it had when the guard was made, however the scope ends (an
// alarm throws through it).
#pragma once

namespace ncurve::base {

template <class T>
class RestoreOnExit {
public:
  explicit RestoreOnExit(T& var) : var_(var), saved_(var) {}
  RestoreOnExit(const RestoreOnExit&) = delete;
  RestoreOnExit& operator=(const RestoreOnExit&) = delete;
  ~RestoreOnExit() { var_ = saved_; }

private:
  T& var_;
  T saved_;
};

}  // namespace ncurve::base
