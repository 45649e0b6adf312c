// POPEN, PCLOS, DPRNT and BPRNT (FANUC operator's manual, custom macro, "external output commands"):
// POPEN sends DC2, PCLOS DC4; DPRNT sends characters and variable values as decimal digits, BPRNT
// variable values as 32-bit binary; both end with the end-of-block code of ISO output.
#include "machine/macro_output.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>

#include "machine/executor.hpp"

namespace ncurve::machine {

namespace {
constexpr char kDC2 = 0x12, kDC4 = 0x14;

// |value| * 10^decimals rounded half away from zero; a value written in decimals (0.0005) that
// binary holds just below its half still rounds up.
double scaled_whole(double value, int decimals) {
  const double steps = std::fabs(value) * std::pow(10.0, decimals);
  return std::floor(steps + 0.5 + steps * 1e-12 + 1e-12);
}
}  // namespace

char iso_code(char c, bool parity) {
  unsigned char u = static_cast<unsigned char>(c == '*' ? ' ' : c) & 0x7F;
  if (parity && (std::popcount(u) & 1)) u |= 0x80;
  return static_cast<char>(u);
}

std::string end_of_block(const MachineProfile& p) {
  if (p.eob_cr_lf) return "\r\n";
  if (p.eob_lf_only) return "\n";
  return "\n\r\r";
}

std::string dprnt_number(double value, int integers, int decimals, bool no_spaces) {
  if (!std::isfinite(value)) value = 0;
  const double whole = scaled_whole(value, decimals);
  const double limit = std::pow(10.0, integers + decimals);
  const double shown = std::fmod(whole, limit);  // digits above the integer ones are not sent
  std::string digits = fmt::format("{:0{}.0f}", shown, integers + decimals);
  std::string out;
  if (value < 0 && shown != 0) out += '-';
  else if (!no_spaces) out += ' ';
  // leading zeros of the integer part; its units digit is always sent (ncurve's reading)
  for (int i = 0; i < integers; ++i) {
    if (digits[i] != '0' || i == integers - 1) {
      out.append(digits, i, integers - i);
      break;
    }
    if (!no_spaces) out += ' ';
  }
  if (decimals > 0) {
    out += '.';
    out.append(digits, integers, decimals);
  }
  return out;
}

std::optional<std::array<unsigned char, 4>> bprnt_number(double value, int decimals) {
  if (!std::isfinite(value)) return std::nullopt;
  const double whole = scaled_whole(value, decimals);
  const double v = value < 0 ? -whole : whole;
  if (v > 2147483647.0 || v < -2147483648.0) return std::nullopt;
  const auto u = static_cast<std::uint32_t>(static_cast<std::int32_t>(v));
  return std::array<unsigned char, 4>{static_cast<unsigned char>(u >> 24), static_cast<unsigned char>(u >> 16),
                                      static_cast<unsigned char>(u >> 8), static_cast<unsigned char>(u)};
}

void Executor::external_output(const nc::Block& b) {
  ExternalOutput& out = result_.output;
  const bool parity = profile_.output_parity;
  if (b.kind == nc::Statement::popen) {
    out.bytes += kDC2;
    out.open = true;
    return;
  }
  if (!out.open && !out.warned_unopened) {
    out.warned_unopened = true;
    warn("NC2060", fmt::format("{} without a POPEN before it: the manual opens the device with POPEN (DC2) first; "
                               "ncurve sends the output all the same",
                               b.kind == nc::Statement::pclos ? "PCLOS" : b.kind == nc::Statement::dprnt ? "DPRNT" : "BPRNT"),
         b.column);
  }
  if (b.kind == nc::Statement::pclos) {
    out.bytes += kDC4;
    out.open = false;
    return;
  }
  std::string line;
  for (std::uint32_t i = b.words_begin; i < b.words_end; ++i) {
    const nc::PrintItem& item = unit_->prints[i];
    if (item.var.empty()) {
      for (char c : item.text) {
        out.bytes += iso_code(c, parity);
        line += c == '*' ? ' ' : c;
      }
      continue;
    }
    const nc::Value v = eval(item.var);
    const double value = v.vacant ? 0.0 : v.v;  // the manual: a vacant variable is 0
    if (b.kind == nc::Statement::dprnt) {
      const std::string text = dprnt_number(value, item.integers, item.decimals, profile_.dprnt_no_spaces);
      for (char c : text) out.bytes += iso_code(c, parity);
      line += text;
      continue;
    }
    const auto bytes = bprnt_number(value, item.decimals);
    if (!bytes)
      alarm("PS0003", fmt::format("BPRNT: {} with {} decimal places does not fit in 32 bits (the manual names no "
                                  "alarm for it; ncurve stops here)", value, item.decimals),
            item.column);
    out.bytes.append(reinterpret_cast<const char*>(bytes->data()), 4);
    line += fmt::format("<{:02X}{:02X}{:02X}{:02X}>", (*bytes)[0], (*bytes)[1], (*bytes)[2], (*bytes)[3]);
  }
  for (char c : end_of_block(profile_)) out.bytes += iso_code(c, parity);
  if (out.lines.size() < ExternalOutput::kMaxLines) out.lines.push_back(std::move(line));
  else ++out.lines_left_out;
}

}  // namespace ncurve::machine
