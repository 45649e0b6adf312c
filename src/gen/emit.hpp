// Pieces of program text shared by the program forms: numbers as the control reads them,
// axis words, the header, the approach and retract, curve expressions in macro variables.
#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gen/generate.hpp"

namespace ncurve::gen::detail {

constexpr int kFirstTemp = 150;  // macro temporaries #150..

// Builds the text and counts its lines (to find the contour's blocks in the round trip).
struct Writer {
  std::string text;
  std::uint32_t line = 0;
  bool modes_written = false;  // by the set-up (see begin_setup)
  void block(std::string_view b);
  void lines(const std::string& text);  // each non-empty line a block
};

std::string comment_text(std::string s);
int decimals_of(double increment);
std::string number(double v, int decimals);
void append_number(std::string& out, double v, int decimals);
bool is_lathe(const Options& o);
double feed_of(const Options& o);

// Letters and values for the machine axes of a point (lathe X as a diameter).
struct AxisWords {
  const Options& o;
  int decimals;
  bool with_z;  // mill: Z follows the curve
  std::string operator()(const geom::Vec3& p) const;
  void append(std::string& out, const geom::Vec3& p) const;
};

std::string header(const geom::Curve& curve, const Options& o, const std::string& method);
std::string modes(const Options& o);
// The modes line, unless the set-up wrote it already.
void modes_block(Writer& w, const Options& o);
std::string feed_number(const Options& o, double feed);  // F's digits: 4, 6 for inches per revolution

// The set-up (tool, spindle, coolant: Options::tool ..), after the header and before any depth-pass
// loop, so that it is done once: the modes line first (the forms then leave theirs out). And its
// end before M30: coolant off, spindle stop.
bool has_setup(const Options& o);
void begin_setup(Writer& w, const Options& o, int decimals);
void end_setup(Writer& w, const Options& o);

// An inch program's options (Options::inch): the lengths in inches, the machine's increment that of
// its inch input; every form then writes them as it writes millimetres.
constexpr double kMmPerInch = 25.4;
Options in_inches(const Options& o);
// A length in mm as a program in these options' units writes it (the header's figures stay in mm).
double in_program_units(const Options& o, double mm);

// Depth passes (mill, plane curve, Options::step_down > 0): a WHILE loop (DO3) around the whole
// pass from its variables to the retract, #199 the pass's depth; the plunge feeds to Z#199.
constexpr int kPassDepth = 199;
bool depth_passes(const Options& o);
void begin_passes(Writer& w, const Options& o, int decimals);
void end_passes(Writer& w, const Options& o);
std::string plunge_z(const Options& o, double z, int decimals);  // "Z-1.000" or "Z#199"

// Approach before the contour and retract after it.
struct Frame {
  std::string before_start;  // rapid moves to above the start point
  std::string to_depth;      // feed to the start of the contour
  std::string retract;
};
Frame frame(const Options& o, const AxisWords& words, const geom::Vec3& start, const geom::Vec3& end, int dec,
            double feed);

// Machine axis `axis` of the curve point at #100 (lathe X as a radius; the caller doubles it).
geom::Sym axis_sym(const geom::Curve& curve, const AxisMap& map, int axis);

// Assignments of temporaries (from next_temp on) and the words X[..] Y[..] for the machine
// axes given as expressions (letter, expression).
struct MacroWords {
  std::vector<std::string> assignments;
  std::string words;
};
MacroWords macro_words(const std::vector<std::pair<char, geom::Sym>>& axes, int& next_temp);

// The words of a point: their letters and machine axes, lathe X as a diameter (twice the radius
// the axis holds) and Z, mill X, Y and Z where the contour leaves its plane.
struct WordAxis {
  char letter;
  int axis;
  bool diameter;
};
std::vector<WordAxis> word_axes(const Options& o, bool with_z);

// The axes of the curve point at #100 as the control's words.
std::vector<std::pair<char, geom::Sym>> point_axes(const geom::Curve& curve, const AxisMap& map, const Options& o,
                                                   bool with_z);

}  // namespace ncurve::gen::detail
