// The setup of a run: the stock, the fixtures and the tool library, read from a TOML setup file
// (docs/setup.md), and the defaults that stand in for what it does not give. Work coordinates,
// mm (a lathe's X as a radius, as in the moves).
#pragma once
#include <array>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "machine/move.hpp"
#include "sim/tool_library.hpp"

namespace ncurve::sim {

using Point3 = std::array<double, 3>;

// An axis-aligned box.
struct AxisBox {
  Point3 min{}, max{};
};

// A bar (inner_diameter 0) or a tube about the Z axis, from its face at Z = face to face - length.
struct Cylinder {
  double diameter = 0, inner_diameter = 0;
  double length = 0;
  double face = 0;
};

// An STL file, kept as a path (relative paths resolved against the setup file's folder);
// scale turns its numbers into mm (25.4 under inch = true).
struct StlFile {
  std::string path;
  double scale = 1;
};

using Stock = std::variant<AxisBox, Cylinder, StlFile>;

struct Fixture {
  std::string name;
  std::variant<AxisBox, StlFile> shape;
};

struct SetupFile {
  std::string origin;                  // the file read
  std::optional<Stock> stock;          // none: default_stock_box
  std::vector<Fixture> fixtures;
  ToolLibrary tools;
  std::optional<int> tool_in_spindle;  // the T number in the spindle when the program starts
  std::vector<std::string> defaulted;  // keys left out and what stands for them, in words
};

// Throws std::runtime_error "file:line:column: error: ..." naming the key and what is wrong.
SetupFile read_setup(const std::string& path);
SetupFile parse_setup(const std::string& toml_text, const std::string& origin);

// The defaults in force, in words, one a line: for no setup file (nullptr), or for what the
// given one leaves out.
std::vector<std::string> setup_defaults(const SetupFile* setup, bool lathe = false);

// The default stock of a mill: the box around the cutting moves (lines and arcs, not rapids),
// widened by the tool's radius to the sides and below, whose top is the highest level a cutting
// move starts from. tool_radius(T) gives each tool's radius; the tool changes at each tool_change
// move (its code), first_tool is in the spindle before the first; tool_radius(T, D) has the D
// offset in force at the move too. None without a cutting move.
class DefaultStockBox final : public machine::MoveSink {
public:
  DefaultStockBox(std::function<double(int, int)> tool_radius, int first_tool = 0)
      : tool_radius_(std::move(tool_radius)), tool_(first_tool) {}
  void on_move(const machine::Move& m) override;
  std::optional<AxisBox> box() const;

private:
  std::function<double(int, int)> tool_radius_;
  int tool_;
  std::optional<AxisBox> box_;
  double top_ = 0;
};

std::optional<AxisBox> default_stock_box(std::span<const machine::Move> moves,
                                         const std::function<double(int)>& tool_radius, int first_tool = 0);

}  // namespace ncurve::sim
