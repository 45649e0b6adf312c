// Signs that a program was written for another machine than the profile's (see the header).
#include "machine/profile/profile_hints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace ncurve::machine {
namespace {

struct BlockWords {
  std::vector<int> g;  // x10
  bool has[26] = {};
  double value[26] = {};
  std::uint16_t column[26] = {};
  bool has_g(int code) const { return std::ranges::find(g, code) != g.end(); }
  bool any_of(const char* letters) const {
    for (const char* c = letters; *c; ++c)
      if (has[*c - 'A']) return true;
    return false;
  }
};

BlockWords words_of(const nc::Program& p, const nc::Block& b) {
  BlockWords w;
  for (std::uint32_t i = b.words_begin; i < b.words_end; ++i) {
    const nc::Word& word = p.words[i];
    if (word.letter < 'A' || word.letter > 'Z') continue;  // ,C ,R ,A (kept in lower case)
    if (!word.literal) {
      w.has[word.letter - 'A'] = true;  // present, value unknown before the run
      continue;
    }
    if (word.letter == 'G') w.g.push_back(static_cast<int>(std::lround(word.value * 10)));
    w.has[word.letter - 'A'] = true;
    w.value[word.letter - 'A'] = word.value;
    w.column[word.letter - 'A'] = word.column;
  }
  return w;
}

// T0101: four digits typed, tool number and offset number alike (a turret's T code).
bool lathe_t_word(const nc::Program& p, const nc::Block& b, std::uint16_t column) {
  const std::string text = p.file->line(b.line);
  if (column == 0 || column > text.size()) return false;
  std::string digits;
  for (std::size_t k = column; k < text.size() && digits.size() < 5; ++k) {
    if (text[k] >= '0' && text[k] <= '9') digits += text[k];
    else if (text[k] != ' ') break;
  }
  return digits.size() == 4 && digits[0] == '0' && digits.substr(0, 2) == digits.substr(2, 2) && digits != "0000";
}

}  // namespace

ProfileHints::ProfileHints(const MachineProfile& profile)
    : profile_(profile), mill_(!profile.lathe()), system_a_(profile.lathe() && profile.gcode_system == 'A') {
  for (int code : profile.g_code_macros) motion_calls_ = motion_calls_ || (code >= 1 && code <= 3);
}

namespace {
template <class Sign>
void note(Sign& s, const char* what, const nc::Program& p, const nc::Block& b, std::uint16_t column) {
  if (s.seen()) return;
  s = Sign{what, p.file.get(), b.line, column ? column : b.column};
}

template <class Sign>
nc::Diagnostic warning(std::string code, const std::vector<const Sign*>& signs, const std::string& head,
                       const std::string& advice) {
  std::string list;
  for (const Sign* s : signs) {
    if (!s->seen()) continue;
    list += fmt::format("{}{} at line {}", list.empty() ? "" : ", ", s->what, s->line);
  }
  const Sign* first = nullptr;
  for (const Sign* s : signs)
    if (s->seen() && (!first || s->line < first->line)) first = s;
  return nc::Diagnostic{nc::Severity::warning, std::move(code), fmt::format("{} ({}): {}", head, list, advice),
                        nc::Span{first->file, first->line, first->column, 1}};
}

}  // namespace

void ProfileHints::see(const nc::Program& program, const nc::Program& p) {
  if (!mill_ && !system_a_) return;
  if (&program != program_) {
    program_ = &program;
    g99_ = false;
  }
  const bool mill = mill_;
  const MachineProfile& profile = profile_;
  for (const nc::Block& b : p.blocks) {
    if (b.kind != nc::Statement::nc || b.error >= 0) continue;
    // a block without T and without G codes but G00..G03 (most of an expanded program) shows no
    // more than a feed below 1 under G99 on a mill, U or W on a lathe
    bool telling = motion_calls_;
    for (std::uint32_t i = b.words_begin; i < b.words_end && !telling; ++i) {
      const nc::Word& word = p.words[i];
      telling = word.letter == 'T' ||
                (word.letter == 'G' && word.literal && !(word.value == 0 || word.value == 1 || word.value == 2 ||
                                                         word.value == 3));
    }
    if (!telling) {
      const nc::Word* feed = nullptr;  // the last F written as a number, as words_of keeps it
      for (std::uint32_t i = b.words_begin; i < b.words_end; ++i) {
        const nc::Word& word = p.words[i];
        if (word.letter == 'F' && word.literal) feed = &word;
        if (!mill && (word.letter == 'U' || word.letter == 'W')) uses_u_w_ = true;
      }
      if (mill && feed && g99_ && !inch_ && feed->value > 0 && feed->value < 1)
        note(per_rev_, "G99 with a feed below 1 (mm per revolution)", p, b, feed->column);
      continue;
    }
    const BlockWords w = words_of(p, b);
    bool call = w.has_g(650) || w.has_g(660) || w.has_g(661);
    for (int code : profile.g_code_macros) call = call || (code != 0 && w.has_g(code * 10));
    if (call) continue;  // the words of a macro call are its arguments
    if (w.has_g(200)) inch_ = true;
    if (mill) {
      if (w.has['T' - 'A'] && lathe_t_word(p, b, w.column['T' - 'A']))
        note(t_word_, "a T word of tool and offset number (T0101 style)", p, b, w.column['T' - 'A']);
      if (w.has_g(500) && w.has['S' - 'A']) note(g50_s_, "G50 S (spindle speed clamp)", p, b, 0);
      if (w.has_g(960)) note(g96_, "G96 (constant surface speed)", p, b, 0);
      if (w.has_g(990)) g99_ = true;
      if (w.has_g(980)) g99_ = false;
      const double f = w.value['F' - 'A'];
      if (g99_ && !inch_ && w.has['F' - 'A'] && f > 0 && f < 1)
        note(per_rev_, "G99 with a feed below 1 (mm per revolution)", p, b, w.column['F' - 'A']);
    } else {
      if (w.has['U' - 'A'] || w.has['W' - 'A']) uses_u_w_ = true;
      for (int g : {770, 780, 790})
        if (w.has_g(g)) note(b_cycle_, "G77/G78/G79 (system B turning cycles)", p, b, 0);
      if (w.has_g(950)) note(g95_, "G95 (feed per revolution in system B)", p, b, 0);
      const bool axes = w.any_of("XZUW");
      const bool motion = w.has_g(0) || w.has_g(10) || w.has_g(20) || w.has_g(30);
      if ((w.has_g(900) || w.has_g(910)) && (!axes || motion))
        note(mode_g90_, "G90/G91 as absolute/incremental mode", p, b, 0);
      if (w.has_g(940) && !axes) note(feed_mode_g94_, "G94 without axes (feed per minute in system B)", p, b, 0);
    }
  }
}

std::vector<nc::Diagnostic> ProfileHints::warnings() const {
  std::vector<nc::Diagnostic> out;
  if (mill_) {
    const int count = t_word_.seen() + g50_s_.seen() + g96_.seen() + per_rev_.seen();
    if (count >= 2)
      out.push_back(warning("NC2030", std::vector<const Sign*>{&t_word_, &g50_s_, &g96_, &per_rev_},
                            "this looks like a lathe program",
                            "on a mill these mean other things; run it with --machine fanuc-lathe (or a lathe "
                            "profile of your own)"));
  } else if (system_a_ && (b_cycle_.seen() || g95_.seen() || (!uses_u_w_ && (mode_g90_.seen() || feed_mode_g94_.seen())))) {
    out.push_back(warning("NC2031", std::vector<const Sign*>{&b_cycle_, &g95_, &mode_g90_, &feed_mode_g94_},
                          "this looks like a G-code system B program",
                          "in system A, G90 and G94 are turning cycles and G91, G95, G77..G79 are no G codes; set "
                          "gcode_system = \"B\" in the profile's [machine] table"));
  }
  return out;
}

std::vector<nc::Diagnostic> profile_hints(const ProgramLibrary& library, const MachineProfile& profile) {
  const nc::Program* main = library.main();
  if (!main) return {};
  ProfileHints hints(profile);
  for (const auto& owned : library.programs())
    if (owned->file == main->file) hints.see(*owned, *owned);
  return hints.warnings();
}

}  // namespace ncurve::machine
