#include "gen/emit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace ncurve::gen::detail {

using geom::Sym;
using geom::SymOp;
using geom::Vec3;

void Writer::block(std::string_view b) {
  text += b;
  text += '\n';
  ++line;
}

void Writer::lines(const std::string& t) {
  std::size_t pos = 0;
  while (pos <= t.size()) {
    std::size_t eol = t.find('\n', pos);
    if (eol == std::string::npos) eol = t.size();
    if (eol > pos) block(t.substr(pos, eol - pos));
    pos = eol + 1;
  }
}

std::string comment_text(std::string s) {
  for (char& c : s) {
    if (c == '(' || c == ')') c = ' ';
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  if (s.size() > 200) s.resize(200);
  return s;
}

int decimals_of(double increment) { return std::max(0, static_cast<int>(std::lround(-std::log10(increment)))); }

namespace {

// v with `decimals` decimals when v * 10^decimals is within a millionth of a whole number (as
// coordinates on the increment are) and its digits fit: the same text as the general path,
// without formatting the double. False otherwise.
bool append_grid_number(std::string& out, double v, int decimals) {
  static constexpr double kPow10[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
  if (decimals < 0 || decimals > 9) return false;
  const double scaled = v * kPow10[decimals];
  const double whole = std::nearbyint(scaled);
  if (!(std::fabs(scaled - whole) < 1e-6) || !(std::fabs(whole) < 1e15)) return false;
  char digits[24];
  const auto magnitude = static_cast<long long>(std::fabs(whole));
  const int length = static_cast<int>(std::to_chars(digits, digits + sizeof digits, magnitude).ptr - digits);
  auto fraction_digit = [&](int i) {  // i-th decimal; zeros before the digits of a small number
    const int at = length - decimals + i;
    return at < 0 ? '0' : digits[at];
  };
  int fraction = decimals;  // trailing zeros dropped
  while (fraction > 0 && fraction_digit(fraction - 1) == '0') --fraction;
  if (std::max(1, length - decimals) + fraction > nc::kPortableDigits && fraction > 0) return false;
  if (magnitude != 0 && whole < 0) out += '-';
  if (length <= decimals) out += '0';
  else out.append(digits, static_cast<std::size_t>(length - decimals));
  out += '.';
  for (int i = 0; i < fraction; ++i) out += fraction_digit(i);
  return true;
}

}  // namespace

void append_number(std::string& out, double v, int decimals) {
  if (append_grid_number(out, v, decimals)) return;
  char buf[400];  // fits any double in fixed notation
  std::string_view s;
  for (;; --decimals) {  // fewer decimals until the number fits the digits every control takes
    const std::size_t n = fmt::format_to_n(buf, sizeof buf, "{:.{}f}", v, std::max(decimals, 0)).size;
    s = std::string_view(buf, std::min(n, sizeof buf));
    if (s.find('.') != std::string_view::npos)
      while (s.back() == '0') s.remove_suffix(1);
    if (decimals <= 0 || std::count_if(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }) <=
                             nc::kPortableDigits)
      break;
  }
  if (s == "-0." || s == "-0") s = "0.";
  out += s;
  if (s.find('.') == std::string_view::npos) out += '.';
}

std::string number(double v, int decimals) {
  std::string s;
  append_number(s, v, decimals);
  return s;
}

bool is_lathe(const Options& o) { return o.profile.lathe(); }

double feed_of(const Options& o) { return o.feed > 0 ? o.feed : (is_lathe(o) ? 0.1 : 200.0); }

void AxisWords::append(std::string& out, const Vec3& p) const {
  const bool lathe = is_lathe(o);
  out += 'X';
  append_number(out, lathe ? 2 * p[0] : p[0], decimals);
  out += lathe ? " Z" : " Y";
  append_number(out, lathe ? p[2] : p[1], decimals);
  if (with_z && !lathe) {
    out += " Z";
    append_number(out, p[2], decimals);
  }
}

std::string AxisWords::operator()(const Vec3& p) const {
  std::string s;
  append(s, p);
  return s;
}

std::string header(const geom::Curve& curve, const Options& o, const std::string& method) {
  std::string params;
  for (const auto& p : curve.params()) params += fmt::format(" {}={:.10g}", p.name, p.value);
  // lengths in mm, as given (an inch program's options hold them in inches)
  auto mm = [&](double v) { return o.inch ? fmt::format("{:.10g}", v * kMmPerInch) : fmt::format("{}", v); };
  std::string text =
      fmt::format("O{:04d} (NCURVE {} {})\n(CURVE {}{} T={:.10g}..{:.10g})\n(TOLERANCE {} MM, FORM {}{})\n",
                  o.program_number, comment_text(curve.name()), comment_text(to_string(o.form)),
                  comment_text(curve.name()), comment_text(params), curve.t0(), curve.t1(), mm(o.tol),
                  comment_text(to_string(o.form)), method.empty() ? "" : ", " + comment_text(method));
  const char* side = o.side == Side::left ? "LEFT" : "RIGHT";
  if (o.tool_radius > 0 && !is_lathe(o))
    text += fmt::format("(CUTTER CENTRE PATH: TOOL RADIUS {} MM, {} OF THE CURVE)\n", mm(o.tool_radius), side);
  else if (o.tool_radius > 0 && (o.tip == 0 || o.tip == 9))
    text += fmt::format("(NOSE CENTRE PATH: NOSE RADIUS {} MM, {} OF THE CURVE)\n", mm(o.tool_radius), side);
  else if (o.tool_radius > 0)  // tips 1..8: the nose centre offset, then moved to the tip
    text += fmt::format("(IMAGINARY TOOL TIP {} PATH: NOSE RADIUS {} MM, THE NOSE CENTRE {} OF THE CURVE)\n", o.tip,
                        mm(o.tool_radius), side);
  if (o.inch) text += "(INCH PROGRAM: COORDINATES AND FEEDS IN INCHES; THE CURVE IS IN MM)\n";
  return text;
}

std::string modes(const Options& o) {
  const char* units = o.inch ? "G20" : "G21";
  if (is_lathe(o)) return fmt::format("{} G18 {}", units, o.profile.gcode_system == 'A' ? "G99" : "G90 G95");
  return fmt::format("{} G17 G90 G94 G54", units);
}

void modes_block(Writer& w, const Options& o) {
  if (!w.modes_written) w.block(modes(o));
}

std::string feed_number(const Options& o, double feed) { return number(feed, o.inch && is_lathe(o) ? 6 : 4); }

bool has_setup(const Options& o) { return o.tool > 0 || o.spindle > 0 || o.css > 0 || o.coolant; }

void begin_setup(Writer& w, const Options& o, int dec) {
  if (!has_setup(o)) return;
  w.block(modes(o));
  w.modes_written = true;
  const bool lathe = is_lathe(o);
  if (o.tool > 0) w.block(lathe ? fmt::format("T{:02d}{:02d}", o.tool, o.tool) : fmt::format("T{} M06", o.tool));
  const char* rotation = o.spindle_ccw ? "M04" : "M03";
  if (o.css > 0) {
    if (o.max_rpm > 0) w.block(fmt::format("{} S{}", o.profile.gcode_system == 'A' ? "G50" : "G92", o.max_rpm));
    // m/min, or feet a minute in an inch program
    const long speed = o.inch ? std::lround(o.css / 0.3048) : o.css;
    w.block(fmt::format("G96 S{} {}", speed, rotation));
  } else if (o.spindle > 0) {
    w.block(fmt::format("{}S{} {}", lathe ? "G97 " : "", o.spindle, rotation));
  }
  if (o.tool > 0 && !lathe) w.block(fmt::format("G00 G43 Z{} H{}", number(o.clearance, dec), o.tool));
  if (o.coolant) w.block("M08");
}

void end_setup(Writer& w, const Options& o) {
  if (o.coolant) w.block("M09");
  if (o.spindle > 0 || o.css > 0) w.block("M05");
}

Options in_inches(const Options& o) {
  Options u = o;
  u.inch = true;
  u.tol = o.tol / kMmPerInch;
  u.feed = feed_of(o) / kMmPerInch;
  u.depth = o.depth / kMmPerInch;
  u.clearance = o.clearance / kMmPerInch;
  u.step_down = o.step_down / kMmPerInch;
  u.tool_radius = o.tool_radius / kMmPerInch;
  // the inch input increment, in inches, is a tenth of the metric one in mm (IS-B 0.001 mm, 0.0001 in)
  u.profile.increment = o.profile.increment / 10;
  // the control checks an arc's end radius in mm against No.3410 (see machine/motion.cpp)
  u.profile.arc_radius_tolerance = o.profile.arc_radius_tolerance / kMmPerInch;
  return u;
}

double in_program_units(const Options& o, double mm) { return o.inch ? mm / kMmPerInch : mm; }

bool depth_passes(const Options& o) { return o.step_down > 0 && !is_lathe(o); }

void begin_passes(Writer& w, const Options& o, int dec) {
  if (!depth_passes(o)) return;
  w.block(fmt::format("#{}=0 (DEPTH OF THE PASS: {} DOWN TO {})", kPassDepth, number(o.step_down, dec),
                      number(-o.depth, dec)));
  w.block(fmt::format("WHILE [#{} GT {}] DO3", kPassDepth, number(-o.depth, dec)));
  w.block(fmt::format("#{0}=#{0}-{1}", kPassDepth, number(o.step_down, dec)));
  w.block(fmt::format("IF [#{0} LT {1}] THEN #{0}={1}", kPassDepth, number(-o.depth, dec)));
}

void end_passes(Writer& w, const Options& o) {
  if (depth_passes(o)) w.block("END3");
}

std::string plunge_z(const Options& o, double z, int dec) {
  return depth_passes(o) ? fmt::format("Z#{}", kPassDepth) : fmt::format("Z{}", number(z, dec));
}

Frame frame(const Options& o, const AxisWords& words, const Vec3& start, const Vec3& end, int dec, double feed) {
  Frame f;
  if (is_lathe(o)) {
    f.before_start = fmt::format("G00 X{} Z{}", number(2 * (start[0] + o.clearance), dec),
                                 number(start[2] + o.clearance, dec));
    f.to_depth = fmt::format("G01 {} F{}", words(start), feed_number(o, feed));
    f.retract = fmt::format("G00 X{}", number(2 * (end[0] + o.clearance), dec));
    return f;
  }
  f.before_start = fmt::format("G00 Z{}\nX{} Y{}", number(o.clearance, dec), number(start[0], dec),
                               number(start[1], dec));
  f.to_depth = fmt::format("G01 {} F{}", plunge_z(o, start[2], dec), feed_number(o, feed));
  f.retract = fmt::format("G00 Z{}", number(o.clearance, dec));
  return f;
}

Sym axis_sym(const geom::Curve& curve, const AxisMap& map, int axis) {
  Sym s = map.from[axis] >= 0 ? curve.position()[map.from[axis]] : geom::konst(0);
  return geom::make(SymOp::add, s, geom::konst(map.offset[axis]));
}

MacroWords macro_words(const std::vector<std::pair<char, Sym>>& axes, int& next_temp) {
  MacroWords mw;
  std::vector<std::pair<int, Sym>> temps;
  for (const auto& [letter, s] : axes) {
    Sym limited = geom::limit_depth(s, 4, next_temp, temps);  // X[...] adds the fifth bracket
    mw.words += fmt::format("{}{}[{}]", mw.words.empty() ? "" : " ", letter, geom::to_macro(limited));
  }
  for (const auto& [var, s] : temps) mw.assignments.push_back(fmt::format("#{}={}", var, geom::to_macro(s)));
  return mw;
}

std::vector<WordAxis> word_axes(const Options& o, bool with_z) {
  if (is_lathe(o)) return {{'X', 0, true}, {'Z', 2, false}};
  if (with_z) return {{'X', 0, false}, {'Y', 1, false}, {'Z', 2, false}};
  return {{'X', 0, false}, {'Y', 1, false}};
}

std::vector<std::pair<char, Sym>> point_axes(const geom::Curve& curve, const AxisMap& map, const Options& o,
                                             bool with_z) {
  std::vector<std::pair<char, Sym>> axes;
  for (const WordAxis& w : word_axes(o, with_z)) {
    const Sym s = axis_sym(curve, map, w.axis);
    axes.emplace_back(w.letter, w.diameter ? geom::make(SymOp::mul, geom::konst(2), s) : s);
  }
  return axes;
}

}  // namespace ncurve::gen::detail
