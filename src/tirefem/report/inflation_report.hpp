#pragma once
// Tables, surfaces and figures of an inflation result, ready for the writers.
#include <vector>

#include "tirefem/analysis/inflation.hpp"
#include "tirefem/forms/rim_flange_form.hpp"
#include "tirefem/io/csv_writer.hpp"
#include "tirefem/io/plot_writer.hpp"
#include "tirefem/io/vtu_writer.hpp"
#include "tirefem/report/shell_results.hpp"

namespace tirefem {

struct InflationSummary {
  double crown_radius_growth_mm = 0.0;    // radial displacement of the breaker face at the equator
  double section_width_growth_mm = 0.0;   // growth of the carcass section width (full tyre)
  double max_carcass_cord_force_N = 0.0;  // largest tension of a cord of the inner face's plies
  double max_belt_cord_force_N = 0.0;     // largest tension of a cord of the outer face's plies
  double max_carcass_cord_strain = 0.0;
  double max_belt_cord_strain = 0.0;
  std::vector<RimFlangeLoad> rim_flanges;  // the inflated bead's push on the rim flanges (none without)
};

InflationSummary summarize_inflation(const TyreMesh& tyre_mesh, const Eigen::VectorXd& displacement,
                                     const std::vector<ElementResult>& elements);

// Element-centre distributions along the meridian in the circumferential row nearest φ = 0.
CsvTable meridian_table(const TyreMesh& tyre_mesh, const TyreDescription& tyre,
                        const Eigen::VectorXd& displacement, const std::vector<ElementResult>& elements);

// Both faces as quad surfaces (reference positions, displacement as point data, results as cell data).
VtuMesh shell_vtu(const TyreMesh& tyre_mesh, const TyreDescription& tyre,
                  const Eigen::VectorXd& displacement, const std::vector<ElementResult>& elements);

// Figures from the meridian table: cord tensions, face resultants, and the deformed cross-section.
std::vector<std::pair<std::string, Plot>> meridian_plots(const CsvTable& table, const TyreMesh& tyre_mesh,
                                                         const Eigen::VectorXd& displacement);

}  // namespace tirefem
