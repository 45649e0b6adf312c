// The tool library: [tools] of a setup file read into mill tools and lathe inserts, the defaults of
// what an entry leaves out, and the tool that stands for one without an entry.
#include "sim/tool_library.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "sim/setup_toml.hpp"

namespace ncurve::sim {

const char* to_string(MillKind k) {
  switch (k) {
    case MillKind::flat: return "flat";
    case MillKind::ball: return "ball";
    case MillKind::bull_nose: return "bull-nose";
    case MillKind::drill: return "drill";
    case MillKind::chamfer: return "chamfer";
    case MillKind::tap: return "tap";
  }
  return "flat";
}

const MillTool* ToolLibrary::mill(int number) const {
  auto it = tools.find(number);
  return it == tools.end() ? nullptr : std::get_if<MillTool>(&it->second);
}

const LatheInsert* ToolLibrary::insert(int number) const {
  auto it = tools.find(number);
  return it == tools.end() ? nullptr : std::get_if<LatheInsert>(&it->second);
}

constexpr double kStickOutPerDiameter = 4;  // a tool's stick-out when not given

MillTool default_mill_tool(double radius) {
  MillTool t;
  t.diameter = 2 * std::max(radius, 0.0);
  t.shank_diameter = t.diameter;
  t.stick_out = t.flute_length = kStickOutPerDiameter * t.diameter;
  return t;
}

LatheInsert default_insert(double nose_radius, int tip) {
  LatheInsert t;
  t.nose_radius = std::max(nose_radius, 0.0);
  t.tip = std::clamp(tip, 0, 9);
  return t;
}

std::string describe(int number, const Tool& tool) {
  if (const auto* m = std::get_if<MillTool>(&tool)) {
    static const char* const names[] = {"flat end mill", "ball end mill", "bull-nose end mill", "drill",
                                        "chamfer mill", "tap"};
    std::string s = fmt::format("T{} {} D{:g}", number, names[static_cast<int>(m->kind)], m->diameter);
    if (m->kind == MillKind::bull_nose) s += fmt::format(" R{:g}", m->corner_radius);
    if (m->point_angle > 0) s += fmt::format(" {:g}°", m->point_angle);
    s += fmt::format(", flutes {:g}, stick-out {:g}", m->flute_length, m->stick_out);
    if (!m->holder.empty()) s += fmt::format(", holder of {} pieces", m->holder.size());
    if (!m->centre_cutting) s += ", not centre-cutting";
    return m->name.empty() ? s : s + " (" + m->name + ")";
  }
  const auto& i = std::get<LatheInsert>(tool);
  std::string s = fmt::format("T{} insert R{:g} tip {}, {:g}°", number, i.nose_radius, i.tip, i.insert_angle);
  if (i.width > 0) s += fmt::format(", width {:g}", i.width);
  return i.name.empty() ? s : s + " (" + i.name + ")";
}

namespace setup_toml {
namespace {

std::vector<HolderSegment> read_holder(const Reader& r, const toml::node& node, const std::string& key) {
  const toml::array* a = node.as_array();
  if (!a || a->empty())
    r.fail(node, fmt::format("'{}' must be an array of pieces from the tool upwards: "
                             "[{{ diameter = 32, length = 40 }}, {{ diameter = [32, 50], length = 10 }}]", key));
  std::vector<HolderSegment> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const std::string where = fmt::format("{}[{}]", key, i);
    const toml::table& t = r.table(*a->get(i), where);
    r.only_keys(t, where, {"diameter", "length"});
    const std::string why = "a holder piece is { diameter = D, length = L } (a cone: diameter = [lower, upper])";
    const toml::node& d = r.required(t, "diameter", where, why);
    HolderSegment s;
    if (const toml::array* pair = d.as_array()) {
      if (pair->size() != 2)
        r.fail(d, fmt::format("'{}.diameter' of a cone is two numbers [lower, upper]", where));
      s.lower = r.length(*pair->get(0), where + ".diameter", Range::positive);
      s.upper = r.length(*pair->get(1), where + ".diameter", Range::positive);
    } else {
      s.lower = s.upper = r.length(d, where + ".diameter", Range::positive);
    }
    s.length = r.length(r.required(t, "length", where, why), where + ".length", Range::positive);
    out.push_back(s);
  }
  return out;
}

MillTool read_mill(const Reader& r, const toml::table& t, const std::string& where, MillKind kind,
                   std::vector<std::string>& notes) {
  switch (kind) {
    case MillKind::bull_nose:
      r.only_keys(t, where, {"kind", "name", "diameter", "corner_radius", "flute_length", "shank_diameter",
                             "stick_out", "holder", "centre_cutting", "max_spindle_speed"});
      break;
    case MillKind::drill:
    case MillKind::chamfer:
      r.only_keys(t, where, {"kind", "name", "diameter", "point_angle", "flute_length", "shank_diameter",
                             "stick_out", "holder", "centre_cutting", "max_spindle_speed"});
      break;
    default:
      r.only_keys(t, where, {"kind", "name", "diameter", "flute_length", "shank_diameter", "stick_out", "holder",
                             "centre_cutting", "max_spindle_speed"});
  }
  const auto key = [&](std::string_view k) { return dotted(where, k); };
  MillTool m;
  m.kind = kind;
  if (const toml::node* n = t.get("name")) m.name = r.text(*n, key("name"));
  m.diameter = r.length(r.required(t, "diameter", where, "a mill tool needs its cutting diameter"), key("diameter"),
                        Range::positive);
  if (kind == MillKind::ball) m.corner_radius = m.diameter / 2;
  if (kind == MillKind::bull_nose) {
    const toml::node& n = r.required(t, "corner_radius", where, "a bull-nose end mill needs its corner radius");
    m.corner_radius = r.length(n, key("corner_radius"), Range::positive);
    if (m.corner_radius > m.diameter / 2)
      r.fail(n, fmt::format("'{}' {:g} is more than half the diameter {:g}", key("corner_radius"),
                            m.corner_radius / r.scale(), m.diameter / r.scale()));
  }
  if (kind == MillKind::drill || kind == MillKind::chamfer) {
    m.point_angle = kind == MillKind::drill ? 118 : 90;
    if (const toml::node* n = t.get("point_angle")) m.point_angle = r.angle(*n, key("point_angle"), 0, 180);
    else notes.push_back(fmt::format("point_angle = {:g}", m.point_angle));
  }
  const toml::node* flutes = t.get("flute_length");
  const toml::node* stick = t.get("stick_out");
  if (flutes) m.flute_length = r.length(*flutes, key("flute_length"), Range::positive);
  if (stick) m.stick_out = r.length(*stick, key("stick_out"), Range::positive);
  if (!stick) {
    m.stick_out = std::max(kStickOutPerDiameter * m.diameter, m.flute_length);
    notes.push_back(fmt::format("stick_out = {:g} mm ({})", m.stick_out,
                                m.stick_out == m.flute_length ? "the flute length" : "4 x the diameter"));
  }
  if (!flutes) {
    m.flute_length = m.stick_out;
    notes.push_back(fmt::format("flute_length = {:g} mm (the stick-out: all of it cuts)", m.flute_length));
  } else if (stick && m.flute_length > m.stick_out) {
    r.fail(*flutes, fmt::format("'{}' {:g} is longer than the stick-out {:g}: the flutes would end inside the holder",
                                key("flute_length"), m.flute_length / r.scale(), m.stick_out / r.scale()));
  }
  m.shank_diameter = m.diameter;
  if (const toml::node* n = t.get("shank_diameter")) m.shank_diameter = r.length(*n, key("shank_diameter"), Range::positive);
  else notes.push_back(fmt::format("shank_diameter = {:g} mm (the diameter)", m.shank_diameter));
  if (const toml::node* n = t.get("holder")) m.holder = read_holder(r, *n, key("holder"));
  else notes.push_back("no holder (its contacts are not checked)");
  if (const toml::node* n = t.get("centre_cutting")) m.centre_cutting = r.flag(*n, key("centre_cutting"));
  else notes.push_back("centre_cutting = true");
  if (const toml::node* n = t.get("max_spindle_speed"))
    m.max_spindle_speed = r.number(*n, key("max_spindle_speed"), Range::non_negative);
  return m;
}

LatheInsert read_insert(const Reader& r, const toml::table& t, const std::string& where,
                        std::vector<std::string>& notes) {
  r.only_keys(t, where, {"kind", "name", "nose_radius", "tip", "insert_angle", "clearance_angle", "width",
                         "holder_width", "holder_length"});
  const auto key = [&](std::string_view k) { return dotted(where, k); };
  LatheInsert i;
  if (const toml::node* n = t.get("name")) i.name = r.text(*n, key("name"));
  i.nose_radius = r.length(r.required(t, "nose_radius", where, "an insert needs its nose radius (0 for a sharp point)"),
                           key("nose_radius"), Range::non_negative);
  i.tip = r.whole(r.required(t, "tip", where, "an insert needs its imaginary tool nose number 0..9"), key("tip"), 0, 9);
  if (const toml::node* n = t.get("insert_angle")) i.insert_angle = r.angle(*n, key("insert_angle"), 0, 180);
  else notes.push_back(fmt::format("insert_angle = {:g}°", i.insert_angle));
  if (const toml::node* n = t.get("clearance_angle")) i.clearance_angle = r.angle(*n, key("clearance_angle"), 0, 90);
  else notes.push_back(fmt::format("clearance_angle = {:g}°", i.clearance_angle));
  if (const toml::node* n = t.get("width")) i.width = r.length(*n, key("width"), Range::non_negative);
  if (const toml::node* n = t.get("holder_width")) i.holder_width = r.length(*n, key("holder_width"), Range::non_negative);
  if (const toml::node* n = t.get("holder_length"))
    i.holder_length = r.length(*n, key("holder_length"), Range::non_negative);
  if (i.holder_width == 0 || i.holder_length == 0) notes.push_back("no holder (its contacts are not checked)");
  return i;
}

// A [tools] key: a tool number, digits only.
int tool_number(const Reader& r, const toml::key& k) {
  const std::string s(k.str());
  const bool digits = !s.empty() && s.size() <= 8 && std::ranges::all_of(s, [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  const int n = digits ? std::stoi(s) : 0;
  if (n < 1)
    r.fail(k.source(), fmt::format("'tools.{}' is not a tool number: the keys of [tools] are T numbers 1 .. 99999999 "
                                   "(a lathe's turret station: T0203 is tools.2)", s));
  return n;
}

}  // namespace

ToolLibrary read_tools(const Reader& r, const toml::table& tools, std::vector<std::string>& defaulted) {
  ToolLibrary lib;
  std::map<int, const toml::key*> keys;
  for (const auto& [k, node] : tools) {
    const int number = tool_number(r, k);
    const std::string where = fmt::format("tools.{}", k.str());
    const toml::table& t = r.table(node, where);
    if (auto [it, fresh] = keys.emplace(number, &k); !fresh) {  // the later of the two in the file
      const toml::key& later = it->second->source().begin.line > k.source().begin.line ? *it->second : k;
      r.fail(later.source(), fmt::format("tool {} is given twice: tools.{} and tools.{}", number, it->second->str(), k.str()));
    }
    const toml::node& kind_node =
        r.required(t, "kind", where, "kind = \"flat\", \"ball\", \"bull-nose\", \"drill\", \"chamfer\", \"tap\" or \"insert\"");
    const std::string kind = r.text(kind_node, dotted(where, "kind"));
    std::vector<std::string> notes;
    if (kind == "insert") {
      lib.tools.emplace(number, read_insert(r, t, where, notes));
    } else {
      static const std::pair<const char*, MillKind> kinds[] = {
          {"flat", MillKind::flat},   {"ball", MillKind::ball},       {"bull-nose", MillKind::bull_nose},
          {"drill", MillKind::drill}, {"chamfer", MillKind::chamfer}, {"tap", MillKind::tap}};
      const auto* it = std::ranges::find_if(kinds, [&](const auto& p) { return kind == p.first; });
      if (it == std::end(kinds))
        r.fail(kind_node, fmt::format("'{}.kind' must be \"flat\", \"ball\", \"bull-nose\", \"drill\", \"chamfer\", "
                                      "\"tap\" (mill tools) or \"insert\" (a lathe's), not \"{}\"", where, kind));
      lib.tools.emplace(number, read_mill(r, t, where, it->second, notes));
    }
    if (!notes.empty()) {
      std::string line = fmt::format("{} ({}): ", where, kind);
      for (std::size_t i = 0; i < notes.size(); ++i) line += (i ? ", " : "") + notes[i];
      defaulted.push_back(line);
    }
  }
  return lib;
}

}  // namespace setup_toml
}  // namespace ncurve::sim
