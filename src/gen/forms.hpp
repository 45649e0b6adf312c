// The program forms, each writing the text and the lines of its contour for the round trip.
#pragma once
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
};

struct Emitted {
  std::string text;
  std::uint32_t first = 0, last = 0;  // the contour's lines in the text
  std::vector<std::pair<std::string, double>> parameters;  // control parameters the program needs
  std::string macro;  // cycle: the macro program alone, as a tape for the control's memory
};

std::string arc_words(const Context& c, const geom::Piece& p);  // I J (K) of an arc
void parameter_blocks(Writer& w, const geom::Curve& curve);      // #101=.. (NAME: DOC)
// The macro forms' opening: tape start, header, depth-pass loop, the variables of the curve
// (#100 = t, its parameters, #110 t start, #111 t end).
void macro_preamble(Writer& w, const Context& c, const std::string& method);
// Rapid to above the start point given as macro words, then feed to it.
void approach(Writer& w, const Context& c, const MacroWords& start);

// The loop's move (its temporaries, then G01 to `move`, the contour's only line), END1, the
// retract and the end of the program.
Emitted close_loop(Writer& w, const Context& c, const MacroWords& move);
// The retract, M30 and the closing %.
void end_program(Writer& w, const Context& c);

Emitted adaptive_macro(const Context& c);
// The adaptive loop's pieces (shared with the curve cycles): the step from the curvature behind
// and ahead (#118, #127, #128, #129, least curvature #117, factor #116 -> new #129); at #100 the
// derivatives #120.., speed #126, signed curvature #127, its size #128 and the vertex offset
// #130 (+-#115 outward, 0 at the end); the vertex's axes (the curve point moved by #130).
void step_blocks(Writer& w);
std::vector<std::string> curvature_blocks(const Context& c, int& next_temp);
std::vector<std::pair<char, geom::Sym>> vertex_axes(const Context& c);
Emitted cycle(const Context& c);

// The adaptive macro's step rule run natively (what the control will compute): the parameters
// of the vertices for a step factor; exposed for tests and benchmarks.
struct AdaptiveRule {
  double offset = 0;     // vertices moved outward from the curve by this much (tolerance band), mm
  double factor = 0;     // parameter step = factor / sqrt(curvature ahead) / speed
  double min_curvature = 0;
  double first_step = 0;  // parameter step of the first move
};
AdaptiveRule adaptive_rule(const Context& c);

}  // namespace ncurve::gen::detail
