#include "geom/curve.hpp"

#include "base/parallel.hpp"
#include "base/vector_clones.hpp"

#include <fmt/format.h>

#include <cctype>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "nc/program.hpp"

namespace ncurve::geom {
namespace {

const char* const kFunctionWords[] = {"SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "ROUND", "FIX",
                                      "FUP", "LN",  "EXP", "POW",  "ADP",  "BIN",  "BCD",  "MOD", "AND",   "OR",
                                      "XOR"};

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

void variables_of(const Sym& e, std::vector<int>& out) {
  if (e->op == SymOp::var) out.push_back(e->var);
  if (e->a) variables_of(e->a, out);
  if (e->b) variables_of(e->b, out);
}

}  // namespace

const std::vector<CurveSpec>& catalogue() {
  static const std::vector<CurveSpec> curves = {
      {"spiral", "Archimedean spiral r = r0 + pitch*t/360 about (cx, cy), counter-clockwise for t rising",
       {{"r0", 1.0, "radius at t = 0, mm"},
        {"pitch", 4 * 3.14159265358979, "radius increase per turn, mm"},
        {"cx", 0, "centre X, mm"},
        {"cy", 0, "centre Y, mm"}},
       "CX+[R0+PITCH*t/360]*COS[t]", "CY+[R0+PITCH*t/360]*SIN[t]", "0", 0, 360, "t = polar angle, degrees"},
      {"spiral-cw", "Archimedean spiral r = r0 + pitch*t/360 about (cx, cy), clockwise for t rising",
       {{"r0", 1.0, "radius at t = 0, mm"},
        {"pitch", 4 * 3.14159265358979, "radius increase per turn, mm"},
        {"cx", 0, "centre X, mm"},
        {"cy", 0, "centre Y, mm"}},
       "CX+[R0+PITCH*t/360]*COS[t]", "CY-[R0+PITCH*t/360]*SIN[t]", "0", 0, 360,
       "t = clockwise polar angle, degrees"},
      {"hyperbola", "lathe hyperbola X = a/cos t (radius), Z = b*tan t (seed 003)",
       {{"a", 100, "radius at t = 0, mm"}, {"b", 202.4, "Z scale, mm"}},
       "A/COS[t]", "0", "B*TAN[t]", -20, 20, "t = alpha, degrees, inside (-90, 90)", true},
      {"ellipse", "ellipse x = a cos t, y = b sin t",
       {{"a", 40, "semi-axis along X, mm"}, {"b", 20, "semi-axis along Y, mm"}},
       "A*COS[t]", "B*SIN[t]", "0", 0, 360, "t = eccentric angle, degrees"},
      {"parabola", "parabola y = x^2 / (4 f)", {{"f", 10, "focal length, mm"}},
       "t", "t*t/[4*F]", "0", -20, 20, "t = x, mm"},
      {"involute", "involute of a circle", {{"rb", 20, "base circle radius, mm"}},
       "RB*[COS[t]+t*PI/180*SIN[t]]", "RB*[SIN[t]-t*PI/180*COS[t]]", "0", 5, 120,
       "t = roll angle, degrees (t = 0 is a cusp)"},
      {"sine", "sine wave y = amp sin(360 x / wavelength)", {{"amp", 5, "amplitude, mm"}, {"wavelength", 40, "mm"}},
       "t", "AMP*SIN[360*t/WAVELENGTH]", "0", 0, 80, "t = x, mm"},
      {"cycloid", "cycloid of a circle rolling on X", {{"r", 10, "rolling circle radius, mm"}},
       "R*[t*PI/180-SIN[t]]", "R*[1-COS[t]]", "0", 10, 350, "t = rolling angle, degrees (cusps at 0, 360 ...)"},
      {"trochoid", "trochoid: point at distance d from the centre of a circle of radius r rolling on X",
       {{"r", 10, "rolling circle radius, mm"}, {"d", 5, "point distance from the centre, mm"}},
       "R*t*PI/180-D*SIN[t]", "R-D*COS[t]", "0", 0, 720, "t = rolling angle, degrees"},
      {"helix", "helix about Z", {{"r", 20, "radius, mm"}, {"lead", 5, "Z rise per turn, mm"}},
       "R*COS[t]", "R*SIN[t]", "LEAD*t/360", 0, 720, "t = angle, degrees"},
      {"rotor", "screw-rotor end profile of seed 004 (s = atan(sin 5u / (1.4 - cos 5u)) - u)", {},
       "63*SIN[t]-7.5*SIN[6*t]+20*SIN[ATAN[SIN[5*t]]/[1.4-COS[5*t]]-t]",
       "63*COS[t]-7.5*COS[6*t]-20*COS[ATAN[SIN[5*t]]/[1.4-COS[5*t]]-t]", "0", 0, 72, "t = u, degrees"},
  };
  return curves;
}

const CurveSpec* find_curve(const std::string& name) {
  for (const auto& c : catalogue())
    if (c.name == name) return &c;
  return nullptr;
}

const std::vector<std::string>& function_words() {
  static const std::vector<std::string> words(std::begin(kFunctionWords), std::end(kFunctionWords));
  return words;
}

std::vector<NameUse> names_in(const std::string& text) {
  std::vector<NameUse> out;
  for (std::size_t i = 0; i < text.size();) {
    if (!is_name_start(text[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && is_name_char(text[j])) ++j;
    const std::string word = upper(text.substr(i, j - i));
    const bool function = std::find(std::begin(kFunctionWords), std::end(kFunctionWords), word) != std::end(kFunctionWords);
    if (!function && word != "T" && word != "PI") {
      std::size_t next = j;
      while (next < text.size() && text[next] == ' ') ++next;
      out.push_back({text.substr(i, j - i), i + 1, next < text.size() && (text[next] == '[' || text[next] == '(')});
    }
    i = j;
  }
  return out;
}

std::string substitute_names(const std::string& text, const std::vector<std::string>& params) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    char c = text[i];
    if (is_name_start(c)) {
      std::size_t j = i;
      while (j < text.size() && is_name_char(text[j])) ++j;
      std::string word = upper(text.substr(i, j - i));
      bool function = false;
      for (const char* f : kFunctionWords) function = function || word == f;
      if (function) {
        out += word;
      } else if (word == "T") {
        out += fmt::format("#{}", kTVar);
      } else if (word == "PI") {
        out += "3.14159265358979";
      } else {
        std::size_t k = 0;
        while (k < params.size() && upper(params[k]) != word) ++k;
        if (k == params.size()) {
          std::string known = "t, PI";
          for (const auto& p : params) known += ", " + p;
          throw std::runtime_error(fmt::format("'{}' at column {} is not a function of the macro language nor a name "
                                               "of this curve ({})",
                                               text.substr(i, j - i), i + 1, known));
        }
        out += fmt::format("#{}", kFirstParamVar + static_cast<int>(k));
      }
      i = j;
      continue;
    }
    out += c == '(' ? '[' : c == ')' ? ']' : c;
    ++i;
  }
  return out;
}

Curve::Curve(const CurveSpec& spec, const std::map<std::string, double>& values, nc::EvalOptions options)
    : name_(spec.name), t0_(spec.from), t1_(spec.to), options_(options) {
  std::vector<std::string> names;
  for (const auto& p : spec.params) {
    names.push_back(p.name);
    if (params_.size() >= static_cast<std::size_t>(kVarCount - kFirstParamVar))
      throw std::runtime_error(fmt::format("{}: too many parameters", spec.name));
    params_.push_back(Param{p.name, kFirstParamVar + static_cast<int>(params_.size()), p.value, p.doc});
  }
  for (const auto& given : values) {
    const std::string& name = given.first;
    const double value = given.second;
    auto it = std::find_if(params_.begin(), params_.end(), [&](const Param& p) { return p.name == name; });
    if (it == params_.end()) {
      std::string known;
      for (const auto& p : params_) known += (known.empty() ? "" : ", ") + p.name;
      throw std::runtime_error(
          fmt::format("{} has no parameter '{}' (it has: {})", spec.name, name, known.empty() ? "none" : known));
    }
    it->value = value;
  }
  const std::string* texts[3] = {&spec.x, &spec.y, &spec.z};
  const char* axis = "xyz";
  for (int a = 0; a < 3; ++a) {
    std::string origin = fmt::format("{} {}(t)", spec.name, axis[a]);
    std::string macro;
    try {
      macro = substitute_names(texts[a]->empty() ? "0" : *texts[a], names);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(fmt::format("{}: {}", origin, e.what()));
    }
    nc::CompiledExpr code = nc::compile_expression(macro, origin);
    sym_pos_[a] = from_code(code.code, origin);
    std::vector<int> used;
    variables_of(sym_pos_[a], used);
    for (int var : used) {
      bool known = var == kTVar;
      for (const auto& p : params_) known = known || p.var == var;
      if (!known)
        throw std::runtime_error(fmt::format(
            "{}: the expression reads #{}, which is neither t (#{}) nor a parameter (a name next to digits? "
            "spaces do not separate words in the macro language)",
            origin, var, kTVar));
    }
  }
  compile(options);
}

void Curve::compile(nc::EvalOptions options) {
  for (int a = 0; a < 3; ++a) {
    try {
      SymBudget budget(kMaxSymNodes);
      sym_d1_[a] = simplify(derivative(sym_pos_[a], kTVar));
      sym_d2_[a] = simplify(derivative(sym_d1_[a], kTVar));
    } catch (const SymTooLarge&) {
      throw std::runtime_error(fmt::format(
          "{} {}(t): its derivatives need more than {} expression nodes (the second derivative of a product of n "
          "factors has n^3 terms): write the expression shorter, e.g. a repeated factor as POW[u,n] or a "
          "product of sines as a sum",
          name_, "xyz"[a], kMaxSymNodes));
    }
  }
  // the tapes read t alone: the parameters are constants in them
  std::map<int, double> values;
  for (const auto& p : params_) values[p.var] = p.value;
  auto bound = [&](const std::array<Sym, 3>& e) {
    std::vector<Sym> out;
    for (const Sym& s : e) out.push_back(bind(s, values, options));
    return out;
  };
  const std::vector<int> t_only{kTVar};
  pos_ = Tape(bound(sym_pos_), options, t_only);
  d1_ = Tape(bound(sym_d1_), options, t_only);
  d2_ = Tape(bound(sym_d2_), options, t_only);
  std::vector<Sym> all = bound(sym_pos_);
  for (const auto* e : {&sym_d1_, &sym_d2_})
    for (const Sym& s : bound(*e)) all.push_back(s);
  jet_ = Tape(all, options, t_only);
}

Vec3 Curve::eval(const Tape& tape, double t, double scale) const {
  const double at = sense_ * t;
  Vec3 out;
  tape(&at, out.data());
  return {out[0] * scale, out[1] * scale, out[2] * scale};
}

Curve::Jet Curve::jet(double t) const {
  const double at = sense_ * t;
  double out[9];
  jet_(&at, out);
  const double s = sense_;
  return {{out[0], out[1], out[2]}, {s * out[3], s * out[4], s * out[5]}, {out[6], out[7], out[8]}};
}

Curve Curve::reversed() const {
  Curve out = *this;
  out.sense_ = -sense_;
  out.t0_ = -t1_;
  out.t1_ = -t0_;
  return out;
}

Curve Curve::scaled(double divisor) const {
  forwards("scaling");
  Curve out = *this;
  for (Sym& s : out.sym_pos_) s = simplify(make(SymOp::div, s, konst(divisor)));
  out.compile(options_);
  out.scaled_ = true;
  return out;
}

void Curve::forwards(const char* what) const {
  if (sense_ < 0) throw std::logic_error(fmt::format("{}: {} of a curve traced backwards", name_, what));
  if (scaled_) throw std::logic_error(fmt::format("{}: {} of a scaled curve", name_, what));
}

void Curve::jets(std::span<const double> t, std::span<Jet> out) const {
  constexpr std::size_t kLanes = Tape::kLanes;
  std::array<double, kLanes> in;
  std::array<double, 9 * kLanes> values;
  for (std::size_t first = 0; first < t.size(); first += kLanes) {
    const std::size_t n = std::min(kLanes, t.size() - first);
    std::copy_n(t.begin() + static_cast<std::ptrdiff_t>(first), n, in.begin());
    std::fill(in.begin() + static_cast<std::ptrdiff_t>(n), in.end(), in[n - 1]);
    jet_lanes(in.data(), values.data());
    for (std::size_t j = 0; j < n; ++j) {
      Jet& e = out[first + j];
      for (std::size_t k = 0; k < 3; ++k) {
        e.p[k] = values[k * kLanes + j];
        e.d1[k] = values[(3 + k) * kLanes + j];
        e.d2[k] = values[(6 + k) * kLanes + j];
      }
    }
  }
}

void Curve::jet_lanes(const double* t, double* out) const {
  constexpr std::size_t kLanes = Tape::kLanes;
  std::array<double, kLanes> in;
  for (std::size_t j = 0; j < kLanes; ++j) in[j] = sense_ * t[j];
  jet_.lanes(in.data(), out);
  for (std::size_t j = 3 * kLanes; j < 6 * kLanes; ++j) out[j] = sense_ * out[j];
}

Curve Curve::offset(double radius, bool left, int u, int v) const {
  forwards("offset");
  const int w = 3 - u - v;
  if (depends_on(sym_pos_[w], kTVar))
    throw std::runtime_error(fmt::format("{}: a tool radius offset needs a plane curve; this one leaves the plane", name_));
  // concave side closer than the radius: the offset curve would turn back (gouge)
  constexpr int kSamples = 8192, kBatch = 256;
  const double side = left ? 1 : -1;
  double worst = 0, worst_t = t0_;
  std::array<double, kBatch> ts;
  std::array<Jet, kBatch> batch;
  std::vector<double> speed2(kSamples + 1);
  for (int first = 0; first <= kSamples; first += kBatch) {
    const int n = std::min(kBatch, kSamples + 1 - first);
    for (int j = 0; j < n; ++j) ts[static_cast<std::size_t>(j)] = t0_ + (t1_ - t0_) * (first + j) / kSamples;
    jets(std::span(ts).first(static_cast<std::size_t>(n)), batch);
    for (int j = 0; j < n; ++j) {
      const Vec3 &a = batch[static_cast<std::size_t>(j)].d1, &b = batch[static_cast<std::size_t>(j)].d2;
      const double speed = std::hypot(a[u], a[v]);
      speed2[static_cast<std::size_t>(first + j)] = speed * speed;
      const double k = side * (a[u] * b[v] - a[v] * b[u]) / (speed * speed * speed);  // > 0: turning towards the tool
      if (k > worst) worst = k, worst_t = ts[static_cast<std::size_t>(j)];
    }
  }
  // where the curve stops (at an end: validate() refuses one inside) it has no direction, and so
  // no side to offset to (as validate() judges a stop: a millionth of the median speed)
  const double start2 = speed2.front(), end2 = speed2.back();
  std::nth_element(speed2.begin(), speed2.begin() + kSamples / 2, speed2.end());
  const double stopped2 = 1e-12 * speed2[kSamples / 2];
  for (const auto& [at, s2] : {std::pair{t0_, start2}, std::pair{t1_, end2}})
    if (!(s2 > stopped2))
      throw std::runtime_error(fmt::format(
          "{}: the curve stops at t = {:.6g}, where its direction and so the side of a tool radius offset are "
          "undefined: end the range a little inside it, or program the contour without a tool radius",
          name_, at));
  if (worst * radius >= 1) {
    Vec3 p = point(worst_t);
    throw std::runtime_error(fmt::format(
        "{}: the tool radius {} mm is larger than the concave radius of curvature {:.4f} mm at t = {:.6g} "
        "({:.4f}, {:.4f}, {:.4f}): the cutter would gouge there",
        name_, radius, 1 / worst, worst_t, p[0], p[1], p[2]));
  }
  Curve out = *this;
  Sym speed = make(SymOp::sqrt, make(SymOp::add, make(SymOp::mul, sym_d1_[u], sym_d1_[u]),
                                     make(SymOp::mul, sym_d1_[v], sym_d1_[v])));
  Sym r = konst(side * radius);
  out.sym_pos_[u] = make(SymOp::sub, sym_pos_[u], make(SymOp::div, make(SymOp::mul, r, sym_d1_[v]), speed));
  out.sym_pos_[v] = make(SymOp::add, sym_pos_[v], make(SymOp::div, make(SymOp::mul, r, sym_d1_[u]), speed));
  out.compile(options_);
  return out;
}

double Curve::curvature(double t, Vec3* normal) const {
  Vec3 v = d1(t), acc = d2(t);
  double speed2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  double along = (acc[0] * v[0] + acc[1] * v[1] + acc[2] * v[2]) / speed2;
  Vec3 perp{acc[0] - along * v[0], acc[1] - along * v[1], acc[2] - along * v[2]};
  double k = norm(perp) / speed2;
  if (normal) {
    double n = norm(perp);
    *normal = n > 0 ? Vec3{perp[0] / n, perp[1] / n, perp[2] / n} : Vec3{0, 0, 0};
  }
  return k;
}

namespace {

// The checks of a batch of Tape::kLanes jets (outputs p, d1, d2 as the jet tape gives them),
// lane by lane on vectors: where a value is not finite or too far, the squared speed, and
// whether the step from the lane before (the previous batch's last before lane 0) leaves the
// tangent's reach. Flags are all ones where set (vector compares give such lanes).
struct LaneChecks {
  static constexpr std::size_t kLanes = Tape::kLanes;
  std::int64_t undefined[kLanes], jumps[kLanes];
  double speed2[kLanes];
};

// lane j, the lane before's point and velocity given
[[gnu::always_inline]] inline void check_lane(std::size_t j, const double* __restrict jet, double px, double py,
                                              double pz, double pvx, double pvy, double pvz, double dt,
                                              LaneChecks& out) {
  constexpr std::size_t n = LaneChecks::kLanes;
  const double x = jet[j], y = jet[n + j], z = jet[2 * n + j];
  const double vx = jet[3 * n + j], vy = jet[4 * n + j], vz = jet[5 * n + j];
  // NaN or infinity in any of them makes the sum NaN or infinite, and all - all not 0
  const double all = x + y + z + vx + vy + vz + jet[6 * n + j] + jet[7 * n + j] + jet[8 * n + j];
  const bool undefined = !(all - all == 0) | (std::fabs(x) > 1e6) | (std::fabs(y) > 1e6) | (std::fabs(z) > 1e6);
  const double speed2 = vx * vx + vy * vy + vz * vz;
  const double before2 = pvx * pvx + pvy * pvy + pvz * pvz;
  const double sx = x - px, sy = y - py, sz = z - pz;
  // ten times the faster speed's step, at least 1e-9 mm (squared: no square root)
  const double reach2 = 100 * (speed2 > before2 ? speed2 : before2) * dt * dt + 1e-18;
  // a smooth curve moves along its tangent; through a pole (1/cos at 90 degrees) it jumps back
  const bool backwards = (sx * vx + sy * vy + sz * vz < 0) & (sx * pvx + sy * pvy + sz * pvz < 0);
  const bool jumps = (sx * sx + sy * sy + sz * sz > reach2) | backwards;
  out.undefined[j] = -static_cast<std::int64_t>(undefined);
  out.jumps[j] = -static_cast<std::int64_t>(jumps);
  out.speed2[j] = speed2;
}

// All lanes; whether any is undefined or jumps (lane 0's jump counted only with `from_before`).
NCURVE_VECTOR_CLONES bool check_lanes(const double* __restrict jet, const double* __restrict before, bool from_before,
                                      double dt, LaneChecks& out) {
  constexpr std::size_t n = LaneChecks::kLanes;
  check_lane(0, jet, before[0], before[1], before[2], before[3], before[4], before[5], dt, out);
  if (!from_before) out.jumps[0] = 0;
  for (std::size_t j = 1; j < n; ++j)
    check_lane(j, jet, jet[j - 1], jet[n + j - 1], jet[2 * n + j - 1], jet[3 * n + j - 1], jet[4 * n + j - 1],
               jet[5 * n + j - 1], dt, out);
  std::int64_t any = 0;
  for (std::size_t j = 0; j < n; ++j) any |= out.undefined[j] | out.jumps[j];
  return any != 0;
}

}  // namespace

Survey Curve::survey() const {
  Survey s;
  std::array<double, Survey::kPoints> ts;
  std::array<Jet, Survey::kPoints> jets_at;
  for (std::size_t i = 0; i < Survey::kPoints; ++i)
    ts[i] = t0_ + (t1_ - t0_) * static_cast<double>(i) / Survey::kSteps;
  jets(ts, jets_at);
  for (std::size_t i = 0; i < Survey::kPoints; ++i)
    for (std::size_t c = 0; c < 3; ++c) s.d1(c)[i] = jets_at[i].d1[c], s.d2(c)[i] = jets_at[i].d2[c];
  return s;
}

Survey Curve::validate() const {
  forwards("validate");
  if (!(t1_ > t0_)) throw std::runtime_error(fmt::format("{}: the range {}..{} is empty", name_, t0_, t1_));
  constexpr int kSamples = 4096, kPart = 512;
  constexpr int kLanes = static_cast<int>(Tape::kLanes);
  // every kSurveyed-th sample is the survey's (the same t: a power of two apart); batches start on one
  constexpr int kSurveyed = kSamples / static_cast<int>(Survey::kSteps);
  static_assert(kSamples % Survey::kSteps == 0 && kPart % kSurveyed == 0 && kLanes % kSurveyed == 0);
  constexpr int kParts = kSamples / kPart, kEighths = kSamples / 8 + 1;
  static_assert(kLanes % 8 == 0);
  Survey survey;
  const double dt = (t1_ - t0_) / kSamples;
  std::array<double, kEighths> eighth_speed2;  // squared speeds of every eighth sample, for the median
  std::array<double, kParts> least_speed2;     // each part's least
  auto sample = [&](int i) { return t0_ + (t1_ - t0_) * i / kSamples; };
  // in parts on all cores, each in batches; a part checks the step into its first sample too
  base::for_each_on_cores(kParts, [&](std::size_t k) {
    const int first = static_cast<int>(k) * kPart, last = first + kPart;
    auto own = [&](int i) { return i < last || last == kSamples; };  // the last is the next part's first
    alignas(64) double ts[kLanes], jet[9 * kLanes];
    double before[6] = {};  // p and d1 of the sample before the batch
    double least = std::numeric_limits<double>::infinity();
    LaneChecks checks;
    for (int b = first; b <= last; b += kLanes) {
      const int n = std::min(kLanes, last + 1 - b);
      for (int j = 0; j < kLanes; ++j) ts[j] = sample(b + std::min(j, n - 1));
      jet_.lanes(ts, jet);
      if (check_lanes(jet, before, b > first, dt, checks)) {
        for (int j = 0; j < n; ++j) {
          const int i = b + j;
          if (checks.undefined[j])
            throw std::runtime_error(fmt::format(
                "{}: not defined or singular at t = {:.6g} (x, y, z = {:.6g}, {:.6g}, {:.6g}): choose a range that "
                "avoids it",
                name_, sample(i), jet[j], jet[kLanes + j], jet[2 * kLanes + j]));
          if (checks.jumps[j])
            throw std::runtime_error(fmt::format(
                "{}: jumps between t = {:.6g} and t = {:.6g} (singular or discontinuous)", name_, sample(i - 1),
                sample(i)));
        }
      }
      for (int j = 0; j < n; ++j) least = std::min(least, checks.speed2[j]);
      for (int j = 0; j < n; j += 8)
        if (own(b + j)) eighth_speed2[static_cast<std::size_t>((b + j) / 8)] = checks.speed2[j];
      for (int j = 0; j < n; j += kSurveyed) {
        if (!own(b + j)) continue;
        const auto i = static_cast<std::size_t>((b + j) / kSurveyed);
        for (std::size_t c = 0; c < 3; ++c)
          survey.d1(c)[i] = jet[(3 + c) * Tape::kLanes + j], survey.d2(c)[i] = jet[(6 + c) * Tape::kLanes + j];
      }
      for (int c = 0; c < 6; ++c) before[c] = jet[c * kLanes + kLanes - 1];
    }
    least_speed2[k] = least;
  });
  // stopped: slower than a millionth of the median speed (as squares: the same order)
  constexpr auto kMiddle = static_cast<std::ptrdiff_t>(kEighths / 2);
  std::nth_element(eighth_speed2.begin(), eighth_speed2.begin() + kMiddle, eighth_speed2.end());
  const double stopped2 = 1e-12 * eighth_speed2[kMiddle];
  // A stop at an end of the range is no cusp: the curve starts from rest or comes to rest there.
  // The samples next to it that are as slow (a stop of higher order) are excused while the speed
  // grows away from the end; a stop inside the range is refused.
  for (int k = 0; k < kParts; ++k) {
    if (!(least_speed2[static_cast<std::size_t>(k)] <= stopped2)) continue;
    // a part where it may stop: its speeds again (the same jets), for the first such sample
    std::vector<double> ts;
    for (int i = k * kPart; i <= (k + 1) * kPart; ++i) ts.push_back(sample(i));
    std::vector<Jet> at(ts.size());
    jets(ts, at);
    std::vector<double> speed2(at.size());
    for (std::size_t i = 0; i < at.size(); ++i) {
      const Vec3& v = at[i].d1;
      speed2[i] = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    }
    std::size_t from = 0, to = at.size();  // the samples not excused
    if (k == 0)
      while (from < to && speed2[from] <= stopped2 && (from == 0 || speed2[from] > speed2[from - 1])) ++from;
    if (k == kParts - 1)
      while (to > from && speed2[to - 1] <= stopped2 && (to == at.size() || speed2[to - 1] > speed2[to])) --to;
    for (std::size_t i = from; i < to; ++i) {
      if (speed2[i] <= stopped2)
        throw std::runtime_error(fmt::format(
            "{}: the curve stops at t = {:.6g} (zero speed: a cusp or a point where the tangent is undefined); "
            "split the range there",
            name_, ts[i]));
    }
  }
  return survey;
}

}  // namespace ncurve::geom
