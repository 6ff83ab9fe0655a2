#include "reports/results/exported_models.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "reports/report_error.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ','))
    out.push_back(cell);
  if (!line.empty() && line.back() == ',')
    out.emplace_back();
  return out;
}

double number(const std::string& text, const fs::path& file, int line) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    throw ReportError(fmt::format("{}:{}: '{}' is not a finite number", file.string(), line, text));
  return v;
}

/// The rows of a CSV file after its header, which must be `header`.
std::vector<std::vector<std::string>> read_csv(const fs::path& file, const std::string& header) {
  std::ifstream in(file);
  if (!in)
    throw ReportError(
        fmt::format("{}: cannot be read (not a `contact-suite export` model?)", file.string()));
  std::string line;
  if (!std::getline(in, line) || line != header)
    throw ReportError(fmt::format("{}: the header is not '{}'", file.string(), header));
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    if (!line.empty())
      rows.push_back(split(line));
  }
  return rows;
}

ExportedModel read_model(const fs::path& dir) {
  ExportedModel m;
  m.name = dir.filename().string();
  const fs::path nodes = dir / "nodes.csv", elements = dir / "elements.csv",
                 model = dir / "model.csv";
  int line = 1;
  for (const auto& r : read_csv(nodes, "id,x,y")) {
    ++line;
    if (r.size() != 3)
      throw ReportError(fmt::format("{}:{}: expected 3 fields", nodes.string(), line));
    m.nodes[std::lround(number(r[0], nodes, line))] = {number(r[1], nodes, line),
                                                       number(r[2], nodes, line)};
  }
  line = 1;
  for (const auto& r : read_csv(elements, "id,type,body,n1,n2,n3,n4,n5,n6,n7,n8")) {
    ++line;
    if (r.size() != 11 || (r[1] != "Q4" && r[1] != "Q8"))
      throw ReportError(
          fmt::format("{}:{}: expected a Q4 or Q8 row of 11 fields", elements.string(), line));
    ExportedModel::Element e;
    e.body = static_cast<int>(number(r[2], elements, line));
    const std::array<int, 8> order = r[1] == "Q4" ? std::array<int, 8>{3, 4, 5, 6, -1, -1, -1, -1}
                                                  : std::array<int, 8>{3, 7, 4, 8, 5, 9, 6, 10};
    for (const int column : order) {
      if (column < 0)
        break;
      const long id = std::lround(number(r[column], elements, line));
      if (!m.nodes.contains(id))
        throw ReportError(
            fmt::format("{}:{}: node {} is not in nodes.csv", elements.string(), line, id));
      e.ring.push_back(id);
    }
    m.block_elements += e.body == 0;
    m.elements.push_back(std::move(e));
  }
  line = 1;
  for (const auto& r : read_csv(model, "key,value")) {
    ++line;
    if (r.size() == 2 && r[0] == "contact_half_width_a")
      m.a = number(r[1], model, line);
  }
  if (!(m.a > 0.0))
    throw ReportError(fmt::format("{}: no positive contact_half_width_a", model.string()));
  return m;
}

bool safe_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-' || c == '.' || c == '=';
  });
}

}  // namespace

std::vector<ExportedModel> read_exported_models(const fs::path& export_dir) {
  const fs::path models_dir = export_dir / "models";
  std::error_code ec;
  if (!fs::is_directory(models_dir, ec))
    throw ReportError(
        fmt::format("{}: no models/ directory (not a `contact-suite export` "
                    "output)",
                    export_dir.string()));
  std::vector<fs::path> dirs;
  for (const auto& entry : fs::directory_iterator(models_dir, ec)) {
    if (entry.is_directory())
      dirs.push_back(entry.path());
  }
  std::sort(dirs.begin(), dirs.end());
  std::vector<ExportedModel> models;
  for (const auto& d : dirs) {
    if (!safe_name(d.filename().string()))
      throw ReportError(
          fmt::format("{}: a model name may hold letters, digits and _-.= only", d.string()));
    models.push_back(read_model(d));
  }
  return models;
}

}  // namespace cs::reports
