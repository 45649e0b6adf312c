#include "serve/tool_columns.hpp"

#include <algorithm>
#include <cmath>

#include "report/writers.hpp"
#include "serve/json_out.hpp"

namespace ncurve::serve {

void FeedColumns::made(const machine::Move& m) {
  const std::uint64_t index = seen_++;
  if (index < limit_) {
    programmed_.push_back(0);
    peak_.push_back(0);
    end_.push_back(0);
  }
  if (motion::Planner::plans(m)) waiting_.push_back(index);
}

void FeedColumns::planned(const motion::BlockTime& b) {
  if (waiting_.empty()) return;  // (cannot happen: the planner times only the moves it plans)
  const std::uint64_t index = waiting_.front();
  waiting_.pop_front();
  if (index >= programmed_.size()) return;
  programmed_[index] = static_cast<float>(b.programmed);
  peak_[index] = static_cast<float>(b.v_peak);
  end_[index] = static_cast<float>(b.v_out);
}

void FeedColumns::write_json(fmt::memory_buffer& b) const {
  auto it = fmt::appender(b);
  fmt::format_to(it, "{{\"count\":{},\"complete\":{},", peak_.size(), seen_ <= limit_ ? "true" : "false");
  if (seen_ > limit_)
    fmt::format_to(it, "\"message\":{},", json_string(fmt::format("the answer holds the feeds of the first {} moves of {} "
                                                                   "(max_moves)", peak_.size(), seen_)));
  auto tenth = [&](float v) { put_number(b, v, 10); };  // mm/min to 0.1
  put_array(b, "feed_programmed", programmed_, tenth);
  b.push_back(',');
  put_array(b, "feed_peak", peak_, tenth);
  b.push_back(',');
  put_array(b, "feed_end", end_, tenth);
  b.push_back('}');
}

namespace {

double distance_to_segment(const geom::Vec3& p, const geom::Vec3& a, const geom::Vec3& b) {
  double ab[3], ap[3], len2 = 0, dot = 0;
  for (int k = 0; k < 3; ++k) {
    ab[k] = b[k] - a[k];
    ap[k] = p[k] - a[k];
    len2 += ab[k] * ab[k];
    dot += ab[k] * ap[k];
  }
  const double u = len2 > 0 ? std::clamp(dot / len2, 0.0, 1.0) : 0;
  double d2 = 0;
  for (int k = 0; k < 3; ++k) d2 += (ap[k] - u * ab[k]) * (ap[k] - u * ab[k]);
  return std::sqrt(d2);
}

}  // namespace

CurvePolyline curve_polyline(const geom::Curve& curve, const geom::Placement& placement, double within,
                             std::size_t most) {
  // Pieces of t, split in halves, a round at a time, where a quarter point lies further from the
  // chord than `within`; 64 equal pieces to start, so that a wave is not missed between two points.
  struct Piece {
    double t0, t1;
    geom::Vec3 p0, p1;
  };
  const auto at = [&](double t) { return placement(curve.point(t)); };
  constexpr int kStart = 64;
  const double t0 = curve.t0(), t1 = curve.t1();
  std::vector<Piece> pieces;
  for (int k = 0; k < kStart; ++k) {
    const double a = t0 + (t1 - t0) * k / kStart, b = k + 1 == kStart ? t1 : t0 + (t1 - t0) * (k + 1) / kStart;
    pieces.push_back({a, b, k ? pieces.back().p1 : at(a), at(b)});
  }
  CurvePolyline out;
  for (;;) {
    std::vector<char> split(pieces.size(), 0);
    std::size_t splits = 0;
    double worst = 0;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const Piece& q = pieces[i];
      double d = 0;
      for (double f : {0.25, 0.5, 0.75}) d = std::max(d, distance_to_segment(at(q.t0 + (q.t1 - q.t0) * f), q.p0, q.p1));
      worst = std::max(worst, d);
      if (d > within) split[i] = 1, ++splits;
    }
    out.within = worst;
    if (splits == 0 || pieces.size() + splits + 1 > most) break;
    std::vector<Piece> next;
    next.reserve(pieces.size() + splits);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const Piece& q = pieces[i];
      if (!split[i]) {
        next.push_back(q);
        continue;
      }
      const double m = 0.5 * (q.t0 + q.t1);
      const geom::Vec3 pm = at(m);
      next.push_back({q.t0, m, q.p0, pm});
      next.push_back({m, q.t1, pm, q.p1});
    }
    pieces = std::move(next);
  }
  out.points.reserve(pieces.size() + 1);
  out.points.push_back(pieces.front().p0);
  for (const Piece& q : pieces) out.points.push_back(q.p1);
  return out;
}

void write_gen_geometry(fmt::memory_buffer& b, const CurvePolyline& curve, const gen::Stats& stats,
                        const machine::MachineProfile& profile) {
  const report::OutputFrame frame(profile);
  auto it = fmt::appender(b);
  auto num = [&](double v) { put_number(b, v, 1e9); };  // nm: the polyline lies on the curve to far below a µm
  fmt::format_to(it, ",\"reference\":{{\"count\":{},\"within_mm\":", curve.points.size());
  put_number(b, curve.within, 1e9);
  std::vector<double> x, y, z;
  x.reserve(curve.points.size());
  y.reserve(curve.points.size());
  z.reserve(curve.points.size());
  for (const geom::Vec3& p : curve.points) x.push_back(frame.x(p[0])), y.push_back(p[1]), z.push_back(p[2]);
  b.push_back(',');
  put_array(b, "x", x, num);
  b.push_back(',');
  put_array(b, "y", y, num);
  b.push_back(',');
  put_array(b, "z", z, num);
  b.append(std::string_view("},\"move_deviation\":{"));
  put_array(b, "index", stats.run_index, [&](std::size_t v) { fmt::format_to(it, "{}", v); });
  b.push_back(',');
  put_array(b, "mm", stats.run_deviation, num);
  b.push_back('}');
}

}  // namespace ncurve::serve
