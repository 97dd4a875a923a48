#pragma once
// Tables, plots and summary entries of a rolling study's tyre-practice figures (MODEL.md §7, issue 11):
// the W-axis forces and moments (ISO 8855 / TYDEX, see RollingFigures) of every state, the lateral
// force and aligning moment against slip angle, and the combined (κ, α) grid with its friction ellipse.
// Pure functions: nothing is solved or written here.
#include <toml++/toml.h>

#include "tirefem/analysis/rolling.hpp"
#include "tirefem/io/csv_writer.hpp"
#include "tirefem/io/plot_writer.hpp"

namespace tirefem {

// The tyre-practice keys of a state or sweep point: slip_angle_deg, camber_deg, mu, Fx_N, Fy_N, Fz_N,
// Mz_Nmm (aligning), overturning_moment_Nmm, rolling_resistance_moment_Nmm, pneumatic_trail_mm (when
// |Fy| > 1e-3 Fz), centre_of_pressure_mm [X, Y].
void insert_tyre_figures(toml::table& t, const RollingFigures& f, double slip_angle_deg, double camber_deg, double mu);

// One row per point of the α sweep (or of the combined grid), by κ then α: slip_angle_deg, camber_deg,
// slip, rolling_radius_mm, deflection_mm, Fx_N, Fy_N, Fz_N, Mz_Nmm, overturning_moment_Nmm,
// pneumatic_trail_mm (NaN when Fy ≈ 0), Fy_over_Fz, stick_area_fraction, newton_iterations,
// factorizations, time_s.
CsvTable angle_sweep_table(const RollingResult& result);
CsvTable combined_slip_table(const RollingResult& result);

// Fy [N] against α [deg] with ±μ Fz; Mz [N·m] against α [deg]. For a non-empty α sweep.
Plot lateral_force_plot(const RollingResult& result);
Plot aligning_moment_plot(const RollingResult& result);
// The combined grid: Fy against Fx, one curve per slip κ (through its slip angles), and the friction
// circle of radius μ Fz (Fz the grid's mean). For a non-empty grid.
Plot friction_ellipse_plot(const RollingResult& result);

// The summary's angle_sweep and combined arrays and the cornering stiffness (when found).
void insert_cornering_summary(toml::table& t, const RollingResult& result);

}  // namespace tirefem
