// Expressions compiled once to postfix code, and the evaluator that runs that code.
#pragma once
#include <cstdint>
#include <vector>

#include "nc/value.hpp"

namespace ncurve::nc {

enum class Op : std::uint8_t {
  konst, var, var_indirect, neg, pos,
  add, sub, mul, div, mod, band, bor, bxor,
  eq, ne, gt, ge, lt, le,
  sin, cos, tan, asin, acos, atan1, atan2_slash, atan2_comma,
  sqrt, abs, round, fix, fup, ln, exp, pow, adp, bin, bcd,
};

struct Instr {
  Op op;
  std::uint16_t column;  // 1-based column of the operator in its line, for diagnostics
  std::int32_t var;      // variable number for Op::var
  double k;              // constant for Op::konst
};

// A range of instructions in a Program's code pool.
struct Expr {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  bool empty() const { return begin == end; }
};

constexpr int kMaxEvalStack = 48;

// The range of a macro value (0i manual, custom macro: -10^47 .. 10^47); a result beyond it, at any
// step of an expression, is PS0111 CALCULATED DATA OVERFLOW. The negation also catches NaN.
constexpr double kMaxMagnitude = 1e47;
inline bool out_of_range(double x) { return !(x >= -kMaxMagnitude && x <= kMaxMagnitude); }

// Settings that change what a function returns (machine profile).
struct EvalOptions {
  bool atan_signed = false;   // No.6004#0 NAT: ATAN -180..180 and ASIN -90..90 when set
  bool atan_comma = false;    // ATAN[a,b] accepted (30i)
  double adp_scale = 1000.0;  // ADP: 1 / least input increment
};

enum class EvalFault : std::uint8_t {
  none, divide_by_zero, domain, overflow, not_on_this_control,
};

struct EvalResult {
  Value value;
  EvalFault fault = EvalFault::none;
  std::uint16_t column = 0;  // where the fault happened
};

// Pure function part of the evaluator (no variables involved).
// Sine and cosine of a degree angle; exactly 0 or +-1 where they are (SIN[180] is 0, not 1.2e-16).
void sincos_deg(double deg, double& s, double& c);
EvalFault apply_unary(Op op, double a, double& out, const EvalOptions& o);
EvalFault apply_binary(Op op, double a, double b, double& out, const EvalOptions& o);

// Runs code; Vars provides `Value read(int number, std::uint16_t column)` (may throw an Alarm).
template <class Vars>
EvalResult evaluate(const Instr* pc, const Instr* end, Vars& vars, const EvalOptions& o) {
  Value stack[kMaxEvalStack];
  int top = -1;
  for (; pc != end; ++pc) {
    switch (pc->op) {
      case Op::konst: stack[++top] = Value::of(pc->k); break;
      case Op::var:
        stack[++top] = vars.read(pc->var, pc->column);
        if (out_of_range(stack[top].v)) return {{}, EvalFault::overflow, pc->column};
        break;
      case Op::var_indirect: {
        double n = stack[top].number();
        if (!(n > -2147483648.0 && n < 2147483647.0)) return {{}, EvalFault::domain, pc->column};
        stack[top] = vars.read(static_cast<int>(n < 0 ? n - 0.5 : n + 0.5), pc->column);
        if (out_of_range(stack[top].v)) return {{}, EvalFault::overflow, pc->column};
        break;
      }
      case Op::neg: if (!stack[top].vacant) stack[top].v = -stack[top].v; break;
      case Op::pos: break;
      case Op::eq: {
        Value b = stack[top--];
        Value a = stack[top];
        stack[top] = Value::of((a.vacant && b.vacant) || (!a.vacant && !b.vacant && a.v == b.v) ? 1.0 : 0.0);
        break;
      }
      case Op::ne: {
        Value b = stack[top--];
        Value a = stack[top];
        stack[top] = Value::of((a.vacant && b.vacant) || (!a.vacant && !b.vacant && a.v == b.v) ? 0.0 : 1.0);
        break;
      }
      case Op::add: {
        const double b = stack[top--].number();
        const double r = stack[top].number() + b;
        if (out_of_range(r)) return {{}, EvalFault::overflow, pc->column};
        stack[top] = Value::of(r);
        break;
      }
      case Op::sub: {
        const double b = stack[top--].number();
        const double r = stack[top].number() - b;
        if (out_of_range(r)) return {{}, EvalFault::overflow, pc->column};
        stack[top] = Value::of(r);
        break;
      }
      case Op::mul: {
        const double b = stack[top--].number();
        const double r = stack[top].number() * b;
        if (out_of_range(r)) return {{}, EvalFault::overflow, pc->column};
        stack[top] = Value::of(r);
        break;
      }
      case Op::div: {
        const double b = stack[top--].number();
        if (b == 0.0) return {{}, EvalFault::divide_by_zero, pc->column};
        const double r = stack[top].number() / b;
        if (out_of_range(r)) return {{}, EvalFault::overflow, pc->column};
        stack[top] = Value::of(r);
        break;
      }
      case Op::mod: case Op::band: case Op::bor: case Op::bxor:
      case Op::gt: case Op::ge: case Op::lt: case Op::le: case Op::pow:
      case Op::atan2_slash: case Op::atan2_comma: {
        double b = stack[top--].number();
        double out = 0;
        EvalFault f = apply_binary(pc->op, stack[top].number(), b, out, o);
        if (f != EvalFault::none) return {{}, f, pc->column};
        stack[top] = Value::of(out);
        break;
      }
      default: {
        double out = 0;
        EvalFault f = apply_unary(pc->op, stack[top].number(), out, o);
        if (f != EvalFault::none) return {{}, f, pc->column};
        stack[top] = Value::of(out);
        break;
      }
    }
  }
  return {top >= 0 ? stack[top] : Value{}, EvalFault::none, 0};
}

}  // namespace ncurve::nc
