#include "serve/move_columns.hpp"

#include <numbers>

#include "machine/rapid_path.hpp"

namespace ncurve::serve {

using machine::Move;
using machine::MoveKind;

MoveColumns::MoveColumns(const machine::MachineProfile& profile, FileTable& files, std::size_t limit)
    : frame_(profile), files_(files), limit_(limit), profile_(profile) {
  for (char a : std::string_view("ABC"))
    if (profile.axes.find(a) != std::string::npos) rotary_.push_back(machine::axis_index(a));
  abc_.resize(rotary_.size());
  sabc_.resize(rotary_.size());
}

void MoveColumns::on_move(const Move& m) {
  if (kind_.size() >= limit_) {
    ++dropped_;
    return;
  }
  const auto index = static_cast<std::uint32_t>(kind_.size());
  const bool placed = m.is_motion() || m.kind == MoveKind::dwell;
  const machine::AxisVector& end = m.end;  // an event's: where the program has the tool
  if (placed && (index == 0 || m.start != last_end_)) {
    start_at_.push_back(index);
    sx_.push_back(frame_.x(m.start[0]));
    sy_.push_back(m.start[1]);
    sz_.push_back(m.start[2]);
    for (std::size_t r = 0; r < rotary_.size(); ++r) sabc_[r].push_back(m.start[rotary_[r]]);
  }
  kind_.push_back(static_cast<std::uint8_t>(m.kind));
  file_.push_back(files_.index(m.file));
  line_.push_back(m.line);
  x_.push_back(frame_.x(end[0]));
  y_.push_back(end[1]);
  z_.push_back(end[2]);
  for (std::size_t r = 0; r < rotary_.size(); ++r) abc_[r].push_back(end[rotary_[r]]);
  f_.push_back(m.kind == MoveKind::line || m.kind == MoveKind::arc ? m.feed : 0.0);
  if (m.kind == MoveKind::arc) {
    arc_at_.push_back(index);
    cx_.push_back(frame_.x(m.center[0]));
    cy_.push_back(m.center[1]);
    cz_.push_back(m.center[2]);
    sweep_.push_back(m.sweep * 180 / std::numbers::pi);
    plane_.push_back(m.plane);
    cw_.push_back(m.clockwise ? 1 : 0);
  }
  if (m.kind == MoveKind::rapid && !profile_.linear_rapid) {
    const auto path = machine::rapid_path(m.start, m.end, profile_);
    for (std::size_t k = 1; k + 1 < path.size(); ++k) {
      corner_at_.push_back(index);
      kx_.push_back(frame_.x(path[k][0]));
      ky_.push_back(path[k][1]);
      kz_.push_back(path[k][2]);
    }
  }
  if (m.is_motion()) note_programmed(m, index);
  if (!placed) {
    code_at_.push_back(index);
    code_.push_back(m.code);
  }
  if (placed) last_end_ = m.end;
}

void MoveColumns::note_programmed(const Move& m, std::uint32_t index) {
  // (the tip matters to a compensated arc only)
  const bool arc = m.compensated && m.kind == MoveKind::arc;
  const std::array<double, 2> tip = arc && nose_tip_ && profile_.lathe() ? nose_tip_() : std::array<double, 2>{};
  const auto piece = contour_.on_motion(m, tip);
  if (!piece) return;
  programmed_at_.push_back(index);
  px_.push_back(frame_.x(piece->end[0]));
  py_.push_back(piece->end[1]);
  pz_.push_back(piece->end[2]);
  psx_.push_back(frame_.x(piece->start[0]));
  psy_.push_back(piece->start[1]);
  psz_.push_back(piece->start[2]);
  if (!piece->arc) return;
  programmed_arc_at_.push_back(index);
  pcx_.push_back(frame_.x(piece->centre[0]));
  pcy_.push_back(piece->centre[1]);
  pcz_.push_back(piece->centre[2]);
  psweep_.push_back(piece->sweep * 180 / std::numbers::pi);
}

void MoveColumns::write_json(Columns& out) const {
  fmt::memory_buffer& b = out.json;
  auto it = fmt::appender(b);
  auto num = [&](double v) { put_number(b, v); };
  auto whole = [&](auto v) { fmt::format_to(it, "{}", static_cast<long long>(v)); };
  fmt::format_to(it, "{{\"count\":{},\"complete\":{},", kind_.size(), complete() ? "true" : "false");
  if (dropped_)
    fmt::format_to(it, "\"message\":{},", json_string(fmt::format("the answer holds the first {} moves of {} (max_moves)",
                                                                  kind_.size(), kind_.size() + dropped_)));
  b.append(std::string_view("\"kinds\":["));
  for (int k = 0; k < 10; ++k) fmt::format_to(it, "{}\"{}\"", k ? "," : "", machine::to_string(static_cast<MoveKind>(k)));
  b.append(std::string_view("],"));
  put_array(out, "kind", kind_, whole);
  b.push_back(',');
  put_array(out, "file", file_, whole);
  b.push_back(',');
  put_array(out, "line", line_, whole);
  const char* names[] = {"a", "b", "c"};
  auto axes = [&](const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                  const std::vector<std::vector<double>>& abc) {
    b.push_back(',');
    put_array(out, "x", x, num);
    b.push_back(',');
    put_array(out, "y", y, num);
    b.push_back(',');
    put_array(out, "z", z, num);
    for (std::size_t r = 0; r < rotary_.size(); ++r) {
      b.push_back(',');
      put_array(out, names[rotary_[r] - 3], abc[r], num);
    }
  };
  axes(x_, y_, z_, abc_);
  b.push_back(',');
  put_array(out, "f", f_, num);
  b.append(std::string_view(",\"starts\":{"));
  put_array(out, "index", start_at_, whole);
  axes(sx_, sy_, sz_, sabc_);
  b.append(std::string_view("},\"arcs\":{"));
  put_array(out, "index", arc_at_, whole);
  b.push_back(',');
  put_array(out, "cx", cx_, num);
  b.push_back(',');
  put_array(out, "cy", cy_, num);
  b.push_back(',');
  put_array(out, "cz", cz_, num);
  b.push_back(',');
  put_array(out, "plane", plane_, whole);
  b.push_back(',');
  put_array(out, "cw", cw_, whole);
  b.push_back(',');
  put_array(out, "sweep_deg", sweep_, num);
  b.append(std::string_view("},\"codes\":{"));
  put_array(out, "index", code_at_, whole);
  b.push_back(',');
  put_array(out, "code", code_, whole);
  b.append(std::string_view("},\"corners\":{"));
  put_array(out, "index", corner_at_, whole);
  b.push_back(',');
  put_array(out, "x", kx_, num);
  b.push_back(',');
  put_array(out, "y", ky_, num);
  b.push_back(',');
  put_array(out, "z", kz_, num);
  b.append(std::string_view("},\"programmed\":{"));
  put_array(out, "index", programmed_at_, whole);
  b.push_back(',');
  put_array(out, "x", px_, num);
  b.push_back(',');
  put_array(out, "y", py_, num);
  b.push_back(',');
  put_array(out, "z", pz_, num);
  b.push_back(',');
  put_array(out, "sx", psx_, num);
  b.push_back(',');
  put_array(out, "sy", psy_, num);
  b.push_back(',');
  put_array(out, "sz", psz_, num);
  b.append(std::string_view("},\"programmed_arcs\":{"));
  put_array(out, "index", programmed_arc_at_, whole);
  b.push_back(',');
  put_array(out, "cx", pcx_, num);
  b.push_back(',');
  put_array(out, "cy", pcy_, num);
  b.push_back(',');
  put_array(out, "cz", pcz_, num);
  b.push_back(',');
  put_array(out, "sweep_deg", psweep_, num);
  b.append(std::string_view("}}"));
}

}  // namespace ncurve::serve
