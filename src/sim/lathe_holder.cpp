#include "sim/lathe_holder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "machine/profile.hpp"

namespace ncurve::sim {

using geom::V2;

namespace {

constexpr double kMostLength = 1000;  // no body beyond this, mm (a fuzzed library)

bool usable(double v) { return std::isfinite(v) && v > 0 && v <= kMostLength; }

ToolOutline quad(V2 a, V2 b, V2 c, V2 d) {
  std::vector<V2> p{a, b, c, d};
  double area = 0;
  for (std::size_t i = 0; i < 4; ++i) area += geom::cross(p[i], p[(i + 1) % 4]);
  if (area < 0) std::reverse(p.begin(), p.end());
  return {std::move(p)};
}

std::vector<LatheBody> insert_holder(const LatheInsert& i, const ToolOutline& cutting) {
  if (!usable(i.holder_width) || !usable(i.holder_length) || cutting.empty()) return {};
  const int tip = i.tip >= 1 && i.tip <= 8 ? i.tip : 3;
  const machine::TipDirection d = machine::tip_direction(tip);
  V2 s, w;  // along the shank, away from the insert; across it, into the insert's side
  bool centred = false;
  if (d.x < 0) {
    s = {0, 1};
    w = {d.z != 0 ? -static_cast<double>(d.z) : 1.0, 0};
    centred = d.z == 0;
  } else if (d.x > 0) {
    s = {1, 0};
    w = {0, -1};
    centred = d.z == 0;
  } else {
    s = {-static_cast<double>(d.z), 0};
    w = {0, 1};
    centred = true;
  }
  double along = -std::numeric_limits<double>::infinity();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const V2& p : cutting.points) {
    along = std::max(along, geom::dot(p, s));
    lo = std::min(lo, geom::dot(p, w));
    hi = std::max(hi, geom::dot(p, w));
  }
  const double from = centred ? (lo + hi - i.holder_width) / 2 : lo, to = from + i.holder_width;
  const double end = along + i.holder_length;
  return {{quad(along * s + from * w, end * s + from * w, end * s + to * w, along * s + to * w), "holder"}};
}

std::vector<LatheBody> axial_bodies(const MillTool& t) {
  std::vector<LatheBody> out;
  // a piece from z0 to z1 above the tip, its diameter from d0 to d1, about the axis
  auto piece = [&](double z0, double z1, double d0, double d1, const char* what) {
    if (!(std::isfinite(z0) && z1 > z0 && z1 <= 2 * kMostLength && usable(d0) && usable(d1))) return;
    out.push_back({quad({z0, -d0 / 2}, {z1, -d1 / 2}, {z1, d1 / 2}, {z0, d0 / 2}), what});
  };
  if (t.shank_diameter > t.diameter) piece(t.flute_length, t.stick_out, t.shank_diameter, t.shank_diameter, "shank");
  double z = t.stick_out;
  for (const HolderSegment& h : t.holder) {
    if (!usable(h.length)) break;
    piece(z, z + h.length, h.lower, h.upper, "holder");
    z += h.length;
  }
  return out;
}

}  // namespace

std::vector<LatheBody> lathe_bodies(const Tool& tool, const ToolOutline& cutting) {
  if (const auto* i = std::get_if<LatheInsert>(&tool)) return insert_holder(*i, cutting);
  return axial_bodies(std::get<MillTool>(tool));
}

}  // namespace ncurve::sim
