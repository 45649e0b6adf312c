#include "report/html_page.hpp"

#include <stdexcept>

#include "report/svg_text.hpp"
#include "report/web_assets.hpp"

namespace ncurve::report {

namespace {

void append_script_json(std::string& out, std::string_view json) {
  std::size_t plain = 0;  // the text from here to i needs no escape
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    const bool separator = c == '\xE2' && i + 2 < json.size() && json[i + 1] == '\x80' &&
                           (json[i + 2] == '\xA8' || json[i + 2] == '\xA9');
    if (c != '<' && c != '>' && c != '&' && !separator) continue;
    out.append(json.substr(plain, i - plain));
    if (c == '<') out += "\\u003c";
    else if (c == '>') out += "\\u003e";
    else if (c == '&') out += "\\u0026";
    else out += json[i + 2] == '\xA8' ? "\\u2028" : "\\u2029", i += 2;
    plain = i + 1;
  }
  out.append(json.substr(plain));
}

}  // namespace

std::string script_json(std::string_view json) {
  std::string out;
  out.reserve(json.size() + 64);
  append_script_json(out, json);
  return out;
}

namespace {

// A page file: its text must not end the <script> or <style> element it goes in.
std::string_view inline_asset(std::string_view name) {
  const std::string_view text = web::asset(name);
  if (text.empty()) throw std::logic_error("web asset missing: " + std::string(name));
  return text;
}

}  // namespace

std::string backplot_html(const HtmlPageInput& in) {
  const std::string_view page = inline_asset("run.html");
  std::string out;
  out.reserve(in.data_json.size() + in.summary_json.size() + 1'200'000);
  // each {{name}} of the template is replaced; what is put in is not read again
  std::size_t at = 0;
  while (true) {
    const std::size_t open = page.find("{{", at);
    if (open == std::string_view::npos) break;
    const std::size_t close = page.find("}}", open);
    if (close == std::string_view::npos) break;
    out.append(page.substr(at, open - at));
    const std::string_view key = page.substr(open + 2, close - open - 2);
    if (key == "title") out += xml_escape(in.title);
    else if (key == "summary") append_script_json(out, in.summary_json);
    else if (key == "data") append_script_json(out, in.data_json);
    else out.append(inline_asset(key));
    at = close + 2;
  }
  out.append(page.substr(at));
  return out;
}

}  // namespace ncurve::report
