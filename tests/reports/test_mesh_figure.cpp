// Figure 3: the mesh pictures are drawn from an export directory; every model is read and
// checked first, and a directory or file that is not an export's is one ReportError naming it.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "reports/figures/mesh_figure.hpp"
#include "reports/report_error.hpp"
#include "support/temp_dir.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;

/// A two-body model: one block element and one indenter element above it.
void write_model(const fs::path& dir, const std::string& elements_extra = "") {
  fs::create_directories(dir);
  std::ofstream(dir / "nodes.csv") << "id,x,y\n1,0,0\n2,1,0\n3,1,1\n4,0,1\n5,0,-1\n6,1,-1\n";
  std::ofstream(dir / "elements.csv")
      << "id,type,body,n1,n2,n3,n4,n5,n6,n7,n8\n1,Q4,0,1,2,3,4,,,,\n2,Q4,1,5,6,2,1,,,,\n"
      << elements_extra;
  std::ofstream(dir / "model.csv")
      << "key,value\nanalysis,plane_strain\ncontact_half_width_a,0.5\n";
}

TEST(MeshFigure, DrawsEachModelWithItsCounts) {
  const cs::testing::TempDir tmp;
  write_model(tmp.path() / "export" / "models" / "H_p_C_Q4");
  const FigureSet set = render_mesh_figures(tmp.path() / "export", tmp.path() / "report");
  ASSERT_EQ(set.figures.size(), 1u);
  EXPECT_EQ(set.figures[0].file, "figures/mesh_H_p_C_Q4.png");
  EXPECT_NE(set.figures[0].caption_md.find("1 elements in the indented block, 1 in the indenter"),
            std::string::npos)
      << set.figures[0].caption_md;
  if (set.unavailable.empty()) {
    EXPECT_TRUE(set.figures[0].produced) << set.figures[0].error;
    EXPECT_GT(fs::file_size(tmp.path() / "report" / set.figures[0].file), 0u);
  }
  const std::string md = mesh_figures_section(set);
  EXPECT_EQ(md.rfind("## The meshes (Figure 3)", 0), 0u);
}

TEST(MeshFigure, RefusesWhatIsNotAnExport) {
  const cs::testing::TempDir tmp;
  EXPECT_THROW(render_mesh_figures(tmp.path() / "none", tmp.path() / "r"), ReportError);
  write_model(tmp.path() / "a" / "models" / "M", "3,Q4,0,1,2,3,99,,,,\n");  // unknown node
  EXPECT_THROW(render_mesh_figures(tmp.path() / "a", tmp.path() / "r"), ReportError);
  write_model(tmp.path() / "b" / "models" / "bad'name");
  EXPECT_THROW(render_mesh_figures(tmp.path() / "b", tmp.path() / "r"), ReportError);
  write_model(tmp.path() / "c" / "models" / "M");
  std::ofstream(tmp.path() / "c" / "models" / "M" / "nodes.csv") << "id,x,y\n1,0,zero\n";
  try {
    render_mesh_figures(tmp.path() / "c", tmp.path() / "r");
    ADD_FAILURE() << "accepted a bad number";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find("nodes.csv:2: 'zero' is not a finite number"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(tmp.path() / "r" / "figures")) << "nothing drawn before the check";
}

}  // namespace
}  // namespace cs::reports
