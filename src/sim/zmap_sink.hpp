// The move stream cut into a Z-map: each rapid, line and XY arc with the tool in the spindle
// (rapids cut too; telling that apart is the checks' work).
#pragma once
#include <cstdint>
#include <map>
#include <optional>

#include "machine/move.hpp"
#include "sim/tool_shape.hpp"
#include "sim/zmap.hpp"

namespace ncurve::sim {

class ZMapSink final : public machine::MoveSink {
public:
  // tools: the shape of each T number. The tool in the spindle changes on each tool change
  // event (M06 on a mill); `spindle` is the one in it before the first.
  ZMapSink(ZMap& map, std::map<int, ToolShape> tools, std::optional<int> spindle = std::nullopt);

  void on_move(const machine::Move& m) override;

  struct Counts {
    std::uint64_t cut = 0;          // moves cut into the map
    std::uint64_t no_tool = 0;      // motion with no tool in the spindle or a T number without a shape
    std::uint64_t not_xy_arc = 0;   // arcs in G18/G19, not simulated yet
  };
  const Counts& counts() const { return counts_; }

private:
  ZMap& map_;
  std::map<int, ToolShape> tools_;
  const ToolShape* tool_ = nullptr;
  Counts counts_;
};

}  // namespace ncurve::sim
