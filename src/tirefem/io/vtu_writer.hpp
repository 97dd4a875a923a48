#pragma once
// ParaView files for a quadrilateral surface mesh or a point cloud: one XML UnstructuredGrid (.vtu, ASCII
// data) per state, and a .pvd collection that lists a series of them (load steps, rolling positions)
// against a time value.
#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace tirefem {

struct VtuMesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 4>> quads;  // point indices, counter-clockwise seen from the outward side
  std::vector<int> vertices;              // single-point cells (a point cloud), after the quads
  // Named fields (name with units, e.g. "p_MPa"); one value per point or per cell (quads, then vertices).
  std::vector<std::pair<std::string, std::vector<double>>> point_scalars, cell_scalars;
  std::vector<std::pair<std::string, std::vector<Eigen::Vector3d>>> point_vectors, cell_vectors;
};

// Writes `mesh` as VTK_QUAD cells followed by VTK_VERTEX cells. Before writing anything, checks that every
// quad and vertex index is a valid point,
// every field has one entry per point or cell, field names are non-empty and unique within point and
// within cell data, and all numbers are finite (VTK's ASCII reader rejects "nan"); throws
// std::invalid_argument naming the file and the field. Throws std::runtime_error naming the file when it
// cannot be written. Numbers are written in the shortest form that reads back exactly.
void write_vtu(const std::filesystem::path& file, const VtuMesh& mesh);

// Writes a ParaView collection: each (time, file) pair becomes a <DataSet timestep=... file=...>; `file`
// is stored as given, normally relative to the folder of the .pvd (e.g. "vtu/step_003.vtu").
void write_pvd(const std::filesystem::path& pvd,
               const std::vector<std::pair<double, std::string>>& time_and_file);

}  // namespace tirefem
