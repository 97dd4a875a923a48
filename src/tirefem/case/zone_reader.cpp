#include "tirefem/case/zone_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "tirefem/case/case_reader.hpp"
#include "tirefem/element/section.hpp"

namespace tirefem::case_reading {

namespace {

Ply read_ply(TomlFields& f, const toml::node& n, const std::string& path, std::string name) {
  const toml::table& t = f.table(n, path,
                                 {"description", "cord_modulus", "cord_area", "ends_per_mm", "angle",
                                  "thickness", "rubber_modulus", "rubber_poisson", "cord_poisson",
                                  "cord_compression_modulus"});
  if (const toml::node* d = f.get(t, path, "description")) f.string(*d, join(path, "description"));
  Ply p;
  p.name = std::move(name);
  p.cord_modulus = f.req_number(t, path, "cord_modulus", " (MPa)");
  p.cord_area = f.req_number(t, path, "cord_area", " (mm², one cord)");
  p.ends_per_mm = f.req_number(t, path, "ends_per_mm", " (cords per mm)");
  p.angle_deg = f.req_number(t, path, "angle", " (degrees to the circumferential direction, 90 = radial)");
  p.thickness = f.req_number(t, path, "thickness", " (mm)");
  p.rubber_modulus = f.req_number(t, path, "rubber_modulus", " (MPa)");
  f.opt_number(t, path, "rubber_poisson", p.rubber_poisson, "");
  f.opt_number(t, path, "cord_poisson", p.cord_poisson, "");
  if (f.get(t, path, "cord_compression_modulus"))
    p.cord_compression_modulus = f.req_number(t, path, "cord_compression_modulus", " (MPa)");
  check_ply(f.checker(), p, path);
  return p;
}

// rubber = { E, nu, thickness } or an array of them: their isotropic membrane stiffness, summed, into the
// face's rubber share (and Σ μ t).
void read_rubber_layers(TomlFields& f, const toml::node& r, const std::string& rp, FaceLayup& face) {
  std::vector<std::pair<const toml::node*, std::string>> layers;
  if (r.is_array()) {
    const toml::array& a = f.array(r, rp, "rubber layers { E, nu, thickness }");
    for (std::size_t i = 0; i < a.size(); ++i) layers.emplace_back(&a[i], index(rp, i));
  } else {
    layers.emplace_back(&r, rp);
  }
  for (const auto& [node, lp] : layers) {
    const toml::table& lt = f.table(*node, lp, {"E", "nu", "thickness"});
    const double e = f.req_number(lt, lp, "E", " (MPa)");
    double nu = 0.49;
    f.opt_number(lt, lp, "nu", nu, "");
    const double h = f.req_number(lt, lp, "thickness", " (mm)");
    f.checker().plausible(e, kModulus, join(lp, "E"));
    f.checker().in_range(nu, 0.0, 0.5, join(lp, "nu"));
    f.checker().plausible(h, kThickness, join(lp, "thickness"));
    face.rubber_stiffness += isotropic_membrane(e, nu, h);
    face.rubber_shear_stiffness += e / (2.0 * (1.0 + nu)) * h;
  }
}

Eigen::Matrix3d read_stiffness(TomlFields& f, const toml::node& s, const std::string& sp) {
  const toml::array& rows = f.array(s, sp, "3 rows of 3 numbers (N/mm)");
  if (rows.size() != 3) f.fail(sp, fmt::format("must have 3 rows of 3 numbers (got {} rows)", rows.size()));
  Eigen::Matrix3d a;
  for (int i = 0; i < 3; ++i) {
    const std::vector<double> row = f.numbers(rows[i], index(sp, i), " (N/mm)");
    if (row.size() != 3) f.fail(index(sp, i), fmt::format("must have 3 numbers (got {})", row.size()));
    for (int j = 0; j < 3; ++j) a(i, j) = row[j];
  }
  check_face_stiffness(f.checker(), a, sp);
  return a;
}

FaceLayup read_face(TomlFields& f, const toml::node& n, const std::string& path,
                    const std::map<std::string, Ply>& plies, CordRubberRule default_rule) {
  const toml::table& t =
      f.table(n, path, {"plies", "rubber", "stiffness", "rule", "bending_stiffness", "in_plane_bending_stiffness"});
  FaceLayup face;
  face.rule = default_rule;
  if (const toml::node* r = f.get(t, path, "rule")) face.rule = read_rule(f, *r, join(path, "rule"));
  if (const toml::node* pl = f.get(t, path, "plies")) {
    const std::string pp = join(path, "plies");
    const toml::array& a = f.array(*pl, pp, "ply names or ply tables");
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (a[i].is_table()) {
        face.plies.push_back(read_ply(f, a[i], index(pp, i), index(pp, i)));
        continue;
      }
      const std::string name = f.string(a[i], index(pp, i));
      const auto it = plies.find(name);
      if (it == plies.end()) {
        std::string known;
        for (const auto& [k, v] : plies) known += (known.empty() ? "" : ", ") + k;
        f.fail(index(pp, i), fmt::format("unknown ply \"{}\" (defined in [tyre.plies]: {})", name,
                                         known.empty() ? "none" : known));
      }
      face.plies.push_back(it->second);
    }
  }
  Eigen::Matrix3d direct = Eigen::Matrix3d::Zero();
  bool has_direct = false;
  if (const toml::node* r = f.get(t, path, "rubber")) {
    read_rubber_layers(f, *r, join(path, "rubber"), face);
    direct += face.rubber_stiffness;
    has_direct = true;
  }
  if (const toml::node* s = f.get(t, path, "stiffness")) {
    direct += read_stiffness(f, *s, join(path, "stiffness"));
    has_direct = true;
  }
  if (has_direct) face.direct_stiffness = direct;
  if (face.plies.empty() && !has_direct) f.fail(path, "a face needs at least one of plies, rubber or stiffness");
  for (const auto& [key, target] : {std::pair{"bending_stiffness", &face.bending_stiffness},
                                     std::pair{"in_plane_bending_stiffness", &face.in_plane_bending_stiffness}}) {
    const toml::node* b = f.get(t, path, key);
    if (!b) continue;
    const std::string bp = join(path, key);
    const std::vector<double> d = f.numbers(*b, bp, " (N·mm)");
    if (d.size() != 2) f.fail(bp, fmt::format("must be [meridional, circumferential] (got {} numbers)", d.size()));
    *target = {d[0], d[1]};
  }
  return face;
}

}  // namespace

CordRubberRule read_rule(TomlFields& f, const toml::node& n, const std::string& path) {
  const std::string s = f.string(n, path);
  if (s == "halpin_tsai") return CordRubberRule::halpin_tsai;
  if (s == "gough_tangorra") return CordRubberRule::gough_tangorra;
  f.fail(path, fmt::format("must be \"halpin_tsai\" or \"gough_tangorra\" (got \"{}\")", s));
}

std::map<std::string, Ply> read_plies(TomlFields& f, const toml::table& tyre, const std::string& tyre_path) {
  std::map<std::string, Ply> plies;
  if (const toml::node* pl = f.get(tyre, tyre_path, "plies")) {
    const std::string plp = join(tyre_path, "plies");
    f.mark(plp, pl->source().begin);
    const toml::table* pt = pl->as_table();
    if (!pt) f.fail(plp, fmt::format("must be a table of named plies (got {})", type_name(pl->type())));
    for (auto&& [k, v] : *pt) {
      const std::string name(k.str());
      plies.emplace(name, read_ply(f, v, join(plp, name), name));
    }
  }
  return plies;
}

std::vector<Zone> read_zones(TomlFields& f, const toml::table& tyre, const std::string& tyre_path,
                             const std::map<std::string, Ply>& plies, CordRubberRule default_rule) {
  const std::string zp = join(tyre_path, "zones");
  const toml::array& zones =
      f.array(f.need(tyre, tyre_path, "zones", "an array of tables [[tyre.zones]]"), zp, "tables [[tyre.zones]]");
  std::vector<Zone> result;
  for (std::size_t k = 0; k < zones.size(); ++k) {
    const std::string p = index(zp, k);
    const toml::table& zt =
        f.table(zones[k], p, {"name", "s_end", "inner", "outer", "core_shear_modulus", "core_normal_modulus"});
    Zone z;
    z.name = fmt::format("zone {}", k);
    if (const toml::node* v = f.get(zt, p, "name")) z.name = f.string(*v, join(p, "name"));
    z.s_end = f.req_number(zt, p, "s_end", " (mm of arc length from the equator)");
    z.inner = read_face(f, f.need(zt, p, "inner", "a face table { plies = [...] }"), join(p, "inner"), plies,
                        default_rule);
    z.outer = read_face(f, f.need(zt, p, "outer", "a face table { plies, rubber or stiffness }"),
                        join(p, "outer"), plies, default_rule);
    z.core_shear_modulus = f.req_number(zt, p, "core_shear_modulus", " (MPa)");
    z.core_normal_modulus = f.req_number(zt, p, "core_normal_modulus", " (MPa)");
    result.push_back(std::move(z));
  }
  return result;
}

void check_ply(const FieldChecker& c, const Ply& p, const std::string& path) {
  c.plausible(p.cord_modulus, kModulus, join(path, "cord_modulus"));
  c.positive(p.cord_area, join(path, "cord_area"));
  c.positive(p.ends_per_mm, join(path, "ends_per_mm"));
  c.in_range(p.angle_deg, -90.0, 90.0, join(path, "angle"));
  c.plausible(p.thickness, kThickness, join(path, "thickness"));
  c.plausible(p.rubber_modulus, kModulus, join(path, "rubber_modulus"));
  c.in_range(p.rubber_poisson, 0.0, 0.5, join(path, "rubber_poisson"));
  c.in_range(p.cord_poisson, 0.0, 0.5, join(path, "cord_poisson"));
  if (p.cord_compression_modulus)
    c.in_range(*p.cord_compression_modulus, 0.0, p.cord_modulus, join(path, "cord_compression_modulus"));
  const double vc = p.cord_area * p.ends_per_mm / p.thickness;
  if (!(vc < 1.0))
    c.fail(path, fmt::format("cord volume fraction cord_area × ends_per_mm / thickness must be < 1 (got {})", vc));
}

void check_face_stiffness(const FieldChecker& c, const Eigen::Matrix3d& a, const std::string& path) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c.finite(a(i, j), index(index(path, i), j));
  const double tol = 1e-9 * a.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(a(i, j) - a(j, i)) > tol)
        c.fail(path, fmt::format("must be symmetric (A[{}][{}] = {} but A[{}][{}] = {})", i, j, a(i, j), j, i,
                                 a(j, i)));
  if (a.llt().info() != Eigen::Success || !(a.diagonal().minCoeff() > 0))
    c.fail(path, "must be positive definite (N/mm, Voigt order [11, 22, 12])");
  for (int i = 0; i < 3; ++i)
    if (!(a(i, i) <= kMaxFaceStiffness))
      c.fail(index(index(path, i), i),
             fmt::format("must be ≤ {:g} N/mm (the plausibility bound for any real tyre; got {:g})",
                         kMaxFaceStiffness, a(i, i)));
}

void check_face(const FieldChecker& c, const FaceLayup& f, const std::string& path) {
  if (f.plies.empty() && !f.direct_stiffness) c.fail(path, "a face needs at least one of plies, rubber or stiffness");
  for (std::size_t i = 0; i < f.plies.size(); ++i) check_ply(c, f.plies[i], index(join(path, "plies"), i));
  if (f.direct_stiffness) check_face_stiffness(c, *f.direct_stiffness, join(path, "stiffness"));
  for (int i = 0; i < 2; ++i) {
    c.plausible(f.bending_stiffness[i], kFaceBendingStiffness, index(join(path, "bending_stiffness"), i));
    c.plausible(f.in_plane_bending_stiffness[i], kFaceBendingStiffness,
                index(join(path, "in_plane_bending_stiffness"), i));
  }
}

void check_zones(const FieldChecker& c, const std::vector<Zone>& zones, double length, const std::string& path) {
  if (zones.empty()) c.fail(path, "at least one zone is needed");
  double previous = 0.0;
  for (std::size_t k = 0; k < zones.size(); ++k) {
    const Zone& z = zones[k];
    const std::string p = index(path, k);
    c.finite(z.s_end, join(p, "s_end"));
    if (!(z.s_end > previous))
      c.fail(join(p, "s_end"),
             k == 0 ? fmt::format("must be > 0 (got {})", z.s_end)
                    : fmt::format("must be greater than the previous zone's s_end = {} (got {})", previous, z.s_end));
    previous = z.s_end;
    check_face(c, z.inner, join(p, "inner"));
    check_face(c, z.outer, join(p, "outer"));
    c.plausible(z.core_shear_modulus, kModulus, join(p, "core_shear_modulus"));
    c.plausible(z.core_normal_modulus, kModulus, join(p, "core_normal_modulus"));
  }
  if (std::abs(previous - length) > kZoneEndTolerance)
    c.fail(join(index(path, zones.size() - 1), "s_end"),
           fmt::format("the last zone must end at the bead, s = {:.3f} mm, the profile's arc length (within "
                       "{} mm; got {})",
                       length, kZoneEndTolerance, previous));
}

}  // namespace tirefem::case_reading
