#include "tirefem/case/tyre_reader.hpp"

#include "tirefem/case/plausibility_bounds.hpp"
#include "tirefem/case/profile_reader.hpp"
#include "tirefem/case/tread_reader.hpp"
#include "tirefem/case/zone_reader.hpp"
#include "tirefem/tyre/tyre_mesh.hpp"

namespace tirefem::case_reading {

TyreRead read_tyre(TomlFields& f, const toml::node& n, const std::string& path) {
  const toml::table& t = f.table(n, path, {"name", "cord_rubber_rule", "rubber_law", "profile", "plies", "zones",
                                           "interlayer", "tread", "rim_flange"});
  TyreRead r;
  TyreDescription& d = r.tyre;
  if (const toml::node* v = f.get(t, path, "name")) d.name = f.string(*v, join(path, "name"));
  CordRubberRule default_rule = CordRubberRule::halpin_tsai;
  if (const toml::node* v = f.get(t, path, "cord_rubber_rule"))
    default_rule = read_rule(f, *v, join(path, "cord_rubber_rule"));
  if (const toml::node* v = f.get(t, path, "rubber_law"))
    d.rubber_law = f.choice(*v, join(path, "rubber_law"), {"saint_venant_kirchhoff", "neo_hookean"}) == 1
                       ? RubberLaw::neo_hookean
                       : RubberLaw::saint_venant_kirchhoff;
  d.profile = read_profile(f, t, path);
  const std::map<std::string, Ply> plies = read_plies(f, t, path);
  d.zones = read_zones(f, t, path, plies, default_rule);
  r.shear_modulus_given = read_interlayer_and_tread(f, t, path, d);
  if (const toml::node* v = f.get(t, path, "rim_flange")) {
    const std::string fp = join(path, "rim_flange");
    const toml::table& ft = f.table(*v, fp, {"radius", "stiffness"});
    d.rim_flange = RimFlangeDescription{f.req_number(ft, fp, "radius", " (mm)"),
                                        f.req_number(ft, fp, "stiffness", " (N/mm³)")};
  }
  return r;
}

double check_tyre(const FieldChecker& c, const TyreDescription& t, bool rolls) {
  const double length = check_profile(c, t.profile, "tyre.profile.points");
  check_zones(c, t.zones, length, "tyre.zones");
  check_interlayer_and_tread(c, t, length, rolls);
  if (t.rim_flange) {
    c.plausible(t.rim_flange->radius, kFlangeRadius, "tyre.rim_flange.radius");
    c.plausible(t.rim_flange->stiffness, kTreadStiffness, "tyre.rim_flange.stiffness");
  }
  return length;
}

double tyre_outer_radius(const TyreDescription& t) {
  return t.profile.front().y() + t.interlayer_thickness.at(0.0) + tread_height_at(t, 0.0);
}

}  // namespace tirefem::case_reading
