// The program forms, each writing the text and the lines of its contour for the round trip.
#pragma once
#include <memory>
#include <stdexcept>
#include <string>

#include "gen/emit.hpp"

namespace ncurve::gen::detail {

// What every form needs to know about the curve on this machine.
struct Context {
  const geom::Curve& curve;
  const Options& o;
  AxisMap map;
  bool with_z;  // mill: Z follows the curve
  int dec;      // decimals of the machine increment
  double feed;
  AxisWords words;
  geom::Fit fit;
  geom::Vec3 start, end;  // snapped machine coordinates of the curve's ends
  // what the round trip measures against: the curve and options in mm (the same as curve and o
  // but in an inch program, whose curve and options are in inches)
  const geom::Curve& measured_curve;
  const Options& measured_o;
};

class Speculation;  // generate.cpp

struct Emitted {
  std::string text;
  std::uint32_t first = 0, last = 0;  // the contour's lines in the text
  std::vector<std::pair<std::string, double>> parameters;  // control parameters the program needs
  std::string macro;  // cycle: the macro program alone, as a tape for the control's memory
  std::shared_ptr<Speculation> speculation;  // expanded lines: the path measured meanwhile
};

std::string arc_words(const Context& c, const geom::Piece& p);  // I J (K) of an arc
void parameter_blocks(Writer& w, const geom::Curve& curve);      // #101=.. (NAME: DOC)
// The macro forms' opening: tape start, header (method may be empty), depth-pass loop, the
// variables of the curve (#100 = t and `more_variables` in a comment, its parameters, #t_start t
// start, #111 t end).
void macro_preamble(Writer& w, const Context& c, const std::string& method, const std::string& more_variables = "",
                    int t_start = 110);
// Rapid to above the start point given as macro words, then feed to it.
void approach(Writer& w, const Context& c, const MacroWords& start);

// The loop's move (its temporaries, then G01 to `move`, the contour's only line), END1, the
// retract and the end of the program.
Emitted close_loop(Writer& w, const Context& c, const MacroWords& move);
// The retract, M30 and the closing %.
void end_program(Writer& w, const Context& c);

// The program text(value) for the largest value, from `value` down in 1 % steps (each rounded
// by `round`), whose round trip under `on_control` (options in mm) is within the tolerance; else
// `failure`.
template <class Round, class Text>
Emitted tightened(const Context& c, const Options& on_control, double value, Round round, Text text,
                  const std::string& failure) {
  for (int attempt = 0; attempt < 40 && value > 0; ++attempt, value = round(value * 0.99)) {
    Emitted e = text(value);
    if (round_trip(e.text, c.measured_curve, on_control, e.first, e.last).max_deviation <= on_control.tol) return e;
  }
  throw std::runtime_error(failure);
}

Emitted adaptive_macro(const Context& c);
// The adaptive loop (shared with the curve cycles). Before it: the curve's parameters, the t
// start in #t_start and the t end in #111, #1 the aim (deviation at a step's middle, mm), #2 the
// vertex offset outward (tolerance band, mm), #3 the longest t step and #13 the t step tried
// first. adaptive_start sets #5 (t at the vertex A) to #t_start (nothing to do if that is #5)
// and #6 = 0, so that the loop's first trial finds the start vertex (#21.., the curve point at
// #5 rounded) and runs `approach` (blocks moving there, may be empty); adaptive_loop moves to
// #111 and returns the line of its one G01 block.
void adaptive_start(Writer& w, int t_start = 110);
std::uint32_t adaptive_loop(Writer& w, const Context& c, const std::string& approach);
Emitted cycle(const Context& c);

}  // namespace ncurve::gen::detail
