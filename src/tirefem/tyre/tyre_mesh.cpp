#include "tirefem/tyre/tyre_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "tirefem/mesh/revolution_mesh.hpp"
#include "tirefem/tyre/ply_stiffness.hpp"

namespace tirefem {

std::vector<double> meridional_stations(double length, std::vector<double> breaks, int elements) {
  std::sort(breaks.begin(), breaks.end());
  std::vector<double> ends{0.0};
  const double tiny = 1e-9 * length;
  for (double b : breaks)
    if (b > ends.back() + tiny && b < length - tiny) ends.push_back(b);
  ends.push_back(length);
  const int pieces = static_cast<int>(ends.size()) - 1;
  if (elements < pieces)
    throw std::invalid_argument("tyre mesh: " + std::to_string(elements) + " meridional elements for " +
                                std::to_string(pieces) + " zones; need at least one per zone");
  std::vector<double> ideal(pieces);
  std::vector<int> count(pieces);
  int total = 0;
  for (int k = 0; k < pieces; ++k) {
    ideal[k] = elements * (ends[k + 1] - ends[k]) / length;
    count[k] = std::max(1, static_cast<int>(std::floor(ideal[k])));
    total += count[k];
  }
  while (total < elements) {  // largest remainders first
    int best = 0;
    for (int k = 1; k < pieces; ++k)
      if (ideal[k] - count[k] > ideal[best] - count[best]) best = k;
    ++count[best], ++total;
  }
  while (total > elements) {  // only when the one-per-piece minimum overshot
    int worst = -1;
    for (int k = 0; k < pieces; ++k)
      if (count[k] > 1 && (worst < 0 || ideal[k] - count[k] < ideal[worst] - count[worst])) worst = k;
    --count[worst], --total;
  }
  std::vector<double> s{0.0};
  for (int k = 0; k < pieces; ++k)
    for (int e = 1; e <= count[k]; ++e)
      s.push_back(e == count[k] ? ends[k + 1] : ends[k] + (ends[k + 1] - ends[k]) * e / count[k]);
  return s;
}

std::vector<double> uniform_stations(double length, int elements) {
  if (elements < 1) throw std::invalid_argument("tyre mesh: need at least 1 meridional element");
  std::vector<double> s(elements + 1);
  for (int k = 0; k <= elements; ++k) s[k] = length * k / elements;
  s.back() = length;
  return s;
}

int zone_at(const TyreDescription& tyre, double s) {
  if (tyre.zones.empty()) throw std::invalid_argument("tyre: no zones");
  const double u = std::abs(s);
  for (std::size_t k = 0; k + 1 < tyre.zones.size(); ++k)
    if (u <= tyre.zones[k].s_end) return static_cast<int>(k);
  return static_cast<int>(tyre.zones.size()) - 1;
}

double tread_height_at(const TyreDescription& tyre, double s) {
  const double u = std::abs(s);
  return u <= tyre.tread_end_s ? tyre.tread_height.at(u) : 0.0;
}

TyreMesh build_tyre_mesh(const TyreDescription& tyre, const MeshSettings& settings) {
  if (tyre.zones.empty()) throw std::invalid_argument("tyre mesh: the tyre has no zones");
  if (settings.meridional_elements < 1 || settings.circumferential_elements < 3)
    throw std::invalid_argument("tyre mesh: need at least 1 meridional and 3 circumferential elements");
  const MeridianProfile half(tyre.profile);
  const double length = half.length();

  std::vector<double> stations;
  if (settings.meridional_grading == MeshSettings::MeridionalGrading::uniform_arc_length) {
    stations = uniform_stations(length, settings.meridional_elements);
  } else {
    // Zone ends must be element edges; the tread edge too, unless it would make a sliver element or there
    // are too few elements for it.
    std::vector<double> breaks;
    for (std::size_t k = 0; k + 1 < tyre.zones.size(); ++k) breaks.push_back(tyre.zones[k].s_end);
    const double min_gap = 0.5 * length / settings.meridional_elements;
    const bool tread_break = tyre.tread_end_s > min_gap && tyre.tread_end_s < length - min_gap &&
                             std::none_of(breaks.begin(), breaks.end(),
                                          [&](double b) { return std::abs(b - tyre.tread_end_s) < min_gap; }) &&
                             settings.meridional_elements >= static_cast<int>(breaks.size()) + 2;
    if (tread_break) breaks.push_back(tyre.tread_end_s);
    stations = meridional_stations(length, breaks, settings.meridional_elements);
  }

  TyreMesh result;
  result.half_model = settings.half_model;
  result.rim_flange = tyre.rim_flange;
  result.meridional_grading = settings.meridional_grading;
  result.profile = settings.half_model ? half : half.mirrored();
  std::vector<double> s_values;
  if (settings.half_model) {
    s_values = stations;
  } else {
    for (auto it = stations.rbegin(); it != stations.rend(); ++it) s_values.push_back(-*it);
    s_values.insert(s_values.end(), stations.begin() + 1, stations.end());
  }

  result.axis_z = half.point(0.0).y() + tyre.interlayer_thickness.at(0.0) + tread_height_at(tyre, 0.0);

  RevolutionMeshSpec spec;
  spec.meridian = result.profile.meridian();
  spec.s_values = s_values;
  spec.phi_values =
      circumferential_stations(settings.circumferential_elements, settings.circumferential_refinement);
  spec.closed = true;
  spec.axis_z = result.axis_z;
  spec.outer_offset = [&tyre](double s) { return tyre.interlayer_thickness.at(std::abs(s)); };
  result.mesh = build_revolution_mesh(spec);

  std::vector<ElementSection> zone_sections;
  for (const Zone& z : tyre.zones) {
    ElementSection sec;
    sec.inner_face = face_stiffness(z.inner);
    sec.outer_face = face_stiffness(z.outer);
    sec.inner_face_bending = z.inner.bending_stiffness;
    sec.outer_face_bending = z.outer.bending_stiffness;
    sec.inner_face_in_plane_bending = z.inner.in_plane_bending_stiffness;
    sec.outer_face_in_plane_bending = z.outer.in_plane_bending_stiffness;
    sec.inner_cords = face_cord_softening(z.inner);
    sec.outer_cords = face_cord_softening(z.outer);
    if (tyre.rubber_law == RubberLaw::neo_hookean) {
      sec.inner_rubber = {z.inner.rubber_shear_stiffness, z.inner.rubber_stiffness};
      sec.outer_rubber = {z.outer.rubber_shear_stiffness, z.outer.rubber_stiffness};
    }
    sec.core_shear_modulus = z.core_shear_modulus;
    sec.core_normal_modulus = z.core_normal_modulus;
    sec.enhanced_faces = settings.faces == MeshSettings::Faces::enhanced;
    zone_sections.push_back(sec);
  }

  const ShellMesh& mesh = result.mesh;
  const int ne = mesh.element_count();
  result.sections.resize(ne);
  result.element_zone.resize(ne);
  result.element_s.resize(ne);
  result.pressure_elements.resize(ne);
  for (int j = 0; j < mesh.v_elements(); ++j)
    for (int i = 0; i < mesh.u_elements(); ++i) {
      const int e = mesh.element_index(i, j);
      const double s = 0.5 * (mesh.u_values[i] + mesh.u_values[i + 1]);
      const int zone = zone_at(tyre, s);
      result.element_s[e] = s;
      result.element_zone[e] = zone;
      result.sections[e] = zone_sections[zone];
      result.pressure_elements[e] = e;
    }

  std::vector<int>& fixed = result.fixed_dofs;
  auto fix_pairs = [&](GridEdge edge) {
    for (int p : mesh.edge_pairs(edge))
      for (int c = 0; c < 6; ++c) fixed.push_back(6 * p + c);
  };
  fix_pairs(GridEdge::u_max);
  if (settings.half_model) {
    for (int p : mesh.edge_pairs(GridEdge::u_min)) {
      fixed.push_back(inner_dof(p, 0));
      fixed.push_back(outer_dof(p, 0));
    }
  } else {
    fix_pairs(GridEdge::u_min);
  }
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
  return result;
}

bool mirror_symmetric(const TyreMesh& tm) {
  if (tm.half_model) return false;
  const auto orthotropic = [](const MembraneStiffness& a) {
    const double scale = a.cwiseAbs().maxCoeff();
    return std::abs(a(0, 2)) <= 1e-10 * scale && std::abs(a(1, 2)) <= 1e-10 * scale &&
           std::abs(a(2, 0)) <= 1e-10 * scale && std::abs(a(2, 1)) <= 1e-10 * scale;
  };
  for (const ElementSection& s : tm.sections)
    if (!orthotropic(s.inner_face) || !orthotropic(s.outer_face)) return false;
  return true;
}

}  // namespace tirefem
