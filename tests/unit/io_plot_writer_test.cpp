// Plot writer: script and data are always written; PNG and SVG are rendered when gnuplot is on PATH.
#include <cmath>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "scratch_dir.hpp"
#include "tirefem/io/plot_writer.hpp"

namespace tirefem {
namespace {
namespace fs = std::filesystem;

// A scratch folder of this file's own.
struct ScratchDir : test::ScratchDir {
  ScratchDir() : test::ScratchDir("io_plot") {}
};
using test::read_file;

bool gnuplot_on_path() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

void expect_rendered(const fs::path& stem) {
  const std::string png = read_file(fs::path(stem) += ".png");
  ASSERT_GE(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const std::string svg = read_file(fs::path(stem) += ".svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

Plot load_deflection() {
  Plot plot{"Load characteristic, p = 0.2 MPa", "deflection [mm]", "Qz [N]", {}, false};
  PlotSeries fe{"tirefem (it's \"FE\")", {}, {}, "linespoints pt 7"};
  PlotSeries test{"measured", {}, {}, "points"};
  for (int i = 0; i <= 10; ++i) {
    fe.x.push_back(2.0 * i);
    fe.y.push_back(150.0 * i + 4.0 * i * i);
    test.x.push_back(2.0 * i + 1.0);
    test.y.push_back(160.0 * i + 3.5 * i * i);
  }
  plot.series = {fe, test};
  return plot;
}

TEST(IoPlotWriter, WritesScriptDataAndImages) {
  if (!gnuplot_on_path()) GTEST_SKIP() << "gnuplot is not on PATH";
  ScratchDir scratch;
  const fs::path stem = scratch.path / "load_deflection";
  Plot plot = load_deflection();
  plot.series[0].y[3] = std::nan("");  // a gap, not a failure
  EXPECT_TRUE(write_plot(stem, plot));
  expect_rendered(stem);
  const std::string gp = read_file(scratch.path / "load_deflection.gp");
  EXPECT_NE(gp.find("data = 'load_deflection.dat'"), std::string::npos) << gp;  // relative: restylable
  EXPECT_EQ(gp.find(scratch.path.string()), std::string::npos) << "script must not hold absolute paths";
  EXPECT_NE(gp.find("it''s \"FE\""), std::string::npos) << gp;
  const std::string dat = read_file(scratch.path / "load_deflection.dat");
  EXPECT_NE(dat.find("6 NaN\n"), std::string::npos) << dat;
  EXPECT_NE(dat.find("\n\n\n# series 1: measured\n"), std::string::npos) << dat;
}

TEST(IoPlotWriter, ReversedAxisAndDottedStem) {
  if (!gnuplot_on_path()) GTEST_SKIP() << "gnuplot is not on PATH";
  ScratchDir scratch;
  const fs::path stem = scratch.path / "slip_0.5deg";
  Plot plot = load_deflection();
  plot.x_reversed = true;
  EXPECT_TRUE(write_plot(stem, plot));
  expect_rendered(stem);
  EXPECT_NE(read_file(scratch.path / "slip_0.5deg.gp").find("reverse"), std::string::npos);
}

HeatMap pressure_map() {
  HeatMap map{"Contact pressure", "x [mm]", "y [mm]", "p [MPa]", {}, {}, {}, true};
  for (int i = 0; i < 21; ++i) map.x.push_back(-60.0 + 6.0 * i);
  for (int j = 0; j < 11; ++j) map.y.push_back(-50.0 + 10.0 * j);
  for (double y : map.y) {
    map.values.emplace_back();
    for (double x : map.x)
      map.values.back().push_back(std::max(0.0, 0.3 * (1.0 - (x * x) / 3600 - (y * y) / 2500)));
  }
  return map;
}

TEST(IoPlotWriter, HeatMap) {
  if (!gnuplot_on_path()) GTEST_SKIP() << "gnuplot is not on PATH";
  ScratchDir scratch;
  const HeatMap map = pressure_map();
  const fs::path stem = scratch.path / "footprint_pressure";
  EXPECT_TRUE(write_heatmap(stem, map));
  expect_rendered(stem);
  EXPECT_NE(read_file(fs::path(stem) += ".gp").find("pm3d"), std::string::npos);
}

TEST(IoPlotWriter, HeatMapOverlays) {
  if (!gnuplot_on_path()) GTEST_SKIP() << "gnuplot is not on PATH";
  ScratchDir scratch;
  HeatMap map = pressure_map();
  map.values[2][3] = -0.1;  // the overlays are drawn at the lowest value
  PlotSeries slip{"slip", {}, {}, "points pt 7 ps 0.4 lc rgb '#000000'"};
  for (int i = 0; i < 8; ++i) slip.x.push_back(-20.0 + 5.0 * i), slip.y.push_back(30.0);
  slip.y[2] = std::nan("");
  map.overlays = {PlotSeries{"empty", {}, {}, "points"}, slip};
  const fs::path stem = scratch.path / "traction";
  EXPECT_TRUE(write_heatmap(stem, map));
  expect_rendered(stem);
  const std::string gp = read_file(fs::path(stem) += ".gp");
  EXPECT_NE(gp.find("splot data index 0 using 1:2:3 with pm3d notitle, \\\n      data index 1 using "
                    "1:2:(-0.1) with points pt 7 ps 0.4 lc rgb '#000000' title 'slip'"),
            std::string::npos)
      << gp;
  EXPECT_NE(gp.find("set key below"), std::string::npos) << gp;
  const std::string dat = read_file(fs::path(stem) += ".dat");
  EXPECT_NE(dat.find("\n\n\n# overlay: slip\n# x y\n-20 30\n-15 30\n-10 NaN\n"), std::string::npos) << dat;
  EXPECT_EQ(dat.find("empty"), std::string::npos) << dat;

  // Only empty overlays: the script and data of the plain map.
  HeatMap plain = pressure_map(), empty = pressure_map();
  empty.overlays = {PlotSeries{"empty", {}, {}, "points"}};
  EXPECT_TRUE(write_heatmap(scratch.path / "plain", plain));
  EXPECT_TRUE(write_heatmap(scratch.path / "plain_too", empty));
  const auto strip_names = [](std::string text, const std::string& name) {
    for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at))
      text.replace(at, name.size(), "STEM");
    return text;
  };
  EXPECT_EQ(strip_names(read_file(scratch.path / "plain.gp"), "plain"),
            strip_names(read_file(scratch.path / "plain_too.gp"), "plain_too"));
  EXPECT_EQ(read_file(scratch.path / "plain.dat"), read_file(scratch.path / "plain_too.dat"));
  EXPECT_NE(read_file(scratch.path / "plain.gp").find("unset key\n"), std::string::npos);
  EXPECT_EQ(read_file(scratch.path / "plain.gp").find("set key below"), std::string::npos);
}

TEST(IoPlotWriter, RejectsInconsistentInput) {
  ScratchDir scratch;
  Plot plot = load_deflection();
  plot.series[1].y.pop_back();
  EXPECT_THROW(write_plot(scratch.path / "p", plot), std::invalid_argument);
  plot = load_deflection();
  plot.series[0].style = "lines; system 'rm -rf /'";
  EXPECT_THROW(write_plot(scratch.path / "p", plot), std::invalid_argument);
  plot.series.clear();
  EXPECT_THROW(write_plot(scratch.path / "p", plot), std::invalid_argument);

  HeatMap map{"m", "x", "y", "v", {0, 1, 2}, {0, 1}, {{1, 2, 3}, {4, 5}}, false};
  EXPECT_THROW(write_heatmap(scratch.path / "m", map), std::invalid_argument);
  map.values[1].push_back(6);
  map.y = {0};
  EXPECT_THROW(write_heatmap(scratch.path / "m", map), std::invalid_argument);
  map = pressure_map();
  map.overlays = {PlotSeries{"slip", {1.0, 2.0}, {1.0}, "points"}};
  EXPECT_THROW(write_heatmap(scratch.path / "m", map), std::invalid_argument);
  map.overlays = {PlotSeries{"slip", {1.0}, {1.0}, "points; !rm"}};
  EXPECT_THROW(write_heatmap(scratch.path / "m", map), std::invalid_argument);
  EXPECT_FALSE(fs::exists(scratch.path / "p.gp"));
  EXPECT_FALSE(fs::exists(scratch.path / "m.gp"));
}

TEST(IoPlotWriter, WithoutGnuplotWritesScriptAndReportsNotRendered) {
  ScratchDir scratch;
  const char* old_path = std::getenv("PATH");
  const std::string saved = old_path ? old_path : "";
  ::setenv("PATH", scratch.path.c_str(), 1);  // a folder without gnuplot
  bool rendered = true;
  EXPECT_NO_THROW(rendered = write_plot(scratch.path / "lonely", load_deflection()));
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_FALSE(rendered);
  EXPECT_TRUE(fs::exists(scratch.path / "lonely.gp"));
  EXPECT_TRUE(fs::exists(scratch.path / "lonely.dat"));
  EXPECT_FALSE(fs::exists(scratch.path / "lonely.png"));
}

TEST(IoPlotWriter, GnuplotErrorIsReported) {
  if (!gnuplot_on_path()) GTEST_SKIP() << "gnuplot is not on PATH";
  ScratchDir scratch;
  Plot plot = load_deflection();
  plot.series[0].style = "nosuchstyle";
  try {
    write_plot(scratch.path / "broken", plot);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("broken.gp"), std::string::npos) << message;
    EXPECT_NE(message.find("gnuplot failed"), std::string::npos) << message;
  }
}

// In the background, two at a time: every plot is rendered, and the one gnuplot fails on comes back from
// finish() named by its script (the others are not affected).
TEST(IoPlotWriter, BackgroundRendersReportTheFailedScript) {
  if (!gnuplot_on_path()) GTEST_SKIP() << "gnuplot is not on PATH";
  ScratchDir scratch;
  PlotRenderer renderer(2);
  Plot broken = load_deflection();
  broken.series[0].style = "nosuchstyle";
  EXPECT_TRUE(write_plot(scratch.path / "first", load_deflection(), &renderer));
  EXPECT_TRUE(write_plot(scratch.path / "broken", broken, &renderer));
  for (const char* name : {"second", "third"}) EXPECT_TRUE(write_plot(scratch.path / name, load_deflection(), &renderer));
  const std::vector<PlotRenderer::Failure> failed = renderer.finish();
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_EQ(failed[0].script.filename(), "broken.gp");
  EXPECT_NE(failed[0].message.find("gnuplot failed"), std::string::npos) << failed[0].message;
  for (const char* name : {"first", "second", "third"}) expect_rendered(scratch.path / name);
  EXPECT_TRUE(renderer.finish().empty());  // reported once
}

}  // namespace
}  // namespace tirefem
