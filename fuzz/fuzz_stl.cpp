// libFuzzer target: any bytes as an STL file (src/sim/stl_read*): the reader refuses it with a
// message or reads it; a mesh read is rasterised onto a Z-map of its box (src/sim/mesh_top*), as an
// STL stock or fixture is, on at most 10^5 cells.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "sim/mesh_top.hpp"
#include "sim/stl_read.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncurve;
  sim::Mesh mesh;
  try {
    mesh = sim::parse_stl(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.stl");
  } catch (const std::runtime_error&) {
    return 0;  // refused with a message
  }
  try {
    sim::ZMap map(sim::mesh_box(mesh), 0, 64, 1e5);
    sim::start_at_mesh(map, mesh);
    (void)map.volume_removed();
  } catch (const std::invalid_argument&) {
    // a box too long for its width on 10^5 cells
  }
  return 0;
}
