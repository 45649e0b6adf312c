#include "geom/sym.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <tuple>
#include <numbers>
#include <stdexcept>

#include "base/vector_clones.hpp"
#include "nc/diagnostic.hpp"
#include "nc/program.hpp"

namespace ncurve::geom {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Nodes this thread may still allocate under a SymBudget (-1: no budget).
thread_local std::int64_t budget_left = -1;

std::shared_ptr<SymNode> allocate() {
  if (budget_left == 0) throw SymTooLarge();
  if (budget_left > 0) --budget_left;
  return std::make_shared<SymNode>();
}

Sym node(SymOp op, Sym a, Sym b = nullptr) {
  auto n = allocate();
  n->op = op;
  n->a = std::move(a);
  n->b = std::move(b);
  return n;
}

bool is_k(const Sym& e, double k) { return e->op == SymOp::konst && e->k == k; }
bool is_const(const Sym& e) { return e->op == SymOp::konst; }

bool same(const Sym& x, const Sym& y) {
  if (x == y) return true;
  if (!x || !y || x->op != y->op) return false;
  if (x->op == SymOp::konst) return x->k == y->k;
  if (x->op == SymOp::var) return x->var == y->var;
  return same(x->a, y->a) && same(x->b, y->b);
}

nc::Op to_nc(SymOp op) {
  switch (op) {
    case SymOp::sin: return nc::Op::sin;
    case SymOp::cos: return nc::Op::cos;
    case SymOp::tan: return nc::Op::tan;
    case SymOp::asin: return nc::Op::asin;
    case SymOp::acos: return nc::Op::acos;
    case SymOp::atan: return nc::Op::atan1;
    case SymOp::atan2: return nc::Op::atan2_slash;
    case SymOp::sqrt: return nc::Op::sqrt;
    case SymOp::abs: return nc::Op::abs;
    case SymOp::ln: return nc::Op::ln;
    case SymOp::exp: return nc::Op::exp;
    case SymOp::pow: return nc::Op::pow;
    default: return nc::Op::konst;
  }
}

const char* function_name(SymOp op) {
  switch (op) {
    case SymOp::sin: return "SIN";
    case SymOp::cos: return "COS";
    case SymOp::tan: return "TAN";
    case SymOp::asin: return "ASIN";
    case SymOp::acos: return "ACOS";
    case SymOp::atan: case SymOp::atan2: return "ATAN";
    case SymOp::sqrt: return "SQRT";
    case SymOp::abs: return "ABS";
    case SymOp::ln: return "LN";
    case SymOp::exp: return "EXP";
    case SymOp::pow: return "POW";
    default: return "";
  }
}

int digit_count(std::string_view s) {
  return static_cast<int>(std::count_if(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }));
}

// A constant (>= 0) as every FANUC reads it: no exponent, a decimal point, at most 8 digits (the
// leading zero of 0.5 counts; it is left out where the digit is worth more). What 8 digits hold
// to worse than 1e-6 keeps 15 significant digits: the program then fails loudly on an 8-digit
// control instead of cutting a different curve.
std::string number_text(double k) {
  auto fixed = [&](int decimals) {
    std::string s = fmt::format("{:.{}f}", k, decimals);
    if (s.find('.') == std::string::npos) s += '.';
    while (s.back() == '0') s.pop_back();
    return s;
  };
  std::string best;
  for (int decimals = 0; decimals <= 40; ++decimals) {
    std::string s = fixed(decimals);
    if (s.size() > 1 && s[0] == '0' && digit_count(s) > nc::kPortableDigits) s.erase(0, 1);  // .xxxxxxxx
    if (digit_count(s) > nc::kPortableDigits && !best.empty()) break;
    best = s;
    if (std::strtod(s.c_str(), nullptr) == k) return best;
  }
  if (std::fabs(std::strtod(best.c_str(), nullptr) - k) <= 1e-6 * k) return best;
  const int exponent = static_cast<int>(std::floor(std::log10(k)));
  return fixed(std::clamp(nc::kMostDigits - 1 - exponent, 0, 40));
}

// |k| as number_text prints it, and the relative error of that text (1 where it takes more
// digits than every control reads).
struct Number {
  std::string text;
  double error;
};
Number printed(double k) {
  Number n{number_text(std::fabs(k)), 0};
  if (k == 0) return n;
  if (digit_count(n.text) > nc::kPortableDigits) n.error = 1;
  else n.error = std::fabs(std::strtod(n.text.c_str(), nullptr) - std::fabs(k)) / std::fabs(k);
  return n;
}

struct Printed {
  std::string text;
  int depth;
};

// Precedence: 1 sums and signs, 2 products, 3 primaries.
int precedence(const Sym& e) {
  switch (e->op) {
    case SymOp::add: case SymOp::sub: case SymOp::neg: return 1;
    case SymOp::mul: case SymOp::div: return 2;
    default: return 3;
  }
}

Printed print(const Sym& e);

Printed operand(const Sym& e, int needed) {
  Printed p = print(e);
  if (precedence(e) >= needed) return p;
  return {fmt::format("[{}]", p.text), p.depth + 1};
}

Printed print(const Sym& e) {
  switch (e->op) {
    case SymOp::konst: {
      const std::string sign = e->k < 0 ? "-" : "";
      // a small constant 8 digits cannot hold, by its reciprocal: [1./3282.8064]
      Number k = printed(e->k);
      if (k.error > 1e-6) {
        const Number reciprocal = printed(1 / e->k);
        if (reciprocal.error <= 1e-6) return {fmt::format("{}[1./{}]", sign, reciprocal.text), 1};
      }
      return {sign + std::move(k.text), 0};
    }
    case SymOp::var: return {fmt::format("#{}", e->var), 0};
    case SymOp::neg: {
      Printed a = operand(e->a, 2);
      return {fmt::format("-{}", a.text), a.depth};
    }
    case SymOp::add: case SymOp::sub: {
      Printed a = operand(e->a, 1), b = operand(e->b, 2);
      return {a.text + (e->op == SymOp::add ? "+" : "-") + b.text, std::max(a.depth, b.depth)};
    }
    case SymOp::mul: case SymOp::div: {
      Printed a = operand(e->a, 2), b = operand(e->b, 3);
      return {a.text + (e->op == SymOp::mul ? "*" : "/") + b.text, std::max(a.depth, b.depth)};
    }
    case SymOp::atan2: {
      Printed a = print(e->a), b = print(e->b);
      return {fmt::format("ATAN[{}]/[{}]", a.text, b.text), 1 + std::max(a.depth, b.depth)};
    }
    case SymOp::pow: {
      Printed a = print(e->a), b = print(e->b);
      return {fmt::format("POW[{},{}]", a.text, b.text), 1 + std::max(a.depth, b.depth)};
    }
    default: {
      Printed a = print(e->a);
      return {fmt::format("{}[{}]", function_name(e->op), a.text), 1 + a.depth};
    }
  }
}

}  // namespace

SymBudget::SymBudget(std::int64_t nodes) : outer_(budget_left) { budget_left = nodes; }
SymBudget::~SymBudget() { budget_left = outer_; }

Sym konst(double k) {
  auto n = allocate();
  n->op = SymOp::konst;
  n->k = k;
  return n;
}

Sym variable(int number) {
  auto n = allocate();
  n->op = SymOp::var;
  n->var = number;
  return n;
}

namespace {

// A function of constants as the control evaluates it (FANUC's own functions); null where it is
// not one, or faults.
Sym folded(SymOp op, const Sym& a, const Sym& b, const nc::EvalOptions& options) {
  if (!is_const(a) || (b && !is_const(b))) return nullptr;
  double out = 0;
  const nc::EvalFault f = b ? nc::apply_binary(to_nc(op), a->k, b->k, out, options)
                            : nc::apply_unary(to_nc(op), a->k, out, options);
  return f == nc::EvalFault::none && std::isfinite(out) ? konst(out) : nullptr;
}

}  // namespace

Sym make(SymOp op, Sym a, Sym b) {
  switch (op) {
    case SymOp::neg:
      if (is_const(a)) return konst(-a->k);
      if (a->op == SymOp::neg) return a->a;
      return node(op, a);
    case SymOp::add:
      if (is_const(a) && is_const(b)) return konst(a->k + b->k);
      if (is_k(a, 0)) return b;
      if (is_k(b, 0)) return a;
      if (b->op == SymOp::neg) return make(SymOp::sub, a, b->a);
      if (is_const(b) && b->k < 0) return make(SymOp::sub, a, konst(-b->k));
      if (a->op == SymOp::neg) return make(SymOp::sub, b, a->a);
      if (same(a, b)) return make(SymOp::mul, konst(2), a);
      if (b->op == SymOp::sub) return make(SymOp::sub, make(SymOp::add, a, b->a), b->b);  // a+[x-y]: a+x-y
      return node(op, a, b);
    case SymOp::sub:
      if (is_const(a) && is_const(b)) return konst(a->k - b->k);
      if (is_k(b, 0)) return a;
      if (is_k(a, 0)) return make(SymOp::neg, b);
      if (b->op == SymOp::neg) return make(SymOp::add, a, b->a);
      if (is_const(b) && b->k < 0) return make(SymOp::add, a, konst(-b->k));
      if (same(a, b)) return konst(0);
      if (a->op == SymOp::neg && same(a->a, b)) return make(SymOp::neg, make(SymOp::mul, konst(2), b));
      if (b->op == SymOp::add) return make(SymOp::sub, make(SymOp::sub, a, b->a), b->b);  // a-[x+y]: a-x-y
      if (b->op == SymOp::sub) return make(SymOp::add, make(SymOp::sub, a, b->a), b->b);  // a-[x-y]: a-x+y
      return node(op, a, b);
    case SymOp::mul:
      if (is_const(a) && is_const(b)) return konst(a->k * b->k);
      if (is_k(a, 0) || is_k(b, 0)) return konst(0);
      if (is_k(a, 1)) return b;
      if (is_k(b, 1)) return a;
      if (is_k(a, -1)) return make(SymOp::neg, b);
      if (is_k(b, -1)) return make(SymOp::neg, a);
      if (a->op == SymOp::neg) return make(SymOp::neg, make(SymOp::mul, a->a, b));
      if (b->op == SymOp::neg) return make(SymOp::neg, make(SymOp::mul, a, b->a));
      if (is_const(a) && a->k < 0) return make(SymOp::neg, make(SymOp::mul, konst(-a->k), b));
      if (is_const(b) && b->k < 0) return make(SymOp::neg, make(SymOp::mul, a, konst(-b->k)));
      if (is_const(b)) return make(SymOp::mul, b, a);  // constants first: 2.*#1
      if (is_const(a) && b->op == SymOp::mul && is_const(b->a)) return make(SymOp::mul, konst(a->k * b->a->k), b->b);
      return node(op, a, b);
    case SymOp::div:
      if (is_const(a) && is_const(b) && b->k != 0) return konst(a->k / b->k);
      if (is_k(a, 0)) return konst(0);
      if (is_k(b, 1)) return a;
      if (a->op == SymOp::neg) return make(SymOp::neg, make(SymOp::div, a->a, b));
      if (b->op == SymOp::neg) return make(SymOp::neg, make(SymOp::div, a, b->a));
      if (is_const(b) && b->k < 0) return make(SymOp::neg, make(SymOp::div, a, konst(-b->k)));
      return node(op, a, b);
    case SymOp::pow:
      if (is_k(b, 1)) return a;
      if (is_k(b, 0)) return konst(1);
      if (is_k(b, 2)) return make(SymOp::mul, a, a);
      return node(op, a, b);
    default:
      // ASIN and ATAN's range is the control's setting (NAT): bind() folds them with it
      if (op != SymOp::asin && op != SymOp::atan)
        if (Sym k = folded(op, a, b, {})) return k;
      return node(op, a, b);
  }
}

Sym from_code(const std::vector<nc::Instr>& code, const std::string& origin) {
  std::vector<Sym> stack;
  auto pop = [&] {
    Sym s = stack.back();
    stack.pop_back();
    return s;
  };
  for (const nc::Instr& in : code) {
    auto refuse = [&](const char* what) {
      throw nc::Alarm(nc::Diagnostic{nc::Severity::error, "NC9101",
                                     fmt::format("{}: column {}: {} cannot be differentiated in a curve", origin,
                                                 in.column, what),
                                     nc::Span{}});
    };
    switch (in.op) {
      case nc::Op::konst: stack.push_back(konst(in.k)); break;
      case nc::Op::var: stack.push_back(variable(in.var)); break;
      case nc::Op::pos: break;
      case nc::Op::neg: stack.push_back(make(SymOp::neg, pop())); break;
      case nc::Op::add: case nc::Op::sub: case nc::Op::mul: case nc::Op::div:
      case nc::Op::atan2_slash: case nc::Op::atan2_comma: case nc::Op::pow: {
        Sym b = pop();
        Sym a = pop();
        SymOp op = in.op == nc::Op::add   ? SymOp::add
                   : in.op == nc::Op::sub ? SymOp::sub
                   : in.op == nc::Op::mul ? SymOp::mul
                   : in.op == nc::Op::div ? SymOp::div
                   : in.op == nc::Op::pow ? SymOp::pow
                                          : SymOp::atan2;
        stack.push_back(make(op, a, b));
        break;
      }
      case nc::Op::sin: stack.push_back(make(SymOp::sin, pop())); break;
      case nc::Op::cos: stack.push_back(make(SymOp::cos, pop())); break;
      case nc::Op::tan: stack.push_back(make(SymOp::tan, pop())); break;
      case nc::Op::asin: stack.push_back(make(SymOp::asin, pop())); break;
      case nc::Op::acos: stack.push_back(make(SymOp::acos, pop())); break;
      case nc::Op::atan1: stack.push_back(make(SymOp::atan, pop())); break;
      case nc::Op::sqrt: stack.push_back(make(SymOp::sqrt, pop())); break;
      case nc::Op::abs: stack.push_back(make(SymOp::abs, pop())); break;
      case nc::Op::ln: stack.push_back(make(SymOp::ln, pop())); break;
      case nc::Op::exp: stack.push_back(make(SymOp::exp, pop())); break;
      case nc::Op::var_indirect: refuse("an indirect variable #[...]"); break;
      case nc::Op::round: case nc::Op::fix: case nc::Op::fup: refuse("ROUND/FIX/FUP (a step function)"); break;
      case nc::Op::mod: case nc::Op::band: case nc::Op::bor: case nc::Op::bxor: refuse("MOD/AND/OR/XOR"); break;
      case nc::Op::bin: case nc::Op::bcd: case nc::Op::adp: refuse("BIN/BCD/ADP"); break;
      default: refuse("a comparison"); break;
    }
  }
  if (stack.size() != 1)
    throw nc::Alarm(nc::Diagnostic{nc::Severity::error, "PS0114", origin + ": not one expression", nc::Span{}});
  return stack.back();
}

Sym bind(const Sym& e, const std::map<int, double>& values, nc::EvalOptions options) {
  if (e->op == SymOp::var) {
    auto it = values.find(e->var);
    return it == values.end() ? e : konst(it->second);
  }
  if (!e->a) return e;
  Sym a = bind(e->a, values, options);
  Sym b = e->b ? bind(e->b, values, options) : nullptr;
  if (a == e->a && b == e->b) return e;
  switch (e->op) {
    case SymOp::neg:
    case SymOp::add:
    case SymOp::sub:
    case SymOp::mul:
    case SymOp::div: return make(e->op, std::move(a), std::move(b));
    default:
      if (Sym k = folded(e->op, a, b, options)) return k;
      return make(e->op, std::move(a), std::move(b));
  }
}

bool depends_on(const Sym& e, int var) {
  if (!e) return false;
  if (e->op == SymOp::var) return e->var == var;
  return depends_on(e->a, var) || depends_on(e->b, var);
}

Sym derivative(const Sym& e, int var) {
  if (!depends_on(e, var)) return konst(0);
  const Sym& a = e->a;
  const Sym& b = e->b;
  auto d = [&](const Sym& s) { return derivative(s, var); };
  auto mul = [](Sym x, Sym y) { return make(SymOp::mul, std::move(x), std::move(y)); };
  auto div = [](Sym x, Sym y) { return make(SymOp::div, std::move(x), std::move(y)); };
  auto add = [](Sym x, Sym y) { return make(SymOp::add, std::move(x), std::move(y)); };
  auto sub = [](Sym x, Sym y) { return make(SymOp::sub, std::move(x), std::move(y)); };
  auto fn = [](SymOp op, Sym x) { return make(op, std::move(x)); };
  const Sym rad = konst(kDeg);       // d(sin u)/du for u in degrees carries pi/180
  const Sym deg = konst(1.0 / kDeg);  // inverse functions return degrees
  switch (e->op) {
    case SymOp::var: return konst(1);
    case SymOp::neg: return fn(SymOp::neg, d(a));
    case SymOp::add: return add(d(a), d(b));
    case SymOp::sub: return sub(d(a), d(b));
    case SymOp::mul: return add(mul(d(a), b), mul(a, d(b)));
    case SymOp::div:
      if (!depends_on(b, var)) return div(d(a), b);
      return div(sub(mul(d(a), b), mul(a, d(b))), mul(b, b));
    case SymOp::sin: return mul(mul(rad, fn(SymOp::cos, a)), d(a));
    case SymOp::cos: return fn(SymOp::neg, mul(mul(rad, fn(SymOp::sin, a)), d(a)));
    case SymOp::tan: {
      Sym c = fn(SymOp::cos, a);
      return div(mul(rad, d(a)), mul(c, c));
    }
    case SymOp::asin: return div(mul(deg, d(a)), fn(SymOp::sqrt, sub(konst(1), mul(a, a))));
    case SymOp::acos: return fn(SymOp::neg, div(mul(deg, d(a)), fn(SymOp::sqrt, sub(konst(1), mul(a, a)))));
    case SymOp::atan: return div(mul(deg, d(a)), add(konst(1), mul(a, a)));
    case SymOp::atan2:  // ATAN[a]/[b] is the angle of (b, a)
      return div(mul(deg, sub(mul(b, d(a)), mul(a, d(b)))), add(mul(a, a), mul(b, b)));
    case SymOp::sqrt: return div(d(a), mul(konst(2), e));
    case SymOp::abs: return div(mul(a, d(a)), e);
    case SymOp::ln: return div(d(a), a);
    case SymOp::exp: return mul(e, d(a));
    case SymOp::pow:
      if (!depends_on(b, var)) return mul(mul(b, make(SymOp::pow, a, sub(b, konst(1)))), d(a));
      return mul(e, add(mul(d(b), fn(SymOp::ln, a)), div(mul(b, d(a)), a)));
    default: return konst(0);
  }
}

namespace {

// A total order on expressions by structure (op, constant, variable, then operands).
int compare(const Sym& x, const Sym& y) {
  if (x == y) return 0;
  if (!x || !y) return x ? 1 : -1;
  if (x->op != y->op) return x->op < y->op ? -1 : 1;
  if (x->op == SymOp::konst) return x->k < y->k ? -1 : (x->k > y->k ? 1 : 0);
  if (x->op == SymOp::var) return x->var < y->var ? -1 : (x->var > y->var ? 1 : 0);
  if (int c = compare(x->a, y->a)) return c;
  return compare(x->b, y->b);
}

struct Factor {
  Sym base;
  int power;
};
struct Term {
  double coeff = 1;
  std::vector<Factor> factors;  // by compare() of their bases, each base once
};
using Terms = std::vector<Term>;

bool is_sum(const Sym& e) { return e->op == SymOp::add || e->op == SymOp::sub; }

int compare_factors(const std::vector<Factor>& x, const std::vector<Factor>& y) {
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (int c = compare(x[i].base, y[i].base)) return c;
    if (x[i].power != y[i].power) return x[i].power < y[i].power ? -1 : 1;
  }
  return x.size() == y.size() ? 0 : (x.size() < y.size() ? -1 : 1);
}

// a + b, or 0 where they cancel to rounding
double cancelled(double a, double b) {
  const double s = a + b;
  return std::fabs(s) <= 1e-13 * (std::fabs(a) + std::fabs(b)) ? 0.0 : s;
}

void sort_factors(Term& t) {
  std::sort(t.factors.begin(), t.factors.end(),
            [](const Factor& x, const Factor& y) { return compare(x.base, y.base) < 0; });
  std::vector<Factor> merged;
  for (const Factor& f : t.factors) {
    if (!merged.empty() && compare(merged.back().base, f.base) == 0) merged.back().power += f.power;
    else merged.push_back(f);
    if (merged.back().power == 0) merged.pop_back();
  }
  t.factors = std::move(merged);
}

void collect_terms(Terms& terms) {
  for (Term& t : terms) sort_factors(t);
  std::sort(terms.begin(), terms.end(),
            [](const Term& x, const Term& y) { return compare_factors(x.factors, y.factors) < 0; });
  Terms merged;
  for (const Term& t : terms) {
    if (!merged.empty() && compare_factors(merged.back().factors, t.factors) == 0)
      merged.back().coeff = cancelled(merged.back().coeff, t.coeff);
    else merged.push_back(t);
    if (merged.back().coeff == 0) merged.pop_back();
  }
  terms = std::move(merged);
}

void sum_terms(const Sym& e, double scale, Terms& out);
Sym rebuild(Terms terms);

// e^power multiplied into t
void product_factors(const Sym& e, int power, Term& t) {
  switch (e->op) {
    case SymOp::konst:
      if (e->k != 0 || power > 0) {
        t.coeff *= std::pow(e->k, power);
        return;
      }
      break;
    case SymOp::neg:
      if (power % 2) t.coeff = -t.coeff;
      product_factors(e->a, power, t);
      return;
    case SymOp::mul:
      product_factors(e->a, power, t);
      product_factors(e->b, power, t);
      return;
    case SymOp::div:
      product_factors(e->a, power, t);
      product_factors(e->b, -power, t);
      return;
    case SymOp::pow:
      if (e->b->op == SymOp::konst && e->b->k == std::round(e->b->k) && std::fabs(e->b->k) <= 8) {
        product_factors(e->a, power * static_cast<int>(e->b->k), t);
        return;
      }
      break;
    case SymOp::add: case SymOp::sub: {
      Terms inner;
      sum_terms(e, 1, inner);
      collect_terms(inner);
      if (inner.empty()) {
        if (power > 0) t.coeff = 0;
        else t.factors.push_back({e, power});  // a division by zero stays as written
        return;
      }
      if (inner.size() == 1) {
        t.coeff *= std::pow(inner[0].coeff, power);
        for (Factor f : inner[0].factors) t.factors.push_back({f.base, f.power * power});
        return;
      }
      // a sum as one factor: its sign out, and a coefficient of which all its terms' are whole
      // multiples (a*x+2*a*y is a*[x+2*y])
      double least = std::fabs(inner[0].coeff);
      for (const Term& u : inner) least = std::min(least, std::fabs(u.coeff));
      const bool multiples = std::all_of(inner.begin(), inner.end(), [&](const Term& u) {
        const double ratio = std::fabs(u.coeff) / least;
        return ratio <= 64 && std::fabs(ratio - std::round(ratio)) <= 1e-12 * ratio;
      });
      const double content = std::copysign(multiples ? least : 1.0, inner[0].coeff);
      for (Term& u : inner) u.coeff /= content;
      t.coeff *= std::pow(content, power);
      t.factors.push_back({rebuild(std::move(inner)), power});
      return;
    }
    default: break;
  }
  Sym atom = e;
  if (e->a) atom = make(e->op, simplify(e->a), e->b ? simplify(e->b) : nullptr);
  if (atom->op == SymOp::konst && (atom->k != 0 || power > 0)) t.coeff *= std::pow(atom->k, power);
  else t.factors.push_back({atom, power});
}

// scale * e as terms added to out
void sum_terms(const Sym& e, double scale, Terms& out) {
  switch (e->op) {
    case SymOp::add: sum_terms(e->a, scale, out); sum_terms(e->b, scale, out); return;
    case SymOp::sub: sum_terms(e->a, scale, out); sum_terms(e->b, -scale, out); return;
    case SymOp::neg: sum_terms(e->a, -scale, out); return;
    case SymOp::konst: out.push_back(Term{scale * e->k, {}}); return;
    default: break;
  }
  Term t;
  t.coeff = scale;
  product_factors(e, 1, t);
  // a constant times one sum: its terms join this sum
  if (t.factors.size() == 1 && t.factors[0].power == 1 && is_sum(t.factors[0].base)) {
    sum_terms(t.factors[0].base, t.coeff, out);
    return;
  }
  out.push_back(std::move(t));
}

Sym power_of(const Sym& base, int n) {
  Sym p = base;
  for (int i = 1; i < n; ++i) p = make(SymOp::mul, p, base);
  return p;
}

// |coeff| * factors (positive powers over negative ones)
Sym magnitude(const Term& t) {
  // a coefficient whose reciprocal prints closer or shorter divides: x/360. rather than 0.0027778*x
  const double c = std::fabs(t.coeff);
  const Number k = printed(c), reciprocal = printed(1 / c);
  const bool divide = !t.factors.empty() && (reciprocal.error < 0.5 * k.error ||
                                             (reciprocal.error <= 2 * k.error && reciprocal.text.size() < k.text.size()));
  // sines and cosines last: the x and y of a curve often differ only there, and the rest of
  // the product is then one shared subexpression
  std::vector<Sym> front, back;  // multiplied before and after the divisions
  for (const Factor& f : t.factors)
    for (int i = 0; i < f.power; ++i)
      (f.base->op == SymOp::sin || f.base->op == SymOp::cos ? back : front).push_back(f.base);
  if (divide && front.empty()) std::swap(front, back);  // 1/57.29578 would fold to a constant
  Sym num = divide ? nullptr : konst(c);
  auto times = [&](const Sym& x) { num = num ? make(SymOp::mul, num, x) : x; };
  auto over = [&](const Sym& x) { num = make(SymOp::div, num ? num : konst(1), x); };
  for (const Sym& x : front) times(x);
  if (divide) over(konst(1 / c));
  for (const Factor& f : t.factors)
    for (int i = 0; i < -f.power; ++i) over(f.base);
  for (const Sym& x : back) times(x);
  return num ? num : konst(c);
}

Sym rebuild(Terms terms) {
  if (terms.empty()) return konst(0);
  // factors every term shares come out in front: a*x+a*y is a*[x+y]
  std::vector<Factor> common;
  if (terms.size() > 1) {
    for (const Factor& f : terms[0].factors) {
      int power = f.power;
      for (std::size_t i = 1; i < terms.size() && power != 0; ++i) {
        auto it = std::find_if(terms[i].factors.begin(), terms[i].factors.end(),
                               [&](const Factor& g) { return compare(g.base, f.base) == 0; });
        if (it == terms[i].factors.end() || (it->power > 0) != (power > 0)) power = 0;
        else power = power > 0 ? std::min(power, it->power) : std::max(power, it->power);
      }
      if (power != 0) common.push_back({f.base, power});
    }
  }
  if (!common.empty()) {
    for (Term& t : terms) {
      for (const Factor& c : common) t.factors.push_back({c.base, -c.power});
      sort_factors(t);
    }
    Term front{1, common};
    Sym rest = rebuild(std::move(terms));
    Sym f = magnitude(front);
    // the sum first where the common part is a pure divisor: [x+y]/a
    bool divisor_only = std::all_of(common.begin(), common.end(), [](const Factor& c) { return c.power < 0; });
    if (divisor_only) {
      Sym den = konst(1);
      for (const Factor& c : common) den = make(SymOp::mul, den, power_of(c.base, -c.power));
      return make(SymOp::div, rest, den);
    }
    return make(SymOp::mul, f, rest);
  }
  // positive terms first, so that the sum rarely starts with a sign
  std::stable_partition(terms.begin(), terms.end(), [](const Term& t) { return t.coeff > 0; });
  Sym out = magnitude(terms[0]);
  if (terms[0].coeff < 0) out = make(SymOp::neg, out);
  for (std::size_t i = 1; i < terms.size(); ++i)
    out = make(terms[i].coeff > 0 ? SymOp::add : SymOp::sub, out, magnitude(terms[i]));
  return out;
}

}  // namespace

Sym simplify(const Sym& e) {
  Terms terms;
  sum_terms(e, 1, terms);
  collect_terms(terms);
  return rebuild(std::move(terms));
}

std::string to_macro(const Sym& e) { return print(e).text; }
int bracket_depth(const Sym& e) { return print(e).depth; }

Sym limit_depth(const Sym& e, int max_depth, int& next_temp, std::vector<std::pair<int, Sym>>& temps) {
  if (!e->a) return e;
  Sym a = limit_depth(e->a, max_depth, next_temp, temps);
  Sym b = e->b ? limit_depth(e->b, max_depth, next_temp, temps) : nullptr;
  Sym n = node(e->op, a, b);
  while (bracket_depth(n) > max_depth) {
    bool take_a = !b || bracket_depth(a) >= bracket_depth(b);
    Sym& child = take_a ? a : b;
    temps.emplace_back(next_temp, child);
    child = variable(next_temp++);
    n = node(e->op, a, b);
  }
  return n;
}

namespace {

// Structural identity of a node whose operands have the registers a and b.
struct NodeKey {
  SymOp op;
  std::uint64_t k_bits;
  int var, a, b;
  bool operator<(const NodeKey& o) const {
    return std::tie(op, k_bits, var, a, b) < std::tie(o.op, o.k_bits, o.var, o.a, o.b);
  }
};

// The outputs' nodes with equal subtrees (by structure) numbered once, operands before their
// users: each distinct node, its operands' numbers (-1: none), and the outputs' numbers.
struct Interned {
  std::vector<Sym> nodes;
  std::vector<int> a, b;
  std::vector<int> roots;
};

// With any_order, a+b and b+a (a*b and b*a) are one node, its operands in the order of their numbers.
Interned intern(const std::vector<Sym>& outputs, bool any_order = false) {
  Interned in;
  std::map<NodeKey, int> ids;
  auto visit = [&](auto& self, const Sym& e) -> int {
    int a = e->a ? self(self, e->a) : -1;
    int b = e->b ? self(self, e->b) : -1;
    if (any_order && (e->op == SymOp::add || e->op == SymOp::mul) && b < a) std::swap(a, b);
    NodeKey key{e->op, e->op == SymOp::konst ? std::bit_cast<std::uint64_t>(e->k) : 0,
                e->op == SymOp::var ? e->var : 0, a, b};
    auto [it, fresh] = ids.try_emplace(key, static_cast<int>(in.nodes.size()));
    if (fresh) {
      in.nodes.push_back(e);
      in.a.push_back(a);
      in.b.push_back(b);
    }
    return it->second;
  };
  for (const Sym& e : outputs) in.roots.push_back(visit(visit, e));
  return in;
}

}  // namespace

std::vector<Sym> share_subexpressions(const std::vector<Sym>& outputs, int& next_temp,
                                      std::vector<std::pair<int, Sym>>& temps, const std::vector<int>& output_vars) {
  const Interned in = intern(outputs);
  std::map<int, int> own_var;  // node -> the variable of the first output it is
  for (std::size_t i = 0; i < output_vars.size() && i < in.roots.size(); ++i) own_var.try_emplace(in.roots[i], output_vars[i]);
  const std::vector<Sym>& nodes = in.nodes;
  const std::vector<int>&ops_a = in.a, &ops_b = in.b;
  std::vector<int> uses(nodes.size(), 0);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (ops_a[i] >= 0) ++uses[static_cast<std::size_t>(ops_a[i])];
    if (ops_b[i] >= 0) ++uses[static_cast<std::size_t>(ops_b[i])];
  }
  for (int r : in.roots) ++uses[static_cast<std::size_t>(r)];
  constexpr std::size_t kVariableLength = 4;  // "#150"
  std::vector<Sym> built(nodes.size());
  auto build = [&](auto& self, int id) -> Sym {
    const auto i = static_cast<std::size_t>(id);
    if (built[i]) return built[i];
    const Sym& e = nodes[i];
    Sym out = e;
    if (e->a) {
      // the second operand's temporaries numbered first: sequenced, so that every compiler writes
      // the same macro (as function arguments the two calls' order was unspecified)
      Sym b = ops_b[i] >= 0 ? self(self, ops_b[i]) : nullptr;
      Sym a = self(self, ops_a[i]);
      out = node(e->op, std::move(a), std::move(b));
    }
    const bool long_constant = e->op == SymOp::konst && to_macro(out).size() > 2 * kVariableLength;
    if (uses[i] > 1 && (e->a || long_constant) && to_macro(out).size() > kVariableLength) {
      auto own = own_var.find(id);
      const int v = own != own_var.end() ? own->second : next_temp++;
      temps.emplace_back(v, out);
      out = variable(v);
    }
    return built[i] = out;
  };
  std::vector<Sym> rewritten;
  for (int r : in.roots) rewritten.push_back(build(build, r));
  return rewritten;
}

Tape::Tape(const std::vector<Sym>& outputs, nc::EvalOptions options, const std::vector<int>& inputs)
    : options_(options) {
  // operands first; equal subtrees share a register (its node's number)
  const Interned in = intern(outputs, true);
  registers_ = static_cast<int>(in.nodes.size());
  auto constant = [&](int reg, double& k) {
    if (reg < 0) return false;
    const SymNode& n = *in.nodes[static_cast<std::size_t>(reg)];
    k = n.k;
    return n.op == SymOp::konst;
  };
  for (std::size_t i = 0; i < in.nodes.size(); ++i) {
    const SymNode& e = *in.nodes[i];
    Step s{Code::call, e.op, false, static_cast<int>(i), in.a[i], in.b[i], e.k};
    double k = 0;
    switch (e.op) {
      case SymOp::konst: s.code = Code::konst; break;
      case SymOp::var:
        s.code = Code::var;
        s.a = e.var;
        if (!inputs.empty()) {
          auto it = std::find(inputs.begin(), inputs.end(), e.var);
          if (it == inputs.end()) throw std::invalid_argument(fmt::format("the tape reads #{}, not an input", e.var));
          s.a = static_cast<int>(it - inputs.begin());
        }
        break;
      case SymOp::neg: s.code = Code::neg; break;
      case SymOp::add:
      case SymOp::mul:
        s.code = e.op == SymOp::add ? Code::add : Code::mul;
        if (constant(s.a, k)) std::swap(s.a, s.b);
        if (constant(s.b, k)) s.code = e.op == SymOp::add ? Code::add_k : Code::mul_k, s.k = k, s.b = -1;
        break;
      case SymOp::sub:
        s.code = Code::sub;
        if (constant(s.b, k)) s.code = Code::sub_k, s.k = k, s.b = -1;
        else if (constant(s.a, k)) s.code = Code::k_sub, s.k = k, s.a = s.b, s.b = -1;
        break;
      case SymOp::div:
        s.code = Code::div;
        if (constant(s.b, k) && k != 0) s.code = Code::mul_k, s.k = 1 / k, s.b = -1;  // a product is faster
        else if (constant(s.a, k)) s.code = Code::k_div, s.k = k, s.a = s.b, s.b = -1;
        break;
      default: break;
    }
    steps_.push_back(s);
  }
  outputs_ = in.roots;
  // a sine and a cosine of one register: the first computes both, the second is dropped
  std::map<int, std::size_t> sine_of, cosine_of;  // operand register -> step
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    if (steps_[i].op == SymOp::sin) sine_of[steps_[i].a] = i;
    if (steps_[i].op == SymOp::cos) cosine_of[steps_[i].a] = i;
  }
  std::vector<bool> dropped(steps_.size(), false);
  for (const auto& [operand, si] : sine_of) {
    auto c = cosine_of.find(operand);
    if (c == cosine_of.end()) continue;
    std::size_t first = std::min(si, c->second), second = std::max(si, c->second);
    steps_[first].paired = true;
    steps_[first].b = steps_[second].dst;
    dropped[second] = true;
  }
  // from the outputs back: steps whose register nothing reads
  std::vector<bool> read(static_cast<std::size_t>(registers_), false);
  for (int r : outputs_) read[static_cast<std::size_t>(r)] = true;
  for (std::size_t i = steps_.size(); i-- > 0;) {
    const Step& s = steps_[i];
    if (dropped[i]) continue;
    if (!read[static_cast<std::size_t>(s.dst)] && !(s.paired && read[static_cast<std::size_t>(s.b)])) {
      dropped[i] = true;
      continue;
    }
    if (s.a >= 0 && s.code != Code::var) read[static_cast<std::size_t>(s.a)] = true;
    if (s.b >= 0 && !s.paired) read[static_cast<std::size_t>(s.b)] = true;
  }
  std::vector<Step> kept;
  for (std::size_t i = 0; i < steps_.size(); ++i)
    if (!dropped[i]) kept.push_back(steps_[i]);
  steps_ = std::move(kept);
}

namespace {

// sin and cos of degrees, lane by lane without branches (so that the loop runs on vectors):
// x = 90q + r exactly, then Taylor series in r's radians (|r| <= 45 degrees: terms to the 18th
// power leave less than 1e-19), then the quadrant. Whole multiples of 90 degrees come out exact,
// as from nc::sincos_deg.
NCURVE_VECTOR_CLONES void sincos_deg_lanes(const double* __restrict x, double* __restrict s, double* __restrict c) {
  constexpr double kRound = 0x1.8p52;  // adding and subtracting it rounds to a whole number
  for (std::size_t j = 0; j < Tape::kLanes; ++j) {
    const double q = (x[j] / 90 + kRound) - kRound;
    const double r = (x[j] - q * 90) * kDeg;
    const double q4 = q - 4 * ((q / 4 + kRound) - kRound);  // -2 .. 2
    const double r2 = r * r;
    double sr = 1.0 / 39916800 - r2 * (1.0 / 6227020800 - r2 * (1.0 / 1307674368000 - r2 * (1.0 / 355687428096000)));
    double cr = 1.0 / 3628800 - r2 * (1.0 / 479001600 - r2 * (1.0 / 87178291200 - r2 * (1.0 / 20922789888000 - r2 * (1.0 / 6402373705728000))));
    sr = r * (1 - r2 * (1.0 / 6 - r2 * (1.0 / 120 - r2 * (1.0 / 5040 - r2 * (1.0 / 362880 - r2 * sr)))));
    cr = 1 - r2 * (0.5 - r2 * (1.0 / 24 - r2 * (1.0 / 720 - r2 * (1.0 / 40320 - r2 * cr))));
    // quadrants in arithmetic, which runs on vectors: odd is 1 for q4 = +-1, else 0
    const double w = std::fabs(q4), odd = w * (2 - w);
    const double sine = odd * cr + (1 - odd) * sr, cosine = odd * sr + (1 - odd) * cr;
    // the sine is negative for q4 = -2, -1, 2, the cosine for q4 = -2, 1, 2
    s[j] = (q4 * (q4 - 1) > 0 ? -sine : sine) + 0.0;  // + 0: no negative zero
    c[j] = (q4 * (q4 + 1) > 0 ? -cosine : cosine) + 0.0;
  }
  for (std::size_t j = 0; j < Tape::kLanes; ++j)  // beyond the rounding trick's reach, or not finite
    if (!(std::fabs(x[j]) < 0x1p50)) nc::sincos_deg(x[j], s[j], c[j]);
}

// d[j] = f(a[j], b[j]) for every lane (the operands never share the result's register).
template <class F>
inline void each_lane(double* __restrict d, const double* __restrict a, const double* __restrict b, F f) {
  for (std::size_t j = 0; j < Tape::kLanes; ++j) d[j] = f(a[j], b[j]);
}

// x / y, NaN where y is 0 as from the one-point tape (x / 0 is infinite or NaN, times 0 NaN)
inline double quotient(double x, double y) {
  const double zero = y == 0 ? 1.0 : 0.0;
  return x / y * (1 - zero);
}

}  // namespace

NCURVE_VECTOR_CLONES void Tape::lanes(const double* in, double* out) const {
  constexpr std::size_t kOnStack = 64;
  alignas(64) double on_stack[kOnStack * kLanes];
  std::vector<double> on_heap;
  double* r = on_stack;
  if (static_cast<std::size_t>(registers_) > kOnStack) {
    on_heap.resize(static_cast<std::size_t>(registers_) * kLanes);
    r = on_heap.data();
  }
  auto reg = [&](int i) { return r + static_cast<std::size_t>(i) * kLanes; };
  for (const Step& s : steps_) {
    double* d = reg(s.dst);
    const double* a = s.code == Code::var ? in + static_cast<std::size_t>(s.a) * kLanes : s.a >= 0 ? reg(s.a) : nullptr;
    const double* b = s.b >= 0 && !s.paired ? reg(s.b) : nullptr;
    const double k = s.k;
    switch (s.code) {
      case Code::konst: std::fill(d, d + kLanes, k); break;
      case Code::var: std::copy(a, a + kLanes, d); break;
      case Code::neg: each_lane(d, a, a, [](double x, double) { return -x; }); break;
      case Code::add: each_lane(d, a, b, [](double x, double y) { return x + y; }); break;
      case Code::sub: each_lane(d, a, b, [](double x, double y) { return x - y; }); break;
      case Code::mul: each_lane(d, a, b, [](double x, double y) { return x * y; }); break;
      case Code::div: each_lane(d, a, b, [](double x, double y) { return quotient(x, y); }); break;
      case Code::add_k: each_lane(d, a, a, [k](double x, double) { return x + k; }); break;
      case Code::sub_k: each_lane(d, a, a, [k](double x, double) { return x - k; }); break;
      case Code::k_sub: each_lane(d, a, a, [k](double x, double) { return k - x; }); break;
      case Code::mul_k: each_lane(d, a, a, [k](double x, double) { return x * k; }); break;
      case Code::k_div: each_lane(d, a, a, [k](double x, double) { return quotient(k, x); }); break;
      case Code::call:
        if (s.paired || s.op == SymOp::sin || s.op == SymOp::cos) {
          alignas(64) double sine[kLanes], cosine[kLanes];
          sincos_deg_lanes(a, sine, cosine);
          std::copy_n(s.op == SymOp::sin ? sine : cosine, kLanes, d);
          if (s.paired) std::copy_n(s.op == SymOp::sin ? cosine : sine, kLanes, reg(s.b));
        } else {
          for (std::size_t j = 0; j < kLanes; ++j) {
            const nc::EvalFault f = b ? nc::apply_binary(to_nc(s.op), a[j], b[j], d[j], options_)
                                      : nc::apply_unary(to_nc(s.op), a[j], d[j], options_);
            if (f != nc::EvalFault::none) d[j] = std::numeric_limits<double>::quiet_NaN();
          }
        }
        break;
    }
  }
  for (std::size_t i = 0; i < outputs_.size(); ++i) std::copy_n(reg(outputs_[i]), kLanes, out + i * kLanes);
}

void Tape::operator()(const double* in, double* out) const {
  constexpr int kOnStack = 256;
  double on_stack[kOnStack];
  std::vector<double> on_heap;
  double* r = on_stack;
  if (registers_ > kOnStack) {
    on_heap.resize(static_cast<std::size_t>(registers_));
    r = on_heap.data();
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Step& s : steps_) {
    double& d = r[s.dst];
    switch (s.code) {
      case Code::konst: d = s.k; break;
      case Code::var: d = in[s.a]; break;
      case Code::neg: d = -r[s.a]; break;
      case Code::add: d = r[s.a] + r[s.b]; break;
      case Code::sub: d = r[s.a] - r[s.b]; break;
      case Code::mul: d = r[s.a] * r[s.b]; break;
      case Code::div: d = r[s.b] == 0 ? nan : r[s.a] / r[s.b]; break;
      case Code::add_k: d = r[s.a] + s.k; break;
      case Code::sub_k: d = r[s.a] - s.k; break;
      case Code::k_sub: d = s.k - r[s.a]; break;
      case Code::mul_k: d = r[s.a] * s.k; break;
      case Code::k_div: d = r[s.a] == 0 ? nan : s.k / r[s.a]; break;
      case Code::call:
        if (s.paired) {
          double sine = 0, cosine = 0;
          nc::sincos_deg(r[s.a], sine, cosine);
          d = s.op == SymOp::sin ? sine : cosine;
          r[s.b] = s.op == SymOp::sin ? cosine : sine;
        } else if (s.b >= 0) {
          if (nc::apply_binary(to_nc(s.op), r[s.a], r[s.b], d, options_) != nc::EvalFault::none) d = nan;
        } else if (nc::apply_unary(to_nc(s.op), r[s.a], d, options_) != nc::EvalFault::none) {
          d = nan;
        }
        break;
    }
  }
  for (std::size_t i = 0; i < outputs_.size(); ++i) out[i] = r[outputs_[i]];
}

}  // namespace ncurve::geom
