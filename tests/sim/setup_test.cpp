// The setup file (src/sim/setup*, tool_library*): each key, each error with its position, the
// default stock box, and the shipped setups.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>

#include "sim/setup.hpp"

using namespace ncurve::sim;
using ncurve::machine::Move;
using ncurve::machine::MoveKind;

namespace {

std::string error_of(const std::string& text) {
  try {
    parse_setup(text, "s.toml");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

const char* const kMill = R"(tool_in_spindle = 1

[stock]
shape = "box"
min = [-50, -40, -30]
max = [50, 40, 0.5]

[[fixtures]]
name = "fixed jaw"
shape = "box"
min = [-60, -60, -30]
max = [60, -40, -5]

[[fixtures]]
name = "table"
shape = "stl"
file = "table.stl"

[tools.1]
kind = "flat"
name = "10 mm 3-flute"
diameter = 10
flute_length = 22
shank_diameter = 10
stick_out = 35
holder = [{ diameter = 25, length = 20 }, { diameter = [25, 44.45], length = 15 }]
centre_cutting = false
max_spindle_speed = 12000

[tools.2]
kind = "bull-nose"
diameter = 16
corner_radius = 0.8

[tools.3]
kind = "drill"
diameter = 6.8
point_angle = 135

[tools.4]
kind = "chamfer"
diameter = 12

[tools.5]
kind = "ball"
diameter = 6

[tools.6]
kind = "tap"
diameter = 8
)";

}  // namespace

TEST(SimSetup, MillKeys) {
  const SetupFile s = parse_setup(kMill, "jobs/mill.toml");
  EXPECT_EQ(s.origin, "jobs/mill.toml");
  EXPECT_EQ(s.tool_in_spindle, 1);
  const auto& box = std::get<AxisBox>(*s.stock);
  EXPECT_EQ(box.min, (Point3{-50, -40, -30}));
  EXPECT_EQ(box.max, (Point3{50, 40, 0.5}));
  ASSERT_EQ(s.fixtures.size(), 2u);
  EXPECT_EQ(s.fixtures[0].name, "fixed jaw");
  EXPECT_EQ(std::get<AxisBox>(s.fixtures[0].shape).max, (Point3{60, -40, -5}));
  EXPECT_EQ(s.fixtures[1].name, "table");
  EXPECT_EQ(std::get<StlFile>(s.fixtures[1].shape).path, "jobs/table.stl");  // beside the setup file
  EXPECT_EQ(std::get<StlFile>(s.fixtures[1].shape).scale, 1);

  const MillTool* t1 = s.tools.mill(1);
  ASSERT_NE(t1, nullptr);
  EXPECT_EQ(t1->kind, MillKind::flat);
  EXPECT_EQ(t1->name, "10 mm 3-flute");
  EXPECT_EQ(t1->diameter, 10);
  EXPECT_EQ(t1->radius(), 5);
  EXPECT_EQ(t1->corner_radius, 0);
  EXPECT_EQ(t1->flute_length, 22);
  EXPECT_EQ(t1->shank_diameter, 10);
  EXPECT_EQ(t1->stick_out, 35);
  ASSERT_EQ(t1->holder.size(), 2u);
  EXPECT_FALSE(t1->holder[0].cone());
  EXPECT_EQ(t1->holder[0].lower, 25);
  EXPECT_EQ(t1->holder[0].length, 20);
  EXPECT_TRUE(t1->holder[1].cone());
  EXPECT_EQ(t1->holder[1].upper, 44.45);
  EXPECT_FALSE(t1->centre_cutting);
  EXPECT_EQ(t1->max_spindle_speed, 12000);
  EXPECT_EQ(t1->point_angle, 0);

  const MillTool* t2 = s.tools.mill(2);
  ASSERT_NE(t2, nullptr);
  EXPECT_EQ(t2->kind, MillKind::bull_nose);
  EXPECT_EQ(t2->corner_radius, 0.8);
  EXPECT_EQ(t2->stick_out, 64);     // 4 x the diameter
  EXPECT_EQ(t2->flute_length, 64);  // the stick-out
  EXPECT_EQ(t2->shank_diameter, 16);
  EXPECT_TRUE(t2->holder.empty());
  EXPECT_TRUE(t2->centre_cutting);
  EXPECT_EQ(t2->max_spindle_speed, 0);
  EXPECT_EQ(s.tools.mill(3)->kind, MillKind::drill);
  EXPECT_EQ(s.tools.mill(3)->point_angle, 135);
  EXPECT_EQ(s.tools.mill(4)->point_angle, 90);  // a chamfer mill's default
  EXPECT_EQ(s.tools.mill(5)->corner_radius, 3);  // a ball: half the diameter
  EXPECT_EQ(s.tools.mill(6)->kind, MillKind::tap);
  EXPECT_EQ(s.tools.insert(1), nullptr);
  EXPECT_EQ(s.tools.mill(7), nullptr);
}

TEST(SimSetup, LatheKeys) {
  const SetupFile s = parse_setup(R"(
[stock]
shape = "tube"
diameter = 50
inner_diameter = 20
length = 80
face = 1.5

[[fixtures]]
name = "jaw"
shape = "box"
min = [25, -10, -100]
max = [45, 10, -70]

[tools.1]
kind = "insert"
name = "CNMG 120404"
nose_radius = 0.4
tip = 3
insert_angle = 80
clearance_angle = 5
holder_width = 25
holder_length = 150

[tools.02]
kind = "insert"
nose_radius = 0.2
tip = 8
width = 3
)",
                                  "l.toml");
  const auto& c = std::get<Cylinder>(*s.stock);
  EXPECT_EQ(c.diameter, 50);
  EXPECT_EQ(c.inner_diameter, 20);
  EXPECT_EQ(c.length, 80);
  EXPECT_EQ(c.face, 1.5);
  const LatheInsert* i = s.tools.insert(1);
  ASSERT_NE(i, nullptr);
  EXPECT_EQ(i->name, "CNMG 120404");
  EXPECT_EQ(i->nose_radius, 0.4);
  EXPECT_EQ(i->tip, 3);
  EXPECT_EQ(i->insert_angle, 80);
  EXPECT_EQ(i->clearance_angle, 5);
  EXPECT_EQ(i->holder_width, 25);
  EXPECT_EQ(i->holder_length, 150);
  EXPECT_EQ(i->width, 0);
  const LatheInsert* g = s.tools.insert(2);  // "02" is tool 2
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->width, 3);
  EXPECT_EQ(g->tip, 8);
  EXPECT_EQ(lathe_tool_number(203), 2);

  const SetupFile bar = parse_setup("[stock]\nshape = \"cylinder\"\ndiameter = 50\nlength = 70\n", "b.toml");
  EXPECT_EQ(std::get<Cylinder>(*bar.stock).inner_diameter, 0);
  EXPECT_EQ(std::get<Cylinder>(*bar.stock).face, 0);
  const SetupFile stl = parse_setup("[stock]\nshape = \"stl\"\nfile = \"/parts/blank.stl\"\n", "dir/b.toml");
  EXPECT_EQ(std::get<StlFile>(*stl.stock).path, "/parts/blank.stl");  // absolute: as given
}

TEST(SimSetup, InchConvertsLengthsOnly) {
  const SetupFile s = parse_setup(R"(inch = true
[stock]
shape = "box"
min = [-1, -1, -1]
max = [1, 1, 0]
[[fixtures]]
name = "plate"
shape = "stl"
file = "plate.stl"
[tools.1]
kind = "drill"
diameter = 0.25
stick_out = 2
point_angle = 118
max_spindle_speed = 3000
[tools.2]
kind = "insert"
nose_radius = 0.0156
tip = 3
insert_angle = 55
)",
                                  "i.toml");
  EXPECT_EQ(std::get<AxisBox>(*s.stock).min, (Point3{-25.4, -25.4, -25.4}));
  EXPECT_EQ(std::get<StlFile>(s.fixtures[0].shape).scale, 25.4);
  EXPECT_DOUBLE_EQ(s.tools.mill(1)->diameter, 6.35);
  EXPECT_DOUBLE_EQ(s.tools.mill(1)->stick_out, 50.8);
  EXPECT_EQ(s.tools.mill(1)->point_angle, 118);
  EXPECT_EQ(s.tools.mill(1)->max_spindle_speed, 3000);
  EXPECT_DOUBLE_EQ(s.tools.insert(2)->nose_radius, 0.0156 * 25.4);
  EXPECT_EQ(s.tools.insert(2)->insert_angle, 55);
  EXPECT_EQ(parse_setup("inch = false\n[tools.1]\nkind = \"flat\"\ndiameter = 10\n", "m.toml").tools.mill(1)->diameter, 10);
}

TEST(SimSetup, DefaultsInWords) {
  const std::vector<std::string> none = setup_defaults(nullptr);
  ASSERT_EQ(none.size(), 4u);
  EXPECT_EQ(none[0], "stock: the box around the cutting moves, widened by the tool's radius to the sides and below, "
                     "its top the highest level a cutting move starts from");
  EXPECT_EQ(none[1], "fixtures: none");
  EXPECT_EQ(none[2], "tool in the spindle at the start: none; the first tool change (M06, a lathe's T) puts one in");
  EXPECT_EQ(none[3], "tools: no library: each tool is a flat end mill of the radius of the D offset in force when "
                     "it first cuts (on a lathe an insert of its offset's nose radius and imaginary tip)");
  const SetupFile s = parse_setup(kMill, "m.toml");
  const std::vector<std::string> some = setup_defaults(&s);
  ASSERT_GE(some.size(), 2u);
  EXPECT_EQ(some[0], "a tool not in the library: a flat end mill of the radius of the D offset in force when it "
                     "first cuts (on a lathe an insert of its offset's nose radius and imaginary tip)");
  EXPECT_EQ(some[1], "tools.2 (bull-nose): stick_out = 64 mm (4 x the diameter), flute_length = 64 mm (the stick-out: "
                     "all of it cuts), shank_diameter = 16 mm (the diameter), no holder (its contacts are not checked), "
                     "centre_cutting = true");
  const MillTool d = default_mill_tool(4);
  EXPECT_EQ(d.kind, MillKind::flat);
  EXPECT_EQ(d.diameter, 8);
  EXPECT_EQ(d.flute_length, 32);
  EXPECT_EQ(default_insert(0.8, 3).nose_radius, 0.8);
  EXPECT_EQ(describe(1, s.tools.tools.at(1)),
            "T1 flat end mill D10, flutes 22, stick-out 35, holder of 2 pieces, not centre-cutting (10 mm 3-flute)");
  EXPECT_EQ(describe(4, s.tools.tools.at(4)), "T4 chamfer mill D12 90°, flutes 48, stick-out 48");
}

// Each error: its position and its words.
TEST(SimSetup, Errors) {
  EXPECT_EQ(error_of("stok = 1\n"),
            "s.toml:1:1: error: unknown key 'stok' at the top level (inch, tool_in_spindle, stock, fixtures, tools)");
  EXPECT_EQ(error_of("[stock]\nshape = \"box\"\nmin = [0, 0, 0]\nmax = [1, 1, 1]\nradius = 3\n"),
            "s.toml:5:1: error: unknown key 'radius' in [stock] (shape, min, max)");
  EXPECT_EQ(error_of("[tools.4]\nkind = \"flat\"\ndiameter = 6\ncorner_radius = 1\n"),
            "s.toml:4:1: error: unknown key 'corner_radius' in [tools.4] (kind, name, diameter, flute_length, "
            "shank_diameter, stick_out, holder, centre_cutting, max_spindle_speed)");
  EXPECT_EQ(error_of("[tools.4]\nkind = \"insert\"\nnose_radius = 0.4\ntip = 3\ndiameter = 6\n"),
            "s.toml:5:1: error: unknown key 'diameter' in [tools.4] (kind, name, nose_radius, tip, insert_angle, "
            "clearance_angle, width, holder_width, holder_length)");
  EXPECT_EQ(error_of("[stock]\nmin = [0, 0, 0]\n"),
            "s.toml:1:1: error: 'stock.shape' is missing: shape = \"box\", \"cylinder\", \"tube\" or \"stl\" says "
            "which the stock is");
  EXPECT_EQ(error_of("[stock]\nshape = \"sphere\"\n"),
            "s.toml:2:9: error: 'stock.shape' must be \"box\", \"cylinder\", \"tube\" or \"stl\", not \"sphere\"");
  EXPECT_EQ(error_of("[stock]\nshape = \"box\"\nmin = [0, 10, 0]\nmax = [1, 5, 1]\n"),
            "s.toml:4:7: error: 'stock.max' must exceed 'stock.min' on every axis: Y max 5 is not above min 10");
  EXPECT_EQ(error_of("[stock]\nshape = \"box\"\nmin = [0, 0]\nmax = [1, 1, 1]\n"),
            "s.toml:3:7: error: 'stock.min' must be an array of 3 numbers [x, y, z]");
  EXPECT_EQ(error_of("[stock]\nshape = \"box\"\nmin = [0, \"a\", 0]\nmax = [1, 1, 1]\n"),
            "s.toml:3:11: error: 'stock.min' must be a number");
  EXPECT_EQ(error_of("[stock]\nshape = \"cylinder\"\ndiameter = -5\nlength = 10\n"),
            "s.toml:3:12: error: 'stock.diameter' must be more than zero, not -5");
  EXPECT_EQ(error_of("[stock]\nshape = \"cylinder\"\ndiameter = 50\n"),
            "s.toml:1:1: error: 'stock.length' is missing: a cylinder is given by diameter, length (and face)");
  EXPECT_EQ(error_of("[stock]\nshape = \"tube\"\ndiameter = 50\ninner_diameter = 50\nlength = 10\n"),
            "s.toml:4:18: error: 'stock.inner_diameter' must be less than the diameter 50");
  EXPECT_EQ(error_of("[stock]\nshape = \"cylinder\"\ndiameter = 50\nlength = nan\n"),
            "s.toml:4:10: error: 'stock.length' must be a finite number, not nan");
  EXPECT_EQ(error_of("[stock]\nshape = \"stl\"\nfile = 3\n"), "s.toml:3:8: error: 'stock.file' must be a string");
  EXPECT_EQ(error_of("stock = 3\n"), "s.toml:1:9: error: 'stock' must be a table");
  EXPECT_EQ(error_of("tools = 3\n"), "s.toml:1:9: error: 'tools' must be a table");
  EXPECT_EQ(error_of("[tools]\n1 = 5\n"), "s.toml:2:5: error: 'tools.1' must be a table");
  EXPECT_EQ(error_of("inch = 1\n"), "s.toml:1:8: error: 'inch' must be true or false");
  EXPECT_EQ(error_of("tool_in_spindle = 1.5\n"),
            "s.toml:1:19: error: 'tool_in_spindle' must be a whole number from 0 to 99999999, not 1.5");
}

TEST(SimSetup, FixtureAndToolErrors) {
  EXPECT_EQ(error_of("[fixtures]\nname = \"a\"\n"),
            "s.toml:1:1: error: 'fixtures' must be an array of tables: one [[fixtures]] each");
  EXPECT_EQ(error_of("[[fixtures]]\nshape = \"box\"\n"),
            "s.toml:1:1: error: 'fixtures[0].name' is missing: each fixture has a name, used in the warnings about it");
  EXPECT_EQ(error_of("[[fixtures]]\nname = \"j\"\nshape = \"cylinder\"\n"),
            "s.toml:3:9: error: 'fixtures[0].shape' must be \"box\" or \"stl\", not \"cylinder\"");
  EXPECT_EQ(error_of("[[fixtures]]\nname = \"j\"\nshape = \"stl\"\nfile = \"j.stl\"\n"
                     "[[fixtures]]\nname = \"j\"\nshape = \"stl\"\nfile = \"k.stl\"\n"),
            "s.toml:5:1: error: fixture name 'j' is given twice");
  EXPECT_EQ(error_of("[tools.T1]\nkind = \"flat\"\n"),
            "s.toml:1:8: error: 'tools.T1' is not a tool number: the keys of [tools] are T numbers 1 .. 99999999 "
            "(a lathe's turret station: T0203 is tools.2)");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"flat\"\ndiameter = 6\n[tools.01]\nkind = \"flat\"\ndiameter = 6\n"),
            "s.toml:4:8: error: tool 1 is given twice: tools.01 and tools.1");
  EXPECT_EQ(error_of("[tools.1]\ndiameter = 6\n"),
            "s.toml:1:1: error: 'tools.1.kind' is missing: kind = \"flat\", \"ball\", \"bull-nose\", \"drill\", "
            "\"chamfer\", \"tap\" or \"insert\"");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"endmill\"\n"),
            "s.toml:2:8: error: 'tools.1.kind' must be \"flat\", \"ball\", \"bull-nose\", \"drill\", \"chamfer\", "
            "\"tap\" (mill tools) or \"insert\" (a lathe's), not \"endmill\"");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"ball\"\n"),
            "s.toml:1:1: error: 'tools.1.diameter' is missing: a mill tool needs its cutting diameter");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"bull-nose\"\ndiameter = 10\n"),
            "s.toml:1:1: error: 'tools.1.corner_radius' is missing: a bull-nose end mill needs its corner radius");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"bull-nose\"\ndiameter = 10\ncorner_radius = 6\n"),
            "s.toml:4:17: error: 'tools.1.corner_radius' 6 is more than half the diameter 10");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"flat\"\ndiameter = 10\nflute_length = 40\nstick_out = 30\n"),
            "s.toml:4:16: error: 'tools.1.flute_length' 40 is longer than the stick-out 30: the flutes would end "
            "inside the holder");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"drill\"\ndiameter = 10\npoint_angle = 180\n"),
            "s.toml:4:15: error: 'tools.1.point_angle' is an angle in degrees more than 0 and less than 180, not 180");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"flat\"\ndiameter = 10\ncentre_cutting = \"yes\"\n"),
            "s.toml:4:18: error: 'tools.1.centre_cutting' must be true or false");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"flat\"\ndiameter = 10\nholder = [{ diameter = 30 }]\n"),
            "s.toml:4:11: error: 'tools.1.holder[0].length' is missing: a holder piece is { diameter = D, length = L } "
            "(a cone: diameter = [lower, upper])");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"flat\"\ndiameter = 10\nholder = [{ diameter = [30, 40, 50], length = 5 }]\n"),
            "s.toml:4:24: error: 'tools.1.holder[0].diameter' of a cone is two numbers [lower, upper]");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"flat\"\ndiameter = 10\nholder = [{ diameter = 30, length = 5, d = 1 }]\n"),
            "s.toml:4:40: error: unknown key 'd' in [tools.1.holder[0]] (diameter, length)");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"insert\"\nnose_radius = 0.4\ntip = 10\n"),
            "s.toml:4:7: error: 'tools.1.tip' must be a whole number from 0 to 9, not 10");
  EXPECT_EQ(error_of("[tools.1]\nkind = \"insert\"\ntip = 3\n"),
            "s.toml:1:1: error: 'tools.1.nose_radius' is missing: an insert needs its nose radius (0 for a sharp point)");
}

TEST(SimSetup, TomlErrorsAndFiles) {
  EXPECT_EQ(error_of("[stock\n").substr(0, 20), "s.toml:1:7: error: E");
  std::string deep = "a";
  for (int i = 0; i < 40; ++i) deep += ".a";
  EXPECT_EQ(error_of(deep + " = 1\n").substr(0, 38), "s.toml:1:64: error: a dotted key of mo");
  try {
    read_setup("/nonexistent/x.setup.toml");
    FAIL() << "read a file that is not there";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/x.setup.toml: error: cannot open the setup file");
  }
}

// Every shipped setup reads; each names a program beside it.
TEST(SimSetup, ShippedExamplesRead) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(NCURVE_SOURCE_DIR "/examples")) {
    const std::string name = e.path().filename().string();
    if (!name.ends_with(".setup.toml")) continue;
    ++n;
    SCOPED_TRACE(name);
    EXPECT_NO_THROW(read_setup(e.path().string()));
    const std::string program = name.substr(0, name.size() - std::string(".setup.toml").size()) + ".nc";
    EXPECT_TRUE(std::filesystem::exists(e.path().parent_path() / program)) << program;
  }
  EXPECT_GE(n, 2);
}

// The ```toml blocks of docs/setup.md are setups that read.
TEST(SimSetup, DocumentedExamplesRead) {
  std::ifstream in(NCURVE_SOURCE_DIR "/docs/setup.md");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  const std::regex block("```toml\n([^`]*)```");
  int n = 0;
  for (std::sregex_iterator it(doc.begin(), doc.end(), block), end; it != end; ++it, ++n) {
    SCOPED_TRACE((*it)[1].str());
    EXPECT_NO_THROW(parse_setup((*it)[1].str(), "docs/setup.md"));
  }
  EXPECT_GE(n, 2);
}

namespace {

Move line(MoveKind kind, Point3 a, Point3 b) {
  Move m;
  m.kind = kind;
  for (int i = 0; i < 3; ++i) {
    m.start[i] = a[i];
    m.end[i] = b[i];
  }
  return m;
}

Move tool_change(int t) {
  Move m;
  m.kind = MoveKind::tool_change;
  m.code = t;
  return m;
}

}  // namespace

// Worked by hand: T1 (radius 5) plunges from Z2 to Z-3 at X0 Y0 and cuts to X40; T2 (radius 3)
// cuts a half circle of radius 10 about X40 Y0 at Z-6 (G03 from X50 through Y10 to X30) and a
// line from Z4 down to Z-1; rapids at Z50 and past X100 count for nothing.
TEST(SimSetup, DefaultStockBox) {
  std::vector<Move> moves;
  moves.push_back(tool_change(1));
  moves.push_back(line(MoveKind::rapid, {0, 0, 50}, {0, 0, 2}));
  moves.push_back(line(MoveKind::line, {0, 0, 2}, {0, 0, -3}));
  moves.push_back(line(MoveKind::line, {0, 0, -3}, {40, 0, -3}));
  moves.push_back(line(MoveKind::rapid, {40, 0, -3}, {120, 0, 50}));
  moves.push_back(tool_change(2));
  Move arc = line(MoveKind::arc, {50, 0, -6}, {30, 0, -6});
  arc.center = {40, 0, -6};
  arc.sweep = std::numbers::pi;
  moves.push_back(arc);
  moves.push_back(line(MoveKind::line, {30, 0, 4}, {30, 0, -1}));
  const auto radius = [](int t) { return t == 1 ? 5.0 : t == 2 ? 3.0 : 0.0; };
  const std::optional<AxisBox> box = default_stock_box(moves, radius);
  ASSERT_TRUE(box);
  // X: T1 from 0 - 5, T2's arc to 50 + 3; Y: T1 -5, the arc's top 10 + 3; Z: the arc -6 - 3, top 4
  EXPECT_EQ(box->min, (Point3{-5, -5, -9}));
  EXPECT_EQ(box->max, (Point3{53, 13, 4}));
  // clockwise the other way round: the half below, Y down to -10 - 3
  arc.sweep = -std::numbers::pi;
  const std::optional<AxisBox> below = default_stock_box(std::vector<Move>{tool_change(2), arc}, radius);
  EXPECT_EQ(below->min, (Point3{27, -13, -9}));
  EXPECT_EQ(below->max, (Point3{53, 3, -6}));
  // the tool in the spindle before the first change; no cutting move, no box
  const std::optional<AxisBox> first = default_stock_box(std::vector<Move>{moves[2]}, radius, 2);
  EXPECT_EQ(first->min, (Point3{-3, -3, -6}));
  EXPECT_EQ(first->max, (Point3{3, 3, 2}));
  EXPECT_FALSE(default_stock_box(std::vector<Move>{moves[1]}, radius));
}

// A whole turn of a helix reaches every side of its circle; a G18 arc is taken in Z and X.
TEST(SimSetup, DefaultStockBoxOfHelixAndG18Arc) {
  const auto none = [](int) { return 0.0; };
  Move helix = line(MoveKind::arc, {10, 0, 0}, {10, 0, -2});
  helix.sweep = -2 * std::numbers::pi;
  helix.clockwise = true;
  const std::optional<AxisBox> h = default_stock_box(std::vector<Move>{helix}, none);
  EXPECT_EQ(h->min, (Point3{-10, -10, -2}));
  EXPECT_EQ(h->max, (Point3{10, 10, 0}));
  // G18: from X10 Z0 about X0 Z0 counter-clockwise about Y (Z towards X) by half a turn: through
  // Z-10 to X-10
  Move zx = line(MoveKind::arc, {10, 0, 0}, {-10, 0, 0});
  zx.plane = 18;
  zx.sweep = std::numbers::pi;
  const std::optional<AxisBox> b = default_stock_box(std::vector<Move>{zx}, none);
  EXPECT_EQ(b->min, (Point3{-10, 0, -10}));
  EXPECT_EQ(b->max, (Point3{10, 0, 0}));
}
