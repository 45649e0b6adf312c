// A curve named on the command line (`ncurve gen`, `ncurve analyze --curve`): a catalogue name or
// expr with --x/--y/--z/--t, and its parameters as --NAME VALUE pairs.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "geom/curve.hpp"
#include "machine/profile.hpp"

namespace ncurve::app {

struct CurveArgs {
  std::string name;  // catalogue name or "expr"
  std::string x, y, z, t_range;
  std::optional<double> from, to;
};

// extras: the --NAME VALUE pairs the option parser left over. Throws std::runtime_error.
geom::Curve build_curve(const CurveArgs& a, const std::vector<std::string>& extras,
                        const machine::MachineProfile& profile);

}  // namespace ncurve::app
