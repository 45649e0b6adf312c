// The cut part in the path plot's panels (`run --plot` with --verify): from above (XY) a picture of
// its depth, shaded as the 3D page shades it; from the front (XZ) and the side (YZ) its outline, the
// highest material over each column.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "geom/plane.hpp"
#include "report/svg_plot.hpp"
#include "sim/part_stl.hpp"

namespace ncurve::report {

// An <image> of the part's top, one pixel a grid point, in the XY panel's frame.
std::string part_top_svg(const sim::PartGrid& part, const plot::Frame& f);
// A filled outline of the part seen along Y (axis 0: X across, Z up) or along X (axis 1: Y across).
std::string part_side_svg(const sim::PartGrid& part, const plot::Frame& f, int axis);
// The part's colour at a height: light grey at the stock's top, darker down to the deepest cut.
std::array<std::uint8_t, 3> part_shade(double height, double top, double deepest);

// A lathe's cut part in its ZX panel: the half-section's polygons (Z across, X the radius up),
// holes cut out (even-odd fill).
std::string section_svg(const std::vector<std::vector<geom::V2>>& polygons, const plot::Frame& f);

// A PNG file of w x h RGB pixels (rows from the top), compressed with zlib.
std::string png_rgb(int w, int h, const std::vector<std::uint8_t>& rgb);

}  // namespace ncurve::report
