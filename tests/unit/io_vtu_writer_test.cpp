// VTU/PVD writer: a two-quad mesh read back as text; lengths and indices are validated by field name.
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "scratch_dir.hpp"
#include "tirefem/io/vtu_writer.hpp"

namespace tirefem {
namespace {
namespace fs = std::filesystem;

// A scratch folder of this file's own.
struct ScratchDir : test::ScratchDir {
  ScratchDir() : test::ScratchDir("io_vtu") {}
};
using test::read_file;

// Whitespace-separated tokens of the first element whose opening tag contains `marker`.
std::vector<std::string> element_tokens(const std::string& text, const std::string& marker) {
  const std::size_t tag = text.find(marker);
  if (tag == std::string::npos) return {};
  const std::size_t begin = text.find('>', tag) + 1;
  const std::size_t end = text.find('<', begin);
  std::vector<std::string> tokens;
  std::istringstream in(text.substr(begin, end - begin));
  for (std::string token; in >> token;) tokens.push_back(token);
  return tokens;
}

// Rough well-formedness: every opening tag is closed in order; <?...?> and <.../> stand alone.
bool tags_balanced(const std::string& text) {
  std::vector<std::string> open;
  for (std::size_t lt = text.find('<'); lt != std::string::npos; lt = text.find('<', lt + 1)) {
    const std::size_t gt = text.find('>', lt);
    if (gt == std::string::npos) return false;
    const std::string tag = text.substr(lt + 1, gt - lt - 1);
    if (tag.empty() || tag.front() == '?' || tag.back() == '/') continue;
    const std::string name =
        tag.substr(tag.front() == '/' ? 1 : 0, tag.find(' ') - (tag.front() == '/' ? 1 : 0));
    if (tag.front() != '/') {
      open.push_back(name);
    } else {
      if (open.empty() || open.back() != name) return false;
      open.pop_back();
    }
  }
  return open.empty();
}

//  3 --- 4 --- 5
//  |  0  |  1  |
//  0 --- 1 --- 2
VtuMesh two_quads() {
  VtuMesh mesh;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) mesh.points.emplace_back(10.0 * i, 10.0 * j, 0.5 * i);
  mesh.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  mesh.point_scalars = {{"p_MPa", {0.0, 0.1, 0.2, 0.3, 0.4, 0.5}}};
  mesh.point_vectors = {{"u_mm", std::vector<Eigen::Vector3d>(6, Eigen::Vector3d(1.0, -2.0, 0.25))}};
  mesh.cell_scalars = {{"strain_cord", {1e-3, -2e-3}}, {"zone", {1.0, 2.0}}};
  mesh.cell_vectors = {{"normal", {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()}}};
  return mesh;
}

TEST(IoVtuWriter, TwoQuadMeshReadsBack) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "mesh.vtu";
  write_vtu(file, two_quads());
  const std::string text = read_file(file);

  EXPECT_EQ(text.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"", 0), 0u);
  EXPECT_TRUE(tags_balanced(text)) << text;
  EXPECT_NE(text.find("<Piece NumberOfPoints=\"6\" NumberOfCells=\"2\">"), std::string::npos) << text;
  EXPECT_EQ(element_tokens(text, "Name=\"connectivity\""),
            (std::vector<std::string>{"0", "1", "4", "3", "1", "2", "5", "4"}));
  EXPECT_EQ(element_tokens(text, "Name=\"offsets\""), (std::vector<std::string>{"4", "8"}));
  EXPECT_EQ(element_tokens(text, "Name=\"types\""), (std::vector<std::string>{"9", "9"}));
  EXPECT_EQ(element_tokens(text, "Name=\"Points\""),
            (std::vector<std::string>{"0", "0", "0", "10", "0", "0.5", "20", "0", "1", "0", "10", "0", "10",
                                      "10", "0.5", "20", "10", "1"}));
  EXPECT_EQ(element_tokens(text, "Name=\"p_MPa\""),
            (std::vector<std::string>{"0", "0.1", "0.2", "0.3", "0.4", "0.5"}));
  EXPECT_EQ(element_tokens(text, "Name=\"strain_cord\""), (std::vector<std::string>{"0.001", "-0.002"}));
  EXPECT_EQ(element_tokens(text, "Name=\"u_mm\"").size(), 18u);
  EXPECT_NE(text.find("Name=\"u_mm\" NumberOfComponents=\"3\""), std::string::npos);
  EXPECT_NE(text.find("<PointData Scalars=\"p_MPa\" Vectors=\"u_mm\">"), std::string::npos);
  EXPECT_NE(text.find("<CellData Scalars=\"strain_cord\" Vectors=\"normal\">"), std::string::npos);
  // PointData and CellData come before Points and Cells inside the Piece, as VTK writes them.
  EXPECT_LT(text.find("<PointData"), text.find("<CellData"));
  EXPECT_LT(text.find("<CellData"), text.find("<Points>"));
}

TEST(IoVtuWriter, MeshWithoutFieldsHasNoDataSections) {
  ScratchDir scratch;
  VtuMesh mesh = two_quads();
  mesh.point_scalars.clear();
  mesh.point_vectors.clear();
  mesh.cell_scalars.clear();
  mesh.cell_vectors.clear();
  write_vtu(scratch.path / "bare.vtu", mesh);
  const std::string text = read_file(scratch.path / "bare.vtu");
  EXPECT_TRUE(tags_balanced(text));
  EXPECT_EQ(text.find("PointData"), std::string::npos);
  EXPECT_EQ(text.find("CellData"), std::string::npos);
}

void expect_invalid(const VtuMesh& mesh, const std::string& fragment) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "bad.vtu";
  try {
    write_vtu(file, mesh);
    FAIL() << "expected an exception mentioning " << fragment;
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_NE(message.find("bad.vtu"), std::string::npos) << message;
  }
  EXPECT_FALSE(fs::exists(file));
}

TEST(IoVtuWriter, ValidatesFieldsAndIndices) {
  VtuMesh mesh = two_quads();
  mesh.point_scalars[0].second.pop_back();
  expect_invalid(mesh, "point field 'p_MPa' has 5 values, expected 6");

  mesh = two_quads();
  mesh.cell_vectors[0].second.push_back(Eigen::Vector3d::Zero());
  expect_invalid(mesh, "cell field 'normal' has 3 values, expected 2");

  mesh = two_quads();
  mesh.quads[1][2] = 6;
  expect_invalid(mesh, "quad 1 refers to point 6");

  mesh = two_quads();
  mesh.cell_scalars[1].second[0] = std::numeric_limits<double>::quiet_NaN();
  expect_invalid(mesh, "cell field 'zone' entry 0");

  mesh = two_quads();
  mesh.point_vectors.push_back({"p_MPa", mesh.point_vectors[0].second});
  expect_invalid(mesh, "point field 'p_MPa' appears twice");
}

TEST(IoVtuWriter, EscapesFieldNames) {
  ScratchDir scratch;
  VtuMesh mesh = two_quads();
  mesh.cell_scalars[0].first = "a<b & \"c\"";
  write_vtu(scratch.path / "names.vtu", mesh);
  const std::string text = read_file(scratch.path / "names.vtu");
  EXPECT_NE(text.find("Name=\"a&lt;b &amp; &quot;c&quot;\""), std::string::npos);
  EXPECT_TRUE(tags_balanced(text));
}

TEST(IoVtuWriter, VertexCellsFollowTheQuads) {
  ScratchDir scratch;
  VtuMesh cloud;  // a point cloud: 3 vertex cells, no quads
  for (int i = 0; i < 3; ++i) cloud.points.emplace_back(i, 0.0, 0.0);
  cloud.vertices = {0, 1, 2};
  cloud.point_scalars = {{"status", {0.0, 1.0, 2.0}}};
  write_vtu(scratch.path / "cloud.vtu", cloud);
  std::string text = read_file(scratch.path / "cloud.vtu");
  EXPECT_TRUE(tags_balanced(text)) << text;
  EXPECT_NE(text.find("<Piece NumberOfPoints=\"3\" NumberOfCells=\"3\">"), std::string::npos) << text;
  EXPECT_EQ(element_tokens(text, "Name=\"connectivity\""), (std::vector<std::string>{"0", "1", "2"}));
  EXPECT_EQ(element_tokens(text, "Name=\"offsets\""), (std::vector<std::string>{"1", "2", "3"}));
  EXPECT_EQ(element_tokens(text, "Name=\"types\""), (std::vector<std::string>{"1", "1", "1"}));

  VtuMesh mixed = two_quads();  // cell fields: one value per quad, then per vertex
  mixed.vertices = {5};
  mixed.cell_scalars = {{"zone", {1.0, 2.0, 3.0}}};
  mixed.cell_vectors.clear();
  write_vtu(scratch.path / "mixed.vtu", mixed);
  text = read_file(scratch.path / "mixed.vtu");
  EXPECT_TRUE(tags_balanced(text)) << text;
  EXPECT_NE(text.find("NumberOfCells=\"3\""), std::string::npos) << text;
  EXPECT_EQ(element_tokens(text, "Name=\"connectivity\""),
            (std::vector<std::string>{"0", "1", "4", "3", "1", "2", "5", "4", "5"}));
  EXPECT_EQ(element_tokens(text, "Name=\"offsets\""), (std::vector<std::string>{"4", "8", "9"}));
  EXPECT_EQ(element_tokens(text, "Name=\"types\""), (std::vector<std::string>{"9", "9", "1"}));

  mixed.cell_scalars[0].second.pop_back();
  expect_invalid(mixed, "cell field 'zone' has 2 values, expected 3");
  cloud.vertices[1] = 3;
  expect_invalid(cloud, "vertex 1 refers to point 3");
}

TEST(IoVtuWriter, PvdListsTheSeries) {
  ScratchDir scratch;
  const fs::path pvd = scratch.path / "inflation.pvd";
  write_pvd(pvd, {{0.25, "vtu/step_001.vtu"}, {0.5, "vtu/step_002.vtu"}, {1.0, "vtu/step_003.vtu"}});
  const std::string text = read_file(pvd);
  EXPECT_TRUE(tags_balanced(text)) << text;
  EXPECT_NE(text.find("<VTKFile type=\"Collection\""), std::string::npos);
  EXPECT_NE(text.find("<DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"vtu/step_001.vtu\"/>"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("timestep=\"1\" group=\"\" part=\"0\" file=\"vtu/step_003.vtu\""), std::string::npos);
  EXPECT_THROW(write_pvd(pvd, {{std::numeric_limits<double>::infinity(), "a.vtu"}}), std::invalid_argument);
  EXPECT_THROW(write_pvd(pvd, {{0.0, ""}}), std::invalid_argument);
}

}  // namespace
}  // namespace tirefem
