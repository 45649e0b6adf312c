// libFuzzer target: any bytes as a cutter profile file and as an end-profile point list.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "helicoid/cutter.hpp"
#include "helicoid/profile.hpp"
#include "io/number_rows.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncurve;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    auto cutter = helicoid::DiscCutter::from_text(text, "fuzz.csv");
    for (int k = 0; k <= 8; ++k) (void)cutter.at(cutter.length() * k / 8);
  } catch (const std::runtime_error&) {
  }
  try {
    auto rows = io::read_number_rows(text, "fuzz.csv", 2, 2);
    if (rows.size() > 200) return 0;
    std::vector<helicoid::V2> points;
    for (const auto& r : rows) points.push_back({r.values[0], r.values[1]});
    auto profile = helicoid::EndProfile::from_points("fuzz", points);
    (void)profile.first_hit(10, 0.5 * (profile.r_min() + profile.r_max()) * 0.1);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
