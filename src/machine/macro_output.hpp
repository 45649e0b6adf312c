// Custom Macro B external output commands POPEN, PCLOS, DPRNT and BPRNT: the bytes the control
// sends through its reader/punch interface, as the FANUC 0i / 16i / 30i operator's manuals give them
// (docs/macro-output.md).
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ncurve::machine {

struct MachineProfile;

// What a run sent: every byte (DC2, characters, binary values, end-of-block codes, DC4) and each
// DPRNT/BPRNT line as readable text.
struct ExternalOutput {
  std::string bytes;
  std::vector<std::string> lines;  // the first kMaxLines; '*' shown as a space, BPRNT values as <hex>
  std::size_t lines_left_out = 0;
  bool open = false;               // between POPEN and PCLOS
  bool warned_unopened = false;
  static constexpr std::size_t kMaxLines = 1000;
};

// The code the control sends a character in: ISO (ASCII), with the even parity bit on bit 7 when
// parity is set. '*' is sent as a space.
char iso_code(char c, bool parity);

// The end-of-block code of ISO output: CR LF (No.0100#2 CRF), LF (No.0100#3 NCR) or LF CR CR.
std::string end_of_block(const MachineProfile& p);

// A DPRNT value in the format [integers decimals]: sign, integer digits (leading zeros a space
// each, or nothing with No.6001#1 PRT = 1), decimal point and decimals, rounded; digits above the
// integer ones are not sent. A vacant variable is 0.
std::string dprnt_number(double value, int integers, int decimals, bool no_spaces);

// A BPRNT value: value * 10^decimals rounded to a whole number, as 32-bit two's complement, highest
// byte first; nothing when it does not fit in 32 bits.
std::optional<std::array<unsigned char, 4>> bprnt_number(double value, int decimals);

}  // namespace ncurve::machine
