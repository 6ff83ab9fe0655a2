#include "reports/figures/mesh_figure.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "reports/figures/gnuplot.hpp"
#include "reports/report_error.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;

/// One exported model, as far as a picture needs it.
struct MeshModel {
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

MeshModel read_model(const fs::path& dir) {
  MeshModel m;
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
    MeshModel::Element e;
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

/// Element outlines of one body as gnuplot data: each ring closed, a blank line between.
std::string outlines(const MeshModel& m, int body) {
  std::string out;
  for (const auto& e : m.elements) {
    if (e.body != body)
      continue;
    for (std::size_t i = 0; i <= e.ring.size(); ++i) {
      const auto& p = m.nodes.at(e.ring[i % e.ring.size()]);
      out += fmt::format("{:.9g} {:.9g}\n", p[0], p[1]);
    }
    out += "\n";
  }
  return out;
}

std::string panel(const fs::path& block, const fs::path& indenter, const std::string& title,
                  const std::string& ranges) {
  return fmt::format(
      "set title {}\n{}plot {} with lines lw 0.6 lc rgb '#1f77b4' title 'indented block', {} "
      "with lines lw 0.6 lc rgb '#d62728' title 'indenter'\n",
      gnuplot_quote(title), ranges, gnuplot_quote(block.string()),
      gnuplot_quote(indenter.string()));
}

void draw(const Gnuplot& gnuplot, const fs::path& work, const fs::path& out_root,
          const MeshModel& m, Figure& figure) {
  const fs::path block = work / (m.name + "_block.dat"), indenter = work / (m.name + "_ind.dat");
  std::ofstream(block) << outlines(m, 0);
  std::ofstream(indenter) << outlines(m, 1);
  const fs::path png = out_root / figure.file;
  std::error_code ec;
  fs::create_directories(png.parent_path(), ec);
  const double a = m.a;
  std::string script = fmt::format(
      "set terminal {} size 1240,560 noenhanced{}\nset output {}\nset size ratio -1\n"
      "set key below horizontal\nset xlabel 'x'\nset ylabel 'z (into the block)'\n"
      "set multiplot layout 1,2\n",
      gnuplot.terminal, gnuplot.terminal == "pngcairo" ? " font 'Sans,10'" : "",
      gnuplot_quote(png.string()));
  script += panel(block, indenter, m.name + ": the whole model",
                  "set autoscale\nset yrange [*:*] reverse\n");
  script += panel(block, indenter, fmt::format("{}: near the contact (a = {:.4g})", m.name, a),
                  fmt::format("set xrange [0:{:.9g}]\nset yrange [{:.9g}:{:.9g}]\n", 2.0 * a,
                              1.25 * a, -0.75 * a));
  script += "unset multiplot\nset output\n";
  const fs::path script_file = work / (m.name + ".gp");
  std::ofstream(script_file) << script;
  figure.error = run_gnuplot(gnuplot, script_file, work / (m.name + ".log"));
  figure.produced =
      figure.error.empty() && fs::is_regular_file(png, ec) && fs::file_size(png, ec) > 0;
  if (!figure.produced && figure.error.empty())
    figure.error = "gnuplot wrote no image";
}

bool safe_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-' || c == '.' || c == '=';
  });
}

}  // namespace

FigureSet render_mesh_figures(const fs::path& export_dir, const fs::path& out_root,
                              const FigureOptions& options) {
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
  std::vector<MeshModel> models;
  for (const auto& d : dirs) {
    if (!safe_name(d.filename().string()))
      throw ReportError(
          fmt::format("{}: a model name may hold letters, digits and _-.= only", d.string()));
    models.push_back(read_model(d));
  }
  FigureSet set;
  const auto gnuplot = find_gnuplot(options.gnuplot_program);
  if (!gnuplot)
    set.unavailable = fmt::format(
        "`{}` with a PNG terminal was not found, so the meshes were not "
        "drawn",
        options.gnuplot_program);
  const ScratchDir work;
  for (const auto& m : models) {
    Figure f;
    f.kind = FigureKind::mesh;
    f.file = "figures/mesh_" + m.name + ".png";
    f.caption_md =
        fmt::format("{}: {} elements in the indented block, {} in the indenter.", m.name,
                    m.block_elements, static_cast<int>(m.elements.size()) - m.block_elements);
    if (gnuplot)
      draw(*gnuplot, work.path(), out_root, m, f);
    else
      f.error = set.unavailable;
    set.figures.push_back(std::move(f));
  }
  return set;
}

std::string mesh_figures_section(const FigureSet& figures) {
  if (figures.figures.empty())
    return {};
  std::string out =
      "## The meshes (Figure 3)\n\n"
      "The coarse meshes as the suite builds them (drawn from `contact-suite export`), the "
      "whole model beside a zoom on the contact; z points into the indented block. M and F "
      "halve and quarter every element.\n\n";
  for (const auto& f : figures.figures) {
    out += f.produced ? fmt::format("![{}]({})\n\n{}\n\n", f.caption_md, f.file, f.caption_md)
                      : fmt::format("{} (not drawn: {})\n\n", f.caption_md, f.error);
  }
  return out;
}

}  // namespace cs::reports
