// Text in SVG: markup characters become entities, well-formed UTF-8 stays, anything else becomes
// U+FFFD; every plot writer puts user text through it.
#include <gtest/gtest.h>

#include <string>

#include "gen/generate.hpp"
#include "report/motion_plots.hpp"
#include "report/svg_text.hpp"

using ncurve::report::xml_escape;

namespace {
const std::string kFffd = "\xEF\xBF\xBD";
}

TEST(SvgText, MarkupCharactersBecomeEntities) {
  EXPECT_EQ(xml_escape(R"(a & b < c > d "e" 'f')"), "a &amp; b &lt; c &gt; d &quot;e&quot; &apos;f&apos;");
  EXPECT_EQ(xml_escape("&amp;"), "&amp;amp;");  // an entity typed by the user is text, not markup
  EXPECT_EQ(xml_escape(""), "");
}

TEST(SvgText, WellFormedUtf8Stays) {
  const std::string text = "\xC2\xB5m \xC3\xA9t\xC3\xA9 \xE2\x80\x94 \xF0\x9F\x98\x80";  // µm été — 😀
  EXPECT_EQ(xml_escape(text), text);
  EXPECT_EQ(xml_escape("tab\there\nline\r"), "tab\there\nline\r");
}

TEST(SvgText, BytesThatAreNotUtf8BecomeReplacementCharacters) {
  EXPECT_EQ(xml_escape("caf\xE9.nc"), "caf" + kFffd + ".nc");                    // Latin-1 é
  EXPECT_EQ(xml_escape("\xC0\xAF"), kFffd + kFffd);                               // overlong '/'
  EXPECT_EQ(xml_escape("\xE0\x80\xAF"), kFffd + kFffd + kFffd);                   // overlong, three bytes
  EXPECT_EQ(xml_escape("\xED\xA0\x80"), kFffd + kFffd + kFffd);                   // a surrogate
  EXPECT_EQ(xml_escape("\xF4\x90\x80\x80"), kFffd + kFffd + kFffd + kFffd);       // above U+10FFFF
  EXPECT_EQ(xml_escape("ab\xE2\x82"), "ab" + kFffd + kFffd);                      // cut short at the end
  EXPECT_EQ(xml_escape("\xE2\x82x"), kFffd + kFffd + "x");                        // cut short by a letter
  EXPECT_EQ(xml_escape("\x80"), kFffd);                                           // a lone continuation
}

TEST(SvgText, CharactersXmlRefusesBecomeReplacementCharacters) {
  EXPECT_EQ(xml_escape(std::string("a\x01" "b\x1F" "c", 5)), "a" + kFffd + "b" + kFffd + "c");
  EXPECT_EQ(xml_escape(std::string("\0", 1)), kFffd);
  EXPECT_EQ(xml_escape("\xEF\xBF\xBE\xEF\xBF\xBF"), kFffd + kFffd);  // U+FFFE, U+FFFF
}

TEST(SvgText, PlotsEscapeTheirTitles) {
  const std::string name = "a&b <c> \"d\" 'e' \xE9";
  const std::string escaped = "a&amp;b &lt;c&gt; &quot;d&quot; &apos;e&apos; " + kFffd;
  // the feed plot and the deviation plot carry the program's name in their titles
  const std::string feed = ncurve::report::feed_svg({{0, 100, 90, false}, {10, 100, 100, false}}, name);
  EXPECT_NE(feed.find(escaped), std::string::npos);
  EXPECT_EQ(feed.find(name), std::string::npos);
  const std::string dev = ncurve::report::deviation_svg({{0, 0, 1, 1, 0.001, 0}}, {{0, 0}, {1, 1}}, 0, name, name, name, name);
  EXPECT_NE(dev.find(escaped), std::string::npos);
  EXPECT_EQ(dev.find(name), std::string::npos);
  // gen --plot names the curve
  ncurve::geom::CurveSpec spec;
  spec.name = name;
  spec.x = "10*COS[t]";
  spec.y = "10*SIN[t]";
  spec.z = std::string(1, '0');  // (assigning the literal trips a false -Wrestrict in GCC 12)
  ncurve::geom::Curve curve(spec, {});
  ncurve::gen::Options o;
  ncurve::gen::Stats s;
  s.path = {{10, 0, -1}, {0, 10, -1}};
  const std::string plot = ncurve::gen::plot_svg(curve, o, s);
  EXPECT_NE(plot.find(escaped), std::string::npos);
  EXPECT_EQ(plot.find(name), std::string::npos);
}
