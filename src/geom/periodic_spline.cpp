#include "geom/periodic_spline.hpp"

#include <Eigen/Sparse>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ncurve::geom {

PeriodicSpline::PeriodicSpline(const std::vector<std::array<double, 2>>& points) : p_(points) {
  const std::size_t n = points.size();
  if (n < 4) throw std::runtime_error(fmt::format("a closed spline needs at least 4 points, not {}", n));
  s_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = points[i];
    const auto& b = points[(i + 1) % n];
    double h = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (!(h > 0)) throw std::runtime_error(fmt::format("points {} and {} coincide", i + 1, (i + 1) % n + 1));
    s_[i + 1] = s_[i] + h;
  }
  total_ = s_[n];
  p_.push_back(points[0]);
  // h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (slope_i - slope_{i-1}), indices modulo n:
  // symmetric and diagonally dominant, so LDL^T.
  auto h = [&](std::size_t i) { return s_[i + 1] - s_[i]; };
  std::vector<Eigen::Triplet<double>> t;
  Eigen::MatrixXd rhs(static_cast<Eigen::Index>(n), 2);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = (i + n - 1) % n, next = (i + 1) % n;
    const double hp = h(prev), hi = h(i);
    const auto ei = static_cast<int>(i);
    t.emplace_back(ei, ei, 2 * (hp + hi));
    t.emplace_back(ei, static_cast<int>(prev), hp);
    t.emplace_back(ei, static_cast<int>(next), hi);
    for (int c = 0; c < 2; ++c)
      rhs(ei, c) = 6 * ((points[next][c] - points[i][c]) / hi - (points[i][c] - points[prev][c]) / hp);
  }
  Eigen::SparseMatrix<double> a(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  a.setFromTriplets(t.begin(), t.end());  // duplicates (n = 2 neighbours) add up
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success) throw std::runtime_error("the closed spline's system is singular");
  Eigen::MatrixXd m = solver.solve(rhs);
  m_.resize(n + 1);
  for (std::size_t i = 0; i <= n; ++i) m_[i] = {m(static_cast<int>(i % n), 0), m(static_cast<int>(i % n), 1)};
}

void PeriodicSpline::eval(double s, std::array<double, 2>& point, std::array<double, 2>& d1) const {
  s = std::fmod(s, total_);
  if (s < 0) s += total_;
  std::size_t i = static_cast<std::size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin());
  i = std::clamp<std::size_t>(i, 1, s_.size() - 1) - 1;
  const double h = s_[i + 1] - s_[i], a = s_[i + 1] - s, b = s - s_[i];
  for (int c = 0; c < 2; ++c) {
    const double mi = m_[i][c], mj = m_[i + 1][c];
    const double ci = p_[i][c] / h - mi * h / 6, cj = p_[i + 1][c] / h - mj * h / 6;
    point[c] = mi * a * a * a / (6 * h) + mj * b * b * b / (6 * h) + ci * a + cj * b;
    d1[c] = -mi * a * a / (2 * h) + mj * b * b / (2 * h) - ci + cj;
  }
}

}  // namespace ncurve::geom
