// The part in the SVG plots: the PNG read back with zlib's own inflate, the picture placed on the
// panel's frame and the outlines' heights, worked by hand on a grid of 3 x 2 points.
#include <gtest/gtest.h>
#include <zlib.h>

#include <regex>
#include <string>
#include <vector>

#include "report/part_svg.hpp"

namespace ncurve::report {
namespace {

std::uint32_t be32(const std::string& s, std::size_t at) {
  return (std::uint32_t{static_cast<std::uint8_t>(s[at])} << 24) | (std::uint32_t{static_cast<std::uint8_t>(s[at + 1])} << 16) |
         (std::uint32_t{static_cast<std::uint8_t>(s[at + 2])} << 8) | std::uint32_t{static_cast<std::uint8_t>(s[at + 3])};
}

TEST(PartSvg, PngReadsBack) {
  std::vector<std::uint8_t> rgb;
  for (int k = 0; k < 3 * 2 * 3; ++k) rgb.push_back(static_cast<std::uint8_t>(13 * k));
  const std::string png = png_rgb(3, 2, rgb);
  ASSERT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  std::size_t at = 8;
  std::string idat;
  std::vector<std::string> types;
  while (at < png.size()) {
    const std::uint32_t len = be32(png, at);
    const std::string type = png.substr(at + 4, 4), body = png.substr(at + 8, len);
    const std::string typed = type + body;
    EXPECT_EQ(be32(png, at + 8 + len), crc32(0, reinterpret_cast<const Bytef*>(typed.data()), static_cast<uInt>(typed.size())))
        << type;
    if (type == "IHDR") {
      EXPECT_EQ(be32(body, 0), 3u);
      EXPECT_EQ(be32(body, 4), 2u);
      EXPECT_EQ(body.substr(8), std::string("\x08\x02\x00\x00\x00", 5));
    }
    if (type == "IDAT") idat += body;
    types.push_back(type);
    at += 12 + len;
  }
  EXPECT_EQ(types, (std::vector<std::string>{"IHDR", "IDAT", "IEND"}));
  std::vector<std::uint8_t> raw(2 * (1 + 9));
  uLongf size = raw.size();
  ASSERT_EQ(uncompress(raw.data(), &size, reinterpret_cast<const Bytef*>(idat.data()), idat.size()), Z_OK);
  ASSERT_EQ(size, raw.size());
  for (int j = 0; j < 2; ++j) {
    EXPECT_EQ(raw[j * 10], 0);  // no filter
    for (int k = 0; k < 9; ++k) EXPECT_EQ(raw[j * 10 + 1 + k], rgb[j * 9 + k]);
  }
  EXPECT_THROW(png_rgb(3, 2, std::vector<std::uint8_t>(5)), std::invalid_argument);
}

sim::PartGrid grid() {
  // points at X 0, 1, 2 and Y 10, 12; heights: row Y10 {0, -1, 0}, row Y12 {-2, 0, 0}
  sim::PartGrid g;
  g.nx = 3, g.ny = 2, g.x0 = 0, g.y0 = 10, g.dx = 1, g.dy = 2, g.bottom = -5, g.top = 0;
  g.heights = {0, -1, 0, -2, 0, 0};
  return g;
}

TEST(PartSvg, PictureOnTheFrame) {
  plot::Frame f;  // u -10..10 over 200 px from x 100, v 0..20 over 200 px from y 50 (up)
  f.left = 100, f.top = 50, f.width = 200, f.height = 200, f.u0 = -10, f.u1 = 10, f.v0 = 0, f.v1 = 20;
  const std::string s = part_top_svg(grid(), f);
  // cells from X -0.5 to 2.5 and Y 9 to 13: x 195..225, y (20 - 13) * 10 + 50 = 120 to 160
  EXPECT_NE(s.find("x=\"195.00\" y=\"120.00\" width=\"30.00\" height=\"40.00\""), std::string::npos) << s;
  auto near = [](std::array<std::uint8_t, 3> got, std::array<int, 3> want) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1) << k;
  };
  near(part_shade(0, 0, -2), {214, 217, 222});   // the top: 0.84, 0.85, 0.87 of 255
  near(part_shade(-2, 0, -2), {128, 133, 148});  // the deepest: 0.50, 0.52, 0.58
  near(part_shade(-1, 0, -2), {171, 175, 185});  // half way: 0.67, 0.685, 0.725
}

TEST(PartSvg, OutlinesTheHighestOfEachColumn) {
  plot::Frame f;
  f.left = 0, f.top = 0, f.width = 100, f.height = 100, f.u0 = -5, f.u1 = 15, f.v0 = -10, f.v1 = 10;
  // along Y (front): X columns' highest 0, 0, 0; along X (side): Y rows' highest 0 (row 10), 0 (row 12)
  const std::string front = part_side_svg(grid(), f, 0);
  // from (X -0.5, bottom -5) up to 0 and across to 0.5, 1.5, 2.5, down to the bottom
  EXPECT_NE(front.find("d=\"M22.50,75.00V50.00H27.50V50.00H32.50V50.00H37.50V75.00Z\""), std::string::npos) << front;
  sim::PartGrid g = grid();
  g.heights = {-1, -1, -1, -2, -3, -2};  // row Y10 highest -1, row Y12 highest -2
  const std::string side = part_side_svg(g, f, 1);
  // Y 9 to 11 at -1 (y 55), 11 to 13 at -2 (y 60)
  EXPECT_NE(side.find("d=\"M70.00,75.00V55.00H80.00V60.00H90.00V75.00Z\""), std::string::npos) << side;
}

}  // namespace
}  // namespace ncurve::report

namespace ncurve::report {
namespace {

TEST(PartSvg, SectionAsItsPolygons) {
  plot::Frame f;  // Z -10..10 over x 0..200, the radius 0..20 over y 200..0
  f.left = 0, f.top = 0, f.width = 200, f.height = 200, f.u0 = -10, f.u1 = 10, f.v0 = 0, f.v1 = 20;
  const std::vector<std::vector<geom::V2>> polygons = {{{-10, 0}, {0, 0}, {0, 10}, {-10, 10}}, {{-5, 2}, {-5, 4}, {-2, 4}}};
  const std::string s = section_svg(polygons, f);
  EXPECT_NE(s.find("d=\"M0.00,200.00L100.00,200.00L100.00,100.00L0.00,100.00ZM50.00,180.00L50.00,160.00L80.00,160.00Z\""),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("fill-rule=\"evenodd\""), std::string::npos);
  EXPECT_EQ(section_svg({{{0, 0}, {1, 1}}}, f), "");  // nothing to fill
}

}  // namespace
}  // namespace ncurve::report
