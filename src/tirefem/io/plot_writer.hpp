#pragma once
// Plots rendered by gnuplot. For a stem "out/load_deflection" the writer keeps the script
// load_deflection.gp and its data load_deflection.dat (both refer to each other by file name only, so the
// user can restyle and re-render with `gnuplot load_deflection.gp` in that folder, also after the folder
// has been moved) and renders load_deflection.png (pngcairo, 1000×700) and load_deflection.svg.
//
// Texts (titles, labels, legend) are printed literally (no enhanced-text markup: "s_mm" shows an
// underscore, not a subscript); UTF-8 is fine ("°", "²").
#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <sys/types.h>

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
  bool key_top_left = false;  // the key in the top left corner (default: top right), where the data rise to the right
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

// gnuplot runs on the scripts in the background, at most `at_once` at a time, while the caller goes on
// writing (a results folder has some 35 plots at about 0.1 s of gnuplot each).
class PlotRenderer {
 public:
  struct Failure {
    std::filesystem::path script;
    std::string message;  // gnuplot's, or why it could not be started
  };
  explicit PlotRenderer(int at_once = 2) : at_once_(at_once) {}
  PlotRenderer(const PlotRenderer&) = delete;
  PlotRenderer& operator=(const PlotRenderer&) = delete;
  ~PlotRenderer();  // waits for the renders still running
  // Starts gnuplot on `script` in the script's folder, once fewer than `at_once` run. False when no
  // `gnuplot` executable is on PATH (nothing started).
  bool start(const std::filesystem::path& script);
  // Waits for every render started; returns those that failed since the last call.
  std::vector<Failure> finish();

 private:
  struct Running {
    std::filesystem::path script;
    pid_t pid;
    int error_fd;  // gnuplot's stderr
  };
  void wait_oldest();
  int at_once_;
  std::optional<std::optional<std::filesystem::path>> gnuplot_;  // looked up on the first start
  std::deque<Running> running_;
  std::vector<Failure> failures_;
};

// Write stem.gp and stem.dat, then run gnuplot on them. Returns true when stem.png and stem.svg were
// rendered, false when no `gnuplot` executable is on PATH (the script and data are still written, so the
// caller can warn and the user can render later). Throws std::invalid_argument naming the plot and the
// series for inconsistent input, std::runtime_error naming the file for I/O failure, and
// std::runtime_error with gnuplot's messages when gnuplot fails. With a `renderer`, gnuplot runs in the
// background: true then means a render was started, and its failure, if any, comes from renderer->finish().
bool write_plot(const std::filesystem::path& stem, const Plot& plot, PlotRenderer* renderer = nullptr);
bool write_heatmap(const std::filesystem::path& stem, const HeatMap& map, PlotRenderer* renderer = nullptr);

}  // namespace tirefem
