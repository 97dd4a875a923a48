#pragma once
// Tables, plots, maps, point clouds and summaries of a steady-rolling result (analysis/rolling.hpp), ready
// for the writers (pure functions: nothing is solved or written here). The paper's Fig. 7 is the
// tangential stress over (s, φ) with the stick and slip zones: traction_map_s_phi.
//
// The tread-point reports take one state of the result; they need its per-point vectors (normal,
// tangential), one entry per result.tread_points (std::invalid_argument otherwise, e.g. for a state that
// failed before it had any). The patch window is that of footprint_report.hpp: the points with qn > 0
// (without contact: those of largest penetration) plus kPatchMarginPoints rows / columns; a half model is
// mirrored (s → −s) in the map only.
//
// qy = TreadTraction::force.y() / TreadPoint::weight is the y component of the tangential stress on the
// tyre in the model's axes (MPa); TreadTraction::traction is the same stress signed along the support's
// motion (the support moves in −y under a tyre that travels in +y).
#include <toml++/toml.h>

#include <string>

#include "tirefem/analysis/rolling.hpp"
#include "tirefem/io/csv_writer.hpp"
#include "tirefem/io/plot_writer.hpp"
#include "tirefem/io/vtu_writer.hpp"
#include "tirefem/report/footprint_report.hpp"

namespace tirefem {

// "free", "given_slip", "given_radius", "full_stick", "full_slip".
std::string rolling_state_kind_name(RollingStateSpec::Kind kind);

// One row per entry of result.states: state (the kind's index: 0 free, 1 given_slip, 2 given_radius,
// 3 full_stick, 4 full_slip), slip, rolling_radius_mm, loaded_radius_mm, Qz_N, Qy_N, Mx_Nmm,
// stick_area_fraction, contact_area_mm2, max_traction_MPa, contact_iterations, newton_iterations,
// factorizations, solves, time_s, converged (0/1). CSV holds numbers only: comment lines name each row's
// state. Values that are not defined (slip of a spinning wheel, Rk of a locked one) and the figures of a
// state that did not converge are NaN ("nan"), as a comment line says. Further comments: the study,
// support, μ, travel direction, deflection, Re and the slip stiffness.
CsvTable rolling_states_table(const RollingResult& result);

// One row per sweep point: slip, rolling_radius_mm, Qz_N, Qy_N, Mx_Nmm, Qy_over_Qz (NaN at Qz = 0),
// stick_area_fraction, contact_iterations, newton_iterations, factorizations, time_s.
CsvTable slip_sweep_table(const RollingResult& result);

// The longitudinal force–slip curve: Qy [N] against κ, and the friction limits ±μ Qz (Qz of each sweep
// point) as one dashed series "±μ Qz" (the two lines separated by a gap). No points when the sweep is
// empty (write_plot rejects that: write it only for a sweep).
Plot slip_sweep_plot(const RollingResult& result);

// One row per tread point in the window (the model's own points, not mirrored), sorted by φ, then s:
// s_mm, phi_deg, x_mm, y_mm, z_mm (current position), pressure_MPa, traction_MPa (along the support's
// motion), qy_MPa, shear_mm, status (0 out, 1 stick, 2 slip).
CsvTable rolling_tread_table(const RollingResult& result, const RollingStateResult& state);

// Fig. 7: qy [MPa] over (s [mm], φ [deg]) on the grid of tread points in the window, mirrored for a half
// model; grid nodes without a tread point show 0. Overlay "slip": the slipping points (black dots); the
// contact boundary shows in the colours. The overlay is kept (empty) when nothing slips.
HeatMap traction_map_s_phi(const RollingResult& result, const RollingStateResult& state);

// All tread points (not mirrored) at their current positions as VTK_VERTEX cells, with point fields
// pressure_MPa, traction_MPa, qy_MPa, shear_mm, status.
VtuMesh tread_points_vtu(const RollingResult& result, const RollingStateResult& state);

// name, support (+ drum_diameter_mm), friction, travel ("+y" / "-y"), completed (+ failure),
// target_Qz_N (when set), deflection_mm, loaded_radius_mm, effective_rolling_radius_mm and
// slip_stiffness_N (when set), states = [{name, state, slip and rolling_radius_mm (when set),
// loaded_radius_mm, contact_iterations, newton_iterations, factorizations, time_s, converged, failure (when
// not converged) and, when converged, Qz_N, Qy_N, Mx_Nmm, stick_area_fraction, contact_area_mm2}] (JSON
// takes no NaN: a failed state's figures are left out), sweep = [{slip, rolling_radius_mm, Qz_N, Qy_N,
// Mx_Nmm, stick_area_fraction, newton_iterations, factorizations, time_s}] when there is a sweep.
toml::table rolling_summary(const RollingResult& result);

}  // namespace tirefem
