#pragma once
// The models `contact-suite export` writes (docs/import-export.md: models/<model>/nodes.csv,
// elements.csv, model.csv), read as far as a picture of the mesh needs them: the report does
// not build meshes; it draws what the suite exported.

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace cs::reports {

/// One exported model, as far as a picture needs it.
struct ExportedModel {
  std::string name;  ///< its directory's name, e.g. "H_p_C_Q4"
  std::map<long, std::array<double, 2>> nodes;
  struct Element {
    int body = 0;
    std::vector<long> ring;  ///< node ids around the element (Q8: corner, mid-side, ...)
  };
  std::vector<Element> elements;
  double a = 0.0;  ///< contact half-width, in the model's units
  int block_elements = 0;
};

/// Every model under `export_dir`/models/, by name, each read and checked: a directory that is
/// not an export, a model name other than letters, digits and _-.=, or a malformed file is a
/// ReportError naming it.
std::vector<ExportedModel> read_exported_models(const std::filesystem::path& export_dir);

}  // namespace cs::reports
