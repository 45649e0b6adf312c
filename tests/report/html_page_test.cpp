// run --html: the page's content (the embedded three.js and scripts, the moves encoded, the
// escaping of what the program says) and the compact arrays of BackplotData.
#include <gtest/gtest.h>

#include <cstring>
#include <iterator>
#include <numbers>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "report/backplot_data.hpp"
#include "report/html_page.hpp"
#include "report/web_assets.hpp"
#include "support/run_program.hpp"

using namespace ncurve;

namespace {

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

std::vector<unsigned char> unbase64(const std::string& s) {
  auto digit = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    return c == '+' ? 62 : c == '/' ? 63 : -1;
  };
  std::vector<unsigned char> out;
  unsigned v = 0;
  int bits = 0;
  for (char c : s) {
    const int d = digit(c);
    if (d < 0) break;  // '=' padding
    v = (v << 6) | static_cast<unsigned>(d), bits += 6;
    if (bits >= 8) out.push_back(static_cast<unsigned char>(v >> (bits - 8))), bits -= 8;
  }
  return out;
}

template <class T>
std::vector<T> array(const nlohmann::json& j, const char* key) {
  const auto bytes = unbase64(j.at(key).get<std::string>());
  std::vector<T> out(bytes.size() / sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

struct Page {
  std::string html;
  nlohmann::json data;  // the page's data block, parsed back
  test::Ran ran;
};

// Runs `program` into a BackplotData and makes the page; the data parsed back out of the page.
Page page(const std::string& program, machine::MachineProfile profile = machine::default_mill()) {
  Page p;
  report::BackplotData data(profile);
  auto lib = std::make_unique<machine::ProgramLibrary>();
  lib->add_text("test.nc", program, true);
  machine::Interpreter interp(profile, *lib, {});
  auto result = interp.run(data);
  if (result.alarm) data.stopped(*result.alarm);
  p.html = report::backplot_html({"test.nc", "{\"ok\": true}", data.json(false)});
  const std::string open = "<script type=\"application/json\" id=\"ncurve-data\">";
  const auto from = p.html.find(open);
  EXPECT_NE(from, std::string::npos);
  const auto to = p.html.find("</script>", from);
  p.data = nlohmann::json::parse(p.html.substr(from + open.size(), to - from - open.size()));  // throws on bad UTF-8
  p.ran = test::run(program, profile);
  return p;
}

}  // namespace

TEST(Base64, Rfc4648Vectors) {
  EXPECT_EQ(report::base64("", 0), "");
  EXPECT_EQ(report::base64("f", 1), "Zg==");
  EXPECT_EQ(report::base64("fo", 2), "Zm8=");
  EXPECT_EQ(report::base64("foo", 3), "Zm9v");
  EXPECT_EQ(report::base64("foob", 4), "Zm9vYg==");
  EXPECT_EQ(report::base64("fooba", 5), "Zm9vYmE=");
  EXPECT_EQ(report::base64("foobar", 6), "Zm9vYmFy");
  const unsigned char high[] = {0xFF, 0xFE, 0x00};
  EXPECT_EQ(report::base64(high, 3), "//4A");
}

TEST(HtmlPage, ScriptJsonCannotCloseTheScript) {
  EXPECT_EQ(report::script_json(R"({"a":"</script><!--&"})"), R"({"a":"\u003c/script\u003e\u003c!--\u0026"})");
  EXPECT_EQ(report::script_json("\"\xE2\x80\xA8\xE2\x80\xA9\""), "\"\\u2028\\u2029\"");
  EXPECT_EQ(report::script_json("\"\xE2\x80\xA7\""), "\"\xE2\x80\xA7\"");  // U+2027: left alone
}

TEST(HtmlPage, EmbedsThreeJsAndTheScripts) {
  // the files of Debian's libjs-three 111 and of web/, compiled in
  ASSERT_GT(web::asset("three.min.js").size(), 500'000u);
  EXPECT_NE(web::asset("three.min.js").find("REVISION=\"111\""), std::string_view::npos);
  EXPECT_NE(web::asset("OrbitControls.js").find("OrbitControls"), std::string_view::npos);
  EXPECT_NE(web::asset("backplot.js").find("NcurveBackplot"), std::string_view::npos);
  EXPECT_TRUE(web::asset("nothing.js").empty());
  const Page p = page("G00 X10 Y0\nG01 X20 F100\nM30\n");
  for (const char* name : {"three.min.js", "OrbitControls.js", "backplot-decode.js", "backplot-geometry.js", "backplot-lines.js", "backplot-axes.js", "backplot-holes.js", "backplot-snap.js", "backplot-measure.js", "backplot-part.js", "backplot-programmed.js", "backplot.js",
                           "run.js", "backplot.css"})
    EXPECT_NE(p.html.find(web::asset(name)), std::string::npos) << name;
  // offline: no address to load anything from
  EXPECT_EQ(p.html.find("<script src"), std::string::npos);
  EXPECT_EQ(p.html.find("<link"), std::string::npos);
  EXPECT_EQ(p.html.find("cdn"), std::string::npos);
  for (const char* marker : {"{{title}}", "{{summary}}", "{{data}}", "{{run.js}}", "{{backplot.css}}"})
    EXPECT_EQ(p.html.find(marker), std::string::npos) << marker;  // every marker of the template filled
}

TEST(HtmlPage, EncodesEveryMotion) {
  // 1 rapid, 2 feeds, 1 counter-clockwise half circle of radius 5 about (15, 0) in G17, a dwell
  // and the spindle (not motions: not drawn)
  const Page p = page("G90 G17 G00 X10. Y0 Z2.\nM03 S1000\nG01 Z-1. F200.\nX20.\nG03 X10. Y0 R5.\nG04 P100\nM30\n");
  const auto motions = p.ran.motions();
  ASSERT_EQ(motions.size(), 4u);
  EXPECT_EQ(p.data["motions"], 4);
  const auto kind = array<std::uint8_t>(p.data, "kind");
  EXPECT_EQ(kind, (std::vector<std::uint8_t>{0, 1, 1, 2}));
  const auto end = array<float>(p.data, "end");
  ASSERT_EQ(end.size(), 12u);
  const float want[12] = {10, 0, 2, 10, 0, -1, 20, 0, -1, 10, 0, -1};
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(end[i], want[i], 1e-5) << i;
  const auto arcs = array<float>(p.data, "arcs");
  ASSERT_EQ(arcs.size(), 5u);  // centre X Y Z, sweep, plane
  EXPECT_NEAR(arcs[0], 15, 1e-5);
  EXPECT_NEAR(arcs[1], 0, 1e-5);
  EXPECT_NEAR(arcs[3], 3.14159265f, 1e-5);  // counter-clockwise: positive
  EXPECT_EQ(arcs[4], 17);
  // each motion's block: lines 1, 3, 4, 5 of test.nc
  const auto block = array<std::uint32_t>(p.data, "block");
  const auto line = array<std::uint32_t>(p.data, "block_line");
  ASSERT_EQ(block.size(), 4u);
  std::vector<std::uint32_t> lines;
  for (auto b : block) lines.push_back(line.at(b));
  EXPECT_EQ(lines, (std::vector<std::uint32_t>{1, 3, 4, 5}));
  EXPECT_EQ(p.data["files"][0]["name"], "test.nc");
  // the first motion starts at the machine's start point
  EXPECT_EQ(p.data["jumps"].size(), 1u);
  EXPECT_EQ(p.data["jumps"][0][0], 0);
}

// A rotary A axis (not drawn): its range over the run and each motion's A end, in degrees; a mill
// without one sends none.
TEST(HtmlPage, RotaryAxisEndsAndRange) {
  auto profile = machine::default_mill();
  profile.axes = "XYZA";
  profile.rotary[3].rotary = true;
  const Page p = page("G90 G01 X10. A90. F100.\nX20. A180.\nY5.\nM30\n", profile);
  ASSERT_EQ(p.data["rotary"].size(), 1u);
  EXPECT_EQ(p.data["rotary"][0]["axis"], "A");
  EXPECT_EQ(p.data["rotary"][0]["unit"], "deg");
  EXPECT_EQ(p.data["rotary"][0]["min"], 0.0);
  EXPECT_EQ(p.data["rotary"][0]["max"], 180.0);
  EXPECT_EQ(array<double>(p.data, "rotary_end"), (std::vector<double>{90, 180, 180}));
  const Page mill = page("G90 G01 X10. F100.\nM30\n");
  EXPECT_TRUE(mill.data["rotary"].empty());
  EXPECT_TRUE(array<double>(mill.data, "rotary_end").empty());
}

TEST(HtmlPage, LimitCountsTheRest) {
  machine::MachineProfile profile = machine::default_mill();
  report::BackplotData data(profile, 2);
  auto lib = std::make_unique<machine::ProgramLibrary>();
  lib->add_text("test.nc", "G00 X1\nX2\nX3\nX4\nM30\n", true);
  machine::Interpreter interp(profile, *lib, {});
  interp.run(data);
  EXPECT_EQ(data.motions(), 2u);
  EXPECT_EQ(data.left_out(), 2u);
  EXPECT_NE(data.json(false).find("\"left_out\":2"), std::string::npos);
}

TEST(HtmlPage, HostileCommentStaysText) {
  // the comment closes at alert(1's ')': a PS0009 alarm whose block the page carries as data
  const std::string hostile = "(</script><script>alert(1)</script>)";
  const Page p = page("G00 X1 Y1\nG00 X2 " + hostile + "\nM30\n");
  EXPECT_EQ(p.ran.alarm_code(), "PS0009");
  // the page's own fifteen scripts (two data blocks, thirteen programs), and no other
  EXPECT_EQ(count(p.html, "<script"), 15u);
  EXPECT_EQ(count(p.html, "</script"), 15u);
  EXPECT_EQ(p.html.find("<script>alert"), std::string::npos);
  // the text itself is there, escaped, and reads back unchanged
  EXPECT_EQ(p.data["alarm"]["block"], "G00 X2 " + hostile);
  EXPECT_NE(p.data["files"][0]["text"].get<std::string>().find(hostile), std::string::npos);
  EXPECT_EQ(p.data["alarm"]["code"], "PS0009");
}

TEST(HtmlPage, TitleEscapedAndBytesThatAreNotUtf8Replaced) {
  report::BackplotData data(machine::default_mill());
  const std::string html = report::backplot_html({"<b>x</b>\xFF.nc", "{}", data.json(false)});
  EXPECT_NE(html.find("<title>&lt;b&gt;x&lt;/b&gt;\xEF\xBF\xBD.nc"), std::string::npos);
  // a comment in Latin-1: the page's data is UTF-8 (nlohmann's parser rejects anything else)
  const Page p = page("G00 X1 (CAF\xC9)\nM30\n");
  EXPECT_NE(p.data["files"][0]["text"].get<std::string>().find("CAF\xEF\xBF\xBD)"), std::string::npos);
}

TEST(HtmlPage, LatheKeepsXAsARadius) {
  // X60. on a diameter lathe is 30 mm from the axis; the page says diameter for its labels
  const Page p = page("G00 X60. Z5.\nG01 Z-10. F0.2\nM30\n", machine::default_lathe());
  EXPECT_EQ(p.data["lathe"], true);
  EXPECT_EQ(p.data["diameter"], true);
  const auto end = array<float>(p.data, "end");
  ASSERT_EQ(end.size(), 6u);
  EXPECT_NEAR(end[0], 30, 1e-5);
  EXPECT_NEAR(end[5], -10, 1e-5);
}

// A 40 x 30 rectangle from (0, 0) clockwise under G41 D1 of radius 5 (the cutter outside), its top
// a half circle G02 about (20, 30): the page's programmed contour is the program's, the approach from
// (-20, -20), the sides corner to corner, the arc about (20, 30) sweeping -180°, the G40 move out.
TEST(HtmlPage, ProgrammedContourBesideTheCompensatedPath) {
  machine::MachineProfile profile = machine::default_mill();
  profile.tool_offsets[1].geometry = profile.tool_offsets[1].d_geometry = 5;
  const Page p = page("G90 G17 G21 G54 G00 X-20. Y-20. Z5.\nG01 Z-1. F200.\nG41 D1 G01 X0 Y0 F500.\nY30.\n"
                      "G02 X40. Y30. I20. J0\nG01 Y0\nX0\nG40 G01 X-20. Y-20.\nG00 Z5.\nM30\n",
                      profile);
  const nlohmann::json& pr = p.data["programmed"];
  const double want[][4] = {{-20, -20, 0, 0}, {0, 0, 0, 30}, {0, 30, 40, 30}, {40, 30, 40, 0}, {40, 0, 0, 0}, {0, 0, -20, -20}};
  ASSERT_EQ(pr.size(), std::size(want));
  for (std::size_t e = 0; e < pr.size(); ++e) {
    EXPECT_NEAR(pr[e][1].get<double>(), want[e][0], 1e-9) << e;
    EXPECT_NEAR(pr[e][2].get<double>(), want[e][1], 1e-9) << e;
    EXPECT_NEAR(pr[e][4].get<double>(), want[e][2], 1e-9) << e;
    EXPECT_NEAR(pr[e][5].get<double>(), want[e][3], 1e-9) << e;
    EXPECT_EQ(pr[e][6], -1) << e;
  }
  const nlohmann::json& arcs = p.data["programmed_arcs"];
  ASSERT_EQ(arcs.size(), 1u);
  EXPECT_EQ(arcs[0][0], pr[2][0]);  // the same motion
  EXPECT_NEAR(arcs[0][1].get<double>(), 20, 1e-9);
  EXPECT_NEAR(arcs[0][2].get<double>(), 30, 1e-9);
  EXPECT_NEAR(arcs[0][4].get<double>(), -std::numbers::pi, 1e-9);
  EXPECT_EQ(arcs[0][5], 17);
  // without compensation: none
  const Page plain = page("G00 X0 Y0 Z5.\nG01 X40. F500.\nG02 X0 I-20.\nM30\n");
  EXPECT_TRUE(plain.data["programmed"].empty());
  EXPECT_TRUE(plain.data["programmed_arcs"].empty());
}
