#include "tirefem/io/vtu_writer.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

namespace tirefem {
namespace {

constexpr int vtk_quad = 9;
constexpr int vtk_vertex = 1;
using Buffer = fmt::memory_buffer;

std::string xml_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void write_text_file(const std::filesystem::path& file, std::string_view kind, const Buffer& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out)
    throw std::runtime_error(
        fmt::format("cannot open {} file '{}' for writing: {}", kind, file.string(), std::strerror(errno)));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error(fmt::format("error while writing {} file '{}'", kind, file.string()));
}

// ---- validation -------------------------------------------------------------------------------------

[[noreturn]] void fail(const std::filesystem::path& file, std::string_view what) {
  throw std::invalid_argument(fmt::format("VTU '{}': {}", file.string(), what));
}

void check_finite(const std::filesystem::path& file, std::string_view field, std::size_t index,
                  double value) {
  if (!std::isfinite(value))
    fail(file, fmt::format("{} entry {} is {} (only finite values can be written)", field, index, value));
}

void check_finite(const std::filesystem::path& file, std::string_view field, std::size_t index,
                  const Eigen::Vector3d& value) {
  if (!value.allFinite())
    fail(file, fmt::format("{} entry {} is ({}, {}, {}) (only finite values can be written)", field, index,
                           value.x(), value.y(), value.z()));
}

template <typename Value>
void check_fields(const std::filesystem::path& file, std::string_view location,
                  const std::vector<std::pair<std::string, std::vector<Value>>>& fields, std::size_t expected,
                  std::set<std::string>& names) {
  for (const auto& [name, values] : fields) {
    if (name.empty()) fail(file, fmt::format("a {} field has an empty name", location));
    if (!names.insert(name).second) fail(file, fmt::format("{} field '{}' appears twice", location, name));
    if (values.size() != expected)
      fail(file, fmt::format("{} field '{}' has {} values, expected {} (one per {})", location, name,
                             values.size(), expected, location));
    for (std::size_t i = 0; i < values.size(); ++i)
      check_finite(file, fmt::format("{} field '{}'", location, name), i, values[i]);
  }
}

void check_mesh(const std::filesystem::path& file, const VtuMesh& mesh) {
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    check_finite(file, "point coordinates", i, mesh.points[i]);
  const auto n_points = static_cast<long long>(mesh.points.size());
  for (std::size_t q = 0; q < mesh.quads.size(); ++q)
    for (const int p : mesh.quads[q])
      if (p < 0 || p >= n_points)
        fail(file, fmt::format("quad {} refers to point {}, but there are {} points", q, p, n_points));
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (mesh.vertices[v] < 0 || mesh.vertices[v] >= n_points)
      fail(file, fmt::format("vertex {} refers to point {}, but there are {} points", v, mesh.vertices[v],
                             n_points));
  std::set<std::string> point_names, cell_names;
  check_fields(file, "point", mesh.point_scalars, mesh.points.size(), point_names);
  check_fields(file, "point", mesh.point_vectors, mesh.points.size(), point_names);
  const std::size_t cells = mesh.quads.size() + mesh.vertices.size();
  check_fields(file, "cell", mesh.cell_scalars, cells, cell_names);
  check_fields(file, "cell", mesh.cell_vectors, cells, cell_names);
}

// ---- output -----------------------------------------------------------------------------------------

void append(Buffer& out, double value) { fmt::format_to(std::back_inserter(out), " {}", value); }
void append(Buffer& out, const Eigen::Vector3d& value) {
  fmt::format_to(std::back_inserter(out), " {} {} {}", value.x(), value.y(), value.z());
}

template <typename Value>
void write_array(Buffer& out, std::string_view name, const std::vector<Value>& values) {
  constexpr int components = std::is_same_v<Value, double> ? 1 : 3;
  fmt::format_to(std::back_inserter(out),
                 "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" "
                 "format=\"ascii\">\n         ",
                 xml_escaped(name), components);
  constexpr std::size_t per_line = components == 1 ? 8 : 2;
  for (std::size_t i = 0; i < values.size(); ++i) {
    append(out, values[i]);
    if (i % per_line == per_line - 1 && i + 1 < values.size())
      fmt::format_to(std::back_inserter(out), "\n         ");
  }
  fmt::format_to(std::back_inserter(out), "\n        </DataArray>\n");
}

void write_data_section(Buffer& out, std::string_view tag,
                        const std::vector<std::pair<std::string, std::vector<double>>>& scalars,
                        const std::vector<std::pair<std::string, std::vector<Eigen::Vector3d>>>& vectors) {
  if (scalars.empty() && vectors.empty()) return;
  fmt::format_to(std::back_inserter(out), "      <{}", tag);
  // The first field of each kind is what ParaView colours by when the file is opened.
  if (!scalars.empty())
    fmt::format_to(std::back_inserter(out), " Scalars=\"{}\"", xml_escaped(scalars[0].first));
  if (!vectors.empty())
    fmt::format_to(std::back_inserter(out), " Vectors=\"{}\"", xml_escaped(vectors[0].first));
  fmt::format_to(std::back_inserter(out), ">\n");
  for (const auto& [name, values] : scalars) write_array(out, name, values);
  for (const auto& [name, values] : vectors) write_array(out, name, values);
  fmt::format_to(std::back_inserter(out), "      </{}>\n", tag);
}

void write_cells(Buffer& out, const std::vector<std::array<int, 4>>& quads,
                 const std::vector<int>& vertices) {
  auto o = std::back_inserter(out);
  const std::size_t cells = quads.size() + vertices.size();
  fmt::format_to(
      o, "      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (const auto& q : quads) fmt::format_to(o, "          {} {} {} {}\n", q[0], q[1], q[2], q[3]);
  for (std::size_t v = 0; v < vertices.size(); ++v)
    fmt::format_to(o, "{}{}{}", v % 12 == 0 ? "          " : " ", vertices[v],
                   v % 12 == 11 || v + 1 == vertices.size() ? "\n" : "");
  fmt::format_to(
      o, "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">");
  for (std::size_t c = 0; c < cells; ++c)
    fmt::format_to(o, "{}{}", c % 12 == 0 ? "\n          " : " ",
                   c < quads.size() ? 4 * (c + 1) : 4 * quads.size() + (c - quads.size() + 1));
  fmt::format_to(
      o, "\n        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">");
  for (std::size_t c = 0; c < cells; ++c)
    fmt::format_to(o, "{}{}", c % 24 == 0 ? "\n          " : " ", c < quads.size() ? vtk_quad : vtk_vertex);
  fmt::format_to(o, "\n        </DataArray>\n      </Cells>\n");
}

}  // namespace

void write_vtu(const std::filesystem::path& file, const VtuMesh& mesh) {
  check_mesh(file, mesh);
  Buffer out;
  auto o = std::back_inserter(out);
  fmt::format_to(o,
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                 "header_type=\"UInt64\">\n"
                 "  <UnstructuredGrid>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                 mesh.points.size(), mesh.quads.size() + mesh.vertices.size());
  write_data_section(out, "PointData", mesh.point_scalars, mesh.point_vectors);
  write_data_section(out, "CellData", mesh.cell_scalars, mesh.cell_vectors);
  fmt::format_to(o, "      <Points>\n");
  write_array(out, "Points", mesh.points);
  fmt::format_to(o, "      </Points>\n");
  write_cells(out, mesh.quads, mesh.vertices);
  fmt::format_to(o, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  write_text_file(file, "VTU", out);
}

void write_pvd(const std::filesystem::path& pvd,
               const std::vector<std::pair<double, std::string>>& time_and_file) {
  for (std::size_t i = 0; i < time_and_file.size(); ++i) {
    const auto& [time, file] = time_and_file[i];
    if (!std::isfinite(time))
      throw std::invalid_argument(
          fmt::format("PVD '{}': entry {} ('{}') has time {}", pvd.string(), i, file, time));
    if (file.empty())
      throw std::invalid_argument(fmt::format("PVD '{}': entry {} has an empty file name", pvd.string(), i));
  }
  Buffer out;
  auto o = std::back_inserter(out);
  fmt::format_to(o,
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                 "  <Collection>\n");
  for (const auto& [time, file] : time_and_file)
    fmt::format_to(o, "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", time,
                   xml_escaped(file));
  fmt::format_to(o, "  </Collection>\n</VTKFile>\n");
  write_text_file(pvd, "PVD", out);
}

}  // namespace tirefem
