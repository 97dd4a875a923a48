#pragma once
// The virtual rig's results (analysis/tyre_test.hpp): the measurement table NAME/tyre_test.csv, its plots
// and its summary.json entry.
#include <toml++/toml.h>

#include "tirefem/analysis/tyre_test.hpp"
#include "tirefem/analysis/tyre_test_fit.hpp"
#include "tirefem/io/csv_writer.hpp"
#include "tirefem/io/plot_writer.hpp"

namespace tirefem {

// FZ, KAPPA, ALPHA, GAMMA, FX, FY, MZ, MX (N, –, rad, rad, N, N, N·m, N·m; W axes), then the effective and
// loaded radius, the static patch's length and width at the point's load (m), the series, and the solver
// counts.
CsvTable tyre_test_table(const TyreTestResult& result);
// The load–deflection curve: Qz (N) against δz (mm) from the undeformed tyre, the half model's figures
// for the full tyre.
CsvTable tyre_test_vertical_table(const TyreTestResult& result);
// Per load: the footprint's and free rolling's figures, the slip and cornering stiffness, and the standing
// tyre's stiffness and relaxation lengths (nan where not measured).
CsvTable tyre_test_loads_table(const TyreTestResult& result);

// FX(κ), FY(α), MZ(α) at every load (FE points; with `fit`, the Magic Formula's pure-slip curves at each
// load's Fz), and the vertical characteristic.
Plot tyre_test_fx_plot(const TyreTestResult& result, const TyreTestFit* fit = nullptr);
Plot tyre_test_fy_plot(const TyreTestResult& result, const TyreTestFit* fit = nullptr);
Plot tyre_test_mz_plot(const TyreTestResult& result, const TyreTestFit* fit = nullptr);
Plot tyre_test_vertical_plot(const TyreTestResult& result, const TyreTestFit* fit = nullptr);
// The relaxation lengths σκ and σα (mm) against Fz: the rig's (K/C per load) and, with `fit`, the .tir's
// (PTX*, PTY*). No series when the rig measured none.
Plot tyre_test_relaxation_plot(const TyreTestResult& result, const TyreTestFit* fit = nullptr);
// The combined-slip grid's points, FX against FY per load, with the fit's curves over κ at each slip angle;
// no series without combined points.
Plot tyre_test_combined_plot(const TyreTestResult& result, const TyreTestFit* fit = nullptr);

toml::table tyre_test_summary(const TyreTestResult& result, const TyreTestFit* fit = nullptr);
// One line for the progress output: the fit's errors and the FNOMIN-normalised figures beside those of
// public passenger-tyre files.
std::string tyre_test_fit_line(const TyreTestResult& result, const TyreTestFit& fit);

}  // namespace tirefem
