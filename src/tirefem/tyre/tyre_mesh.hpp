#pragma once
// The tyre as a mesh of three-layer shell elements: a surface of revolution about the wheel axis
// (parallel to x, at height axis_z above the road), u = meridian arc length s, v = angle φ.
//
// Meridional stations (MeshSettings::meridional_grading). zones (the default): the meridian is cut at the
// zone ends and at the tread edge, and the elements are shared out over these pieces in proportion to
// their length (at least one each, largest remainders get the rest), uniform within a piece. So every
// element lies in one zone and on one side of the tread edge. uniform_arc_length: equal elements in s
// whatever the zones; an element takes the zone of its centre, and its tread points beyond the tread
// edge carry no tread (make_tread_points leaves them out).
// Circumferential stations: circumferential_stations(n, refinement), refined around φ = 0 (the patch).
// Half model: s from 0 (equator) to L (bead). Full model: s from −L to L on the mirrored profile, with
// twice meridional_elements elements.
#include <optional>
#include <vector>

#include "tirefem/case/case.hpp"
#include "tirefem/element/section.hpp"
#include "tirefem/mesh/shell_mesh.hpp"
#include "tirefem/tyre/meridian_profile.hpp"

namespace tirefem {

struct TyreMesh {
  ShellMesh mesh;  // inner face = carcass line, outer face at h(s) along the normal (−r', x')
  std::vector<ElementSection> sections;  // per element
  std::vector<int> element_zone;         // per element: index into TyreDescription::zones
  std::vector<double> element_s;         // per element: s of its centre (negative on the mirror side)
  std::vector<int> pressure_elements;    // elements loaded by the inflation pressure (all)
  // Bead: all 6 DOFs of each bead node pair. Half model also: the x displacement of the inner and the
  // outer node of each equator node pair (symmetry). Sorted, unique.
  std::vector<int> fixed_dofs;
  // Height of the wheel axis: the outer radius of the tread surface at the equator, r(0) + h(0) + hp(0),
  // so the undeformed tyre touches z = 0 at φ = 0.
  double axis_z = 0.0;
  MeridianProfile profile;  // the profile the mesh was built on (mirrored in the full model)
  bool half_model = true;
  std::optional<RimFlangeDescription> rim_flange;  // the tyre's, if it leans on one (forms/rim_flange_form.hpp)
  MeshSettings::MeridionalGrading meridional_grading = MeshSettings::MeridionalGrading::zones;

  // Meridian arc length of a node pair.
  double pair_s(int pair) const { return mesh.u_values[pair % mesh.u_nodes()]; }
};

// Throws std::invalid_argument on inconsistent input (validate_case() reports it with field names first).
TyreMesh build_tyre_mesh(const TyreDescription& tyre, const MeshSettings& settings);

// Whether the full model is its own mirror image in the wheel plane x = 0. Its geometry, tread, flanges
// and zones are (the profile is mirrored); its faces are if no face couples stretch and shear (A16 = A26
// = 0 relative to the face's stiffness: a balanced belt pair, cords at 0° or 90°), since the mirror turns
// a cord at +θ into one at −θ. False for a half model (there is nothing to mirror).
bool mirror_symmetric(const TyreMesh& tm);

// Meridional stations of the half model, 0 … L (see above). `breaks` are the interior cut points.
std::vector<double> meridional_stations(double length, std::vector<double> breaks, int elements);

// Equal steps in s: 0, L/n, …, L.
std::vector<double> uniform_stations(double length, int elements);

// Index of the zone containing |s| (the last zone also takes anything beyond its end).
int zone_at(const TyreDescription& tyre, double s);

// Tread height hp at |s|: the table value up to the tread edge, 0 beyond it.
double tread_height_at(const TyreDescription& tyre, double s);

}  // namespace tirefem
