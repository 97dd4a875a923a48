#include "tirefem/forms/winkler_contact_form.hpp"

#include <algorithm>
#include <stdexcept>

#include "tirefem/element/shape_functions.hpp"

namespace tirefem {

std::vector<TreadPoint> make_tread_points(const ShellMesh& mesh, const std::vector<int>& elements,
                                          int quadrature, const std::function<double(double)>& tread_height) {
  const GaussRule rule = gauss_legendre(quadrature);
  std::vector<TreadPoint> points;
  for (int e : elements) {
    const Eigen::Matrix<double, 3, 8> x = mesh.element_reference(e);
    const int iu = e % mesh.u_elements(), jv = e / mesh.u_elements();
    const double u0 = mesh.u_values[iu], u1 = mesh.u_values[iu + 1];
    const double v0 = mesh.v_values[jv], v1 = mesh.v_values[jv + 1];
    for (int i = 0; i < quadrature; ++i) {
      for (int j = 0; j < quadrature; ++j) {
        const double xi = rule.points[i], eta = rule.points[j];
        const BilinearShape sh = bilinear_shape(xi, eta);
        TreadPoint p;
        p.element = e;
        p.pairs = mesh.elements[e];
        p.shape = sh.n;
        p.u = u0 + 0.5 * (1 + xi) * (u1 - u0);
        p.v = v0 + 0.5 * (1 + eta) * (v1 - v0);
        const double hp = tread_height(p.u);
        if (hp < 0) continue;
        p.height = hp;
        const auto outer = x.rightCols<4>();
        const Eigen::Vector3d breaker = outer * sh.n;
        const Eigen::Vector3d a1 = outer * sh.dn_dxi, a2 = outer * sh.dn_deta;
        p.normal = ((outer - x.leftCols<4>()) * sh.n).normalized();
        p.reference = breaker + hp * p.normal;
        p.weight = rule.weights[i] * rule.weights[j] * a1.cross(a2).norm();
        points.push_back(p);
      }
    }
  }
  return points;
}

WinklerContactForm::WinklerContactForm(const ShellMesh& mesh, std::vector<TreadPoint> points,
                                       double stiffness, const RigidSurface& support)
    : mesh_(mesh), points_(std::move(points)), stiffness_(stiffness), support_(support) {
  if (!(stiffness > 0)) throw std::invalid_argument("the tread stiffness kp must be > 0");
  std::stable_sort(points_.begin(), points_.end(),
                   [](const TreadPoint& a, const TreadPoint& b) { return a.element < b.element; });
  for (int k = 0; k < static_cast<int>(points_.size()); ++k)
    if (k == 0 || points_[k].element != points_[k - 1].element) element_begin_.push_back(k);
  element_begin_.push_back(static_cast<int>(points_.size()));
}

std::array<int, 12> tread_point_dofs(const TreadPoint& p) {
  std::array<int, 12> d{};
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c) d[3 * a + c] = outer_dof(p.pairs[a], c);
  return d;
}

Eigen::Vector3d tread_point_position(const TreadPoint& p, const Eigen::VectorXd& u) {
  Eigen::Vector3d x = p.reference;
  for (int a = 0; a < 4; ++a) x += p.shape[a] * u.segment<3>(outer_dof(p.pairs[a], 0));
  return x;
}

void WinklerContactForm::add_pattern(PatternBuilder& pattern) const {
  for (std::size_t k = 0; k + 1 < element_begin_.size(); ++k)
    pattern.add_block(tread_point_dofs(points_[element_begin_[k]]));
}

Eigen::Vector3d WinklerContactForm::position(const TreadPoint& p, const Eigen::VectorXd& u) const {
  return tread_point_position(p, u);
}

bool WinklerContactForm::carries_load(int point, double penetration) const {
  return frozen_.empty() ? penetration > 0 : frozen_[point] != 0;
}

void WinklerContactForm::freeze_region(std::vector<char> region) {
  if (region.size() != points_.size()) throw std::invalid_argument("contact region of the wrong size");
  frozen_ = std::move(region);
}

void WinklerContactForm::assemble(const FormInput& input, SparseSystem& system) const {
  const int groups = static_cast<int>(element_begin_.size()) - 1;
  BlockBatch& batch = system.batch(groups);
#pragma omp parallel for schedule(dynamic, 16)
  for (int k = 0; k < groups; ++k) {
    Eigen::Matrix<double, 12, 1> f = Eigen::Matrix<double, 12, 1>::Zero();
    Eigen::Matrix<double, 12, 12> tangent = Eigen::Matrix<double, 12, 12>::Zero();
    bool any = false;
    for (int q = element_begin_[k]; q < element_begin_[k + 1]; ++q) {
      const TreadPoint& p = points_[q];
      const Penetration g = support_.penetration(position(p, input.displacement), deflection_);
      if (!carries_load(q, g.value)) continue;
      any = true;
      const double kw = stiffness_ * p.weight;
      // Residual ∂/∂u of ½ kp g² w (eqs. 6–11): kp g ∂g/∂x, spread by the shape functions.
      const Eigen::Vector3d point_force = kw * g.value * g.gradient;
      Eigen::Matrix3d point_tangent = kw * g.gradient * g.gradient.transpose();
      if (input.with_tangent && g.value != 0.0) point_tangent += kw * g.value * g.hessian;
      for (int a = 0; a < 4; ++a) {
        f.segment<3>(3 * a) += p.shape[a] * point_force;
        if (!input.with_tangent) continue;
        for (int b = 0; b < 4; ++b)
          tangent.block<3, 3>(3 * a, 3 * b) += p.shape[a] * p.shape[b] * point_tangent;
      }
    }
    if (any) batch.set(k, tread_point_dofs(points_[element_begin_[k]]), f, tangent, input.with_tangent);
  }
  system.add(batch);
}

std::optional<EnergyChange> WinklerContactForm::energy_change(const Eigen::VectorXd& from,
                                                             const Eigen::VectorXd& to, double) const {
  const auto energy = [&](int q, const Eigen::VectorXd& u) {
    const double g = support_.penetration(position(points_[q], u), deflection_).value;
    return carries_load(q, g) ? 0.5 * stiffness_ * points_[q].weight * g * g : 0.0;
  };
  EnergyChange total;
  for (int q = 0; q < static_cast<int>(points_.size()); ++q) {
    const double a = energy(q, from), b = energy(q, to);
    total += {b - a, a + b};
  }
  return total;
}

std::vector<char> WinklerContactForm::region(const Eigen::VectorXd& u) const {
  std::vector<char> r(points_.size());
  for (std::size_t q = 0; q < points_.size(); ++q)
    r[q] = support_.penetration(position(points_[q], u), deflection_).value > 0;
  return r;
}

std::vector<TreadPointState> WinklerContactForm::evaluate(const Eigen::VectorXd& u) const {
  std::vector<TreadPointState> states(points_.size());
  for (std::size_t q = 0; q < points_.size(); ++q) {
    TreadPointState& s = states[q];
    s.position = position(points_[q], u);
    const Penetration g = support_.penetration(s.position, deflection_);
    s.penetration = g.value;
    if (g.value > 0) {
      s.pressure = stiffness_ * g.value;
      s.force = -s.pressure * points_[q].weight * g.gradient;
    }
  }
  return states;
}

}  // namespace tirefem
