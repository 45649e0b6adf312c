// Programmable parameter input (FANUC 0i / 16i / 30i operator's manual, "programmable parameter
// input (G10)"): G10 L52 starts the mode, each block then sets one parameter, G11 ends it.
//   N_ R_      a parameter that is not of an axis      N: parameter number, R: its value
//   N_ P_ R_   an axis parameter                       P: axis number, 1 .. the number of axes
// A bit parameter's R is its eight bits as binary digits, bit 7 first (leading zeros may be left
// out: R100 sets bit 2 only). The parameters ncurve models take effect at once, but those the
// parameter manual marks "power must be off", which wait for the next power-on (alarm PW0000 on the
// control); one ncurve does not model is accepted with a warning naming it.
#include <fmt/format.h>

#include <cmath>

#include "machine/executor.hpp"

namespace ncurve::machine {

namespace {

// Whether ncurve models the parameter `key` ("3401#0", "5132", "1008#0.A").
bool modelled(const MachineProfile& p, const std::string& key) {
  MachineProfile scratch = p;
  try {
    set_parameter(scratch, key, 0);
  } catch (const UnknownParameter&) {
    return false;
  } catch (const std::runtime_error&) {  // modelled, 0 out of its range
  }
  return true;
}

// Parameters the parameter manual marks "power must be off" among those ncurve models.
bool needs_power_off(int n) { return n == 1 || n == 1006 || n == 1008 || n == 1260 || n == 19625; }
// Read when the run starts (the cutter compensation's settings): a change waits for the next run.
bool read_at_start(int n) { return n == 5003 || n == 5008; }

}  // namespace

void Executor::start_parameter_input() {
  for (const Cmd& c : cmds_)
    if (c.letter != 'G' && c.letter != 'L')
      alarm("PS0231", fmt::format("G10 L52 (programmable parameter input) takes no other words: {} here", c.letter),
            c.column);
  parameter_input_ = true;
}

void Executor::parameter_input_block(const nc::Block& b) {
  const Cmd* g = nullptr;
  const Cmd* p = nullptr;
  const Cmd* r = nullptr;
  std::vector<Cmd> words;
  for (std::uint32_t i = b.words_begin; i < b.words_end; ++i) {
    const nc::Word& w = unit_->words[i];
    Cmd c{w.letter, w.decimal_point, w.literal, w.column, w.value, w.decimals};
    if (!w.literal) {
      const nc::Value v = eval(w.expr);
      if (v.vacant) continue;
      c.value = v.v;
    }
    words.push_back(c);
  }
  for (const Cmd& c : words) {
    const Cmd** slot = c.letter == 'G' ? &g : c.letter == 'P' ? &p : c.letter == 'R' ? &r : nullptr;
    if (!slot)
      alarm("PS0231", fmt::format("address {} in programmable parameter input mode: between G10 L52 and G11 a "
                                  "block is N_ R_ or N_ P_ R_ (or G11)", c.letter == 'c' || c.letter == 'r' || c.letter == 'a' ? ',' : c.letter),
            c.column);
    if (*slot) alarm("PS0231", fmt::format("address {} twice in a parameter input block", c.letter), c.column);
    *slot = &c;
  }
  if (g) {
    if (std::lround(g->value * 10) != 110)
      alarm("PS0231", fmt::format("G{} in programmable parameter input mode: only G11 (end of the mode) may be given "
                                  "before it ends",
                                  g->value),
            g->column);
    if (p || r) alarm("PS0231", "G11 ends programmable parameter input: give it in a block of its own", g->column);
    parameter_input_ = false;
    return;
  }
  if (b.sequence < 0) alarm("PS0231", "a parameter input block needs N (the parameter number): N_ R_", b.column);
  if (!r) alarm("PS0231", fmt::format("N{}: a parameter input block needs R (the value): N_ R_", b.sequence), b.column);
  const int n = b.sequence;
  const bool axis = is_axis_parameter(fmt::format("{}", n)) || is_axis_parameter(fmt::format("{}#0", n));
  std::string suffix;
  if (axis) {
    if (!p) alarm("PS0231", fmt::format("parameter No.{} is set per axis: give P (the axis number, 1..{})", n,
                                        profile_.axes.size()), r->column);
    const int a = integer(*p, "P (axis number)");
    if (a < 1 || a > static_cast<int>(profile_.axes.size()))
      alarm("PS0231", fmt::format("P{}: the axis number is 1..{} (axes {})", a, profile_.axes.size(), profile_.axes),
            p->column);
    suffix = fmt::format(".{}", profile_.axes[a - 1]);
  }
  bool bits = n == 1006 || n == 1008;
  for (int bit = 0; bit < 8 && !bits; ++bit) bits = modelled(profile_, fmt::format("{}#{}", n, bit));
  if (!axis && (bits || modelled(profile_, fmt::format("{}", n))) && p)
    alarm("PS0231", fmt::format("parameter No.{} is not an axis parameter: no P", n), p->column);
  if (!bits) {
    const std::string key = fmt::format("{}{}", n, suffix);
    if (!modelled(profile_, key)) {
      warn("NC2061", fmt::format("G10 L52: parameter No.{}{} = {} is accepted; ncurve does not model it, so the run "
                                 "does not depend on it",
                                 n, p ? fmt::format(" P{}", p->value) : "", r->value),
           r->column);
      return;
    }
    set_parameters_by_program(n, {{key, r->value}}, r->column);
    return;
  }
  // bit type: R holds up to eight binary digits, bit 7 first
  const double v = r->value;
  if ((r->literal && r->decimal_point) || v < 0 || v != std::floor(v) || v > 11111111)
    alarm("PS0231", fmt::format("N{} is a bit parameter: R is its bits as binary digits, bit 7 first (R00000100 "
                                "sets bit 2), not {}",
                                n, v),
          r->column);
  auto digits = static_cast<long>(v);
  std::vector<std::pair<std::string, double>> changes;
  for (int bit = 0; bit < 8; ++bit, digits /= 10) {
    const long d = digits % 10;
    if (d > 1)
      alarm("PS0231", fmt::format("N{} R{}: a bit parameter's R has only the digits 0 and 1", n, static_cast<long>(v)),
            r->column);
    const std::string key = fmt::format("{}#{}{}", n, bit, suffix);
    if (modelled(profile_, key)) changes.emplace_back(key, static_cast<double>(d));
    else if (d == 1)
      warn("NC2061", fmt::format("G10 L52: bit No.{}#{}{} = 1 is accepted; ncurve does not model it, so the run does "
                                 "not depend on it",
                                 n, bit, suffix),
           r->column);
  }
  if (!changes.empty()) set_parameters_by_program(n, changes, r->column);
}

// The values of one parameter input block (a bit parameter's modelled bits, or one value), checked
// together, then made.
void Executor::set_parameters_by_program(int n, const std::vector<std::pair<std::string, double>>& changes,
                                            std::uint16_t column) {
  MachineProfile changed = profile_;
  for (const auto& [key, value] : changes) {
    try {
      set_parameter(changed, key, value);
    } catch (const std::runtime_error& e) {
      alarm("PS0231", fmt::format("G10 L52: {}", e.what()), column);
    }
  }
  if (needs_power_off(n)) {
    warn("NC2062", fmt::format("G10 L52: parameter No.{} takes effect at the next power-on (the control raises PW0000 "
                               "POWER MUST BE OFF); this run keeps the value it had",
                               n),
         column);
    return;
  }
  if (read_at_start(n))
    warn("NC2062", fmt::format("G10 L52: parameter No.{} is read when ncurve starts the run (cutter compensation "
                               "settings); the change applies from the next run",
                               n),
         column);
  profile_ = std::move(changed);
  g01_macro_ = g01_calls_macro();
  // values a program also changes (G71 U, G76 P Q R rewrite these parameters), and cached settings
  switch (n) {
    case 5130: thread_chamfer_ = profile_.thread_chamfer; break;
    case 5132: mrc_depth_ = profile_.mrc_depth; break;
    case 5133: mrc_escape_ = profile_.mrc_escape; break;
    case 5135: mrc_relief_x_ = profile_.mrc_relief_x; break;
    case 5136: mrc_relief_z_ = profile_.mrc_relief_z; break;
    case 5137: mrc_divisions_ = profile_.mrc_divisions; break;
    case 5139: mrc_return_ = profile_.mrc_return; break;
    case 5140: g76_min_depth_ = profile_.g76_min_depth; break;
    case 5141: g76_allowance_ = profile_.g76_allowance; break;
    case 5142: g76_finish_count_ = profile_.g76_finish_count; break;
    case 5143: g76_tool_angle_ = profile_.g76_tool_angle; break;
    case 6004: eval_options_.atan_signed = profile_.atan_signed; break;
    case 1300: stroke_.area_outside = profile_.stroke2_outside; break;
    default: break;
  }
}

}  // namespace ncurve::machine
