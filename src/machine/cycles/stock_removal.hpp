// Geometry of the lathe multiple repetitive cycles (G71..G75), free of the interpreter: a finishing
// shape as lines and arcs in the ZX plane, and the tool paths the cycles make from it.
// Coordinates are mm with X as a radius. The stock removal routines are written for G71 (depth of cut
// along X, cuts along Z); G72 is G71 with the axes exchanged (transposed()).
#pragma once
#include <stdexcept>
#include <vector>

#include "geom/plane.hpp"

namespace ncurve::machine::mrc {

// A point of the ZX plane: x is X (a radius), y is Z.
using P2 = geom::V2;

// One element of a shape: a line, or an arc about `centre` turning `sweep` radians (counter-clockwise
// positive in the Z-X plane, Z towards X, as Move::sweep for G18). `rapid`: a G00 block.
struct Element {
  P2 start, end;
  bool arc = false;
  P2 centre;
  double sweep = 0;
  bool rapid = false;
};
using Shape = std::vector<Element>;

// One move of a cycle's path, from where the previous one ended.
struct Step {
  bool rapid = false;
  P2 end;
  bool arc = false;
  P2 centre;
  double sweep = 0;
};
using Path = std::vector<Step>;

P2 point_at(const Element& e, double t);  // t in 0..1 along the element
Shape translated(const Shape& s, P2 by);
Shape transposed(const Shape& s);  // X and Z exchanged: the mirror turns arcs the other way
Path transposed(const Path& p);
P2 transposed(P2 p);

// Index of the first element along which coordinate `axis` (0 X, 1 Z) turns back against the direction
// the shape has taken so far (a monotone shape has none): -1 when it never does.
int first_reversal(const Shape& s, int axis);

// Where the tool may run along Z at X = level without cutting into the shape: the spans, in cutting
// order from z0, of the Z range the shape covers (and the stretch from z0 to its first point) where
// the shape lies at or beyond the level in the infeed direction `d` (-1: towards smaller X).
struct Span {
  double a = 0, b = 0;  // Z at the ends, a first in cutting order
};
std::vector<Span> spans_at(const Shape& c, double z0, double level, int d);

// Stock removal (G71; G72 after transposing): `shape` is the finishing shape already moved by the
// finishing allowance, from its first point A'' to its last B''.
struct Roughing {
  P2 start;                 // A: the tool at the cycle's start
  Shape shape;
  double depth = 0;         // Δd > 0, along X
  double escape = 0;        // e >= 0: the 45-degree retraction at the end of a cut
  bool rapid_infeed = true; // the first shape block is G00 (else the infeed is fed at F)
  bool pockets = false;     // type II
  bool finish_pass = true;  // the last pass along the shape (No.5105 RF1/RF2 = 0)
};
Path stock_removal(const Roughing& r);
// X of the levels the roughing cuts at, in order (type I: one pass per level).
std::vector<double> roughing_levels(const Roughing& r);

// Pattern repeating (G73): `shape` from A's first block's end, as programmed; the passes move it by
// (relief + allowance) falling in `count` steps to the allowance alone, each from A and back to A.
struct Pattern {
  P2 start;
  Shape shape;           // the first element is the block ns (from A)
  P2 relief;             // Δi (radius), Δk
  P2 allowance;          // Δu/2, Δw
  int count = 1;         // d
};
Path pattern_repeating(const Pattern& p);

// End face peck drilling (G74) and, transposed, grooving (G75): pecks along Z of `peck` with a return
// of `back` after each, at positions along X `shift` apart; at the bottom a relief of `relief` along
// X (its sign the direction when there is no X travel, else against the travel), back to the start Z.
struct Pecking {
  P2 start, end;
  double shift = 0, peck = 0, relief = 0, back = 0;
};
Path peck_cycle(const Pecking& p);

// A cycle's path is built whole before it is made: past this many moves it is refused (PathTooLong)
// instead of filling the memory (a peck or a depth of cut of a few increments over a long travel).
inline constexpr std::size_t kMaxCyclePath = 2'000'000;
struct PathTooLong : std::length_error {
  PathTooLong() : std::length_error("more moves than one cycle may make") {}
};

}  // namespace ncurve::machine::mrc
