#include "tirefem/tyre/meridian_profile.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tirefem {

// Cubic spline X(t) through the points, t the cumulative chord length; each component has its own second
// derivatives M at the knots. Arc length s(t) is tabulated at sub-knots (Gauss quadrature) and inverted
// by Newton's method, so s is the true arc length to rounding.
struct MeridianProfile::Spline {
  std::vector<Eigen::Vector2d> points;
  std::vector<double> t;                 // knots
  std::vector<Eigen::Vector2d> m;        // second derivatives at the knots
  std::vector<double> table_t, table_s;  // arc-length table
  std::vector<double> knot_s;            // arc length at each knot
  double length = 0.0;

  int segment(double tq) const {
    const auto it = std::upper_bound(t.begin(), t.end(), tq);
    const int i = static_cast<int>(it - t.begin()) - 1;
    return std::clamp(i, 0, static_cast<int>(t.size()) - 2);
  }
  Eigen::Vector2d value(double tq) const {
    const int i = segment(tq);
    const double h = t[i + 1] - t[i], a = (t[i + 1] - tq) / h, b = (tq - t[i]) / h;
    return a * points[i] + b * points[i + 1] +
           ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6.0;
  }
  Eigen::Vector2d first(double tq) const {
    const int i = segment(tq);
    const double h = t[i + 1] - t[i], a = (t[i + 1] - tq) / h, b = (tq - t[i]) / h;
    return (points[i + 1] - points[i]) / h - (3 * a * a - 1) / 6.0 * h * m[i] +
           (3 * b * b - 1) / 6.0 * h * m[i + 1];
  }
  Eigen::Vector2d second(double tq) const {
    const int i = segment(tq);
    const double h = t[i + 1] - t[i], a = (t[i + 1] - tq) / h, b = (tq - t[i]) / h;
    return a * m[i] + b * m[i + 1];
  }
  // ∫ |X'| dt over [t0, t1] within one segment (5-point Gauss–Legendre; the integrand is smooth there).
  double arc(double t0, double t1) const {
    static constexpr std::array<double, 5> x{0.0, -0.5384693101056831, 0.5384693101056831,
                                             -0.9061798459386640, 0.9061798459386640};
    static constexpr std::array<double, 5> w{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                             0.2369268850561891, 0.2369268850561891};
    const double c = 0.5 * (t0 + t1), r = 0.5 * (t1 - t0);
    double sum = 0.0;
    for (int k = 0; k < 5; ++k) sum += w[k] * first(c + r * x[k]).norm();
    return sum * r;
  }
  double parameter_at(double s) const {
    s = std::clamp(s, 0.0, length);
    const auto it = std::upper_bound(table_s.begin(), table_s.end(), s);
    const int j =
        std::clamp(static_cast<int>(it - table_s.begin()) - 1, 0, static_cast<int>(table_s.size()) - 2);
    const double t0 = table_t[j], t1 = table_t[j + 1], s0 = table_s[j], s1 = table_s[j + 1];
    double tq = t0 + (s - s0) / (s1 - s0) * (t1 - t0);
    for (int iter = 0; iter < 8; ++iter) {
      const double f = s0 + arc(t0, tq) - s;
      tq = std::clamp(tq - f / first(tq).norm(), t0, t1);
      if (std::abs(f) < 1e-14 * (1.0 + length)) break;
    }
    return tq;
  }
};

namespace {

// Second derivatives of one component: natural (y'' = 0) or clamped (y' = slope) at the first knot,
// not-a-knot at the last (natural with fewer than four knots).
Eigen::VectorXd spline_moments(const std::vector<double>& t, const Eigen::VectorXd& y, bool clamp_start,
                               double slope) {
  const int n = static_cast<int>(t.size());
  std::vector<Eigen::Triplet<double>> a;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  auto h = [&](int i) { return t[i + 1] - t[i]; };
  if (clamp_start) {
    a.emplace_back(0, 0, 2 * h(0));
    a.emplace_back(0, 1, h(0));
    rhs[0] = 6.0 * ((y[1] - y[0]) / h(0) - slope);
  } else {
    a.emplace_back(0, 0, 1.0);
  }
  for (int i = 1; i + 1 < n; ++i) {
    a.emplace_back(i, i - 1, h(i - 1));
    a.emplace_back(i, i, 2 * (h(i - 1) + h(i)));
    a.emplace_back(i, i + 1, h(i));
    rhs[i] = 6.0 * ((y[i + 1] - y[i]) / h(i) - (y[i] - y[i - 1]) / h(i - 1));
  }
  if (n >= 4) {
    a.emplace_back(n - 1, n - 1, h(n - 3));
    a.emplace_back(n - 1, n - 2, -(h(n - 3) + h(n - 2)));
    a.emplace_back(n - 1, n - 3, h(n - 2));
  } else {
    a.emplace_back(n - 1, n - 1, 1.0);
  }
  Eigen::SparseMatrix<double> mat(n, n);
  mat.setFromTriplets(a.begin(), a.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(mat);
  if (lu.info() != Eigen::Success) throw std::invalid_argument("meridian profile: spline system is singular");
  return lu.solve(rhs);
}

}  // namespace

MeridianProfile::MeridianProfile(std::vector<Eigen::Vector2d> points) {
  if (points.size() < 2) throw std::invalid_argument("meridian profile: need at least two points");
  if (std::abs(points.front().x()) > 1e-9)
    throw std::invalid_argument("meridian profile: the first point must be on the equator, x = 0 (got x = " +
                                std::to_string(points.front().x()) + ")");
  auto sp = std::make_shared<Spline>();
  const int n = static_cast<int>(points.size());
  sp->t.assign(n, 0.0);
  for (int i = 1; i < n; ++i) {
    const double chord = (points[i] - points[i - 1]).norm();
    if (!(chord > 1e-9))
      throw std::invalid_argument("meridian profile: points " + std::to_string(i - 1) + " and " +
                                  std::to_string(i) + " coincide");
    sp->t[i] = sp->t[i - 1] + chord;
  }
  Eigen::VectorXd xs(n), rs(n);
  for (int i = 0; i < n; ++i) xs[i] = points[i].x(), rs[i] = points[i].y();
  // Symmetry at the equator: x odd in s (x'' = 0), r even in s (r' = 0).
  const Eigen::VectorXd mx = spline_moments(sp->t, xs, false, 0.0);
  const Eigen::VectorXd mr = spline_moments(sp->t, rs, true, 0.0);
  sp->m.resize(n);
  for (int i = 0; i < n; ++i) sp->m[i] = {mx[i], mr[i]};
  sp->points = std::move(points);

  constexpr int kSub = 8;
  sp->table_t.push_back(0.0);
  sp->table_s.push_back(0.0);
  sp->knot_s.push_back(0.0);
  for (int i = 0; i + 1 < n; ++i) {
    for (int k = 1; k <= kSub; ++k) {
      const double ta = sp->t[i] + (sp->t[i + 1] - sp->t[i]) * (k - 1) / kSub;
      const double tb = k == kSub ? sp->t[i + 1] : sp->t[i] + (sp->t[i + 1] - sp->t[i]) * k / kSub;
      sp->table_t.push_back(tb);
      sp->table_s.push_back(sp->table_s.back() + sp->arc(ta, tb));
    }
    sp->knot_s.push_back(sp->table_s.back());
  }
  sp->length = sp->table_s.back();
  spline_ = std::move(sp);
}

double MeridianProfile::half_length() const { return spline_ ? spline_->length : 0.0; }

namespace {

// Maps s to the half profile's arc length u = |s| (checking the range); `flip` when s < 0 (mirror side).
struct HalfParameter {
  double u;
  bool flip;
};

HalfParameter half_parameter(double s, double s_begin, double s_end) {
  const double slack = 1e-9 * (1.0 + s_end - s_begin);
  if (!(s >= s_begin - slack && s <= s_end + slack))
    throw std::out_of_range("meridian profile: s = " + std::to_string(s) + " outside [" +
                            std::to_string(s_begin) + ", " + std::to_string(s_end) + "]");
  s = std::clamp(s, s_begin, s_end);
  return {std::abs(s), s < 0.0};
}

}  // namespace

Eigen::Vector2d MeridianProfile::point(double s) const {
  if (!spline_) throw std::logic_error("meridian profile: empty");
  const HalfParameter h = half_parameter(s, s_begin(), s_end());
  Eigen::Vector2d p = spline_->value(spline_->parameter_at(h.u));
  if (h.flip) p.x() = -p.x();
  return p;
}

Eigen::Vector2d MeridianProfile::tangent(double s) const {
  if (!spline_) throw std::logic_error("meridian profile: empty");
  const HalfParameter h = half_parameter(s, s_begin(), s_end());
  Eigen::Vector2d d = spline_->first(spline_->parameter_at(h.u)).normalized();
  if (h.flip) d.y() = -d.y();  // d/ds of (−x(−s), r(−s)) = (x'(u), −r'(u))
  return d;
}

Eigen::Vector2d MeridianProfile::normal(double s) const {
  const Eigen::Vector2d d = tangent(s);
  return {-d.y(), d.x()};
}

double MeridianProfile::curvature(double s) const {
  if (!spline_) throw std::logic_error("meridian profile: empty");
  const HalfParameter h = half_parameter(s, s_begin(), s_end());
  const double tq = spline_->parameter_at(h.u);
  const Eigen::Vector2d d1 = spline_->first(tq), d2 = spline_->second(tq);
  // κ = (r' x'' − x' r'') / |X'|³; unchanged by the mirror image (both the tangent and the normal flip x).
  return (d1.y() * d2.x() - d1.x() * d2.y()) / std::pow(d1.norm(), 3);
}

Meridian MeridianProfile::meridian() const {
  const MeridianProfile copy = *this;
  return Meridian{[copy](double s) { return copy.point(s); }, [copy](double s) { return copy.tangent(s); }};
}

MeridianProfile MeridianProfile::mirrored() const {
  if (mirrored_) throw std::logic_error("meridian profile: already mirrored");
  MeridianProfile m = *this;
  m.mirrored_ = true;
  return m;
}

const std::vector<Eigen::Vector2d>& MeridianProfile::points() const {
  static const std::vector<Eigen::Vector2d> none;
  return spline_ ? spline_->points : none;
}

const std::vector<double>& MeridianProfile::point_arc_lengths() const {
  static const std::vector<double> none;
  return spline_ ? spline_->knot_s : none;
}

}  // namespace tirefem
