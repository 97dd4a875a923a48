#pragma once
// Tables, maps, surfaces and summaries of a static contact result (load curve or footprint), ready for the
// writers (pure functions: nothing is written here). Figures as in the paper: Fig. 3 load characteristic,
// Fig. 4 contact pressure over (s, φ), Fig. 5 cord strains along the meridian, Fig. 8 breaker cord
// tension along the circumference.
//
// Half models: a result does not say whether it came from a half model; the tread points do (a half
// model has no point with u = s < 0). The maps then mirror the points (s → −s, x → −x) to show the whole
// patch.
#include <toml++/toml.h>

#include <string>
#include <utility>
#include <vector>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/io/csv_writer.hpp"
#include "tirefem/io/plot_writer.hpp"
#include "tirefem/io/vtu_writer.hpp"
#include "tirefem/report/shell_results.hpp"

namespace tirefem {

// Margins of the maps around the contact (points with qn > 0; without contact: the points nearest the
// support, i.e. of largest penetration).
inline constexpr int kPatchMarginPoints = 3;        // tread-point rows / columns (s–φ map, point table)
inline constexpr double kFootprintMarginMm = 10.0;  // road-coordinate footprint map

std::string theory_label(Kinematics kinematics);

// One row per load point: deflection_mm, Qz_N, contact_area_mm2, patch_length_mm, patch_width_mm,
// max_pressure_MPa, mean_pressure_MPa, contact_iterations, newton_iterations, factorizations, increments,
// time_s. Comments name the study, the support and the theory.
CsvTable load_curve_table(const StaticContactResult& result);

// Fig. 3: Qz [N] against δz [mm], one series per curve titled "<support>, <theory>" (null entries skipped).
Plot load_characteristic_plot(const std::vector<const StaticContactResult*>& curves);

// Final state, one row per tread point in the window of pressure_map_s_phi (the contact plus
// kPatchMarginPoints rows / columns of tread points; the points themselves, not mirrored):
// s_mm, phi_deg, x_mm, y_mm, z_mm (current position), penetration_mm, pressure_MPa. Sorted by φ, then s.
CsvTable tread_points_table(const StaticContactResult& result);

// Fig. 4: contact pressure of the final state over (s [mm], φ [deg]) on the grid of tread points, in the
// window contact ± kPatchMarginPoints rows / columns; a half model is mirrored (s → −s). Grid nodes
// without a tread point (no tread) and points out of contact show 0.
HeatMap pressure_map_s_phi(const StaticContactResult& result);

// The footprint: pressure of the final state over road coordinates (x lateral, y travel) on a regular
// grid of spacing cell_mm (nodes at multiples of cell_mm), over the contact extent ± kFootprintMarginMm.
// Each cell of four neighbouring tread points is a quadrilateral in current (x, y); nodes inside it get
// the bilinear interpolation (inverse bilinear map), nodes outside all cells get 0. Half model: mirrored
// (x → −x, the strip between the first point column and its mirror image is bridged). equal_axes.
HeatMap footprint_map_xy(const StaticContactResult& result, double cell_mm = 1.0);

// Fig. 8: breaker (outer face) cord strain and tension along the circumference in the equatorial plane
// (the element column with |s| nearest 0; a tie in a full model goes to s > 0), at element centres.
// Columns: phi_deg, then per state and per ply of the outer face <state>_<ply>_force_N (tension per cord)
// and <state>_<ply>_strain (engineering). A ply name used twice in the face gets _1, _2, … appended.
CsvTable circumferential_belt_table(
    const TyreMesh& tyre_mesh, const TyreDescription& tyre,
    const std::vector<std::pair<std::string, const std::vector<ElementResult>*>>& states);

// One series per *_force_N column of circumferential_belt_table, against φ.
Plot circumferential_belt_plot(const CsvTable& belt_table);

// Fig. 5: carcass and breaker cord strain along the meridian under the patch centre, one series per
// state (label, meridian_table output) and per *_cord_strain column ("loaded, breaker belt1").
Plot meridian_cord_strain_plot(const std::vector<std::pair<std::string, const CsvTable*>>& meridian_tables);

// The support surface at the final deflection: 61 × 61 points over x, y ∈ [−half_extent, half_extent],
// z = SupportSurface::height; point field height_mm.
VtuMesh support_vtu(const StaticContactResult& result, double half_extent_mm = 150.0);

// Contact pressure at the outer node of every node pair: the node's tread point outer + hp(s) ·
// normalize(outer − inner), moved by the outer node's displacement, against the support at the final
// deflection, kp · max(g, 0). 0 where there is no tread (|s| > tread end).
std::vector<double> nodal_contact_pressure(const TyreMesh& tyre_mesh, const TyreDescription& tyre,
                                           const StaticContactResult& result,
                                           const Eigen::VectorXd& displacement);

// shell_vtu of the final state plus the point field contact_pressure_MPa (inner-face points 0).
// `elements`: evaluate_element_results of result.final_state.displacement.
VtuMesh loaded_shell_vtu(const TyreMesh& tyre_mesh, const TyreDescription& tyre,
                         const StaticContactResult& result, const std::vector<ElementResult>& elements);

// name, support (+ drum_diameter_mm), theory, iteration, completed (+ failure when not), points = [{
// deflection_mm, Qz_N, contact_area_mm2, patch_length_mm, patch_width_mm, max_pressure_MPa,
// mean_pressure_MPa, contact_iterations, newton_iterations }].
toml::table load_curve_summary(const StaticContactResult& result);

// name, support (+ drum_diameter_mm), theory, iteration, completed (+ failure), target_Qz_N (when set),
// and of the last point: deflection_mm, Qz_N, contact_area_mm2, patch_length_mm, patch_width_mm,
// max_pressure_MPa, mean_pressure_MPa (left out when there is no point).
toml::table footprint_summary(const StaticContactResult& result);

}  // namespace tirefem
