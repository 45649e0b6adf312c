// What the control checks in the words of one block before acting on them: an address given twice
// (No.3403#6 AD2), G codes of one group, M codes beyond what No.3404#7 M3B allows, and a minus sign
// on an address that takes none (M, S, T, H, D).
#include <fmt/format.h>

#include <array>
#include <cmath>

#include "machine/g_codes.hpp"
#include "machine/executor.hpp"

namespace ncurve::machine {


void Executor::check_block_words() {
  // a minus sign where the address takes none: T-1 would select no tool, S-100 no speed
  for (const Cmd& c : cmds_)
    if (c.value < 0 && takes_no_sign(c.letter))
      alarm("PS0006", fmt::format("{}{}: address {} takes no minus sign", c.letter, c.value, c.letter), c.column);

  const bool strict = profile_.address_duplicate_alarm;
  // G codes of one group: the last one counts (No.3403#6 AD2 = 0), or PS5074 (AD2 = 1)
  // the groups of the control's G-code table (g_codes.cpp): lathe G17 is group 16, G96 group 02
  const GMachine machine = g_machine(profile_);
  for (std::size_t i = 0; i < g_codes_.size(); ++i) {
    const int group = g_group(g_codes_[i], machine);
    if (group == 0) continue;
    for (std::size_t j = i + 1; j < g_codes_.size(); ++j) {
      if (g_group(g_codes_[j], machine) != group || g_codes_[j] == g_codes_[i]) continue;
      std::uint16_t column = 0;
      for (const Cmd& c : cmds_)
        if (c.letter == 'G' && std::lround(c.value * 10) == g_codes_[j]) column = c.column;
      const std::string both = fmt::format("{} and {} of group {:02} in one block", g_name(g_codes_[i]),
                                           g_name(g_codes_[j]), group);
      if (strict) alarm("PS5074", both + " (No.3403#6 AD2 = 1)", column);
      if (repeat_warned_.emplace(prog_, block_index_).second)  // once a block, however often it runs
          warn("NC2005", fmt::format("{}: the control takes the last, {} (No.3403#6 AD2 = 0)", both,
                                   g_name(g_codes_[j])), column);
      break;
    }
  }

  // an address twice: the later value counts (AD2 = 0) or PS5074; M codes up to three with M3B
  const std::size_t m_allowed = profile_.multiple_m_codes ? 3 : 1;
  std::array<std::uint8_t, 26> count{};
  for (const Cmd& c : cmds_) ++count[c.letter - 'A'];
  bool dropped = false;
  for (std::size_t i = 0; i < cmds_.size(); ++i) {
    Cmd& c = cmds_[i];
    const int k = c.letter - 'A';
    const std::size_t allowed = c.letter == 'M' ? m_allowed : 1;
    if (c.letter == 'G' || count[k] <= allowed) continue;
    const Cmd& last = cmds_[slot_[k]];
    const std::string what =
        c.letter == 'M' && !profile_.multiple_m_codes
            ? fmt::format("M{} and M{} in one block: this control takes one M code a block (No.3404#7 M3B = 0)",
                          c.value, last.value)
        : c.letter == 'M' ? fmt::format("more than three M codes in one block (No.3404#7 M3B = 1)")
                          : fmt::format("address {} given twice in one block ({}{} and {}{})", c.letter, c.letter,
                                        c.value, c.letter, last.value);
    if (strict) alarm("PS5074", what + " (No.3403#6 AD2 = 1)", c.column);
    if (repeat_warned_.emplace(prog_, block_index_).second)
      warn("NC2005", fmt::format("{}: the control takes the last (No.3403#6 AD2 = 0)", what), c.column);
    --count[k];
    c.letter = 0;  // dropped
    dropped = true;
  }
  if (!dropped) return;
  std::erase_if(cmds_, [](const Cmd& c) { return c.letter == 0; });
  m_codes_.clear();
  for (std::size_t i = 0; i < cmds_.size(); ++i) {
    slot_[cmds_[i].letter - 'A'] = static_cast<std::uint8_t>(i);
    if (cmds_[i].letter == 'M') m_codes_.push_back(static_cast<int>(std::lround(cmds_[i].value)));
  }
}

// A value computed for an address (X[#1*2]) within the digits the control takes (number_digits):
// counted in least input increments for a dimension, as a whole number otherwise (PS0003).
void Executor::check_word_digits(char letter, double value, bool dimension, std::uint16_t column) const {
  const double per_unit = !dimension ? 1.0 : modal_.inch ? per_unit_inch_ : per_unit_mm_;
  const double limit = digit_limit_;
  if (std::fabs(value) * per_unit < limit - 0.5) return;
  const int decimals = static_cast<int>(std::lround(std::log10(per_unit)));
  alarm("PS0003",
        fmt::format("{}: the value {:g} has more digits than the control takes (at most {:.{}f}{}; {} digits, "
                    "machine profile number_digits)",
                    letter, value, (limit - 1) / per_unit, decimals, dimension ? (modal_.inch ? " in" : " mm") : "",
                    profile_.number_digits),
        column);
}

}  // namespace ncurve::machine
