// The G codes of the FANUC 0i-F / 30i-B tables that ncurve does not simulate.
#pragma once

#include "machine/profile.hpp"

namespace ncurve::machine {

// The function of G code g (x10: 22 for G02.2) on this machine when the control has it and ncurve
// does not simulate it ("involute interpolation (G02.2)"), else nullptr.
const char* g_code_not_simulated(int g, const MachineProfile& p);

}  // namespace ncurve::machine
