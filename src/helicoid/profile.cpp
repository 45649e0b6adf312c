#include "helicoid/profile.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geom/curve.hpp"
#include "geom/periodic_spline.hpp"

namespace ncurve::helicoid {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr int kTable = 8192;     // polar angle cells per turn (0.044 degrees)
constexpr int kOversample = 16;  // curve samples per cell when building the table

}  // namespace

EndProfile::EndProfile(std::string name, Eval eval, double u0, double period, bool place)
    : name_(std::move(name)), eval_(std::move(eval)), u0_(u0), period_(period) {
  if (!(period_ > 0)) throw std::runtime_error(fmt::format("profile {}: empty parameter range", name_));
  V2 p, d;
  eval_(u0_, p, d);
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || norm(p) < 1e-9)
    throw std::runtime_error(fmt::format("profile {}: the start point u = {} is on the axis or undefined", name_, u0_));
  double turn = place ? -std::atan2(p.y, p.x) : 0;
  turn_cos_ = std::cos(turn);
  turn_sin_ = std::sin(turn);

  // Sample, unwrap the polar angle and require it to move one way through exactly one turn.
  const int samples = kTable * kOversample;
  std::vector<double> theta(samples + 1), us(samples + 1), radius(samples + 1);
  for (int k = 0; k <= samples; ++k) {
    double u = u0_ + period_ * k / samples;
    V2 q = point(u);
    if (!std::isfinite(q.x) || !std::isfinite(q.y))
      throw std::runtime_error(fmt::format("profile {}: undefined at u = {:.4f}", name_, u));
    double a = std::atan2(q.y, q.x) / kDeg;
    if (k > 0) a += 360 * std::round((theta[k - 1] - a) / 360);
    theta[k] = a;
    us[k] = u;
    radius[k] = norm(q);
  }
  double winding = theta[samples] - theta[0];
  if (std::abs(std::abs(winding) - 360) > 1e-6)
    throw std::runtime_error(fmt::format("profile {}: the curve must close once around the axis (it turns {:.4f} degrees "
                                         "over u = {}..{})", name_, winding, u0_, u0_ + period_));
  double direction = winding > 0 ? 1 : -1;
  for (int k = 1; k <= samples; ++k)
    if ((theta[k] - theta[k - 1]) * direction <= 0)
      throw std::runtime_error(fmt::format("profile {}: a ray from the axis crosses the curve twice near u = {:.4f}; "
                                           "the profile must be star-shaped about the axis", name_, us[k]));
  if (direction < 0) {
    std::reverse(theta.begin(), theta.end());
    std::reverse(us.begin(), us.end());
    std::reverse(radius.begin(), radius.end());
  }
  // Uniform table over one turn starting at the placed start (theta 0 at u0).
  double base = theta.front();
  theta_.resize(kTable + 1);
  u_.resize(kTable + 1);
  r_.resize(kTable + 1);
  cell_ = 360.0 / kTable;
  std::size_t j = 0;
  for (int k = 0; k <= kTable; ++k) {
    double a = base + cell_ * k;
    while (j + 2 < theta.size() && theta[j + 1] < a) ++j;
    double f = (a - theta[j]) / (theta[j + 1] - theta[j]);
    theta_[k] = a;
    u_[k] = us[j] + f * (us[j + 1] - us[j]);
    r_[k] = radius[j] + f * (radius[j + 1] - radius[j]);
  }
  r_min_ = r_max_ = radius[0];
  for (double r : radius) {
    r_min_ = std::min(r_min_, r);
    r_max_ = std::max(r_max_, r);
  }
  // Between samples the radius can exceed the sampled largest by about r * (step angle)^2 / 8.
  r_max_ *= 1 + 1e-9;
}

EndProfile EndProfile::from_curve(std::shared_ptr<const geom::Curve> curve) {
  double u0 = curve->t0(), period = curve->t1() - curve->t0();
  auto eval = [curve](double u, V2& p, V2& d) {
    auto q = curve->point(u);
    auto v = curve->d1(u);
    p = {q[0], q[1]};
    d = {v[0], v[1]};
  };
  return EndProfile(curve->name(), eval, u0, period);
}

EndProfile EndProfile::from_points(std::string name, const std::vector<V2>& points) {
  std::vector<std::array<double, 2>> xy;
  for (const auto& p : points) xy.push_back({p.x, p.y});
  auto spline = std::make_shared<const geom::PeriodicSpline>(xy);
  const double per_degree = spline->length() / 360;
  auto eval = [spline, per_degree](double u, V2& p, V2& d) {
    std::array<double, 2> q, v;
    spline->eval(u * per_degree, q, v);
    p = {q[0], q[1]};
    d = {v[0] * per_degree, v[1] * per_degree};
  };
  return EndProfile(std::move(name), eval, 0, 360);
}

EndProfile EndProfile::seed004_rotor() {
  auto eval = [](double u_deg, V2& p, V2& d) {
    const double u = u_deg * kDeg;
    const double s5 = std::sin(5 * u), c5 = std::cos(5 * u), den = 1.4 - c5;
    const double s = std::atan(s5 / den) - u;
    const double ds = (7 * c5 - 5) / (s5 * s5 + den * den) - 1;
    const double su = std::sin(u), cu = std::cos(u), s6 = std::sin(6 * u), c6 = std::cos(6 * u);
    const double ss = std::sin(s), cs = std::cos(s);
    p = {63 * su - 7.5 * s6 + 20 * ss, 63 * cu - 7.5 * c6 - 20 * cs};
    d = {(63 * cu - 45 * c6 + 20 * cs * ds) * kDeg, (-63 * su + 45 * s6 + 20 * ss * ds) * kDeg};
  };
  return EndProfile("seed004 rotor", eval, 0, 360);
}

void EndProfile::point_and_d1(double u, V2& p, V2& d) const {
  V2 rp, rd;
  eval_(u, rp, rd);
  p = rotate(rp, turn_cos_, turn_sin_);
  d = rotate(rd, turn_cos_, turn_sin_);
}

V2 EndProfile::point(double u) const {
  V2 p, d;
  point_and_d1(u, p, d);
  return p;
}

V2 EndProfile::d1(double u) const {
  V2 p, d;
  point_and_d1(u, p, d);
  return d;
}

V2 EndProfile::outward_normal(double u) const {
  V2 p, d;
  point_and_d1(u, p, d);
  V2 n{d.y, -d.x};
  if (dot(n, p) < 0) n = -n;
  return n / norm(n);
}

double EndProfile::lookup(const std::vector<double>& table, double theta) const {
  double a = (theta - theta_[0]) / cell_;
  a -= kTable * std::floor(a / kTable);
  int k = std::min(static_cast<int>(a), kTable - 1);
  double f = a - k;
  return table[k] + f * (table[k + 1] - table[k]);
}

double EndProfile::u_at_angle(double theta) const { return lookup(u_, theta); }

double EndProfile::table_radius(double theta) const { return lookup(r_, theta); }

EndProfile::Hit EndProfile::first_hit(double phi, double y) const {
  if (!(std::abs(y) < r_max_)) return {};
  // Walk the polar angle T of the line's points from outside the largest radius inwards
  // (G < 0 outside the profile) to the first crossing, then solve on the exact curve.
  const double s = y >= 0 ? 1 : -1;
  auto G = [&](double T) { return s * (table_radius(T - phi) * std::sin(T * kDeg) - y); };
  double lo = std::asin(y / r_max_) / kDeg - s * cell_, hi = lo;
  for (;;) {
    hi = lo + s * cell_;
    if (s * hi > 180) return {};
    if (G(hi) >= 0) break;
    lo = hi;
  }
  const double c = std::cos(phi * kDeg), sn = std::sin(phi * kDeg);
  // H(u) < 0 outside the line, >= 0 past it; x is the turned point's abscissa.
  auto H = [&](double u, double* dH, double* x, double* dx) {
    V2 p, d;
    point_and_d1(u, p, d);
    *dH = s * (sn * d.x + c * d.y);
    *x = c * p.x - sn * p.y;
    *dx = c * d.x - sn * d.y;
    return s * (sn * p.x + c * p.y - y);
  };
  auto unwrap = [&](double v, double ref) { return v + period_ * std::round((ref - v) / period_); };
  // Newton from the table's crossing, kept inside the bracket widened by a cell.
  double g_lo = G(lo), g_hi = G(hi);
  double cross = lo + (hi - lo) * (-g_lo) / (g_hi - g_lo);
  double u = u_at_angle(cross - phi);
  double a = unwrap(u_at_angle(lo - s * cell_ - phi), u), b = unwrap(u_at_angle(hi + s * cell_ - phi), u);
  if (a > b) std::swap(a, b);
  for (int it = 0; it < 8; ++it) {
    double dh, x, dx, h = H(u, &dh, &x, &dx);
    double step = dh != 0 ? -h / dh : 0;
    if (!std::isfinite(step) || u + step < a || u + step > b) break;
    if (std::abs(step) < 1e-9) return {true, x + dx * step, u + step};
    u += step;
  }
  // Fallback: bisection safeguarded Newton on an exact bracket.
  double dh, x, dx;
  a = unwrap(u_at_angle(lo - phi), u);
  b = unwrap(u_at_angle(hi - phi), a);
  double ha = H(a, &dh, &x, &dx), hb = H(b, &dh, &x, &dx);
  for (int widen = 0; widen < 8 && (ha >= 0 || hb < 0); ++widen) {
    if (ha >= 0) {
      lo -= s * cell_;
      a = unwrap(u_at_angle(lo - phi), b);
      ha = H(a, &dh, &x, &dx);
    }
    if (hb < 0) {
      hi += s * cell_;
      b = unwrap(u_at_angle(hi - phi), a);
      hb = H(b, &dh, &x, &dx);
    }
  }
  if (ha >= 0 || hb < 0) return {};
  u = 0.5 * (a + b);
  for (int it = 0; it < 200; ++it) {
    double h = H(u, &dh, &x, &dx);
    if (h == 0) break;
    if (h < 0) a = u; else b = u;
    double next = u - h / dh;
    if (!(dh != 0 && std::isfinite(next) && (next - a) * (next - b) < 0)) next = 0.5 * (a + b);
    if (std::abs(next - u) < 1e-12) {
      x += dx * (next - u);
      u = next;
      break;
    }
    u = next;
  }
  return {true, x, u};
}

}  // namespace ncurve::helicoid
