// Setup files read from TOML: the top level, [stock] and [[fixtures]]; [tools] in tool_library.cpp.
#include "sim/setup.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/toml_text.hpp"
#include "sim/setup_toml.hpp"

namespace ncurve::sim {
namespace {

using setup_toml::dotted;
using setup_toml::Range;
using setup_toml::Reader;

AxisBox read_box(const Reader& r, const toml::table& t, const std::string& where) {
  const std::string why = "a box is given by its corners min = [x, y, z] and max = [x, y, z]";
  AxisBox b;
  b.min = r.point(r.required(t, "min", where, why), dotted(where, "min"));
  const toml::node& max = r.required(t, "max", where, why);
  b.max = r.point(max, dotted(where, "max"));
  for (int i = 0; i < 3; ++i)
    if (!(b.max[i] > b.min[i]))
      r.fail(max, fmt::format("'{}' must exceed '{}' on every axis: {} max {} is not above min {}", dotted(where, "max"),
                              dotted(where, "min"), "XYZ"[i], b.max[i] / r.scale(), b.min[i] / r.scale()));
  return b;
}

StlFile read_stl(const Reader& r, const toml::table& t, const std::string& where) {
  const toml::node& node = r.required(t, "file", where, "an STL shape names its file: file = \"part.stl\"");
  std::string path = r.text(node, dotted(where, "file"));
  if (path.empty()) r.fail(node, fmt::format("'{}' must name a file", dotted(where, "file")));
  const std::filesystem::path p(path);
  const std::filesystem::path folder = std::filesystem::path(r.origin()).parent_path();
  if (p.is_relative() && !folder.empty()) path = (folder / p).lexically_normal().string();
  return StlFile{path, r.scale()};
}

Cylinder read_cylinder(const Reader& r, const toml::table& t, const std::string& where, bool tube,
                       std::vector<std::string>& defaulted) {
  const std::string why = tube ? "a tube is given by diameter, inner_diameter, length (and face)"
                               : "a cylinder is given by diameter, length (and face)";
  Cylinder c;
  c.diameter = r.length(r.required(t, "diameter", where, why), dotted(where, "diameter"), Range::positive);
  if (tube) {
    const toml::node& inner = r.required(t, "inner_diameter", where, why);
    c.inner_diameter = r.length(inner, dotted(where, "inner_diameter"), Range::positive);
    if (!(c.inner_diameter < c.diameter))
      r.fail(inner, fmt::format("'{}' must be less than the diameter {}", dotted(where, "inner_diameter"),
                                c.diameter / r.scale()));
  }
  c.length = r.length(r.required(t, "length", where, why), dotted(where, "length"), Range::positive);
  if (const toml::node* face = t.get("face")) c.face = r.length(*face, dotted(where, "face"));
  else defaulted.push_back(fmt::format("{}: face at Z0 (face not given)", where));
  return c;
}

Stock read_stock(const Reader& r, const toml::table& t, std::vector<std::string>& defaulted) {
  const std::string where = "stock";
  const toml::node& shape_node =
      r.required(t, "shape", where, "shape = \"box\", \"cylinder\", \"tube\" or \"stl\" says which the stock is");
  const std::string shape = r.text(shape_node, "stock.shape");
  if (shape == "box") {
    r.only_keys(t, where, {"shape", "min", "max"});
    return read_box(r, t, where);
  }
  if (shape == "cylinder") {
    r.only_keys(t, where, {"shape", "diameter", "length", "face"});
    return read_cylinder(r, t, where, false, defaulted);
  }
  if (shape == "tube") {
    r.only_keys(t, where, {"shape", "diameter", "inner_diameter", "length", "face"});
    return read_cylinder(r, t, where, true, defaulted);
  }
  if (shape == "stl") {
    r.only_keys(t, where, {"shape", "file"});
    return read_stl(r, t, where);
  }
  r.fail(shape_node, fmt::format("'stock.shape' must be \"box\", \"cylinder\", \"tube\" or \"stl\", not \"{}\"", shape));
}

Fixture read_fixture(const Reader& r, const toml::table& t, const std::string& where) {
  Fixture f;
  const toml::node& name = r.required(t, "name", where, "each fixture has a name, used in the warnings about it");
  f.name = r.text(name, dotted(where, "name"));
  if (f.name.empty()) r.fail(name, fmt::format("'{}' must not be empty", dotted(where, "name")));
  const toml::node& shape_node = r.required(t, "shape", where, "shape = \"box\" or \"stl\" says which the fixture is");
  const std::string shape = r.text(shape_node, dotted(where, "shape"));
  if (shape == "box") {
    r.only_keys(t, where, {"name", "shape", "min", "max"});
    f.shape = read_box(r, t, where);
  } else if (shape == "stl") {
    r.only_keys(t, where, {"name", "shape", "file"});
    f.shape = read_stl(r, t, where);
  } else {
    r.fail(shape_node, fmt::format("'{}' must be \"box\" or \"stl\", not \"{}\"", dotted(where, "shape"), shape));
  }
  return f;
}

std::vector<Fixture> read_fixtures(const Reader& r, const toml::node& node) {
  const toml::array* a = node.as_array();
  if (!a) r.fail(node, "'fixtures' must be an array of tables: one [[fixtures]] each");
  std::vector<Fixture> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const std::string where = fmt::format("fixtures[{}]", i);
    const toml::node& item = *a->get(i);
    Fixture f = read_fixture(r, r.table(item, where), where);
    for (const Fixture& g : out)
      if (g.name == f.name) r.fail(item, fmt::format("fixture name '{}' is given twice", f.name));
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace

SetupFile parse_setup(const std::string& toml_text, const std::string& origin) {
  const toml::table root = io::parse_toml(toml_text, origin);
  SetupFile s;
  s.origin = origin;
  // inch first: it scales every length of the file
  double scale = 1;
  if (const toml::node* inch = root.get("inch")) scale = Reader(origin, 1).flag(*inch, "inch") ? 25.4 : 1;
  const Reader r(origin, scale);
  r.only_keys(root, "", {"inch", "tool_in_spindle", "stock", "fixtures", "tools"});
  if (const toml::node* t = root.get("tool_in_spindle")) s.tool_in_spindle = r.whole(*t, "tool_in_spindle", 0, 99999999);
  if (const toml::node* t = root.get("stock")) s.stock = read_stock(r, r.table(*t, "stock"), s.defaulted);
  if (const toml::node* t = root.get("fixtures")) s.fixtures = read_fixtures(r, *t);
  if (const toml::node* t = root.get("tools")) s.tools = setup_toml::read_tools(r, r.table(*t, "tools"), s.defaulted);
  return s;
}

SetupFile read_setup(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: error: cannot open the setup file", path));
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_setup(ss.str(), path);
}

}  // namespace ncurve::sim
