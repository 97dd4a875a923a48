#include "tirefem/case/settings_reader.hpp"

#include <fmt/format.h>

namespace tirefem::case_reading {

InflationSettings read_inflation(TomlFields& f, const toml::node& n, const std::string& path) {
  const toml::table& m =
      f.table(n, path, {"enabled", "pressure", "linear", "max_newton_iterations", "residual_tolerance"});
  InflationSettings s;
  f.opt_bool(m, path, "enabled", s.enabled);
  f.opt_number(m, path, "pressure", s.pressure, " (MPa)");
  f.opt_bool(m, path, "linear", s.linear);
  f.opt_integer(m, path, "max_newton_iterations", s.max_newton_iterations);
  f.opt_number(m, path, "residual_tolerance", s.residual_tolerance, "");
  return s;
}

ContactSettings read_contact(TomlFields& f, const toml::node& n, const std::string& path) {
  const toml::table& t = f.table(n, path,
                                 {"quadrature", "iteration", "max_contact_iterations", "region_tolerance",
                                  "max_newton_iterations", "residual_tolerance", "provisional_tolerance",
                                  "reuse_factorizations", "equilibrium", "max_state_iterations"});
  ContactSettings s;
  f.opt_integer(t, path, "quadrature", s.quadrature);
  if (const toml::node* v = f.get(t, path, "iteration"))
    s.iteration = static_cast<ContactSettings::Iteration>(
        f.choice(*v, join(path, "iteration"), {"two_level", "single_loop"}));  // enum order
  f.opt_integer(t, path, "max_contact_iterations", s.max_contact_iterations);
  f.opt_integer(t, path, "region_tolerance", s.region_tolerance);
  f.opt_integer(t, path, "max_newton_iterations", s.max_newton_iterations);
  f.opt_integer(t, path, "max_state_iterations", s.max_state_iterations);
  f.opt_number(t, path, "residual_tolerance", s.residual_tolerance, "");
  f.opt_number(t, path, "provisional_tolerance", s.provisional_tolerance, "");
  f.opt_bool(t, path, "reuse_factorizations", s.reuse_factorizations);
  if (const toml::node* v = f.get(t, path, "equilibrium"))
    s.equilibrium = static_cast<ContactSettings::Equilibrium>(
        f.choice(*v, join(path, "equilibrium"), {"nearest", "stable"}));  // enum order
  return s;
}

void check_inflation(const FieldChecker& c, const InflationSettings& s, const std::string& path) {
  const std::string pp = join(path, "pressure");
  if (s.enabled) c.positive(s.pressure, pp);
  c.plausible(s.pressure, kPressure, pp);
  if (s.max_newton_iterations < 1)
    c.fail(join(path, "max_newton_iterations"), fmt::format("must be ≥ 1 (got {})", s.max_newton_iterations));
  if (s.max_newton_iterations > kMaxIterations)
    c.fail(join(path, "max_newton_iterations"), fmt::format("must be ≤ {} (got {})", kMaxIterations, s.max_newton_iterations));
  c.positive(s.residual_tolerance, join(path, "residual_tolerance"));
}

void check_contact(const FieldChecker& c, const ContactSettings& s, const std::string& path) {
  c.int_range(s.quadrature, 1, kMaxQuadrature, join(path, "quadrature"));
  c.at_least(s.max_contact_iterations, 1, join(path, "max_contact_iterations"));
  c.at_most(s.max_contact_iterations, kMaxIterations, join(path, "max_contact_iterations"));
  c.at_least(s.region_tolerance, 0, join(path, "region_tolerance"));
  c.at_least(s.max_newton_iterations, 1, join(path, "max_newton_iterations"));
  c.at_most(s.max_newton_iterations, kMaxIterations, join(path, "max_newton_iterations"));
  c.at_least(s.max_state_iterations, 1, join(path, "max_state_iterations"));
  c.at_most(s.max_state_iterations, 100 * kMaxIterations, join(path, "max_state_iterations"));
  c.positive(s.residual_tolerance, join(path, "residual_tolerance"));
  c.positive(s.provisional_tolerance, join(path, "provisional_tolerance"));
}

}  // namespace tirefem::case_reading
