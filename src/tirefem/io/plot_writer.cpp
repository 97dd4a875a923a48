#include "tirefem/io/plot_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

extern char** environ;  // POSIX: the environment handed on to gnuplot

namespace tirefem {
namespace fs = std::filesystem;

namespace {

using Buffer = fmt::memory_buffer;

fs::path with_suffix(const fs::path& stem, std::string_view suffix) {
  fs::path p = stem;
  p += suffix;  // appended, not replaced: "slip_0.5deg" + ".png"
  return p;
}

void write_text_file(const fs::path& file, const Buffer& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out)
    throw std::runtime_error(
        fmt::format("cannot open plot file '{}' for writing: {}", file.string(), std::strerror(errno)));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error(fmt::format("error while writing plot file '{}'", file.string()));
}

// A gnuplot single-quoted string: nothing inside is interpreted (no backquote or macro substitution);
// a quote is doubled. Line breaks cannot appear in it and become spaces.
std::string gnuplot_string(std::string_view text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'')
      out += "''";
    else if (c == '\n' || c == '\r')
      out += ' ';
    else
      out += c;
  }
  return out + "'";
}

std::string data_value(double v) { return std::isfinite(v) ? fmt::format("{}", v) : std::string("NaN"); }

// ---- running gnuplot --------------------------------------------------------------------------------

std::optional<fs::path> find_on_path(std::string_view program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::string_view dirs(path);
  while (true) {
    const std::size_t colon = dirs.find(':');
    const std::string_view dir = dirs.substr(0, colon);
    const fs::path candidate = fs::path(dir.empty() ? "." : std::string(dir)) / program;
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return candidate;
    if (colon == std::string_view::npos) return std::nullopt;
    dirs.remove_prefix(colon + 1);
  }
}

// Starts `gnuplot <script name>` inside the script's folder, with no shell in between; its stderr is read
// from the returned descriptor. Throws if it cannot be started.
std::pair<pid_t, int> spawn_gnuplot(const fs::path& gnuplot, const fs::path& script) {
  const fs::path folder = script.has_parent_path() ? script.parent_path() : fs::path(".");
  const std::string name = script.filename().string();

  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0)
    throw std::runtime_error(
        fmt::format("cannot run gnuplot for '{}': pipe: {}", script.string(), std::strerror(errno)));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  std::string program = gnuplot.string();
  char* argv[] = {program.data(), const_cast<char*>(name.c_str()), nullptr};
  pid_t pid = 0;
  const int spawn_error = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  if (spawn_error != 0) {
    ::close(pipe_fds[0]);
    throw std::runtime_error(
        fmt::format("cannot run '{}' for '{}': {}", program, script.string(), std::strerror(spawn_error)));
  }
  return {pid, pipe_fds[0]};
}

// Reads gnuplot's stderr to its end and waits for it; gnuplot's messages if it failed, else nothing.
std::optional<std::string> collect_gnuplot(pid_t pid, int error_fd, const fs::path& script) {
  std::string messages;
  char chunk[4096];
  while (true) {
    const ssize_t n = ::read(error_fd, chunk, sizeof chunk);
    if (n > 0)
      messages.append(chunk, static_cast<std::size_t>(n));
    else if (n == 0 || errno != EINTR)
      break;
  }
  ::close(error_fd);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return std::nullopt;
  while (!messages.empty() && (messages.back() == '\n' || messages.back() == ' ')) messages.pop_back();
  return fmt::format("gnuplot failed on '{}' (exit status {}): {}", script.string(),
                     WIFEXITED(status) ? WEXITSTATUS(status) : -1, messages);
}

// Writes the script and data, then renders if gnuplot is available (now, or by `renderer`).
bool write_and_render(const fs::path& stem, const Buffer& script, const Buffer& data,
                      PlotRenderer* renderer) {
  const fs::path gp = with_suffix(stem, ".gp");
  write_text_file(with_suffix(stem, ".dat"), data);
  write_text_file(gp, script);
  if (renderer) return renderer->start(gp);
  PlotRenderer now(1);
  if (!now.start(gp)) return false;
  const std::vector<PlotRenderer::Failure> failed = now.finish();
  if (!failed.empty()) throw std::runtime_error(failed.front().message);
  return true;
}

// Common head of both kinds of script: where the data are, titles and axis labels.
void write_header(Buffer& gp, const fs::path& stem, std::string_view title, std::string_view x_label,
                  std::string_view y_label) {
  auto o = std::back_inserter(gp);
  fmt::format_to(o, "# Written by tirefem. Edit and re-render in this folder with:  gnuplot {}\n",
                 with_suffix(stem, ".gp").filename().string());
  fmt::format_to(o, "set encoding utf8\n");
  fmt::format_to(o, "data = {}\n", gnuplot_string(with_suffix(stem, ".dat").filename().string()));
  fmt::format_to(o, "set title {}\nset xlabel {}\nset ylabel {}\n", gnuplot_string(title),
                 gnuplot_string(x_label), gnuplot_string(y_label));
}

// Draws the same picture on both terminals: `replot` repeats the plot command, so a user who restyles
// the script edits it in one place.
void write_render_block(Buffer& gp, const fs::path& stem, std::string_view plot_command) {
  auto o = std::back_inserter(gp);
  fmt::format_to(o,
                 "\nset terminal pngcairo size 1000,700 noenhanced font 'Sans,12' linewidth 1.5\n"
                 "set output {}\n{}\n\n",
                 gnuplot_string(with_suffix(stem, ".png").filename().string()), plot_command);
  fmt::format_to(
      o,
      "set terminal svg size 1000,700 noenhanced font 'Sans,12' linewidth 1.5 background rgb 'white'\n"
      "set output {}\nreplot\nunset output\n",
      gnuplot_string(with_suffix(stem, ".svg").filename().string()));
}

void check_style(std::string_view plot_title, std::string_view series_title, std::string_view style) {
  const bool ok = !style.empty() && std::all_of(style.begin(), style.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string_view(" .-_#'").find(c) != std::string_view::npos;
  });
  if (!ok)
    throw std::invalid_argument(
        fmt::format("plot '{}', series '{}': style \"{}\" must be a gnuplot style using only letters, "
                    "digits, spaces and . - _ # '",
                    plot_title, series_title, style));
}

}  // namespace

bool write_plot(const fs::path& stem, const Plot& plot, PlotRenderer* renderer) {
  if (plot.series.empty()) throw std::invalid_argument(fmt::format("plot '{}' has no series", plot.title));
  bool any_point = false;
  for (const PlotSeries& s : plot.series) {
    if (s.x.size() != s.y.size())
      throw std::invalid_argument(fmt::format("plot '{}', series '{}': {} x values but {} y values",
                                              plot.title, s.title, s.x.size(), s.y.size()));
    check_style(plot.title, s.title, s.style);
    any_point = any_point || !s.x.empty();
  }
  if (!any_point) throw std::invalid_argument(fmt::format("plot '{}': every series is empty", plot.title));

  Buffer data;
  auto d = std::back_inserter(data);
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    // Blocks are separated by two blank lines, so that "index k" selects series k.
    fmt::format_to(d, "{}# series {}: {}\n# x y\n", k == 0 ? "" : "\n\n", k, s.title);
    for (std::size_t i = 0; i < s.x.size(); ++i)
      fmt::format_to(d, "{} {}\n", data_value(s.x[i]), data_value(s.y[i]));
  }

  Buffer gp;
  auto o = std::back_inserter(gp);
  write_header(gp, stem, plot.title, plot.x_label, plot.y_label);
  fmt::format_to(o, "set grid\nset key opaque box{}\n", plot.key_top_left ? " top left" : "");
  if (plot.x_reversed) fmt::format_to(o, "set xrange [*:*] reverse\n");
  std::string command = "plot";
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    // An empty series would make gnuplot stop on "no valid points": it is left out of the picture.
    if (s.x.empty()) continue;
    command += fmt::format("{}data index {} using 1:2 with {} title {}",
                           command == "plot" ? " " : ", \\\n     ", k, s.style, gnuplot_string(s.title));
  }
  write_render_block(gp, stem, command);
  return write_and_render(stem, gp, data, renderer);
}

bool write_heatmap(const fs::path& stem, const HeatMap& map, PlotRenderer* renderer) {
  if (map.x.size() < 2 || map.y.size() < 2)
    throw std::invalid_argument(
        fmt::format("heat map '{}' needs at least 2 x and 2 y grid values, has {} and {}", map.title,
                    map.x.size(), map.y.size()));
  if (map.values.size() != map.y.size())
    throw std::invalid_argument(fmt::format("heat map '{}': {} rows of values, expected one per y value ({})",
                                            map.title, map.values.size(), map.y.size()));
  for (std::size_t iy = 0; iy < map.values.size(); ++iy)
    if (map.values[iy].size() != map.x.size())
      throw std::invalid_argument(
          fmt::format("heat map '{}': row {} has {} values, expected one per x value ({})", map.title, iy,
                      map.values[iy].size(), map.x.size()));
  for (const PlotSeries& s : map.overlays) {
    if (s.x.size() != s.y.size())
      throw std::invalid_argument(fmt::format("heat map '{}', overlay '{}': {} x values but {} y values",
                                              map.title, s.title, s.x.size(), s.y.size()));
    check_style(map.title, s.title, s.style);
  }

  Buffer data;
  auto d = std::back_inserter(data);
  fmt::format_to(d, "# x y value: {}\n", map.value_label);
  for (std::size_t iy = 0; iy < map.y.size(); ++iy) {
    for (std::size_t ix = 0; ix < map.x.size(); ++ix)
      fmt::format_to(d, "{} {} {}\n", data_value(map.x[ix]), data_value(map.y[iy]),
                     data_value(map.values[iy][ix]));
    fmt::format_to(d, "\n");  // a blank line ends one scan line of the grid
  }
  // Overlays follow the grid as blocks of their own ("index k", two blank lines apart); the grid alone
  // keeps the plain layout and command of a map without overlays.
  std::string overlay_command;
  double z_overlay = std::numeric_limits<double>::infinity();  // lowest value: inside the z range
  for (const auto& row : map.values)
    for (double v : row)
      if (std::isfinite(v)) z_overlay = std::min(z_overlay, v);
  if (!std::isfinite(z_overlay)) z_overlay = 0.0;
  int block = 0;
  for (const PlotSeries& s : map.overlays) {
    if (s.x.empty()) continue;
    fmt::format_to(d, "\n\n# overlay: {}\n# x y\n", s.title);
    for (std::size_t i = 0; i < s.x.size(); ++i)
      fmt::format_to(d, "{} {}\n", data_value(s.x[i]), data_value(s.y[i]));
    overlay_command += fmt::format(", \\\n      data index {} using 1:2:({}) with {} title {}", ++block,
                                   z_overlay, s.style, gnuplot_string(s.title));
  }

  Buffer gp;
  auto o = std::back_inserter(gp);
  write_header(gp, stem, map.title, map.x_label, map.y_label);
  fmt::format_to(o, "set cblabel {}\n", gnuplot_string(map.value_label));
  fmt::format_to(o,
                 "set view map\nset pm3d at b\nunset key\nset autoscale xfix\nset autoscale yfix\n"
                 "set tics out\n"
                 "# viridis\n"
                 "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')\n");
  if (map.equal_axes) fmt::format_to(o, "set size ratio -1\n");
  if (overlay_command.empty()) {
    write_render_block(gp, stem, "splot data using 1:2:3 with pm3d");
  } else {
    fmt::format_to(o, "set key below\n");
    write_render_block(gp, stem, "splot data index 0 using 1:2:3 with pm3d notitle" + overlay_command);
  }
  return write_and_render(stem, gp, data, renderer);
}

PlotRenderer::~PlotRenderer() {
  while (!running_.empty()) wait_oldest();
}

bool PlotRenderer::start(const fs::path& script) {
  if (!gnuplot_) gnuplot_ = find_on_path("gnuplot");
  if (!*gnuplot_) return false;
  while (static_cast<int>(running_.size()) >= std::max(1, at_once_)) wait_oldest();
  try {
    const auto [pid, error_fd] = spawn_gnuplot(**gnuplot_, script);
    running_.push_back({script, pid, error_fd});
  } catch (const std::runtime_error& e) {
    failures_.push_back({script, e.what()});
  }
  return true;
}

void PlotRenderer::wait_oldest() {
  const Running r = running_.front();
  running_.pop_front();
  if (std::optional<std::string> message = collect_gnuplot(r.pid, r.error_fd, r.script))
    failures_.push_back({r.script, std::move(*message)});
}

std::vector<PlotRenderer::Failure> PlotRenderer::finish() {
  while (!running_.empty()) wait_oldest();
  return std::exchange(failures_, {});
}

}  // namespace tirefem
