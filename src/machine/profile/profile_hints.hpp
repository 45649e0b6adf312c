// Signs that a program was written for another machine than the profile's: a lathe program on a
// mill, a G-code system B program on a system-A lathe. One warning each, naming the likely profile.
#pragma once
#include <vector>

#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "nc/diagnostic.hpp"

namespace ncurve::machine {

// Looks at the programs of the main file only; conservative: ordinary mill programs give nothing.
std::vector<nc::Diagnostic> profile_hints(const ProgramLibrary& library, const MachineProfile& profile);

}  // namespace ncurve::machine
