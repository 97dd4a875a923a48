#include "tirefem/case/mesh_reader.hpp"

#include <fmt/format.h>

#include "tirefem/case/mesh_size_estimate.hpp"

namespace tirefem::case_reading {

MeshSettings read_mesh(TomlFields& f, const toml::node& n, const std::string& path, MeshSettings m) {
  const toml::table& t = f.table(
      n, path,
      {"circumferential_elements", "meridional_elements", "half_model", "circumferential_refinement",
       "meridional_grading", "faces"});
  f.opt_integer(t, path, "circumferential_elements", m.circumferential_elements);
  f.opt_integer(t, path, "meridional_elements", m.meridional_elements);
  f.opt_bool(t, path, "half_model", m.half_model);
  f.opt_number(t, path, "circumferential_refinement", m.circumferential_refinement, "");
  if (const toml::node* v = f.get(t, path, "meridional_grading"))
    m.meridional_grading = f.choice(*v, join(path, "meridional_grading"), {"zones", "uniform_arc_length"}) == 1
                               ? MeshSettings::MeridionalGrading::uniform_arc_length
                               : MeshSettings::MeridionalGrading::zones;
  if (const toml::node* v = f.get(t, path, "faces"))
    m.faces = f.choice(*v, join(path, "faces"), {"compatible", "enhanced"}) == 1 ? MeshSettings::Faces::enhanced
                                                                                 : MeshSettings::Faces::compatible;
  return m;
}

void check_mesh(const FieldChecker& c, const MeshSettings& m, const std::string& path, std::size_t zones) {
  const std::string cp = join(path, "circumferential_elements"), mp = join(path, "meridional_elements");
  if (m.circumferential_elements < 3)
    c.fail(cp, fmt::format("must be ≥ 3 (got {})", m.circumferential_elements));
  // Graded by zones, each zone needs an element; uniform, a zone may fall between element centres.
  if (m.meridional_grading == MeshSettings::MeridionalGrading::zones && m.meridional_elements < static_cast<int>(zones))
    c.fail(mp, fmt::format("must be ≥ the number of zones, {} (got {}), when meridional_grading = \"zones\"",
                           zones, m.meridional_elements));
  if (m.meridional_elements < 1) c.fail(mp, fmt::format("must be ≥ 1 (got {})", m.meridional_elements));
  const std::string rp = join(path, "circumferential_refinement");
  c.finite(m.circumferential_refinement, rp);
  if (!(m.circumferential_refinement >= 1.0))
    c.fail(rp, fmt::format("must be ≥ 1 (got {})", m.circumferential_refinement));

  // What the machine can hold, naming the count further beyond the paper's 120 × 46.
  const MeshSizeEstimate e = estimate_mesh_size(m);
  const double memory = physical_memory_bytes();
  constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
  if (memory > 0 && e.bytes > memory) {
    const bool circumferential = m.circumferential_elements / 120.0 >= m.meridional_elements / 46.0;
    c.fail(circumferential ? cp : mp,
           fmt::format("a {} × {} {} model has {:.3g} elements and {:.3g} DOF; its sparse factorisation needs "
                       "~{:.3g} GiB, this machine has {:.3g} GiB",
                       m.circumferential_elements, m.meridional_elements, m.half_model ? "half" : "full",
                       e.elements, e.dof, e.bytes / kGiB, memory / kGiB));
  }
  if (m.circumferential_elements > kMaxCircumferentialElements)
    c.fail(cp, fmt::format("must be ≤ {} (got {}; ~{:.3g} GiB for the factorisation)", kMaxCircumferentialElements,
                           m.circumferential_elements, e.bytes / kGiB));
  if (m.meridional_elements > kMaxMeridionalElements)
    c.fail(mp, fmt::format("must be ≤ {} (got {}; ~{:.3g} GiB for the factorisation)", kMaxMeridionalElements,
                           m.meridional_elements, e.bytes / kGiB));
}

}  // namespace tirefem::case_reading
