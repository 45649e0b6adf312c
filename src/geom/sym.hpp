// Symbolic expressions over macro variables: built from the macro language (the same parser as
// `ncurve run`), differentiated exactly, simplified, evaluated natively and printed back as
// FANUC macro text (trigonometry in degrees, as on the control).
#pragma once
#include <cstdint>
#include <map>
#include <stdexcept>
#include <memory>
#include <string>
#include <vector>

#include "nc/expr.hpp"

namespace ncurve::geom {

enum class SymOp : std::uint8_t {
  konst, var, neg, add, sub, mul, div,
  sin, cos, tan, asin, acos, atan, atan2, sqrt, abs, ln, exp, pow,
};

struct SymNode;
using Sym = std::shared_ptr<const SymNode>;

struct SymNode {
  SymOp op;
  double k = 0;  // konst
  int var = 0;   // var: macro variable number
  Sym a, b;
};

// While a SymBudget lives, building expressions on its thread allocates at most `nodes` nodes;
// the next one throws SymTooLarge. Differentiation multiplies a long product's size (the second
// derivative of n factors has n^3), so a budget bounds the time and memory of a user's curve.
class SymBudget {
public:
  explicit SymBudget(std::int64_t nodes);
  ~SymBudget();
  SymBudget(const SymBudget&) = delete;
  SymBudget& operator=(const SymBudget&) = delete;

private:
  std::int64_t outer_;
};
struct SymTooLarge : std::runtime_error {
  SymTooLarge() : std::runtime_error("expression too large") {}
};

Sym konst(double k);
Sym variable(int number);
// Builds op(a, b) with local simplification (constant folding, 0 and 1 rules, sign lifting).
Sym make(SymOp op, Sym a, Sym b = nullptr);

// From compiled macro code; throws nc::Alarm for what cannot be differentiated (ROUND, MOD,
// comparisons, indirect variables ...), naming the function.
Sym from_code(const std::vector<nc::Instr>& code, const std::string& origin);

// e with the variables in `values` replaced by those constants, folded as far as they go (a
// function of constants evaluated as the control would, with `options`).
Sym bind(const Sym& e, const std::map<int, double>& values, nc::EvalOptions options = {});

Sym derivative(const Sym& e, int var);
// The same value in a canonical sum-of-products form: nested sums and products flattened, operands
// in one order, like terms and like factors collected (a*b-b*a is 0, x*y/x is y), a sign or a
// common factor taken out of a sum. Products are not multiplied out, so the text never grows by
// more than a few brackets.
Sym simplify(const Sym& e);
bool depends_on(const Sym& e, int var);

// Macro text with the fewest brackets FANUC precedence allows.
std::string to_macro(const Sym& e);
// Bracket nesting of to_macro(e) (a function's argument brackets count, as on the control).
int bracket_depth(const Sym& e);

// Replaces subexpressions by temporaries so that to_macro of the result nests at most max_depth
// brackets; each (variable, expression) in temps must be assigned first, in order.
Sym limit_depth(const Sym& e, int max_depth, int& next_temp, std::vector<std::pair<int, Sym>>& temps);

// Equal subexpressions of several expressions written once: the outputs rewritten over
// temporaries (from next_temp on), each (variable, expression) of temps assigned first, in order.
// A subexpression gets a temporary where it occurs more than once and is longer than a variable
// (a constant: twice as long). With output_vars, an output that others share is assigned to its
// own variable among the temporaries, and comes back as that variable.
std::vector<Sym> share_subexpressions(const std::vector<Sym>& outputs, int& next_temp,
                                      std::vector<std::pair<int, Sym>>& temps,
                                      const std::vector<int>& output_vars = {});

// Straight-line code for fast evaluation of several expressions at once with FANUC's functions
// (nc::apply_unary / apply_binary): equal subexpressions are computed once, a sine and cosine of
// the same angle by one sincos, a constant operand of + - * / is written into its step, and steps
// that no output needs are dropped.
class Tape {
public:
  Tape() = default;
  // With `inputs`, the tape reads its variables from a dense array: in[i] is the value of
  // #inputs[i] (a variable not among them is an error); without, in[n] is the value of #n.
  explicit Tape(const std::vector<Sym>& outputs, nc::EvalOptions options = {}, const std::vector<int>& inputs = {});
  std::size_t outputs() const { return outputs_.size(); }
  // out[i] of output i is NaN on a domain error or division by zero in what it depends on.
  void operator()(const double* in, double* out) const;
  // kLanes points at once, each step's arithmetic on vectors: in[k * kLanes + j] is input k in
  // lane j, out[i * kLanes + j] output i there. Sines and cosines come from a polynomial after an
  // exact reduction in degrees; they may differ from the one-point tape's in the last bits.
  static constexpr std::size_t kLanes = 32;
  void lanes(const double* in, double* out) const;

private:
  // add_k: r[a] + k, k_sub: k - r[a], ... (mul_k also stands for a division by a constant)
  enum class Code : std::uint8_t { konst, var, neg, add, sub, mul, div, add_k, sub_k, k_sub, mul_k, k_div, call };
  struct Step {
    Code code;
    SymOp op;             // call: the function
    bool paired = false;  // a sine or cosine that also writes its partner to register b
    int dst;
    int a = -1, b = -1;   // operand registers; var: a is the input's index
    double k = 0;         // konst and the constant operand
  };
  std::vector<Step> steps_;
  std::vector<int> outputs_;  // registers
  int registers_ = 0;
  nc::EvalOptions options_;
};

}  // namespace ncurve::geom
