// Text inside SVG (XML) documents: every text that may come from the user (file names, titles,
// expressions, machine names) goes through xml_escape before it is written.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace ncurve::report {

// `text` as XML character data or attribute value: & < > " ' as entities; bytes that are not
// well-formed UTF-8, and characters XML 1.0 does not allow (controls other than tab, line feed
// and carriage return; U+FFFE, U+FFFF), each become U+FFFD, so the document stays well-formed
// whatever the input.
inline std::string xml_escape(std::string_view text) {
  static constexpr std::string_view kReplacement = "\xEF\xBF\xBD";
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        case '\t': case '\n': case '\r': out += static_cast<char>(c); break;
        default:
          if (c < 0x20) out += kReplacement;
          else out += static_cast<char>(c);
      }
      ++i;
      continue;
    }
    // a lead byte: how many continuation bytes follow, and its bits
    std::size_t more = 0;
    std::uint32_t code = 0;
    if (c >= 0xC2 && c <= 0xDF) more = 1, code = c & 0x1Fu;
    else if (c >= 0xE0 && c <= 0xEF) more = 2, code = c & 0x0Fu;
    else if (c >= 0xF0 && c <= 0xF4) more = 3, code = c & 0x07u;
    bool ok = more > 0;
    for (std::size_t k = 1; ok && k <= more; ++k) {
      if (i + k >= text.size()) {
        ok = false;
        break;
      }
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next & 0xC0u) != 0x80u) ok = false;
      else code = (code << 6) | (next & 0x3Fu);
    }
    // overlong forms, surrogates and beyond U+10FFFF are not UTF-8
    if (ok && ((more == 2 && code < 0x800) || (more == 3 && (code < 0x10000 || code > 0x10FFFF)) ||
               (code >= 0xD800 && code <= 0xDFFF)))
      ok = false;
    if (ok) {
      // the two non-characters XML refuses, whole
      if (code == 0xFFFE || code == 0xFFFF) out += kReplacement;
      else out.append(text.substr(i, more + 1));
      i += more + 1;
    } else {
      out += kReplacement;  // this byte alone; what follows is read afresh
      ++i;
    }
  }
  return out;
}

}  // namespace ncurve::report
