#include "app/curve_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include "app/cli_checks.hpp"
#include "app/cli_units.hpp"

namespace ncurve::app {
namespace {

bool same_name(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

std::string joined(const std::vector<std::string>& names, const char* separator = ", ") {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : separator) + n;
  return out;
}

// A --NAME VALUE pair as typed.
struct Given {
  std::string option;  // "--a"
  std::string name;    // "a"
  std::string value;
};

// The extras as --NAME VALUE (or --NAME=VALUE) pairs; anything else is an error.
std::vector<Given> given_pairs(const std::vector<std::string>& extras, const CurveArgs& a) {
  std::vector<Given> out;
  for (std::size_t i = 0; i < extras.size(); ++i) {
    const std::string& key = extras[i];
    if (key.rfind("--", 0) != 0 || key.size() < 3) {
      std::string hint = " (one curve at a time; its parameters are given as --NAME VALUE)";
      if (key.size() > 1 && key[0] == '-' && !read_number(key)) {
        const std::string word = key.substr(key.find_first_not_of('-') == std::string::npos ? key.size() : key.find_first_not_of('-'));
        if (auto near = nearest_name(word, a.options)) hint = fmt::format("; did you mean --{}?", *near);
        else hint = " (options and parameters take two dashes: --NAME VALUE)";
      }
      throw std::runtime_error(fmt::format("unexpected argument '{}'{}", key, hint));
    }
    Given g{key, key.substr(2), ""};
    if (auto eq = g.name.find('='); eq != std::string::npos) {
      g.value = g.name.substr(eq + 1);
      g.name = g.name.substr(0, eq);
      g.option = "--" + g.name;
    } else {
      if (i + 1 >= extras.size() || (extras[i + 1].rfind("--", 0) == 0 && !read_number(extras[i + 1])))
        throw std::runtime_error(fmt::format("{} needs a value", key));
      g.value = extras[++i];
    }
    for (const Given& before : out)
      if (same_name(before.name, g.name)) throw std::runtime_error(fmt::format("{} is given twice", g.option));
    out.push_back(std::move(g));
  }
  return out;
}

// "--NAME is not an option of ncurve gen nor a parameter of spiral (r0, pitch, cx, cy); did you mean --tol?"
[[noreturn]] void unknown(const Given& g, const CurveArgs& a, const std::string& curve_params,
                          const std::vector<std::string>& params) {
  std::vector<std::string> candidates = a.options;
  candidates.insert(candidates.end(), params.begin(), params.end());
  std::string what = a.command.empty() ? fmt::format("{} is not", g.option)
                                       : fmt::format("{} is not an option of {} nor", g.option, a.command);
  std::string text = fmt::format("{} {}", what, curve_params);
  if (auto near = nearest_name(g.name, candidates)) text += fmt::format("; did you mean --{}?", *near);
  throw std::runtime_error(text);
}

// --t FROM:TO
std::pair<double, double> t_range(const std::string& text) {
  const std::string expected = "expected FROM:TO, the range of t, e.g. 0:360";
  const auto colon = text.find(':');
  if (text.empty()) throw std::runtime_error(fmt::format("expr needs --t FROM:TO ({})", expected.substr(9)));
  if (colon == std::string::npos) throw std::runtime_error(fmt::format("--t: '{}' has no ':' ({})", text, expected));
  double ends[2];
  const std::string parts[2] = {text.substr(0, colon), text.substr(colon + 1)};
  for (int k = 0; k < 2; ++k) {
    const std::optional<double> v = read_number(parts[k]);
    if (!v) throw std::runtime_error(fmt::format("--t: '{}' is not a number ({})", parts[k], expected));
    if (!std::isfinite(*v)) throw std::runtime_error(fmt::format("--t: {} must be a finite number, got {}",
                                                                 k == 0 ? "FROM" : "TO", parts[k]));
    ends[k] = *v;
  }
  if (!(ends[0] < ends[1]))
    throw std::runtime_error(fmt::format("--t: the range {} is empty (FROM must be below TO)", text));
  return {ends[0], ends[1]};
}

// expr: the names its expressions use are its parameters, in order of first use; a name called
// like a function must be one.
std::vector<std::string> expression_names(const CurveArgs& a) {
  std::vector<std::string> names;
  const std::pair<const char*, const std::string*> texts[] = {{"x", &a.x}, {"y", &a.y}, {"z", &a.z}};
  for (const auto& [axis, text] : texts) {
    for (const geom::NameUse& use : geom::names_in(*text)) {
      if (use.called) {
        const auto near = nearest_name(use.name, geom::function_words());
        throw std::runtime_error(fmt::format(
            "expr {}(t): '{}' at column {} is not a function of the macro language; {}", axis, use.name, use.column,
            near ? fmt::format("did you mean {}?", *near) : "its functions: " + joined(geom::function_words(), " ")));
      }
      if (std::none_of(names.begin(), names.end(), [&](const std::string& n) { return same_name(n, use.name); }))
        names.push_back(use.name);
    }
  }
  return names;
}

// expr: where a parameter is first used, for the message that it has no value
std::string first_use(const CurveArgs& a, const std::string& name) {
  const std::pair<const char*, const std::string*> texts[] = {{"x", &a.x}, {"y", &a.y}, {"z", &a.z}};
  for (const auto& [axis, text] : texts)
    for (const geom::NameUse& use : geom::names_in(*text))
      if (same_name(use.name, name)) return fmt::format("expr {}(t): '{}' at column {}", axis, use.name, use.column);
  return fmt::format("expr: '{}'", name);
}

}  // namespace

geom::Curve build_curve(const CurveArgs& a, const std::vector<std::string>& extras,
                        const machine::MachineProfile& profile) {
  const std::vector<Given> given = given_pairs(extras, a);
  nc::EvalOptions eval;
  eval.atan_signed = profile.atan_signed;
  geom::CurveSpec spec;
  std::vector<std::string> params;  // the curve's parameter names
  std::string curve_params;         // "a parameter of spiral (r0, pitch, cx, cy)"
  if (a.name == "expr") {
    if (a.x.empty() && a.y.empty()) throw std::runtime_error("expr needs --x and --y (and optionally --z)");
    spec.name = "expr";
    spec.x = a.x.empty() ? "0" : a.x;
    spec.y = a.y.empty() ? "0" : a.y;
    spec.z = a.z.empty() ? "0" : a.z;
    std::tie(spec.from, spec.to) = t_range(a.t_range);
    params = expression_names(a);
    curve_params = fmt::format("a name in the expressions ({})", params.empty() ? "they use none" : "they use " + joined(params));
  } else {
    const geom::CurveSpec* found = geom::find_curve(a.name);
    if (!found) {
      std::vector<std::string> names;
      for (const auto& c : geom::catalogue()) names.push_back(c.name);
      const auto near = nearest_name(a.name, names);
      throw std::runtime_error(fmt::format("no curve named '{}' ({}ncurve gen --list shows them)", a.name,
                                           near ? fmt::format("did you mean {}? ", *near) : ""));
    }
    spec = *found;
    for (const auto& p : spec.params) params.push_back(p.name);
    curve_params = fmt::format("a parameter of {} ({})", spec.name, params.empty() ? "it has none" : joined(params));
    std::vector<std::string> expr_only;
    for (const auto& [option, text] : {std::pair{"--x", &a.x}, {"--y", &a.y}, {"--z", &a.z}, {"--t", &a.t_range}})
      if (!text->empty()) expr_only.push_back(option);
    if (!expr_only.empty())
      throw std::runtime_error(fmt::format("{} {} for expr; {} takes its parameters and --from/--to",
                                           joined(expr_only), expr_only.size() > 1 ? "are" : "is", spec.name));
  }
  std::map<std::string, double> values;
  for (const Given& g : given) {
    const auto it = std::find_if(params.begin(), params.end(), [&](const std::string& p) { return same_name(p, g.name); });
    if (it == params.end()) unknown(g, a, curve_params, params);
    // expr: the name as given (the expressions read it in any case); a catalogue curve's as it spells it
    values[a.name == "expr" ? g.name : *it] =
        finite_number(fmt::format("a value of the parameter {}", *it)).read(g.value, g.option);
  }
  if (a.name == "expr") {
    for (const std::string& name : params) {
      if (std::any_of(values.begin(), values.end(), [&](const auto& v) { return same_name(v.first, name); })) continue;
      const auto option = std::find_if(a.options.begin(), a.options.end(),
                                       [&](const std::string& o) { return same_name(o, name); });
      if (option != a.options.end())
        throw std::runtime_error(fmt::format("{} is a parameter named like the option --{} of {}, which takes its "
                                             "value: give the parameter another name",
                                             first_use(a, name), *option, a.command));
      throw std::runtime_error(fmt::format("{} is a parameter without a value: give --{} VALUE", first_use(a, name), name));
    }
    for (const auto& [name, value] : values) spec.params.push_back({name, value, "user parameter"});
  }
  geom::Curve curve(spec, a.name == "expr" ? std::map<std::string, double>{} : values, eval);
  if (a.from) curve.set_range(*a.from, curve.t1());
  if (a.to) curve.set_range(curve.t0(), *a.to);
  if (!(curve.t0() < curve.t1()))
    throw std::runtime_error(fmt::format("the range of t, {:g} to {:g}, is empty: --from must be below --to",
                                         curve.t0(), curve.t1()));
  return curve;
}

void add_curve_options(CLI::App* cmd, CurveArgs& a, const std::string& what) {
  cmd->allow_extras();
  cmd->add_option("--curve", a.name, what);
  cmd->add_option("--x", a.x, "--curve expr: x(t)");
  cmd->add_option("--y", a.y, "--curve expr: y(t)");
  cmd->add_option("--z", a.z, "--curve expr: z(t)");
  cmd->add_option("--t", a.t_range, "--curve expr: range of t as FROM:TO");
  cmd->add_option("--from", a.from, "start of the curve parameter t")->check(units::number("a number", ""));
  cmd->add_option("--to", a.to, "end of the curve parameter t")->check(units::number("a number", ""));
}

}  // namespace ncurve::app
