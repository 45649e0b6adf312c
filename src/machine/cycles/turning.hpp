// A lathe's single cutting cycles (G90, G92, G94; G77, G78, G79 on G-code systems B and C) and the
// multiple threading cycle G76 as expanders, free of the interpreter: the cycle's data in, its moves
// out through a CycleOutput, from the start point A where the tool is. FANUC 0i-TF / 30i-B lathe
// operator's manuals. Coordinates are work coordinates, mm, X as a radius, in the G18 plane.
#pragma once
#include <stdexcept>
#include <vector>

#include "machine/cycles/cycle_output.hpp"

namespace ncurve::machine::turn {

struct Thread {
  double lead = 0;        // F, mm per spindle revolution
  int chamfer = 0;        // r: the chamfer (pull-out) in 0.1 leads (No.5130, G76's P)
  int chamfer_angle = 0;  // No.5131: its angle to the thread axis, degrees (0: 45)
};

// The thread cut of a G92 or G76 pass to `end`: with a chamfer r the tool leaves the thread r
// before the end point's Z and reaches it r * tan(angle) out, toward the retract level out_x.
void thread_pass(const AxisVector& end, double out_x, const Thread& t, double start_angle, CycleOutput& out);

struct SingleCycle {
  int code = 90;           // 90, 92, 94 as system A writes them
  AxisVector end{};        // E: the cutting end point
  double r = 0;            // taper: at the cut's start less at its end, along X (G90, G92) or Z (G94)
  Thread thread;           // G92
  double start_angle = 0;  // G92: Q, the spindle angle the thread starts at, degrees
};
// From A:
//   G90: (1) rapid X to E.x + R, (2) feed to E, (3) feed X back to A.x, (4) rapid Z back to A.z
//   G94: (1) rapid Z to E.z + R, (2) feed to E, (3) feed Z back to A.z, (4) rapid X back to A.x
//   G92: as G90 with (2) a thread pass and (3) at rapid traverse
// CycleOutput::returning comes before (4).
void single_cycle(const SingleCycle& c, CycleOutput& out);
// The side of the cut (1)->(2) that A lies on, in the G18 plane (Z, X): 1 left (G41), -1 right
// (G42), 0 on its line.
int start_side(const SingleCycle& c, const AxisVector& a);

struct MultipleThreading {
  AxisVector end{};        // the thread's end point at full depth
  double taper = 0;        // R (i): X radius at the start less at the end
  double height = 0;       // k, the thread height
  double first = 0;        // Δd, the depth of the first cut
  double min_depth = 0;    // dmin (No.5140, Q of the first block)
  double allowance = 0;    // d, the finishing allowance (No.5141, R of the first block)
  int finish_count = 1;    // m, finishing passes (at least one is made)
  int tool_angle = 0;      // a, degrees
  Thread thread;
  double start_angle = 0;  // Q (Series 10/11 format), degrees
};
inline constexpr std::size_t kMaxThreadPasses = 100000;
struct TooManyPasses : std::length_error {
  TooManyPasses() : std::length_error("more passes than a threading cycle may make") {}
};
// The depths below the crest of the passes: pass n cuts to Δd * sqrt(n), at least dmin deeper than
// the pass before, until k - d; then m finishing passes at k. Past kMaxThreadPasses roughing
// passes: TooManyPasses.
std::vector<double> thread_depths(const MultipleThreading& c);
// G76 from A: each pass starts along the flank of the tool angle (single edge cutting), cuts the
// thread with its chamfer, rapids out to A's X and back to A.
void multiple_threading(const MultipleThreading& c, const std::vector<double>& depths, CycleOutput& out);

}  // namespace ncurve::machine::turn
