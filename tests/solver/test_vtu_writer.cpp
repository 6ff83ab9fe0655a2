// Tests of the .vtu writer: a round trip through a real VTK-format reader (meshio), well-formed
// XML, refusal of bad fields, and atomic writing.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "solver/io/vtu_writer.hpp"
#include "solver/mesh/indenter.hpp"
#include "solver/mesh/mesh_merge.hpp"
#include "solver/mesh/structured_block.hpp"

namespace cs::solver {
namespace {

namespace fs = std::filesystem;

/// A fresh directory for one test, removed at the end.
class VtuWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("cs_vtu_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  int files_in_dir() const {
    int n = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_))
      ++n;
    return n;
  }
  fs::path dir_;
};

/// Two bodies, Q8, with curved indenter surface: nodes with non-round coordinates.
Mesh two_body_mesh() {
  BlockSpec block;
  block.type = ElementType::Q8;
  block.size = {1.0, 0.75};
  block.nx = 3;
  block.nz = 2;
  block.x_spacing = {SpacingKind::Geometric, 1.3, {}};
  block.body_name = "block";
  IndenterSpec indenter;
  indenter.type = ElementType::Q8;
  indenter.profile = circle_profile(3.0, 0.6);
  indenter.surface_x = {0.0, 0.2, 0.4, 0.6};
  indenter.height = 0.3;
  indenter.n_rows = 1;
  return merge_bodies({make_block(block), make_indenter(indenter)});
}

std::vector<VtuField> fields_of(const Mesh& mesh) {
  VtuField displacement{"displacement", 2, {}, true};
  VtuField stress{"stress <xx,zz,xz,tt>", 4, {}, true};  // a name that needs XML escaping
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    const auto& p = mesh.nodes[n];
    displacement.values.push_back(std::sin(p.x()) / 3.0);
    displacement.values.push_back(-1e-7 * std::exp(p.y()));
    for (int c = 0; c < 4; ++c)
      stress.values.push_back(std::cos(n + c * 0.1) * 1e5 / 7.0);
  }
  VtuField pressure{"pressure", 1, {}, false};
  for (int e = 0; e < mesh.n_elements(); ++e)
    pressure.values.push_back(1.0 / (e + 3.0));
  return {displacement, stress, pressure};
}

/// Runs a python3 program, returning its standard output (empty string on failure).
std::string run_python(const std::string& program, int* status) {
  const std::string command = "/usr/bin/python3 -c '" + program + "' 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) {
    *status = -1;
    return {};
  }
  std::string out;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr)
    out += buffer;
  *status = ::pclose(pipe);
  return out;
}

bool meshio_available() {
  int status = 0;
  run_python("import meshio", &status);
  return status == 0;
}

TEST_F(VtuWriterTest, RoundTripThroughMeshio) {
  if (!meshio_available()) {
    GTEST_SKIP() << "python3-meshio is not installed";
  }
  const Mesh mesh = two_body_mesh();
  const auto fields = fields_of(mesh);
  const std::string file = path("model.vtu");
  write_vtu(file, mesh, fields);

  // Prints every number with repr (round-trip precision) in a simple line format.
  const std::string program =
      "import meshio\n"
      "m = meshio.read(\"" +
      file +
      "\")\n"
      "print(len(m.points))\n"
      "for p in m.points: print(repr(float(p[0])), repr(float(p[1])), repr(float(p[2])))\n"
      "print(len(m.cells))\n"
      "for b in m.cells:\n"
      "    print(b.type, len(b.data), len(b.data[0]))\n"
      "    for c in b.data: print(*[int(i) for i in c])\n"
      "d = m.point_data[\"displacement\"]\n"
      "print(d.shape[0], d.shape[1])\n"
      "for r in d: print(*[repr(float(v)) for v in r])\n"
      "for r in m.cell_data[\"pressure\"][0]: print(repr(float(r)))\n"
      "for r in m.cell_data[\"body\"][0]: print(int(r))\n";
  int status = 0;
  const std::string out = run_python(program, &status);
  ASSERT_EQ(status, 0) << out;
  std::istringstream in(out);

  int n_points = 0;
  in >> n_points;
  ASSERT_EQ(n_points, mesh.n_nodes());
  for (int n = 0; n < n_points; ++n) {
    double x, y, z;
    in >> x >> y >> z;
    EXPECT_EQ(x, mesh.nodes[n].x()) << n;  // full precision: bit for bit
    EXPECT_EQ(y, mesh.nodes[n].y()) << n;
    EXPECT_EQ(z, 0.0);
  }
  int n_blocks = 0;
  in >> n_blocks;
  ASSERT_EQ(n_blocks, 1);
  std::string type;
  int n_cells = 0, per = 0;
  in >> type >> n_cells >> per;
  EXPECT_EQ(type, "quad8");  // VTK_QUADRATIC_QUAD
  ASSERT_EQ(n_cells, mesh.n_elements());
  ASSERT_EQ(per, 8);
  for (int e = 0; e < n_cells; ++e) {
    for (int a = 0; a < 8; ++a) {
      int node = -1;
      in >> node;
      EXPECT_EQ(node, mesh.elements[e][a]) << e << " " << a;
    }
  }
  int rows = 0, cols = 0;
  in >> rows >> cols;
  ASSERT_EQ(rows, mesh.n_nodes());
  ASSERT_EQ(cols, 3);  // (u, w) padded with 0
  for (int n = 0; n < rows; ++n) {
    double u, w, zero;
    in >> u >> w >> zero;
    EXPECT_EQ(u, fields[0].values[2 * n]);
    EXPECT_EQ(w, fields[0].values[2 * n + 1]);
    EXPECT_EQ(zero, 0.0);
  }
  for (int e = 0; e < mesh.n_elements(); ++e) {
    double p;
    in >> p;
    EXPECT_EQ(p, fields[2].values[e]);
  }
  for (int e = 0; e < mesh.n_elements(); ++e) {
    int body = -1;
    in >> body;
    EXPECT_EQ(body, mesh.element_body[e]);
  }
  EXPECT_FALSE(in.fail());
}

TEST_F(VtuWriterTest, Q4CellsAndWellFormedXml) {
  BlockSpec spec;
  spec.nx = 2;
  spec.nz = 2;
  const Mesh mesh = make_block(spec);
  const std::string file = path("q4.vtu");
  write_vtu(file, mesh, {{"index", 1, std::vector<double>(mesh.n_nodes(), 1.5), true}});
  const std::string document =
      vtu_document(mesh, {{"index", 1, std::vector<double>(mesh.n_nodes(), 1.5)}});
  EXPECT_NE(document.find("<DataArray type=\"UInt8\" Name=\"types\""), std::string::npos);
  EXPECT_NE(document.find("\n          9\n"), std::string::npos);  // VTK_QUAD
  EXPECT_EQ(document.find("23"), std::string::npos);

  int status = 0;
  const std::string out = run_python(
      "import xml.etree.ElementTree as ET\n"
      "r = ET.parse(\"" +
          file +
          "\").getroot()\n"
          "print(r.tag, r.get(\"type\"), "
          "r.find(\"UnstructuredGrid/Piece\").get(\"NumberOfCells\"))\n",
      &status);
  if (status != 0 && out.find("No such file") != std::string::npos) {
    GTEST_SKIP() << "no python3 to parse the XML";
  }
  ASSERT_EQ(status, 0) << out;
  EXPECT_EQ(out, "VTKFile UnstructuredGrid 4\n");
}

TEST_F(VtuWriterTest, RefusesNonFiniteValuesNamingTheFieldAndWritesNothing) {
  const Mesh mesh = two_body_mesh();
  auto fields = fields_of(mesh);
  fields[0].values[7] = std::numeric_limits<double>::quiet_NaN();
  const std::string file = path("bad.vtu");
  try {
    write_vtu(file, mesh, fields);
    ADD_FAILURE() << "expected VtuError";
  } catch (const VtuError& e) {
    EXPECT_NE(std::string(e.what()).find("'displacement'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("node 3"), std::string::npos) << e.what();
  }
  EXPECT_EQ(files_in_dir(), 0);
}

TEST_F(VtuWriterTest, AnErrorLeavesAnExistingFileUntouched) {
  const Mesh mesh = two_body_mesh();
  const std::string file = path("model.vtu");
  write_vtu(file, mesh, fields_of(mesh));
  const auto size_before = fs::file_size(file);
  auto bad = fields_of(mesh);
  bad[2].values.pop_back();  // wrong size
  EXPECT_THROW(write_vtu(file, mesh, bad), VtuError);
  EXPECT_EQ(fs::file_size(file), size_before);
  EXPECT_EQ(files_in_dir(), 1);  // no temporary left behind
  EXPECT_THROW(write_vtu(path("missing/dir/model.vtu"), mesh, fields_of(mesh)), VtuError);
  EXPECT_EQ(files_in_dir(), 1);
}

// A comment stands after the declaration, where an XML parser keeps reading; one holding "--"
// (which XML forbids inside a comment) is refused rather than written as a broken file.
TEST_F(VtuWriterTest, CommentAfterTheDeclarationAndNoDoubleHyphen) {
  const Mesh mesh = two_body_mesh();
  const std::string document = vtu_document(mesh, fields_of(mesh), " made here ");
  EXPECT_EQ(document.rfind("<?xml version=\"1.0\"?>\n<!-- made here -->\n<VTKFile ", 0), 0u);
  EXPECT_EQ(vtu_document(mesh, fields_of(mesh)).find("<!--"), std::string::npos);
  EXPECT_THROW(vtu_document(mesh, fields_of(mesh), "a -- b"), VtuError);
}

TEST_F(VtuWriterTest, RejectsDuplicateAndEmptyNames) {
  const Mesh mesh = two_body_mesh();
  auto fields = fields_of(mesh);
  fields.push_back(fields[0]);
  EXPECT_THROW(vtu_document(mesh, fields), VtuError);
  fields = fields_of(mesh);
  fields[2].name = "body";  // reserved for the body index
  EXPECT_THROW(vtu_document(mesh, fields), VtuError);
  fields = fields_of(mesh);
  fields[1].name.clear();
  EXPECT_THROW(vtu_document(mesh, fields), VtuError);
}

}  // namespace
}  // namespace cs::solver
