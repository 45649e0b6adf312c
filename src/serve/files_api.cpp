// GET /api/profiles, GET /api/files, GET /api/files/NAME and the page at GET /.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/shipped.hpp"
#include "machine/profile.hpp"
#include "serve/api.hpp"

namespace ncurve::serve {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {
std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace) + "\n"; }
}  // namespace

Answer api_profiles(const ServeConfig& config) {
  json list = json::array();
  for (const std::string& name : app::shipped_profiles()) {
    json p{{"name", name}};
    try {
      const machine::MachineProfile profile = machine::load_profile(app::find_profile(name));
      p["title"] = profile.name;
      p["lathe"] = profile.lathe();
      p["axes"] = profile.axes;
    } catch (const std::exception& e) {
      p["error"] = e.what();
    }
    list.push_back(p);
  }
  return Answer{200, dump(json{{"profiles", list}, {"default", config.machine.empty() ? json(nullptr) : json(config.machine)}})};
}

Answer api_files(const ServeConfig& config) {
  json list = json::array();
  for (const std::string& path : config.files) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    json f{{"name", fs::path(path).filename().string()}, {"path", path}};
    f["bytes"] = ec ? json(nullptr) : json(size);
    list.push_back(f);
  }
  return Answer{200, dump(json{{"files", list}})};
}

Answer api_file(const ServeConfig& config, const std::string& name) {
  for (const std::string& path : config.files) {
    if (fs::path(path).filename().string() != name) continue;
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw ApiError(500, fmt::format("cannot read {}", path));
    return Answer{200, text.str(), "text/plain; charset=utf-8"};
  }
  throw ApiError(404, fmt::format("no file \"{}\" was given to ncurve serve (GET /api/files lists them)", name));
}

Answer page() {
  static constexpr const char* kPage = R"(<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>ncurve workbench</title>
<style>body{font:15px/1.5 system-ui,sans-serif;margin:2em;max-width:60em}textarea{width:100%;height:18em;font:13px monospace}
pre{background:#f4f4f4;padding:1em;overflow:auto;max-height:30em}</style></head>
<body><h1>ncurve workbench</h1>
<p>The full workbench page is still to come. The JSON API answers now: POST /api/run, /api/analyze, /api/gen;
GET /api/profiles, /api/files (see docs/serve.md).</p>
<p><select id="file"></select> <select id="machine"></select> <button id="run">Run</button></p>
<textarea id="program">G90 G17 G21
#1 = 0
WHILE [#1 LT 360] DO1
G01 X[10*COS[#1]] Y[10*SIN[#1]] F500.
#1 = #1 + 30
END1
M30
</textarea>
<pre id="out"></pre>
<script>
const $ = (id) => document.getElementById(id);
fetch('/api/profiles').then(r => r.json()).then(j => {
  for (const p of j.profiles) $('machine').add(new Option(p.name, p.name, false, p.name === 'fanuc-mill'));
});
fetch('/api/files').then(r => r.json()).then(j => {
  $('file').add(new Option('(files given to ncurve serve)', ''));
  for (const f of j.files) $('file').add(new Option(f.name, f.name));
});
$('file').onchange = () => {
  if ($('file').value) fetch('/api/files/' + encodeURIComponent($('file').value)).then(r => r.text()).then(t => $('program').value = t);
};
$('run').onclick = async () => {
  const r = await fetch('/api/run', {method: 'POST', headers: {'Content-Type': 'application/json'},
    body: JSON.stringify({program: $('program').value, name: $('file').value || 'program.nc', machine: $('machine').value})});
  const j = await r.json();
  $('out').textContent = JSON.stringify({status: r.status, error: j.error, summary: j.summary, diagnostics: j.diagnostics}, null, 2);
};
</script></body></html>
)";
  return Answer{200, kPage, "text/html; charset=utf-8"};
}

}  // namespace ncurve::serve
