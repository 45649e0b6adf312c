#include "app/curve_args.hpp"

#include <fmt/format.h>

#include <map>
#include <stdexcept>

namespace ncurve::app {
namespace {

// --name value pairs left over by the option parser are curve parameters.
std::map<std::string, double> curve_parameters(const std::vector<std::string>& extras) {
  std::map<std::string, double> out;
  for (std::size_t i = 0; i < extras.size(); ++i) {
    const std::string& key = extras[i];
    if (key.rfind("--", 0) != 0 || key.size() < 3)
      throw std::runtime_error(fmt::format("unexpected argument '{}'", key));
    std::string name = key.substr(2), value;
    if (auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    } else {
      if (i + 1 >= extras.size()) throw std::runtime_error(fmt::format("{} needs a value", key));
      value = extras[++i];
    }
    try {
      std::size_t used = 0;
      double v = std::stod(value, &used);
      if (used != value.size()) throw std::invalid_argument(value);
      out[name] = v;
    } catch (const std::exception&) {
      throw std::runtime_error(fmt::format("{}: '{}' is not a number", key, value));
    }
  }
  return out;
}

}  // namespace

geom::Curve build_curve(const CurveArgs& a, const std::vector<std::string>& extras,
                        const machine::MachineProfile& profile) {
  auto values = curve_parameters(extras);
  nc::EvalOptions eval;
  eval.atan_signed = profile.atan_signed;
  geom::CurveSpec spec;
  if (a.name == "expr") {
    if (a.x.empty() && a.y.empty()) throw std::runtime_error("expr needs --x and --y (and optionally --z)");
    spec.name = "expr";
    spec.x = a.x.empty() ? "0" : a.x;
    spec.y = a.y.empty() ? "0" : a.y;
    spec.z = a.z.empty() ? "0" : a.z;
    for (const auto& [name, value] : values) spec.params.push_back({name, value, "user parameter"});
    auto colon = a.t_range.find(':');
    if (a.t_range.empty() || colon == std::string::npos) throw std::runtime_error("expr needs --t FROM:TO");
    spec.from = std::stod(a.t_range.substr(0, colon));
    spec.to = std::stod(a.t_range.substr(colon + 1));
  } else {
    const geom::CurveSpec* found = geom::find_curve(a.name);
    if (!found) throw std::runtime_error(fmt::format("no curve named '{}' (ncurve gen --list shows them)", a.name));
    spec = *found;
  }
  geom::Curve curve(spec, values, eval);
  if (a.from) curve.set_range(*a.from, curve.t1());
  if (a.to) curve.set_range(curve.t0(), *a.to);
  return curve;
}

}  // namespace ncurve::app
