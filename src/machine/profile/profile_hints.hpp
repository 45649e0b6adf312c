// Signs that a program was written for another machine than the profile's: a lathe program on a
// mill, a G-code system B program on a system-A lathe. One warning each, naming the likely profile.
#pragma once
#include <vector>

#include "machine/library.hpp"
#include "machine/profile.hpp"
#include "nc/diagnostic.hpp"

namespace ncurve::machine {

// The signs of a file's programs, seen block by block in file order (a piece at a time when streamed).
class ProfileHints {
public:
  explicit ProfileHints(const MachineProfile& profile);
  // Blocks of `program`, in order after those seen before.
  void see(const nc::Program& program, const nc::Program& piece);
  std::vector<nc::Diagnostic> warnings() const;

private:
  struct Sign {
    const char* what = nullptr;
    const nc::SourceFile* file = nullptr;
    std::uint32_t line = 0;
    std::uint16_t column = 0;
    bool seen() const { return file != nullptr; }
  };
  const MachineProfile& profile_;
  bool mill_, system_a_;
  Sign t_word_, g50_s_, g96_, per_rev_;          // a lathe program on a mill
  Sign b_cycle_, g95_, mode_g90_, feed_mode_g94_;  // system B on a system-A lathe
  bool uses_u_w_ = false, inch_ = false, g99_ = false;
  bool motion_calls_ = false;  // G01..G03 call a macro (No.6050..): every block is looked at
  const nc::Program* program_ = nullptr;  // the program being seen
};

// Looks at the programs of the main file only; conservative: ordinary mill programs give nothing.
std::vector<nc::Diagnostic> profile_hints(const ProgramLibrary& library, const MachineProfile& profile);

}  // namespace ncurve::machine
