#include "tirefem/road/support_surface.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace tirefem {

TravelCoordinate SupportSurface::travel(const Eigen::Vector3d& x, double) const {
  TravelCoordinate t;
  t.value = x.y();
  t.gradient = Eigen::Vector3d::UnitY();
  return t;
}

TravelCoordinate SupportSurface::lateral(const Eigen::Vector3d& x, double) const {
  TravelCoordinate t;
  t.value = x.x();
  t.gradient = Eigen::Vector3d::UnitX();
  return t;
}

Penetration RoadPlane::penetration(const Eigen::Vector3d& x, double deflection) const {
  Penetration p;
  p.value = deflection - x.z();
  p.gradient = Eigen::Vector3d(0, 0, -1);
  return p;
}

double RoadPlane::height(double, double, double deflection) const { return deflection; }

TestDrum::TestDrum(double radius) : radius_(radius) {
  if (!(radius > 0)) throw std::invalid_argument("drum radius must be > 0");
}

Penetration TestDrum::penetration(const Eigen::Vector3d& x, double deflection) const {
  // Radius vector from the drum axis in the (y, z) plane.
  const Eigen::Vector3d d(0.0, x.y(), x.z() - (deflection - radius_));
  const double distance = d.norm();
  const Eigen::Vector3d n = d / distance;  // outward normal of the drum
  Penetration p;
  p.value = radius_ - distance;
  p.gradient = -n;
  // ∂²(−|d|)/∂x² = −(P − n nᵀ)/|d|, P the projector on the (y, z) plane.
  Eigen::Matrix3d projector = Eigen::Matrix3d::Zero();
  projector(1, 1) = projector(2, 2) = 1.0;
  p.hessian = -(projector - n * n.transpose()) / distance;
  return p;
}

TravelCoordinate TestDrum::travel(const Eigen::Vector3d& x, double deflection) const {
  // ξ = R atan2(y, w), w = z − z_axis: the arc length along the drum's surface from its top.
  const double y = x.y(), w = x.z() - (deflection - radius_);
  const double rho2 = y * y + w * w, rho4 = rho2 * rho2;
  TravelCoordinate t;
  t.value = radius_ * std::atan2(y, w);
  t.gradient = Eigen::Vector3d(0.0, radius_ * w / rho2, -radius_ * y / rho2);
  t.hessian(1, 1) = -2.0 * radius_ * y * w / rho4;
  t.hessian(2, 2) = 2.0 * radius_ * y * w / rho4;
  t.hessian(1, 2) = t.hessian(2, 1) = radius_ * (y * y - w * w) / rho4;
  return t;
}

double TestDrum::height(double, double y, double deflection) const {
  const double r2 = radius_ * radius_ - y * y;
  return deflection - radius_ + std::sqrt(std::max(r2, 0.0));
}

PolynomialRoad::PolynomialRoad(std::vector<SupportDescription::Term> terms) : terms_(std::move(terms)) {}

namespace {
// x^k and its first two derivatives.
struct PowerValues {
  double value, first, second;
};
PowerValues power(double x, int k) {
  const double v = k == 0 ? 1.0 : std::pow(x, k);
  const double d1 = k >= 1 ? k * std::pow(x, k - 1) : 0.0;
  const double d2 = k >= 2 ? k * (k - 1) * std::pow(x, k - 2) : 0.0;
  return {v, d1, d2};
}
}  // namespace

Penetration PolynomialRoad::penetration(const Eigen::Vector3d& x, double deflection) const {
  double f = 0, fx = 0, fy = 0, fxx = 0, fyy = 0, fxy = 0;
  for (const auto& t : terms_) {
    const PowerValues px = power(x.x(), t.x_power), py = power(x.y(), t.y_power);
    f += t.coefficient * px.value * py.value;
    fx += t.coefficient * px.first * py.value;
    fy += t.coefficient * px.value * py.first;
    fxx += t.coefficient * px.second * py.value;
    fyy += t.coefficient * px.value * py.second;
    fxy += t.coefficient * px.first * py.first;
  }
  Penetration p;
  p.value = f + deflection - x.z();
  p.gradient = Eigen::Vector3d(fx, fy, -1.0);
  p.hessian << fxx, fxy, 0, fxy, fyy, 0, 0, 0, 0;
  return p;
}

bool PolynomialRoad::depends_on_travel() const {
  for (const auto& t : terms_)
    if (t.y_power > 0 && t.coefficient != 0.0) return true;
  return false;
}

double PolynomialRoad::height(double x, double y, double deflection) const {
  return penetration(Eigen::Vector3d(x, y, 0.0), deflection).value;
}

std::unique_ptr<SupportSurface> make_support(const SupportDescription& d) {
  switch (d.kind) {
    case SupportDescription::Kind::plane: return std::make_unique<RoadPlane>();
    case SupportDescription::Kind::drum: return std::make_unique<TestDrum>(0.5 * d.drum_diameter);
    case SupportDescription::Kind::surface: return std::make_unique<PolynomialRoad>(d.terms);
  }
  throw std::invalid_argument("unknown support kind");
}

const char* support_kind_name(SupportDescription::Kind kind) {
  switch (kind) {
    case SupportDescription::Kind::plane: return "plane";
    case SupportDescription::Kind::drum: return "drum";
    case SupportDescription::Kind::surface: return "surface";
  }
  return "?";
}

std::string support_label(const SupportDescription& support) {
  if (support.kind == SupportDescription::Kind::drum)
    return fmt::format("drum {:g} mm", support.drum_diameter);
  return support_kind_name(support.kind);
}

}  // namespace tirefem
