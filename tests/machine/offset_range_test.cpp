// Tool offsets in a profile stay within the control's input range (FANUC 16i/0i, metric IS-B:
// geometry +-999.999 mm, wear +-99.999 mm): a radius of 5e14 mm is refused, not drawn as an arc
// of millions of points.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "machine/profile.hpp"

namespace ncurve::machine {
namespace {

MachineProfile mill(const std::string& offsets, const std::string& memory = "A") {
  return parse_profile("[machine]\noffset_memory = \"" + memory + "\"\n[tool_offsets]\n" + offsets, "p.toml");
}
MachineProfile lathe(const std::string& offsets) {
  return parse_profile("[machine]\ntype = \"lathe\"\naxes = [\"X\", \"Z\"]\n[tool_offsets]\n" + offsets, "p.toml");
}

TEST(OffsetRange, WithinTheControlsRange) {
  EXPECT_DOUBLE_EQ(mill("1 = 999.999\n").tool_offsets.at(1).geometry, 999.999);
  EXPECT_DOUBLE_EQ(mill("2 = -999.999\n").tool_offsets.at(2).d_geometry, -999.999);
  EXPECT_DOUBLE_EQ(mill("3 = { length = 120, length_wear = -99.999 }\n", "B").tool_offsets.at(3).wear, -99.999);
  const auto l = lathe("1 = { x = -999.9, z = 500, r = 0.8, tip = 3, r_wear = 99.99 }\n").lathe_offsets.at(1);
  EXPECT_DOUBLE_EQ(l.tip, 3);
  EXPECT_DOUBLE_EQ(l.r_wear, 99.99);
}

TEST(OffsetRange, BeyondItRefusedWithTheRange) {
  for (const char* bad : {"1 = 1000\n", "1 = 546620210004\n", "1 = -1e300\n", "1 = nan\n", "1 = inf\n"}) {
    try {
      mill(bad);  // throws
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("beyond the control's range"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(mill("1 = { radius = 5, radius_wear = 100 }\n", "C"), std::runtime_error);
  EXPECT_THROW(mill("1 = { length = 1e15 }\n", "C"), std::runtime_error);
  EXPECT_THROW(lathe("1 = { x = 5e14 }\n"), std::runtime_error);
  EXPECT_THROW(lathe("1 = { r = 1000 }\n"), std::runtime_error);
  EXPECT_THROW(lathe("1 = { z_wear = -100 }\n"), std::runtime_error);
  for (const char* tip : {"1.5", "10", "-1", "nan"})
    EXPECT_THROW(lathe(std::string("1 = { r = 0.4, tip = ") + tip + " }\n"), std::runtime_error) << tip;
}

}  // namespace
}  // namespace ncurve::machine
