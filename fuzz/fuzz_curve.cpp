// libFuzzer target: any bytes as a user curve (x, y and z expressions on lines, with a parameter A),
// compiled, differentiated, printed back as macro text, checked and evaluated.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "geom/curve.hpp"
#include "nc/diagnostic.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncurve::geom;
  std::string text(reinterpret_cast<const char*>(data), size);
  CurveSpec spec;
  spec.name = "fuzz";
  std::string* axes[3] = {&spec.x, &spec.y, &spec.z};
  std::size_t pos = 0;
  for (auto* axis : axes) {
    std::size_t eol = text.find('\n', pos);
    *axis = text.substr(pos, eol == std::string::npos ? std::string::npos : eol - pos);
    if (eol == std::string::npos) break;
    pos = eol + 1;
  }
  spec.params = {{"A", 2.5, ""}};
  spec.from = 0;
  spec.to = 90;
  try {
    Curve c(spec, {});
    for (int a = 0; a < 3; ++a) {
      int next = 150;
      std::vector<std::pair<int, Sym>> temps;
      Sym limited = limit_depth(c.second()[a], 5, next, temps);
      if (bracket_depth(limited) > 5) __builtin_trap();  // the promise of limit_depth
      (void)to_macro(c.first()[a]);
    }
    for (double t : {0.0, 1.0, 45.0, 90.0}) {
      (void)c.point(t);
      (void)c.d2(t);
    }
    c.validate();
    if (size < 64) (void)c.offset(1.0, true, 0, 1);
  } catch (const std::runtime_error&) {  // nc::Alarm included: reported, not a crash
  }
  return 0;
}
