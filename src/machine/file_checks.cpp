// The checks of a whole file before its run: NC2001 (words with and without a decimal point), and
// the profile hints; for a streamed file, made piece by piece and given at the end of the run.
#include "machine/executor.hpp"
#include "machine/g_codes.hpp"
#include "machine/word_values.hpp"

#include <fmt/format.h>

#include <cmath>

#include "base/parallel.hpp"

#include "machine/file_checks.hpp"

namespace ncurve::machine {

namespace {
// Whether a block holds a literal M98.
bool calls_subprogram(const nc::Program& p, const nc::Block& b) {
  for (std::uint32_t w = b.words_begin; w < b.words_end; ++w)
    if (p.words[w].letter == 'M' && p.words[w].literal && p.words[w].value == 98) return true;
  return false;
}

// Whether a block holds a literal G code from g_lo to g_hi (x10).
bool block_has_g(const nc::Program& p, const nc::Block& b, int g_lo, int g_hi) {
  for (std::uint32_t w = b.words_begin; w < b.words_end; ++w) {
    const nc::Word& word = p.words[w];
    if (word.letter == 'G' && word.literal && word.value * 10 >= g_lo && word.value * 10 <= g_hi) return true;
  }
  return false;
}

// A number as the control shows it: at most `decimals` places, no trailing zeros.
std::string shown_number(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, std::max(decimals, 0));
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

// Whether block b runs in a drilling canned cycle's mode, `before` the mode the blocks before it left:
// G73/G74/G76/G81..G89 (a lathe's G83..G89) start it, G80 or a group 01 code in the block ends it,
// as the executor's select_canned_cycle and cancel_canned_cycle. A G code the profile makes a macro
// call starts nothing.
bool in_drilling_cycle(const MachineProfile& profile, const nc::Program& p, const nc::Block& b, bool before) {
  const GMachine machine = g_machine(profile);
  bool starts = false, ends = false;
  for (std::uint32_t w = b.words_begin; w < b.words_end; ++w) {
    const nc::Word& word = p.words[w];
    if (word.letter != 'G' || !word.literal) continue;
    const int g = round_int(word.value * 10);
    if (macro_g_code(profile, g)) continue;
    if (drilling_cycle_code(g, profile.lathe())) starts = true;
    if (g == 800 || g_group(g, machine) == 1) ends = true;
  }
  return (before || starts) && !ends;
}

// Programs that mix dimension words with and without a decimal point are a classic source of
// scrapped parts. A word of a macro call (G65, G66, a custom G code) is an argument, not an axis.
// The search goes through a program's blocks in order, a piece at a time when it is streamed.
void search_decimal_points(const MachineProfile& profile, const nc::Program& piece, DecimalPointSearch& found) {
  auto is_call = [&](const nc::Program& p, const nc::Block& b) {
    for (std::uint32_t w = b.words_begin; w < b.words_end; ++w) {
      const nc::Word& word = p.words[w];
      if (word.letter != 'G' || !word.literal) continue;
      int g = round_int(word.value * 10);
      if (g == 650 || g == 660 || g == 661 || macro_g_code(profile, g)) return true;
    }
    return false;
  };
  const nc::Program* p = &piece;
  for (const auto& b : p->blocks) {
    if (b.kind != nc::Statement::nc) continue;  // DPRNT's range indexes Program::prints
    found.in_cycle = in_drilling_cycle(profile, *p, b, found.in_cycle);
    for (std::uint32_t w = b.words_begin; w < b.words_end; ++w) {
      const nc::Word& word = p->words[w];
      if (!word.literal || !scaled_address(word.letter)) continue;
      if (found.in_cycle && word.letter == profile.drilling.repeat_address) continue;  // K: the number of repeats
      if (word.letter == 'Q' && profile.lathe() && block_has_g(*p, b, 700, 730)) continue;  // Q: a sequence number
      if (word.letter == 'Q' && profile.lathe()) continue;  // and a start angle (G32, G92), a depth in increments (G76)
      if (word.letter == 'R' && profile.lathe() && block_has_g(*p, b, 730, 730)) continue;  // G73 R: divisions
      if (word.letter == 'Q' && !profile.lathe() && block_has_g(*p, b, 330, 330)) continue;  // G33's start angle
      if (word.letter == 'Q' && calls_subprogram(*p, b)) continue;  // M98 Q: a sequence number
      if (word.decimal_point) found.with = true;
      else if (word.value != 0 && !found.without) {
        found.without = true;
        found.letter = word.letter;
        found.value = word.value;
        found.column = word.column;
        found.line = b.line;
        found.argument = is_call(*p, b);
      }
    }
  }
}

void warn_decimal_points(const MachineProfile& profile, const nc::Program& program, const DecimalPointSearch& found,
                         std::vector<nc::Diagnostic>& to) {
  if (!found.with || !found.without) return;
  const int decimals = static_cast<int>(std::lround(-std::log10(profile.increment)));
  const std::string word = fmt::format("{}{}", found.letter, shown_number(found.value, 0));
  const std::string read_as = profile.decimal_calculator ? shown_number(found.value, 0)
                                                          : shown_number(found.value * profile.increment, decimals);
  const std::string what = found.argument ? fmt::format("argument {} of a macro call is read as {}", word, read_as)
                                          : fmt::format("{} is read as {} mm", word, read_as);
  to.push_back(nc::Diagnostic{
      nc::Severity::warning, "NC2001",
      profile.decimal_calculator
          ? fmt::format("words with and without a decimal point in one program; {} (calculator-type input, "
                        "No.3401#0 = 1)", what)
          : fmt::format("words with and without a decimal point in one program; {} ({} least input increments, "
                        "No.3401#0 = 0)", what, shown_number(found.value, 0)),
      nc::Span{program.file.get(), found.line, found.column, 1}});
}

}  // namespace

void Executor::warn_mixed_decimal_points(const nc::Program& program) {
  DecimalPointSearch found;
  search_decimal_points(profile_, program, found);
  warn_decimal_points(profile_, program, found, result_.warnings);
}


Executor::~Executor() {
  if (file_checks_ && library_.main()->stream) library_.main()->stream->forget_visitors();  // a run left by an exception
}

// Beside the run: the main file's programs (a library program's when it is called); a streamed
// file's as its pieces are read; all given when the run ends, before the run's own warnings.
void Executor::start_file_checks(const nc::Program& main) {
  file_checks_ = std::make_unique<FileChecks>(profile_);
  // two pieces ahead at most: the checks are faster than the run, and each piece waiting is held in memory
  if (base::cores() > 1) file_checks_->beside = std::make_unique<base::TaskThread>(2);
  if (!main.stream) {  // the file's programs, as profile_hints() takes them, named here: the library may grow
    std::vector<const nc::Program*> file;
    for (const auto& p : library_.programs())
      if (p->file == main.file) file.push_back(p.get());
    FileChecks& c = *file_checks_;
    auto check = [&c, file = std::move(file)] {
      for (const nc::Program* p : file) {
        DecimalPointSearch found;
        search_decimal_points(c.profile, *p, found);
        warn_decimal_points(c.profile, *p, found, c.found);
      }
      for (const nc::Program* p : file) c.hints.see(*p, *p);
      for (nc::Diagnostic& d : c.hints.warnings()) c.found.push_back(std::move(d));
    };
    if (c.beside) c.beside->post(std::move(check));
    else check();
    return;
  }
  main.stream->visit([this](const nc::Program& program, const nc::Program& piece, const std::shared_ptr<const void>& keep) {
    FileChecks& c = *file_checks_;
    auto check = [&c, &program, &piece, keep] {
      if (c.programs.empty() || c.programs.back().first != &program) c.programs.emplace_back(&program, DecimalPointSearch{});
      search_decimal_points(c.profile, piece, c.programs.back().second);
      c.hints.see(program, piece);
    };
    if (c.beside) c.beside->post(std::move(check));
    else check();
  });
}

// The file's warnings come first, as when they are found before the run; the run's then stop at 1000
// in all, as they do when the file's come first (NC2001 of a called program is never held back).
void Executor::finish_file_checks(const nc::Program& main) {
  if (main.stream) {
    library_.read_all();
    main.stream->forget_visitors();
  }
  if (file_checks_->beside) file_checks_->beside->finish();
  std::vector<nc::Diagnostic> all = std::move(file_checks_->found);
  if (main.stream) {
    for (const auto& [program, found] : file_checks_->programs) warn_decimal_points(file_checks_->profile, *program, found, all);
    for (nc::Diagnostic& d : file_checks_->hints.warnings()) all.push_back(std::move(d));
  }
  for (nc::Diagnostic& d : result_.warnings)
    if (d.code == "NC2001" || all.size() < 1000) all.push_back(std::move(d));
  result_.warnings = std::move(all);
  file_checks_.reset();
}

}  // namespace ncurve::machine
