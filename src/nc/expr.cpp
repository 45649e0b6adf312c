#include "nc/expr.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

namespace ncurve::nc {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double round_half_away(double x) { return x < 0 ? -std::floor(-x + 0.5) : std::floor(x + 0.5); }

bool to_integer(double x, std::int64_t& out) {
  double r = round_half_away(x);
  if (!(std::fabs(r) < 9.0e15)) return false;
  out = static_cast<std::int64_t>(r);
  return true;
}

EvalFault finite(double x, double& out) {
  if (out_of_range(x)) return EvalFault::overflow;
  out = x;
  return EvalFault::none;
}

double atan2_deg(double y, double x, bool signed_range) {
  double a = std::atan2(y, x) / kDeg;
  if (!signed_range && a < 0) a += 360.0;
  return a;
}

}  // namespace

void sincos_deg(double deg, double& s, double& c) {
  // whole multiples of 90 degrees exactly
  const double quarters = deg / 90.0;
  if (std::fabs(quarters) < 0x1p52 && static_cast<double>(static_cast<std::int64_t>(quarters)) == quarters &&
      quarters * 90.0 == deg) {
    static constexpr double kSine[4] = {0, 1, 0, -1};
    const auto q = static_cast<std::size_t>(static_cast<std::int64_t>(quarters) & 3);  // two's complement: -1 -> 3
    s = kSine[q];
    c = kSine[(q + 1) & 3];
    return;
  }
#ifdef __GLIBC__
  ::sincos(deg * kDeg, &s, &c);  // one argument reduction for both
#else
  s = std::sin(deg * kDeg);
  c = std::cos(deg * kDeg);
#endif
}

EvalFault apply_unary(Op op, double a, double& out, const EvalOptions& o) {
  double s, c;
  switch (op) {
    case Op::sin: sincos_deg(a, s, c); out = s; return EvalFault::none;
    case Op::cos: sincos_deg(a, s, c); out = c; return EvalFault::none;
    case Op::tan:
      sincos_deg(a, s, c);
      if (std::fabs(c) < 1e-15) return EvalFault::overflow;
      return finite(s / c, out);
    case Op::asin:
      if (a < -1.0 || a > 1.0) return EvalFault::domain;
      out = std::asin(a) / kDeg;
      if (!o.atan_signed && out < 0) out += 360.0;  // 270..90 without NAT
      return EvalFault::none;
    case Op::acos:
      if (a < -1.0 || a > 1.0) return EvalFault::domain;
      out = std::acos(a) / kDeg;
      return EvalFault::none;
    case Op::atan1: out = std::atan(a) / kDeg; return EvalFault::none;
    case Op::sqrt:
      if (a < 0) return EvalFault::domain;
      out = std::sqrt(a);
      return EvalFault::none;
    case Op::abs: out = std::fabs(a); return EvalFault::none;
    case Op::round: out = round_half_away(a); return EvalFault::none;
    case Op::fix: out = std::trunc(a); return EvalFault::none;
    case Op::fup: out = a < 0 ? -std::ceil(-a) : std::ceil(a); return EvalFault::none;
    case Op::ln:
      if (a <= 0) return EvalFault::domain;
      out = std::log(a);
      return EvalFault::none;
    case Op::exp: return finite(std::exp(a), out);
    case Op::adp: return finite(a * o.adp_scale, out);
    case Op::bin: {  // BCD -> binary
      std::int64_t v;
      if (!to_integer(a, v) || v < 0) return EvalFault::domain;
      std::int64_t result = 0, scale = 1;
      for (; v; v >>= 4, scale *= 10) {
        std::int64_t digit = v & 0xF;
        if (digit > 9) return EvalFault::domain;
        result += digit * scale;
      }
      out = static_cast<double>(result);
      return EvalFault::none;
    }
    case Op::bcd: {  // binary -> BCD
      std::int64_t v;
      if (!to_integer(a, v) || v < 0 || v > 99999999) return EvalFault::domain;
      std::int64_t result = 0;
      for (int shift = 0; v; v /= 10, shift += 4) result |= (v % 10) << shift;
      out = static_cast<double>(result);
      return EvalFault::none;
    }
    default: return EvalFault::domain;
  }
}

EvalFault apply_binary(Op op, double a, double b, double& out, const EvalOptions& o) {
  std::int64_t ia, ib;
  switch (op) {
    case Op::gt: out = a > b; return EvalFault::none;
    case Op::ge: out = a >= b; return EvalFault::none;
    case Op::lt: out = a < b; return EvalFault::none;
    case Op::le: out = a <= b; return EvalFault::none;
    case Op::mod:
      if (!to_integer(a, ia) || !to_integer(b, ib)) return EvalFault::overflow;
      if (ib == 0) return EvalFault::divide_by_zero;
      out = static_cast<double>(ia % ib);
      return EvalFault::none;
    case Op::band: case Op::bor: case Op::bxor:
      if (!to_integer(a, ia) || !to_integer(b, ib)) return EvalFault::overflow;
      out = static_cast<double>(op == Op::band ? (ia & ib) : op == Op::bor ? (ia | ib) : (ia ^ ib));
      return EvalFault::none;
    case Op::pow:
      if (a < 0 && b != std::trunc(b)) return EvalFault::domain;
      if (a == 0 && b < 0) return EvalFault::divide_by_zero;
      return finite(std::pow(a, b), out);
    case Op::atan2_comma:
      if (!o.atan_comma) return EvalFault::not_on_this_control;
      [[fallthrough]];
    case Op::atan2_slash:
      if (a == 0 && b == 0) return EvalFault::domain;
      out = atan2_deg(a, b, o.atan_signed);
      return EvalFault::none;
    default: return EvalFault::domain;
  }
}

}  // namespace ncurve::nc
