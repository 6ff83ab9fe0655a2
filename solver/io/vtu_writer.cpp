#include "solver/io/vtu_writer.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

namespace cs::solver {
namespace {

constexpr int kVtkQuad = 9;
constexpr int kVtkQuadraticQuad = 23;

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
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

void check_mesh_for_output(const Mesh& mesh) {
  if (mesh.element_body.size() != mesh.elements.size()) {
    throw VtuError(fmt::format("write_vtu: {} body indices for {} elements",
                               mesh.element_body.size(), mesh.elements.size()));
  }
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    if (!mesh.nodes[n].allFinite()) {
      throw VtuError(fmt::format("write_vtu: node {} has a non-finite coordinate", n));
    }
  }
  for (int e = 0; e < mesh.n_elements(); ++e) {
    for (int a = 0; a < mesh.n_element_nodes(); ++a) {
      const int n = mesh.elements[e][a];
      if (n < 0 || n >= mesh.n_nodes()) {
        throw VtuError(fmt::format("write_vtu: element {} refers to node {} (mesh has {} nodes)", e,
                                   n, mesh.n_nodes()));
      }
    }
  }
}

void check_fields(const Mesh& mesh, const std::vector<VtuField>& fields) {
  std::set<std::string> point_names = {};
  std::set<std::string> cell_names = {"body"};
  for (const auto& f : fields) {
    if (f.name.empty()) {
      throw VtuError("write_vtu: a field has an empty name");
    }
    if (!(f.point_data ? point_names : cell_names).insert(f.name).second) {
      throw VtuError(
          fmt::format("write_vtu: field '{}' is given twice (or is the reserved cell "
                      "field 'body')",
                      f.name));
    }
    if (f.n_components < 1) {
      throw VtuError(fmt::format("write_vtu: field '{}' has {} components (must be >= 1)", f.name,
                                 f.n_components));
    }
    const std::size_t count = f.point_data ? mesh.nodes.size() : mesh.elements.size();
    if (f.values.size() != count * static_cast<std::size_t>(f.n_components)) {
      throw VtuError(
          fmt::format("write_vtu: field '{}' has {} values, expected {} ({} {} x {} "
                      "components)",
                      f.name, f.values.size(), count * f.n_components, count,
                      f.point_data ? "nodes" : "elements", f.n_components));
    }
    for (std::size_t i = 0; i < f.values.size(); ++i) {
      if (!std::isfinite(f.values[i])) {
        throw VtuError(
            fmt::format("write_vtu: field '{}' has a non-finite value ({}) at {} {}, "
                        "component {}",
                        f.name, f.values[i], f.point_data ? "node" : "element", i / f.n_components,
                        i % f.n_components));
      }
    }
  }
}

void append_field(std::string& out, const VtuField& f) {
  const bool pad = f.point_data && f.n_components == 2;  // (u, w) -> (u, w, 0)
  const int written = pad ? 3 : f.n_components;
  out += fmt::format(
      "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" "
      "format=\"ascii\">\n",
      xml_escaped(f.name), written);
  const std::size_t count = f.values.size() / f.n_components;
  for (std::size_t i = 0; i < count; ++i) {
    out += "         ";
    for (int c = 0; c < f.n_components; ++c) {
      out += fmt::format(" {}", f.values[i * f.n_components + c]);
    }
    if (pad)
      out += " 0";
    out += '\n';
  }
  out += "        </DataArray>\n";
}

}  // namespace

std::string vtu_document(const Mesh& mesh, const std::vector<VtuField>& fields,
                         std::string_view comment) {
  check_mesh_for_output(mesh);
  check_fields(mesh, fields);
  if (comment.find("--") != std::string_view::npos)
    throw VtuError("write_vtu: the comment holds \"--\", which XML does not allow in one");
  const int per = mesh.n_element_nodes();
  std::string out;
  out.reserve(64 * (mesh.nodes.size() + mesh.elements.size()) + 1024);
  out += "<?xml version=\"1.0\"?>\n";
  if (!comment.empty())
    out += fmt::format("<!--{}-->\n", comment);
  out +=
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <UnstructuredGrid>\n";
  out += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", mesh.n_nodes(),
                     mesh.n_elements());

  out += "      <PointData>\n";
  for (const auto& f : fields) {
    if (f.point_data)
      append_field(out, f);
  }
  out += "      </PointData>\n      <CellData>\n";
  out += "        <DataArray type=\"Int32\" Name=\"body\" format=\"ascii\">\n";
  for (int e = 0; e < mesh.n_elements(); ++e) {
    out += fmt::format("          {}\n", mesh.element_body[e]);
  }
  out += "        </DataArray>\n";
  for (const auto& f : fields) {
    if (!f.point_data)
      append_field(out, f);
  }
  out += "      </CellData>\n";

  out += "      <Points>\n";
  out += "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : mesh.nodes) {
    out += fmt::format("          {} {} 0\n", p.x(), p.y());
  }
  out += "        </DataArray>\n      </Points>\n";

  out += "      <Cells>\n";
  out += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& e : mesh.elements) {
    out += "         ";
    for (int a = 0; a < per; ++a)
      out += fmt::format(" {}", e[a]);
    out += '\n';
  }
  out += "        </DataArray>\n";
  out += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (int e = 1; e <= mesh.n_elements(); ++e) {
    out += fmt::format("          {}\n", static_cast<long long>(e) * per);
  }
  out += "        </DataArray>\n";
  out += "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  const int type = mesh.type == ElementType::Q4 ? kVtkQuad : kVtkQuadraticQuad;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    out += fmt::format("          {}\n", type);
  }
  out += "        </DataArray>\n      </Cells>\n";
  out += "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<VtuField>& fields,
               std::string_view comment) {
  if (path.empty()) {
    throw VtuError("write_vtu: empty path");
  }
  const std::string document =
      vtu_document(mesh, fields, comment);  // throws before any file exists
  const std::filesystem::path target(path);
  const std::filesystem::path temp =
      target.parent_path() /
      fmt::format(".{}.{}.tmp", target.filename().string(), static_cast<long>(::getpid()));
  {
    std::ofstream file(temp, std::ios::binary | std::ios::trunc);
    if (!file) {
      throw VtuError(fmt::format("write_vtu: cannot create '{}'", temp.string()));
    }
    file.write(document.data(), static_cast<std::streamsize>(document.size()));
    file.flush();
    if (!file) {
      file.close();
      std::error_code ignored;
      std::filesystem::remove(temp, ignored);
      throw VtuError(fmt::format("write_vtu: writing '{}' failed", temp.string()));
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, target, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw VtuError(
        fmt::format("write_vtu: cannot move the file into '{}': {}", path, ec.message()));
  }
}

}  // namespace cs::solver
