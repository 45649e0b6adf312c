// The tool library of a setup: what each tool number holds, mill tools and lathe inserts, with the
// default for a tool the library does not name. Lengths in mm, angles in degrees.
#pragma once
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace ncurve::sim {

enum class MillKind { flat, ball, bull_nose, drill, chamfer, tap };
const char* to_string(MillKind k);  // as the setup file spells it: "flat", "bull-nose", ...

// One piece of a holder's stack, listed from the tool upwards: a cylinder, or a cone whose
// diameter goes from `lower` at its bottom to `upper` at its top.
struct HolderSegment {
  double lower = 0, upper = 0;  // diameters
  double length = 0;
  bool cone() const { return lower != upper; }
};

struct MillTool {
  MillKind kind = MillKind::flat;
  std::string name;
  double diameter = 0;       // cutting diameter
  double corner_radius = 0;  // bull-nose; a ball's is diameter / 2, others 0
  double flute_length = 0;   // cutting length from the tip
  double shank_diameter = 0;
  double stick_out = 0;      // tip to the holder's face
  std::vector<HolderSegment> holder;  // from the holder's face upwards; empty: not modelled
  bool centre_cutting = true;
  double point_angle = 0;         // drill and chamfer: included angle; 0 for the others
  double max_spindle_speed = 0;   // rev/min; 0: no limit of the tool's own
  double radius() const { return diameter / 2; }
};

// A turning, grooving or threading insert in its holder (XZ plane).
struct LatheInsert {
  std::string name;
  double nose_radius = 0;
  int tip = 0;                 // imaginary tool nose number 0..9 (machine::tip_direction)
  double insert_angle = 80;    // included angle of the cutting point
  double clearance_angle = 5;  // the edge across the spindle axis past the perpendicular (a 95-degree holder: 5)
  double width = 0;            // grooving or parting blade's width; 0 for a pointed insert
  double holder_width = 0, holder_length = 0;  // 0: holder not modelled
};

using Tool = std::variant<MillTool, LatheInsert>;

struct ToolLibrary {
  // By tool number: a mill's T number; a lathe's turret station (T0203 -> 2, lathe_tool_number).
  std::map<int, Tool> tools;

  const MillTool* mill(int number) const;
  const LatheInsert* insert(int number) const;
};

// The tool number of a lathe's T code: the digits before its two offset digits.
inline int lathe_tool_number(int t_code) { return t_code / 100; }

// A tool without a library entry: a flat end mill of a D offset's radius; a lathe insert of its
// offset's nose radius and imaginary tip.
MillTool default_mill_tool(double radius);
LatheInsert default_insert(double nose_radius, int tip);

// One line in words: "T3 ball end mill D6, flutes 12, stick-out 30, holder 2 pieces".
std::string describe(int number, const Tool& tool);

}  // namespace ncurve::sim
