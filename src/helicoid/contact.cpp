// The directed-distance model of the disc cutter and the helicoid: the search's set-up, the
// distance along X from a cutter point to the workpiece with its gradient, plane programming,
// the normal angle at an edge, and the stock and cusps passes leave.
#include "helicoid/contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "geom/search.hpp"
#include "helicoid/step_search.hpp"

namespace ncurve::helicoid {
namespace {

EndProfile offset_profile(const EndProfile& base, double distance) {
  auto eval = [base, distance](double u, V2& p, V2& d) {
    auto at = [&](double v) {
      V2 q = base.point(v), n = base.outward_normal(v);
      return q + distance * n;
    };
    p = at(u);
    constexpr double h = 1e-5;
    V2 a = at(u - h), b = at(u + h);
    d = (b - a) / (2 * h);
  };
  return EndProfile(base.name() + " offset", eval, base.u0(), base.period(), false);
}

}  // namespace

double helix_angle(double lead, double radius) {
  return lead == 0 ? 0 : std::atan(2 * std::numbers::pi * radius / std::abs(lead)) / kDeg;
}

std::int64_t Lattice::size(double profile_length) const {
  // in doubles, held below 2^62: a tiny step must not overflow the conversion
  const double na = std::floor(alpha_max / alpha_step + 1e-9), ns = std::floor(profile_length / s_step + 1e-9);
  const double n = (2 * na + 1) * (ns + 1);
  return n < 4e18 ? static_cast<std::int64_t>(n) : std::int64_t{4'000'000'000'000'000'000};
}

Method method_from_name(const std::string& name) {
  if (name == "brute") return Method::brute;
  if (name == "nine-point") return Method::nine_point;
  if (name == "robust") return Method::robust;
  throw std::runtime_error(fmt::format("unknown method '{}' (brute, nine-point or robust)", name));
}

const char* method_name(Method m) {
  switch (m) {
    case Method::brute: return "brute";
    case Method::nine_point: return "nine-point";
    case Method::robust: return "robust";
  }
  return "?";
}

ContactSearch::ContactSearch(Workpiece work, DiscCutter cutter, Setting setting, Lattice lattice)
    : work_(std::move(work)), cutter_(std::move(cutter)), setting_(setting), lattice_(lattice),
      plane_profile_(work_.profile) {
  if (!(lattice_.alpha_step > 0) || !(lattice_.s_step > 0) || !(lattice_.alpha_max > 0) || lattice_.alpha_max >= 90)
    throw std::runtime_error("lattice: steps > 0 and 0 < alpha range < 90 degrees");
  if (lattice_.size(cutter_.length()) > kMostLatticePoints)
    throw std::runtime_error(fmt::format("lattice: {} points, more than {}: a larger step", lattice_.size(cutter_.length()),
                                         kMostLatticePoints));
  double b = setting_.swing * kDeg, h = work_.hand;
  axis_ = {0, -h * std::cos(b), std::sin(b)};
  e2_ = {0, std::sin(b), h * std::cos(b)};
  na_ = static_cast<int>(std::floor(lattice_.alpha_max / lattice_.alpha_step + 1e-9));
  ns_ = static_cast<int>(std::floor(cutter_.length() / lattice_.s_step + 1e-9));
  if (setting_.start_distance <= 0) setting_.start_distance = work_.profile.r_max() + cutter_.outer_radius() + 1;
  for (const auto& e : cutter_.elements())
    if (e.kind == ProfileElement::Kind::arc && e.region == "corner") corner_radius_ = e.radius;
  plane_profile_ = corner_radius_ > 0 ? offset_profile(work_.profile, corner_radius_) : work_.profile;
}

ContactSearch::Distance ContactSearch::distance(double psi, double alpha, double s) const {
  Distance out;
  auto cp = cutter_.at(s);
  double rho = cp.p.x, w = cp.p.y;
  double ca = std::cos(alpha * kDeg), sa = std::sin(alpha * kDeg);
  double A0 = setting_.start_distance;
  Vec3 radial{-ca, sa * e2_[1], sa * e2_[2]};  // unit, from the cutter axis towards the point
  out.q = {A0 + rho * radial[0] + w * axis_[0], rho * radial[1] + w * axis_[1], rho * radial[2] + w * axis_[2]};
  out.n_cutter = {cp.normal.x * radial[0] + cp.normal.y * axis_[0], cp.normal.x * radial[1] + cp.normal.y * axis_[1],
                  cp.normal.x * radial[2] + cp.normal.y * axis_[2]};
  double twist = work_.twist();
  double phi = psi + twist * out.q[2];
  auto hit = work_.profile.first_hit(phi, out.q[1]);
  if (!hit.found) {
    out.d = kInf;
    return out;
  }
  out.hit = true;
  out.x_hit = hit.x;
  out.u = hit.u;
  out.d = out.q[0] - hit.x;
  // Workpiece normal: dS/du x dS/dz of S(u, z) = (R(phi(z)) p(u), z).
  V2 t = work_.profile.d1(hit.u);
  double c = std::cos(phi * kDeg), sn = std::sin(phi * kDeg);
  V2 tw = rotate(t, c, sn);
  double k = twist * kDeg;
  Vec3 n{tw.y, -tw.x, k * (tw.x * hit.x + tw.y * out.q[1])};
  if (n[0] * hit.x + n[1] * out.q[1] < 0) n = {-n[0], -n[1], -n[2]};
  double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  out.n_work = {n[0] / len, n[1] / len, n[2] / len};
  // Gradient: x_hit moves by -(n_y dQy + n_z dQz) / n_x when the line moves.
  Vec3 dq_alpha{rho * sa * kDeg, rho * ca * e2_[1] * kDeg, rho * ca * e2_[2] * kDeg};
  Vec3 dradial_rho{radial[0] * cp.tangent.x, radial[1] * cp.tangent.x, radial[2] * cp.tangent.x};
  Vec3 dq_s{dradial_rho[0] + cp.tangent.y * axis_[0], dradial_rho[1] + cp.tangent.y * axis_[1],
            dradial_rho[2] + cp.tangent.y * axis_[2]};
  auto dx_hit = [&](const Vec3& dq) { return -(n[1] * dq[1] + n[2] * dq[2]) / n[0]; };
  out.d_alpha = dq_alpha[0] - dx_hit(dq_alpha);
  out.d_s = dq_s[0] - dx_hit(dq_s);
  return out;
}

double ContactSearch::plane_distance(double psi) const {
  auto hit = plane_profile_.first_hit(psi, 0);
  if (!hit.found) return std::numeric_limits<double>::quiet_NaN();
  return hit.x + cutter_.outer_radius() - corner_radius_;
}

double ContactSearch::edge_normal_angle(const DiscCutter::Vertex& v, double alpha, const Vec3& n_work) const {
  // The workpiece's inward normal in the frame of the cutter's meridian at alpha: radial, axial
  // (the plane of the profile) and the rest (along the circle).
  const double ca = std::cos(alpha * kDeg), sa = std::sin(alpha * kDeg);
  const Vec3 radial{-ca, sa * e2_[1], sa * e2_[2]}, p{-n_work[0], -n_work[1], -n_work[2]};
  const V2 q{p[0] * radial[0] + p[1] * radial[1] + p[2] * radial[2], p[0] * axis_[0] + p[1] * axis_[1] + p[2] * axis_[2]};
  auto turn = [](V2 a, V2 b) { return std::atan2(cross(a, b), dot(a, b)); };
  // The nearest normal of the fan from `before` to `after` (turning left): q's own direction
  // within it, else the nearer end.
  V2 u = v.before;
  const double sweep = turn(v.before, v.after), at = turn(v.before, q);
  if (norm(q) > 0 && at >= 0 && at <= sweep) {
    u = q / norm(q);
  } else if (dot(q, v.after) > dot(q, v.before)) {
    u = v.after;
  }
  const double cosine = p[0] * (u.x * radial[0] + u.y * axis_[0]) + p[1] * (u.x * radial[1] + u.y * axis_[1]) +
                     p[2] * (u.x * radial[2] + u.y * axis_[2]);
  return std::acos(std::clamp(cosine, -1.0, 1.0)) / kDeg;
}

double ContactSearch::stock(const Contact& pass, double u) const {
  const V2 p = work_.profile.point(u);
  const double twist = work_.twist();
  // Smallest over the helix of the distance to the cutter surface: the largest of its negative.
  auto closeness = [&](double z) {
    double phi = (pass.phase + twist * z) * kDeg;
    double c = std::cos(phi), s = std::sin(phi);
    Vec3 rel{c * p.x - s * p.y - pass.A, s * p.x + c * p.y, z};
    double w = rel[0] * axis_[0] + rel[1] * axis_[1] + rel[2] * axis_[2];
    double rho = std::sqrt(std::max(0.0, rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2] - w * w));
    return -cutter_.signed_distance({rho, w});
  };
  // The helix passes the disc within its radius of the contact's height; 64 samples there, then
  // to 1e-5 mm in z (the distance is flat at its minimum: the error is far below 1e-9 mm).
  const double reach = cutter_.outer_radius(), z0 = pass.work_point[2] - pass.z;
  return -geom::sampled_maximum(closeness, z0 - reach, z0 + reach, 64, 1e-5).value;
}

ContactSearch::Cusp ContactSearch::cusp(const Contact& a, const Contact& b) const {
  const double du = std::remainder(b.u - a.u, work_.profile.period());
  if (std::abs(du) < 1e-9) return {std::max(0.0, std::min(stock(a, a.u), stock(b, a.u))), a.u};
  auto left = [&](double t) {
    double u = a.u + t * du;
    return std::min(stock(a, u), stock(b, u));
  };
  auto top = geom::sampled_maximum(left, 0.0, 1.0, 8);
  return {top.value, a.u + top.at * du};
}

ContactSearch::PassPlan ContactSearch::fewest_passes(const std::vector<Contact>& contacts, double tol) const {
  PassPlan plan;
  if (contacts.empty()) return plan;
  if (!(tol > 0)) throw std::runtime_error("pass tolerance must be > 0 mm");
  std::size_t at = 0;
  plan.passes.push_back(0);
  while (at + 1 < contacts.size()) {
    Cusp reach = cusp(contacts[at], contacts[at + 1]);
    if (reach.height > tol)
      throw std::runtime_error(fmt::format(
          "psi = {:g} and {:g} deg: neighbouring passes leave a cusp of {:.6f} mm (at u = {:.3f} deg), above the "
          "tolerance {:g} mm: make the psi step smaller", contacts[at].psi, contacts[at + 1].psi, reach.height, reach.u, tol));
    std::size_t next = at + 1;
    while (next + 1 < contacts.size()) {
      Cusp c = cusp(contacts[at], contacts[next + 1]);
      if (c.height > tol) break;
      reach = c, ++next;
    }
    plan.passes.push_back(next);
    plan.cusps.push_back(reach);
    at = next;
  }
  return plan;
}

}  // namespace ncurve::helicoid
