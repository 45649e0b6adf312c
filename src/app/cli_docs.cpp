#include "app/cli_docs.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>

#include "app/cli_checks.hpp"
#include "app/shipped.hpp"

namespace ncurve::app {
namespace {

std::vector<const CLI::App*> commands(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App* c) { return !c->get_group().empty(); });
}

std::vector<const CLI::Option*> options(const CLI::App& cmd) {
  const CLI::Option* help = cmd.get_help_ptr();
  return cmd.get_options(
      [help](const CLI::Option* o) { return o != help && o->nonpositional() && !o->get_group().empty(); });
}

std::vector<std::string> names(const CLI::Option& o) {
  std::vector<std::string> n;
  for (const auto& s : o.get_snames()) n.push_back("-" + s);
  for (const auto& l : o.get_lnames()) n.push_back("--" + l);
  return n;
}

// The values of an option checked by CLI::IsMember, from its type name ("TEXT:{a,b,c}").
std::vector<std::string> choices(const CLI::Option& o) {
  std::string t = o.get_type_name();
  auto open = t.find('{'), close = t.rfind('}');
  std::vector<std::string> out;
  if (open == std::string::npos || close == std::string::npos || close < open) return out;
  std::string list = t.substr(open + 1, close - open - 1);
  std::size_t start = 0;
  while (start <= list.size()) {
    auto comma = list.find(',', start);
    std::string item = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!item.empty()) out.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

enum class ValueKind { none, word, file, folder, profile, choice };

ValueKind value_kind(const CLI::Option& o) {
  if (o.get_items_expected_max() == 0) return ValueKind::none;
  if (!choices(o).empty()) return ValueKind::choice;
  const std::string n = o.get_name(false, true);
  if (n.find("--machine") != std::string::npos) return ValueKind::profile;
  if (n.find("--lib") != std::string::npos) return ValueKind::folder;
  const std::string t = o.get_type_name();
  if (t.find("FILE") != std::string::npos || t.find("PROFILE") != std::string::npos) return ValueKind::file;
  for (const char* f : {"output", "plot", "csv", "blocks", "program", "html"})
    if (n.find(f) != std::string::npos) return ValueKind::file;
  return ValueKind::word;
}

// "TEXT:PROFILE" -> "PROFILE", "TEXT:{a,b}" -> "{a,b}"
std::string value_name(const CLI::Option& o) {
  std::string t = o.get_type_name();
  auto colon = t.find(':');
  return colon == std::string::npos ? t : t.substr(colon + 1);
}

std::string roff(std::string s) {
  std::string out;
  for (char c : s) {
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else out += c;
  }
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out = "\\&" + out;
  return out;
}


}  // namespace

std::string bash_completion(const CLI::App& app) {
  std::string s =
      "# bash completion for ncurve, made by `ncurve completion` from its own option definitions\n"
      "_ncurve() {\n"
      "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
      "  COMPREPLY=()\n";
  std::string top = "--help --version";
  for (const auto* c : commands(app)) top += " " + c->get_name();
  s += fmt::format("  if [ \"$COMP_CWORD\" -eq 1 ]; then\n    COMPREPLY=($(compgen -W \"{}\" -- \"$cur\"))\n"
                   "    return\n  fi\n  case \"${{COMP_WORDS[1]}}\" in\n", top);
  const std::string profiles = fmt::format("{}", fmt::join(shipped_profiles(), " "));
  for (const auto* c : commands(app)) {
    std::string all = "--help -h";
    std::string cases;
    for (const auto* o : options(*c)) {
      auto n = names(*o);
      for (const auto& x : n) all += " " + x;
      std::string pattern = fmt::format("{}", fmt::join(n, "|"));
      switch (value_kind(*o)) {
        case ValueKind::none: break;
        case ValueKind::word: cases += fmt::format("        {}) return ;;\n", pattern); break;
        case ValueKind::file:
          cases += fmt::format("        {}) COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n", pattern);
          break;
        case ValueKind::folder:
          cases += fmt::format("        {}) COMPREPLY=($(compgen -d -- \"$cur\")); return ;;\n", pattern);
          break;
        case ValueKind::profile:
          cases += fmt::format(
              "        {}) COMPREPLY=($(compgen -W \"{}\" -- \"$cur\") $(compgen -f -- \"$cur\")); return ;;\n",
              pattern, profiles);
          break;
        case ValueKind::choice:
          cases += fmt::format("        {}) COMPREPLY=($(compgen -W \"{}\" -- \"$cur\")); return ;;\n", pattern,
                               fmt::join(choices(*o), " "));
          break;
      }
    }
    std::string words;  // positional choices (a curve name)
    for (const auto* o : c->get_options([](const CLI::Option* o) { return o->get_positional(); }))
      for (const auto& x : choices(*o)) words += " " + x;
    s += fmt::format("    {})\n      case \"$prev\" in\n{}      esac\n", c->get_name(), cases);
    s += fmt::format("      if [[ \"$cur\" == -* ]]; then COMPREPLY=($(compgen -W \"{}\" -- \"$cur\"))\n", all);
    if (!words.empty())
      s += fmt::format("      else COMPREPLY=($(compgen -W \"{}\" -- \"$cur\") $(compgen -f -- \"$cur\"))\n", words.substr(1));
    else s += "      else COMPREPLY=($(compgen -f -- \"$cur\"))\n";
    s += "      fi ;;\n";
  }
  s += "  esac\n}\ncomplete -o filenames -F _ncurve ncurve\n";
  return s;
}

std::string man_page(const CLI::App& app, const std::string& version) {
  std::string s = fmt::format(".TH NCURVE 1 \"\" \"ncurve {}\" \"User Commands\"\n", version);
  s += ".SH NAME\nncurve \\- " + roff(app.get_description().substr(app.get_description().find(':') + 2)) + "\n";
  s += ".SH SYNOPSIS\n";
  for (const auto* c : commands(app)) {
    s += fmt::format(".B ncurve {}\n", c->get_name());
    for (const auto* o : c->get_options([](const CLI::Option* o) { return o->get_positional(); }))
      s += fmt::format(".I {}\n", roff(o->get_name()));
    s += ".RI [ options ]\n.br\n";
  }
  s += ".B ncurve\n.B \\-\\-version\n";
  s += ".SH DESCRIPTION\nncurve simulates a FANUC 0i/30i control running a part program (the tool path, every "
       "alarm at its block, cycle time), writes programs for curves proven by that simulation, and measures "
       "contour and shape errors.\n";
  s += ".PP\nExit status: 0 done, 1 an alarm or a result outside its tolerance, 2 bad usage or a file that "
       "cannot be read or written.\n";
  s += ".SH COMMANDS\n";
  for (const auto* c : commands(app)) {
    s += fmt::format(".SS \"ncurve {}\"\n{}.\n", c->get_name(), roff(c->get_description()));
    for (const auto* o : c->get_options([](const CLI::Option* o) { return o->get_positional(); }))
      s += fmt::format(".TP\n.I {}\n{}\n", roff(o->get_name()), roff(o->get_description()));
    for (const auto* o : options(*c)) {
      std::string head = fmt::format("\\fB{}\\fR", roff(fmt::format("{}", fmt::join(names(*o), ", "))));
      if (o->get_items_expected_max() != 0) head += " \\fI" + roff(value_name(*o)) + "\\fR";
      s += fmt::format(".TP\n{}\n{}\n", head, roff(o->get_description()));
    }
  }
  s += ".SH FILES\nShipped machine profiles, custom-cycle macros, examples and documentation are in "
       "share/ncurve beside the binary's folder (for example /usr/local/share/ncurve); "
       "\\fB\\-\\-machine\\fR and \\fB\\-\\-lib\\fR take them by name (fanuc\\-lathe, macros).\n";
  s += ".SH SEE ALSO\nThe reference manual in share/doc/ncurve/docs (run.md, gen.md, analyze.md, helicoid.md, "
       "profiles.md).\n";
  return s;
}

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const auto& c : candidates) {
    std::size_t d = edit_distance(word, c);
    if (c.rfind(word, 0) == 0 && word.size() >= 2) d = std::min<std::size_t>(d, 1);  // "ana" for "analyze"
    if (d < best_d) best_d = d, best = c;
  }
  return best_d <= std::max<std::size_t>(1, word.size() / 3) ? best : std::string();
}

}  // namespace ncurve::app
