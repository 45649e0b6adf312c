// Parametric curves x(t), y(t), z(t) written in the macro expression language, with exact first
// and second derivatives; the built-in catalogue is defined the same way.
#pragma once
#include <array>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "geom/sym.hpp"

namespace ncurve::geom {

using Vec3 = std::array<double, 3>;

// Macro variables a curve's expressions use: t is #100, parameters #101.. in order.
constexpr int kTVar = 100;
constexpr int kFirstParamVar = 101;
constexpr int kVarCount = 1000;
// The most expression nodes differentiating one coordinate (twice) may build: about a second and
// tens of MB; the shipped curves need under 2,000, the rotor's tool-radius offset about 71,000.
constexpr std::int64_t kMaxSymNodes = 500000;

struct ParamSpec {
  std::string name;
  double value;
  std::string doc;
};

struct CurveSpec {
  std::string name;
  std::string doc;
  std::vector<ParamSpec> params;  // values are defaults
  std::string x, y, z;            // expressions in t and the parameter names
  double from = 0, to = 360;      // default parameter range
  std::string t_doc = "t in degrees";
  bool lathe = false;  // a turned profile (X a radius, Z along the axis): meant for a lathe profile
};

// The built-in curves, in the order `ncurve gen --list` shows them.
const std::vector<CurveSpec>& catalogue();
const CurveSpec* find_curve(const std::string& name);

// A curve's first and second derivatives at kSteps + 1 equal steps of t over its range
// (t0 + (t1 - t0) * i / kSteps), component by component: what a fit predicts its steps from.
struct Survey {
  static constexpr std::size_t kSteps = 256, kPoints = kSteps + 1;
  std::vector<double> values = std::vector<double>(6 * kPoints);  // d1 x, y, z, d2 x, y, z: kPoints each
  double* d1(std::size_t axis) { return values.data() + axis * kPoints; }
  double* d2(std::size_t axis) { return values.data() + (3 + axis) * kPoints; }
  const double* d1(std::size_t axis) const { return values.data() + axis * kPoints; }
  const double* d2(std::size_t axis) const { return values.data() + (3 + axis) * kPoints; }
};

class Curve {
public:
  // Compiles the spec with the given parameter values (names not in the spec are an error).
  Curve(const CurveSpec& spec, const std::map<std::string, double>& values, nc::EvalOptions options = {});

  const std::string& name() const { return name_; }
  double t0() const { return t0_; }
  double t1() const { return t1_; }
  void set_range(double t0, double t1) { t0_ = t0; t1_ = t1; }

  Vec3 point(double t) const { return eval(pos_, t, 1); }
  Vec3 d1(double t) const { return eval(d1_, t, sense_); }
  Vec3 d2(double t) const { return eval(d2_, t, 1); }
  // Point, first and second derivative together (their common terms computed once).
  struct Jet {
    Vec3 p, d1, d2;
  };
  Jet jet(double t) const;
  // Jets at many parameters, computed several at a time (see Tape::lanes).
  void jets(std::span<const double> t, std::span<Jet> out) const;
  // Jets at Tape::kLanes parameters, as jets() computes them, in the lanes' layout: out[k * kLanes
  // + j] is lane j's p x, y, z (k = 0..2), d1 (3..5), d2 (6..8).
  void jet_lanes(const double* t, double* out) const;
  // Curvature and the unit principal normal (zero where the curve is straight).
  double curvature(double t, Vec3* normal = nullptr) const;

  // Expressions in #100 (t) and #101.. (parameters), for macro programs.
  const std::array<Sym, 3>& position() const { return sym_pos_; }
  const std::array<Sym, 3>& first() const { return sym_d1_; }
  const std::array<Sym, 3>& second() const { return sym_d2_; }
  struct Param {
    std::string name;
    int var;
    double value;
    std::string doc;
  };
  const std::vector<Param>& params() const { return params_; }
  bool planar_z() const { return !depends_on(sym_pos_[2], kTVar); }  // z constant
  bool uses_y() const { return !(sym_pos_[1]->op == SymOp::konst && sym_pos_[1]->k == 0); }

  // Throws std::runtime_error naming t where the curve is undefined, singular or stops inside its
  // range (a cusp; zero speed at t0 or t1 is allowed: it starts from or comes to rest); else
  // gives the survey, from jets the check computes anyway (the same as survey()'s, bit for bit).
  Survey validate() const;
  Survey survey() const;

  // The curve moved by `radius` along its normal in the plane of coordinates (u, v), to the left
  // (counter-clockwise from the tangent) or right: the exact path of a cutter's centre. Throws,
  // naming where, if the radius is larger than a concave radius of curvature (the cutter would
  // gouge) or the curve leaves the plane.
  Curve offset(double radius, bool left, int u, int v) const;

  // The same curve with its coordinates divided by `divisor` (25.4: in inches), derivatives and
  // all; the same parameters. For an inch program's fit and text: validate() and offset() refuse it.
  Curve scaled(double divisor) const;

  // The same curve traced backwards, to fit it from its end: over [-t1, -t0], its point at t is
  // this curve's at -t (bit for bit) and its first derivative changes sign. For evaluation only:
  // its expressions are this curve's, and validate() and offset() refuse it.
  Curve reversed() const;

private:
  // tape's outputs at the parameter t traced, multiplied by `scale`
  Vec3 eval(const Tape& tape, double t, double scale) const;
  void compile(nc::EvalOptions options);  // derivatives and tapes from sym_pos_
  void forwards(const char* what) const;  // throws std::logic_error for a curve traced backwards or scaled

  std::string name_;
  double t0_, t1_;
  double sense_ = 1;  // -1: traced backwards (the tapes see -t)
  bool scaled_ = false;  // by scaled(): for evaluation only
  std::vector<Param> params_;
  std::array<Sym, 3> sym_pos_, sym_d1_, sym_d2_;
  Tape pos_, d1_, d2_, jet_;
  nc::EvalOptions options_;
};

// Text with names (t, parameters, PI) to macro text with #100, #101..; throws on unknown names.
std::string substitute_names(const std::string& text, const std::vector<std::string>& params);

// The function words of the macro language a curve's text may use (SIN, COS, ...).
const std::vector<std::string>& function_words();
// The names in curve text other than t, PI and the function words, in order (each use): where
// (column from 1) and whether it is called (followed by [ or (, as a function is).
struct NameUse {
  std::string name;
  std::size_t column;
  bool called;
};
std::vector<NameUse> names_in(const std::string& text);

}  // namespace ncurve::geom
