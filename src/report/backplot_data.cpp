#include "report/backplot_data.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <nlohmann/json.hpp>

#include "machine/rapid_path.hpp"

namespace ncurve::report {

static_assert(std::endian::native == std::endian::little, "the page reads the arrays as little-endian");

BackplotData::BackplotData(const machine::MachineProfile& profile, std::size_t limit)
    : lathe_(profile.lathe()), x_diameter_(profile.lathe() && profile.diameter_x),
      machine_plane_(profile.lathe() ? 18 : profile.power_on_plane), limit_(limit), profile_(profile), other_(profile) {}

std::uint32_t BackplotData::block_of(const machine::Move& m) {
  if (have_last_block_ && m.file == last_file_ && m.line == last_line_) return last_block_;
  std::uint16_t file = 0xFFFF;  // no file (or past the 65,535th)
  if (m.file) {
    std::size_t i = 0;
    while (i < files_.size() && files_[i] != m.file) ++i;
    if (i == files_.size() && i < 0xFFFF) files_.push_back(m.file);
    if (i < 0xFFFF) file = static_cast<std::uint16_t>(i);
  }
  const std::uint64_t key = (std::uint64_t{file} << 32) | m.line;
  auto [it, added] = block_index_.try_emplace(key, static_cast<std::uint32_t>(block_line_.size()));
  if (added) {
    block_file_.push_back(file);
    block_line_.push_back(m.line);
  }
  last_file_ = m.file, last_line_ = m.line, last_block_ = it->second, have_last_block_ = true;
  return it->second;
}

void BackplotData::on_move(const machine::Move& m) {
  if (!m.is_motion()) return;
  const std::array<double, 3> a{m.start[0], m.start[1], m.start[2]}, b{m.end[0], m.end[1], m.end[2]};
  other_.add(m);
  const bool arc = m.compensated && m.kind == machine::MoveKind::arc;  // (the tip matters to it only)
  const auto piece = contour_.on_motion(m, arc && nose_tip_ && lathe_ ? nose_tip_() : std::array<double, 2>{});
  if (piece && kind_.size() < limit_) {
    const auto at = static_cast<double>(kind_.size());
    programmed_.push_back({at, piece->start[0], piece->start[1], piece->start[2], piece->end[0], piece->end[1], piece->end[2]});
    if (piece->arc)
      programmed_arcs_.push_back({at, piece->centre[0], piece->centre[1], piece->centre[2], piece->sweep,
                                  static_cast<double>(m.plane)});
  }
  if (kind_.size() >= limit_) {
    ++left_out_;
    last_ = b;
    return;
  }
  if (kind_.empty() ? true : a != last_) {  // the first motion's start is its jump
    jump_at_.push_back(static_cast<std::uint32_t>(kind_.size()));
    jump_.push_back(a);
  }
  if (m.kind == machine::MoveKind::rapid && !profile_.linear_rapid) {  // drawn as the machine moves it
    const auto path = machine::rapid_path(m.start, m.end, profile_);
    for (std::size_t k = 1; k + 1 < path.size(); ++k)
      corners_.push_back({static_cast<double>(kind_.size()), path[k][0], path[k][1], path[k][2]});
  }
  kind_.push_back(m.kind == machine::MoveKind::rapid ? 0 : m.kind == machine::MoveKind::line ? 1 : 2);
  for (double v : b) end_.push_back(static_cast<float>(v));
  feed_.push_back(static_cast<float>(m.feed));
  block_.push_back(block_of(m));
  for (int k = 0; k < 3; ++k)
    if (other_.present[k]) other_end_[k].push_back(m.end[3 + k]);
  if (m.kind == machine::MoveKind::arc) {
    for (double v : m.center) arcs_.push_back(static_cast<float>(v));
    arcs_.push_back(static_cast<float>(m.sweep));
    arcs_.push_back(static_cast<float>(m.plane));
  }
  last_ = b;
}

void BackplotData::stopped(const nc::Diagnostic& alarm) {
  alarm_ = alarm;
  alarm_at_ = last_;
}

std::string base64(const void* data, std::size_t bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* p = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((bytes + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes; i += 3) {
    const std::uint32_t v = (std::uint32_t{p[i]} << 16) | (std::uint32_t{p[i + 1]} << 8) | p[i + 2];
    out += kDigits[v >> 18], out += kDigits[(v >> 12) & 63], out += kDigits[(v >> 6) & 63], out += kDigits[v & 63];
  }
  if (const std::size_t rest = bytes - i; rest > 0) {
    const std::uint32_t v = (std::uint32_t{p[i]} << 16) | (rest == 2 ? std::uint32_t{p[i + 1]} << 8 : 0);
    out += kDigits[v >> 18], out += kDigits[(v >> 12) & 63];
    out += rest == 2 ? kDigits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

namespace {

template <class T>
void add_array(std::string& out, const char* key, const std::vector<T>& v) {
  out += fmt::format(",\"{}\":\"", key);
  out += base64(v.data(), v.size() * sizeof(T));
  out += '"';
}

std::string dump(const nlohmann::json& j) { return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); }

}  // namespace

nlohmann::json part_json(const sim::PartGrid& g) {
  return {{"nx", g.nx}, {"ny", g.ny}, {"x0", g.x0}, {"y0", g.y0}, {"dx", g.dx}, {"dy", g.dy}, {"bottom", g.bottom},
          {"top", g.top}, {"heights", base64(g.heights.data(), g.heights.size() * sizeof(float))}};
}

std::string BackplotData::json(bool inch) const {
  nlohmann::json head;
  head["version"] = 1;
  head["lathe"] = lathe_;
  head["diameter"] = x_diameter_;
  head["plane"] = machine_plane_;
  head["inch"] = inch;
  head["motions"] = kind_.size();
  head["left_out"] = left_out_;
  nlohmann::json jumps = nlohmann::json::array();
  for (std::size_t i = 0; i < jump_at_.size(); ++i) jumps.push_back({jump_at_[i], jump_[i][0], jump_[i][1], jump_[i][2]});
  head["jumps"] = jumps;
  nlohmann::json corners = nlohmann::json::array();
  for (const auto& c : corners_) corners.push_back({static_cast<std::uint32_t>(c[0]), c[1], c[2], c[3]});
  head["rapid_corners"] = corners;
  nlohmann::json programmed = nlohmann::json::array(), programmed_arcs = nlohmann::json::array();
  for (const auto& p : programmed_)
    programmed.push_back({static_cast<std::uint32_t>(p[0]), p[1], p[2], p[3], p[4], p[5], p[6]});
  for (const auto& a : programmed_arcs_)
    programmed_arcs.push_back({static_cast<std::uint32_t>(a[0]), a[1], a[2], a[3], a[4], static_cast<int>(a[5])});
  head["programmed"] = programmed;
  head["programmed_arcs"] = programmed_arcs;
  std::size_t text_bytes = 0;
  for (const auto* f : files_) text_bytes += f->size();
  nlohmann::json files = nlohmann::json::array();
  for (const auto* f : files_) {
    nlohmann::json e;
    e["name"] = f->name();
    e["text"] = text_bytes <= kMostSourceBytes ? nlohmann::json(f->all_text()) : nlohmann::json(nullptr);
    files.push_back(e);
  }
  head["files"] = files;
  if (part_) {
    head["part"] = part_json(*part_);
    if (!deviation_.is_null()) head["part"]["deviation"] = deviation_;
  }
  if (lathe_part_) head["part"] = lathe_part_json(*lathe_part_);
  if (alarm_) {
    nlohmann::json a;
    a["code"] = alarm_->code;
    a["message"] = alarm_->message;
    a["file"] = alarm_->span.file ? nlohmann::json(alarm_->span.file->name()) : nlohmann::json(nullptr);
    a["line"] = alarm_->span.line;
    a["block"] = alarm_->span.file ? std::string(alarm_->span.file->line(alarm_->span.line)) : std::string();
    a["at"] = {alarm_at_[0], alarm_at_[1], alarm_at_[2]};
    head["alarm"] = a;
  } else {
    head["alarm"] = nullptr;
  }
  // the A, B and C axes the run moved (not drawn): their ranges, and their ends axis by axis
  nlohmann::json rotary = nlohmann::json::array();
  std::vector<double> rotary_end;
  for (int k = 0; k < 3; ++k) {
    if (!other_.moved(k)) continue;
    rotary.push_back({{"axis", std::string(1, "ABC"[k])}, {"unit", other_.rotary[k] ? "deg" : "mm"},
                      {"min", other_.lo[k]}, {"max", other_.hi[k]}});
    rotary_end.insert(rotary_end.end(), other_end_[k].begin(), other_end_[k].end());
  }
  head["rotary"] = rotary;
  std::string out = dump(head);
  out.pop_back();  // the closing brace: the arrays follow
  const std::size_t bytes = kind_.size() * 21 + arcs_.size() * 4 + block_line_.size() * 6;
  out.reserve(out.size() + bytes / 3 * 4 + 256);
  add_array(out, "kind", kind_);
  add_array(out, "end", end_);
  add_array(out, "feed", feed_);
  add_array(out, "block", block_);
  add_array(out, "arcs", arcs_);
  add_array(out, "block_file", block_file_);
  add_array(out, "block_line", block_line_);
  add_array(out, "rotary_end", rotary_end);
  out += '}';
  return out;
}

}  // namespace ncurve::report
