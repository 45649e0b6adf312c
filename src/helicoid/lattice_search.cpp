// The contact search along X, phase by phase on the cutter's lattice: brute force, the
// nine-point walk traced from the last contacts, or the robust traces (one per element of the
// cutter profile and a watch of the whole); and the deepest penetration at a centre distance.
#include "helicoid/contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "helicoid/step_search.hpp"

namespace ncurve::helicoid {
namespace {

// The lattice rows of each element of the cutter profile (a row on a joint is in both; an element
// shorter than a row may have none: j_hi < j_lo).
std::vector<std::pair<int, int>> element_rows(const DiscCutter& cutter, double s_step, int ns) {
  std::vector<std::pair<int, int>> rows;
  double start = 0;
  for (const auto& e : cutter.elements()) {
    double end = start + e.length();
    rows.emplace_back(static_cast<int>(std::ceil(start / s_step - 1e-9)),
                      std::min(ns, static_cast<int>(std::floor(end / s_step + 1e-9))));
    start = end;
  }
  return rows;
}

using Node = StepSearch::Node;

// Tracing prediction: the line through the two previous contacts.
Node predicted(const std::vector<Node>& path, Node first) {
  if (path.empty()) return first;
  if (path.size() == 1) return path.back();
  const auto& a = path[path.size() - 2];
  const auto& b = path.back();
  return {2 * b.i - a.i, 2 * b.j - a.j};
}

constexpr double kTie = 1e-9;  // mm: well above the evaluation noise (~1e-12), far below any real step
constexpr double kNearTie = 0.05;  // mm: brute force keeps each element's lowest point this close to the best

// The robust search's traces, carried from step to step.
//
// Per element of the cutter profile (corner, each flank) a fine trace of the smallest distance
// within its rows, walked from the tracing prediction.
//
// And a watch of the whole profile, for contacts that rise apart from the traced ones: rows
// about kWatchSpacing apart and the rows at the joints of the elements, each with its smallest
// distance over alpha, m(s), and the slope of that along the profile, m'(s) = d_s there. A
// contact is a basin of m; a new one is born where the slope, rising away from the contact,
// flattens to 0 beyond a ridge (seed 004's rotor with a 70 deg insert: 3 mm up a flank at
// psi = 13 deg, the contact two degrees later), or rises at a joint (the corner's, when the
// contact comes back from a flank). A basin close to the best is descended to the fine lattice
// and given to the element holding it.
//
// A trace or watched row well above the best is left alone for as long as its gap to the best
// could not close at twice the fastest rate the gap has changed lately, per degree of psi (the
// fastest so far, fading by a factor a degree: a rate seen at the crest says little about the
// flank ten degrees on). A watched row also allows for the fastest rate of any row and of the
// best rising, lately: a row asleep for long has no rate of its own to go by.
class RobustTraces {
public:
  explicit RobustTraces(const ContactSearch& cs)
      : ns_(cs.s_cells()), na_(cs.alpha_cells()), alpha_step_(cs.lattice().alpha_step), s_step_(cs.lattice().s_step) {
    std::vector<int> rows;
    for (const auto& [j_lo, j_hi] : element_rows(cs.cutter(), s_step_, ns_))
      if (j_hi >= j_lo) {
        fine_.emplace_back(j_lo, j_hi, Node{0, (j_lo + j_hi) / 2});
        rows.push_back(j_lo), rows.push_back(j_hi);
      }
    window_ = std::max(1, static_cast<int>(std::lround(kWatchSpacing / s_step_)));
    for (int j = 0; j < ns_; j += window_) rows.push_back(j);
    rows.push_back(ns_);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (int j : rows) watch_.push_back(Watch{j});
    for (auto& f : fine_)  // a trace resting on its shoulder sleeps while the watch sees inside its rows
      for (const auto& w : watch_) f.guarded = f.guarded || (w.j > f.j_lo && w.j < f.j_hi);
  }

  // The lattice contact of this step, at phase psi.
  Node next(StepSearch& step, int step_index, double psi) {
    step_ = travel_ > 0 || step_index > 0 ? std::abs(psi - psi_) : 0;
    travel_ += step_;
    psi_ = psi;
    step_index_ = step_index;
    // The trace that held the contact last time first, then the others that are due.
    std::size_t lead = 0;
    for (std::size_t k = 0; k < fine_.size(); ++k)
      if (fine_[k].gap < fine_[lead].gap) lead = k;
    best_ = kInf;
    value_.assign(fine_.size(), kInf);
    node_of_.assign(fine_.size(), Node{0, -1});
    for (std::size_t k = 0; k < fine_.size(); ++k) {
      std::size_t at = (lead + k) % fine_.size();
      if (at != lead && !fine_[at].due(travel_)) continue;
      Node n = advance(fine_[at], step);
      offer(at, n, step.value(n));
      if (on_shoulder(fine_[at], n)) {
        if (at == lead)
          for (auto& f : fine_) f.asleep = false, f.wake = 0;
        else if (fine_[at].guarded)
          fine_[at].asleep = true;
      }
    }
    for (std::size_t k = 0; k < fine_.size(); ++k)  // the element holding the best
      if (node_of_[k].j == node_.j && node_of_[k].i == node_.i && value_[k] == best_) lead_ = k;
    watch(step);
    for (std::size_t k = 0; k < fine_.size(); ++k)
      if (std::isfinite(value_[k]) && !fine_[k].asleep) fine_[k].schedule(value_[k], best_, travel_, step_, 0);
    // The fastest rate lately of a watched row's gap, or of the best rising.
    const double fade = std::pow(kRateFade, step_);
    double fastest = watch_rate_ * fade;
    if (std::isfinite(last_best_) && step_ > 0) fastest = std::max(fastest, (best_ - last_best_) / step_);
    for (auto& w : watch_)
      if (w.measured == step_index) fastest = std::max(fastest, w.schedule(w.m, best_, travel_, step_, watch_rate_ * fade));
    watch_rate_ = fastest;
    last_best_ = best_;
    return node_;
  }

  // This step's lowest lattice point of each element searched (else {0, -1}).
  const std::vector<Node>& element_minima() const { return node_of_; }

private:
  static constexpr double kWatchSpacing = 1.2;  // mm between watched rows
  static constexpr double kRateFade = 0.7;      // per degree of psi
  static constexpr double kRateFloor = 0.01;    // mm per degree
  // A basin of the watch this close above the best is descended: the parabola's error, and
  // the lattice's (the best is a lattice value, the watch's off the lattice below it).
  static constexpr double kWatchMargin = 0.02;
  static constexpr double kAlphaReach = 2;  // deg: the longest Newton step on a watched row
  static constexpr double kRowAccuracy = 1e-2;  // of a watched row's gap: its smallest distance's accuracy

  struct Schedule {
    double gap = kInf, gap_rate = 0;  // mm, mm per degree of psi
    double updated = -1;              // travel of psi at the last update (< 0: none)
    double wake = 0;                  // travel from which it is due
    bool asleep = false;              // until woken
    // Returns the rate the gap changed at since the last update (0 without one).
    double schedule(double value, double best, double travel, double step, double floor_rate) {
      const double g = value - best;
      const bool known = updated >= 0 && std::isfinite(gap) && std::isfinite(g);  // a rate needs two updates
      double seen = 0;
      if (known && travel > updated) {
        const double span = travel - updated;
        seen = std::abs(g - gap) / span;
        gap_rate = std::max(gap_rate * std::pow(kRateFade, span), seen);
      }
      gap = g;
      updated = travel;
      const double rate = std::max({gap_rate, floor_rate, kRateFloor});
      // Checked at the first step from `wake`: a step early, so never later than the gap could close.
      wake = known ? travel + g / (2 * rate) - step : travel;
      return seen;
    }
    bool due(double travel) const { return !asleep && travel >= wake; }
  };

  struct Trace : Schedule {
    Trace(int lo, int hi, Node start) : j_lo(lo), j_hi(hi), first(start) {}
    int j_lo, j_hi;
    Node first;
    std::vector<Node> path;
    bool guarded = false;  // the watch sees rows inside it
    bool due(double travel) {
      if (Schedule::due(travel)) return true;
      if (!path.empty()) path = {path.back()};  // a stale line no longer predicts
      return false;
    }
  };

  // A watched row: its smallest distance over alpha (off the lattice), and the slope along s.
  struct Watch : Schedule {
    explicit Watch(int row) : j(row) {}
    int j;
    double alpha = 0, alpha_before = 0;  // the minimum's alpha at the last two measurements
    double at = -1, at_before = -1;      // their travel of psi
    int measured = -1;                   // step of the last measurement
    double curvature = 0;                // d2 d / d alpha2 at the minimum, per deg^2 (0: unknown)
    double m = kInf, slope = 0;
  };

  void offer(std::size_t k, Node n, double v) {
    if (v < value_[k]) value_[k] = v, node_of_[k] = n;
    if (v < best_) best_ = v, node_ = n;
  }

  Node advance(Trace& t, StepSearch& step) {
    step.restrict_rows(t.j_lo, t.j_hi);
    Node n = t.path.empty() ? step.descend(t.first, 64, kTie) : step.walk(predicted(t.path, t.first), 1, kTie, true);
    t.path.push_back(n);
    return n;
  }

  // A fine trace resting on a row it shares with a neighbour element is that neighbour's
  // shoulder, not a contact of its own: it sleeps until the watch wakes it.
  bool on_shoulder(const Trace& t, Node n) const {
    return (n.j == t.j_lo && t.j_lo > 0) || (n.j == t.j_hi && t.j_hi < ns_);
  }

  // The smallest distance on a watched row, off the lattice: Newton on the exact d_alpha from the
  // alpha its last two measurements predict (or, the first time, its neighbour's), with the
  // curvature the secants give, each step kept only if the distance falls; it stops when the
  // next step would lower the distance by less than the row needs (a row far above the best
  // needs less). Where Newton fails the row's lattice walk starts it again.
  void measure(Watch& w, StepSearch& step, double guess, double guess_curvature) {
    const double ha = alpha_step_, limit = na_ * ha, s = w.j * s_step_;
    auto clamp = [&](double a) { return std::clamp(a, -limit, limit); };
    double a = guess;
    if (w.measured >= 0) {
      a = w.alpha;
      if (w.at_before >= 0 && w.at > w.at_before) {  // moved on as between the last two, as far at most
        const double span = w.at - w.at_before;
        a += (w.alpha - w.alpha_before) * std::min(travel_ - w.at, span) / span;
      }
    } else {
      w.curvature = guess_curvature;
    }
    double enough = kTie;
    auto newton = [&](ContactSearch::Distance& at) {  // false: no way down found
      // the gap known, else as it looks from here
      const double gap = std::isfinite(w.gap) ? w.gap : at.d - best_;
      enough = std::isfinite(gap) ? std::max(kTie, kRowAccuracy * gap) : kTie;
      for (int it = 0; it < 8; ++it) {
        if (!(w.curvature > 0)) {  // a secant over a cell
          double b = a + ha <= limit ? a + ha : a - ha;
          auto there = step.eval(b, s);
          double c = there.hit ? (there.d_alpha - at.d_alpha) / (b - a) : 0;
          if (!(c > 0 && std::isfinite(c))) return false;
          w.curvature = c;
          if (there.d < at.d) a = b, at = there;
        }
        double delta = -at.d_alpha / w.curvature;
        if (w.curvature * delta * delta / 2 < enough) return true;
        delta = std::clamp(delta, -kAlphaReach, kAlphaReach);
        bool fell = false;
        for (int half = 0; half < 4 && !fell; ++half, delta /= 2) {
          double next = clamp(a + delta);
          if (next == a) return true;  // at the end of the range
          auto there = step.eval(next, s);
          if (!there.hit || there.d > at.d) continue;
          double c = (there.d_alpha - at.d_alpha) / (next - a);
          if (c > 0 && std::isfinite(c)) w.curvature = c;
          a = next, at = there, fell = true;
        }
        if (!fell) return false;
      }
      return true;
    };
    a = clamp(a);
    auto at = step.eval(a, s);
    if (!at.hit || !newton(at)) {
      step.restrict_rows(w.j, w.j);
      Node n = step.descend({static_cast<int>(std::lround(a / ha)), w.j}, 16, kTie);
      w.curvature = 0;
      a = step.alpha(n);
      at = step.eval(a, s);
      if (at.hit) newton(at);
    }
    w.alpha_before = w.alpha, w.at_before = w.at;
    w.alpha = a, w.at = travel_, w.measured = step_index_;
    w.m = at.hit ? at.d : kInf;
    w.slope = at.hit ? at.d_s : 0;
  }

  // Rows near the contact within its element are its trace's own basin (its joints aside: a
  // neighbour's basin can lie just across one). A contact on a shoulder is the neighbour's
  // basin, and its element may hold a basin of its own nearby.
  bool near_lead(int j, int pad) const {
    const auto& f = fine_[lead_];
    return !on_shoulder(f, node_) && std::abs(j - node_.j) <= pad && j > f.j_lo && j < f.j_hi;
  }

  void watch(StepSearch& step) {
    // Rows due, measured outwards from the contact (the first time each starts from its
    // inner neighbour's alpha).
    std::size_t centre = 0;
    for (std::size_t k = 0; k < watch_.size(); ++k)
      if (std::abs(watch_[k].j - node_.j) < std::abs(watch_[centre].j - node_.j)) centre = k;
    auto visit = [&](std::size_t k, const Watch& inner) {
      Watch& w = watch_[k];
      if (w.measured >= 0 && near_lead(w.j, window_ - 1)) {
        w.wake = 0;  // due once the contact moves on
      } else if (w.measured < 0 || w.due(travel_)) {
        measure(w, step, inner.alpha, inner.curvature);
      }
      return std::cref(w);
    };
    Watch start{node_.j};
    start.alpha = step.alpha(node_);
    auto inner = visit(centre, start);
    for (std::size_t k = centre + 1; k < watch_.size(); ++k) inner = visit(k, inner);
    inner = std::cref(watch_[centre]);
    for (std::size_t k = centre; k-- > 0;) inner = visit(k, inner);
    // Basins of m: a slope changing sign from - to + between two rows, or an end of the profile
    // the slope rises from; their lowest value by the parabola of the two slopes. The basin
    // around the contact is its trace's; another close to the best has its rows measured again
    // if they are stale, and if it still is, it is descended.
    struct Basin {
      double low = kInf;
      std::size_t from = 0, lo = 0, hi = 0;  // the lower row, and the rows either side
    };
    auto basin = [&](std::size_t k) {
      Basin out;
      const Watch& w = watch_[k];
      if (!std::isfinite(w.m)) return out;
      if (k + 1 < watch_.size() && w.slope < 0 && watch_[k + 1].slope >= 0 && std::isfinite(watch_[k + 1].m)) {
        const Watch& v = watch_[k + 1];
        double h = (v.j - w.j) * s_step_, curv = (v.slope - w.slope) / h;
        out = {std::min(w.m - w.slope * w.slope / (2 * curv), v.m - v.slope * v.slope / (2 * curv)),
               v.m < w.m ? k + 1 : k, k, k + 1};
      } else if (k == 0 && w.slope >= 0) {
        out = {w.m, k, k, std::min(k + 1, watch_.size() - 1)};
      } else if (k + 1 == watch_.size() && w.slope <= 0) {
        out = {w.m, k, k == 0 ? k : k - 1, k};
      }
      return out;
    };
    for (std::size_t k = 0; k < watch_.size(); ++k) {
      Basin b = basin(k);
      if (!(b.low <= best_ + kWatchMargin)) continue;
      if (near_lead(watch_[b.from].j, window_) &&
          (near_lead(watch_[b.lo].j, window_) || near_lead(watch_[b.hi].j, window_) ||
           (node_.j >= watch_[b.lo].j && node_.j <= watch_[b.hi].j)))
        continue;
      bool stale = false;
      for (std::size_t r = b.lo; r <= b.hi; ++r)
        if (watch_[r].measured != step_index_) {
          measure(watch_[r], step, watch_[r].alpha, watch_[r].curvature);
          stale = true;
        }
      if (stale) b = basin(k);
      if (!(b.low <= best_ + kWatchMargin)) continue;
      // Descended over the whole profile (the basin may lie across a joint), then given to the
      // element holding its lowest point.
      const Watch& from = watch_[b.from];
      step.restrict_rows(0, ns_);
      Node m = step.descend({static_cast<int>(std::lround(from.alpha / alpha_step_)), from.j},
                            std::max(1, window_ / 2), kTie);
      for (std::size_t e = 0; e < fine_.size(); ++e) {
        auto& f = fine_[e];
        if (m.j < f.j_lo || m.j > f.j_hi) continue;
        if (step.value(m) < value_[e]) f.path = {m}, f.asleep = false, f.wake = 0;
        offer(e, m, step.value(m));
        break;
      }
    }
  }

  int ns_, na_;
  double alpha_step_, s_step_;
  std::vector<Trace> fine_;
  std::vector<Watch> watch_;
  int window_ = 1;  // rows in kWatchSpacing
  // Travel of psi so far (degrees, either way), this step's, its phase and index.
  double travel_ = 0, step_ = 0, psi_ = 0;
  int step_index_ = 0;
  double watch_rate_ = 0, last_best_ = kInf;
  // This step's best so far, its node, the trace that led, and each fine trace's value and node.
  double best_ = kInf;
  Node node_;
  std::size_t lead_ = 0;
  std::vector<double> value_;
  std::vector<Node> node_of_;
};

}  // namespace

std::vector<Contact> ContactSearch::run(const std::vector<double>& psis, Method method, const StepDone& done) const {
  std::vector<Contact> out;
  std::vector<Node> path;  // lattice contacts so far
  const Node corner{0, static_cast<int>(std::lround(cutter_.corner_middle() / lattice_.s_step))};
  RobustTraces traces(*this);
  const auto rows = element_rows(cutter_, lattice_.s_step, ns_);
  for (std::size_t step_index = 0; step_index < psis.size(); ++step_index) {
    const double psi = psis[step_index];
    StepSearch step(*this, psi);
    Node node;
    std::vector<Node> minima;  // each element's lowest lattice point (j < 0: none)
    switch (method) {
      case Method::brute:
        minima = step.brute(rows, kNearTie);
        node = minima.front();
        for (const auto& m : minima)
          if (m.j >= 0 && (node.j < 0 || step.value(m) < step.value(node))) node = m;
        break;
      case Method::nine_point: node = step.walk(predicted(path, corner), 1, 0.0, false); break;
      case Method::robust:
        node = traces.next(step, static_cast<int>(step_index), psi);
        minima = traces.element_minima();
        break;
    }
    path.push_back(node);
    auto refined = step.refine(node);
    // Where the contact jumps between elements, two of them touch almost at once, and the lattice
    // can rank them otherwise than they are: each whose lattice value, less twice the lattice's
    // coarseness there, is below the refined contact is refined too, and the lower one is it.
    for (const auto& m : minima) {
      if (m.j < 0 || (m.i == node.i && m.j == node.j)) continue;
      step.restrict_rows(0, ns_);
      const double v = step.value(m), low = v - 2 * (v - step.fitted_minimum(m, 1)) - 1e-9;
      if (!(low < refined.d)) continue;
      auto other = step.refine(m);
      if (other.d < refined.d) refined = other;
    }
    const auto& at = refined.at;
    Contact c;
    c.psi = psi;
    c.phase = psi;
    c.A = setting_.start_distance - refined.d;
    c.alpha = refined.alpha;
    c.s = refined.s;
    c.region = cutter_.region(refined.s);
    c.cutter_point = {at.q[0] - refined.d, at.q[1], at.q[2]};
    c.work_point = {at.x_hit, at.q[1], at.q[2]};
    c.u = at.u;
    c.r = std::hypot(at.x_hit, at.q[1]);
    double dot = -(at.n_cutter[0] * at.n_work[0] + at.n_cutter[1] * at.n_work[1] + at.n_cutter[2] * at.n_work[2]);
    c.normal_angle = std::acos(std::clamp(dot, -1.0, 1.0)) / kDeg;
    for (const auto& v : cutter_.vertices())
      if (refined.s == v.s) {  // on an edge: named by the elements meeting there
        c.normal_angle = edge_normal_angle(v, refined.alpha, at.n_work);
        c.region = cutter_.elements()[v.element - 1].region + "/" + cutter_.elements()[v.element].region;
      }
    c.evaluations = step.evaluations();
    c.plane_A = plane_distance(psi);
    out.push_back(c);
    if (done) done(out.size());
  }
  return out;
}

double ContactSearch::deepest_penetration(double psi, double A, std::int64_t* evaluations) const {
  // Scan every 8th lattice point (skipping those the largest-radius bound clears), then descend
  // from the lowest few, apart from each other, to the continuous minimum.
  constexpr int kStride = 8;
  const double contact = setting_.start_distance - A;
  StepSearch step(*this, psi);
  struct Low {
    StepSearch::Node n;
    double d;
  };
  std::vector<Low> low;
  // every 8th row, and the rows either side of each edge (there the distance rises steeply both
  // ways: 8 rows off, a sharp tip is farther than any start is looked for)
  std::vector<int> rows;
  for (int j = 0; j <= ns_; j += kStride) rows.push_back(j);
  for (const auto& v : cutter_.vertices())
    for (double j : {std::floor(v.s / lattice_.s_step), std::ceil(v.s / lattice_.s_step)})
      rows.push_back(std::clamp(static_cast<int>(j), 0, ns_));
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  for (int i = -(na_ / kStride) * kStride; i <= na_; i += kStride)
    for (int j : rows) {
      StepSearch::Node n{i, j};
      if (step.lower_bound(n) >= contact + 0.05) continue;
      double d = step.value(n);
      if (d < contact + 0.05) low.push_back({n, d});
    }
  std::sort(low.begin(), low.end(), [](const Low& a, const Low& b) { return a.d < b.d; });
  std::vector<StepSearch::Node> starts;
  for (const auto& l : low) {
    bool near = false;
    for (const auto& s : starts) near = near || (std::abs(s.i - l.n.i) <= 2 * kStride && std::abs(s.j - l.n.j) <= 2 * kStride);
    if (!near) starts.push_back(l.n);
    if (starts.size() == 8) break;
  }
  double deepest = -kInf;
  for (const auto& s : starts) {
    auto r = step.refine(step.descend(s, kStride / 2, 1e-9));
    deepest = std::max(deepest, contact - r.d);
  }
  if (evaluations) *evaluations = step.evaluations();
  return deepest;
}

}  // namespace ncurve::helicoid
