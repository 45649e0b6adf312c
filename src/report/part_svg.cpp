#include "report/part_svg.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <stdexcept>

#include "report/backplot_data.hpp"

namespace ncurve::report {

namespace {

void put_u32(std::string& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<char>((v >> s) & 0xFF));
}

void chunk(std::string& out, const char* type, const std::string& body) {
  put_u32(out, static_cast<std::uint32_t>(body.size()));
  const std::string typed = std::string(type, 4) + body;
  out += typed;
  put_u32(out, static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(typed.data()),
                                                static_cast<uInt>(typed.size()))));
}

double deepest_of(const sim::PartGrid& g) {
  double d = g.top;
  for (float h : g.heights) d = std::min(d, static_cast<double>(h));
  return d;
}

}  // namespace

std::array<std::uint8_t, 3> part_shade(double height, double top, double deepest) {
  const double t = std::clamp((top - height) / std::max(top - deepest, 1e-9), 0.0, 1.0);
  auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(255 * v)); };
  return {byte(0.84 - 0.34 * t), byte(0.85 - 0.33 * t), byte(0.87 - 0.29 * t)};
}

std::string png_rgb(int w, int h, const std::vector<std::uint8_t>& rgb) {
  if (w <= 0 || h <= 0 || rgb.size() != static_cast<std::size_t>(w) * h * 3)
    throw std::invalid_argument("png_rgb: the pixels do not fill the picture");
  std::vector<std::uint8_t> raw;  // each row: filter 0 (none), then its pixels
  raw.reserve(static_cast<std::size_t>(h) * (3 * w + 1));
  for (int j = 0; j < h; ++j) {
    raw.push_back(0);
    raw.insert(raw.end(), rgb.begin() + static_cast<std::ptrdiff_t>(j) * 3 * w,
               rgb.begin() + static_cast<std::ptrdiff_t>(j + 1) * 3 * w);
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(packed.data()), &size, raw.data(), static_cast<uLong>(raw.size()), 9) != Z_OK)
    throw std::runtime_error("png_rgb: zlib could not compress the picture");
  packed.resize(size);
  std::string out("\x89PNG\r\n\x1a\n", 8), header;
  put_u32(header, static_cast<std::uint32_t>(w));
  put_u32(header, static_cast<std::uint32_t>(h));
  header += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, no filter method, no interlace
  chunk(out, "IHDR", header);
  chunk(out, "IDAT", packed);
  chunk(out, "IEND", "");
  return out;
}

std::string part_top_svg(const sim::PartGrid& g, const plot::Frame& f) {
  if (g.nx <= 0 || g.ny <= 0) return {};
  const double deepest = deepest_of(g);
  std::vector<std::uint8_t> rgb;
  rgb.reserve(static_cast<std::size_t>(g.nx) * g.ny * 3);
  for (int j = g.ny - 1; j >= 0; --j)  // the picture's top row is the highest Y
    for (int i = 0; i < g.nx; ++i) {
      const auto c = part_shade(g.heights[static_cast<std::size_t>(j) * g.nx + i], g.top, deepest);
      rgb.insert(rgb.end(), c.begin(), c.end());
    }
  const std::string png = png_rgb(g.nx, g.ny, rgb);
  const double x0 = g.x0 - g.dx / 2, x1 = g.x0 + (g.nx - 0.5) * g.dx;
  const double y0 = g.y0 - g.dy / 2, y1 = g.y0 + (g.ny - 0.5) * g.dy;
  return fmt::format("<image class=\"part\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" "
                     "preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" "
                     "href=\"data:image/png;base64,{}\"/>\n",
                     f.x(x0), f.y(y1), f.x(x1) - f.x(x0), f.y(y0) - f.y(y1), base64(png.data(), png.size()));
}

std::string part_side_svg(const sim::PartGrid& g, const plot::Frame& f, int axis) {
  if (g.nx <= 0 || g.ny <= 0) return {};
  const int n = axis == 0 ? g.nx : g.ny, across = axis == 0 ? g.ny : g.nx;
  const double u0 = axis == 0 ? g.x0 : g.y0, du = axis == 0 ? g.dx : g.dy;
  std::string d = fmt::format("M{:.2f},{:.2f}", f.x(u0 - du / 2), f.y(g.bottom));
  for (int k = 0; k < n; ++k) {  // each column's highest material, a step a grid point
    double high = g.bottom;
    for (int m = 0; m < across; ++m) {
      const int i = axis == 0 ? k : m, j = axis == 0 ? m : k;
      high = std::max(high, static_cast<double>(g.heights[static_cast<std::size_t>(j) * g.nx + i]));
    }
    fmt::format_to(std::back_inserter(d), "V{:.2f}H{:.2f}", f.y(high), f.x(u0 + (k + 0.5) * du));
  }
  fmt::format_to(std::back_inserter(d), "V{:.2f}Z", f.y(g.bottom));
  const auto c = part_shade(g.top, g.top, g.bottom);
  return fmt::format("<path class=\"part\" d=\"{}\" fill=\"#{:02x}{:02x}{:02x}\" stroke=\"#80858f\" stroke-width=\"0.8\"/>\n",
                     d, c[0], c[1], c[2]);
}

std::string section_svg(const std::vector<std::vector<geom::V2>>& polygons, const plot::Frame& f) {
  std::string d;
  for (const auto& poly : polygons) {
    if (poly.size() < 3) continue;
    for (std::size_t k = 0; k < poly.size(); ++k)
      fmt::format_to(std::back_inserter(d), "{}{:.2f},{:.2f}", k ? 'L' : 'M', f.x(poly[k].x), f.y(poly[k].y));
    d += 'Z';
  }
  if (d.empty()) return {};
  const auto c = part_shade(0, 0, -1);
  return fmt::format("<path class=\"part\" d=\"{}\" fill=\"#{:02x}{:02x}{:02x}\" fill-rule=\"evenodd\" stroke=\"#80858f\" "
                     "stroke-width=\"0.8\"/>\n",
                     d, c[0], c[1], c[2]);
}

}  // namespace ncurve::report
