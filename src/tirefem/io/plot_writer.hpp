#pragma once
// Plots rendered by gnuplot. For a stem "out/load_deflection" the writer keeps the script
// load_deflection.gp and its data load_deflection.dat (both refer to each other by file name only, so the
// user can restyle and re-render with `gnuplot load_deflection.gp` in that folder, also after the folder
// has been moved) and renders load_deflection.png (pngcairo, 1000×700) and load_deflection.svg.
//
// Texts (titles, labels, legend) are printed literally (no enhanced-text markup: "s_mm" shows an
// underscore, not a subscript); UTF-8 is fine ("°", "²").
#include <filesystem>
#include <string>
#include <vector>

namespace tirefem {

struct PlotSeries {
  std::string title;
  std::vector<double> x, y;  // same length; non-finite values leave a gap
  // gnuplot plotting style after "with": "linespoints", "lines", "points pt 7", "lines lc rgb '#c00000'".
  // Only letters, digits, spaces and . - _ # ' are accepted.
  std::string style = "linespoints";
};

struct Plot {
  std::string title, x_label, y_label;  // labels with units, e.g. "deflection [mm]"
  std::vector<PlotSeries> series;
  bool x_reversed = false;
};

// A colour map of values on a rectilinear grid (gnuplot pm3d seen from above). Each quadrilateral between
// four neighbouring grid points is coloured by the mean of its corner values; non-finite values leave a hole.
// Overlays are (x, y) series drawn on top of the map in their style (e.g. "points pt 7 ps 0.4 lc rgb
// '#000000'", marking slip points) and named in a key below the map; empty overlays are left out.
struct HeatMap {
  std::string title, x_label, y_label, value_label;
  std::vector<double> x, y;                 // grid lines, at least 2 each
  std::vector<std::vector<double>> values;  // values[iy][ix]
  bool equal_axes = false;                  // same scale on x and y (e.g. a footprint in mm × mm)
  std::vector<PlotSeries> overlays;
};

// Write stem.gp and stem.dat, then run gnuplot on them. Returns true when stem.png and stem.svg were
// rendered, false when no `gnuplot` executable is on PATH (the script and data are still written, so the
// caller can warn and the user can render later). Throws std::invalid_argument naming the plot and the
// series for inconsistent input, std::runtime_error naming the file for I/O failure, and
// std::runtime_error with gnuplot's messages when gnuplot fails.
bool write_plot(const std::filesystem::path& stem, const Plot& plot);
bool write_heatmap(const std::filesystem::path& stem, const HeatMap& map);

}  // namespace tirefem
