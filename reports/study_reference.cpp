#include "reports/study_reference.hpp"

#include <cstdlib>
#include <fstream>
#include <map>
#include <system_error>

#include <fmt/format.h>

#include "reports/report_error.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',') {
      out.emplace_back();
    } else if (c != '\r') {
      out.back() += c;
    }
  }
  return out;
}

/// A small CSV with a header, no quoting (the study files have none): rows as name -> text.
class CsvFile {
 public:
  CsvFile(const fs::path& path, const std::vector<std::string>& required) : path_(path.string()) {
    std::ifstream in(path);
    if (!in)
      throw ReportError(fmt::format("study data file '{}' cannot be read", path_));
    std::string line;
    if (!std::getline(in, line))
      throw ReportError(fmt::format("study data file '{}' is empty", path_));
    header_ = split_commas(line);
    for (const auto& name : required) {
      if (column(name) < 0)
        throw ReportError(fmt::format("study data file '{}' has no column '{}'", path_, name));
    }
    int line_no = 1;
    while (std::getline(in, line)) {
      ++line_no;
      if (line.empty() || line == "\r")
        continue;
      auto fields = split_commas(line);
      if (fields.size() != header_.size()) {
        throw ReportError(fmt::format("study data file '{}' line {}: {} fields, expected {}", path_,
                                      line_no, fields.size(), header_.size()));
      }
      rows_.push_back(std::move(fields));
      line_numbers_.push_back(line_no);
    }
  }

  std::size_t size() const { return rows_.size(); }
  const std::string& get(std::size_t row, const std::string& name) const {
    return rows_[row][static_cast<std::size_t>(column(name))];
  }
  double number(std::size_t row, const std::string& name) const {
    const std::string& text = get(row, name);
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end == nullptr || *end != '\0') {
      throw ReportError(fmt::format("study data file '{}' line {}: '{}' is not a number ({})",
                                    path_, line_numbers_[row], text, name));
    }
    return v;
  }

 private:
  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header_.size(); ++i) {
      if (header_[i] == name)
        return static_cast<int>(i);
    }
    return -1;
  }

  std::string path_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<int> line_numbers_;
};

bool holds_study_data(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / "ansys_results.csv", ec) &&
         fs::is_regular_file(dir / "ansys_grades.csv", ec);
}

}  // namespace

StudyReference::StudyReference(std::vector<StudyValue> values, std::vector<StudyGrade> grades)
    : values_(std::move(values)), grades_(std::move(grades)) {}

const StudyValue* StudyReference::find_exact_key(
    const std::string& problem, const std::string& quantity, const std::string& element,
    const std::string& algorithm, const std::string& contact, const std::string& mesh) const {
  for (const auto& v : values_) {
    if (v.problem == problem && v.quantity == quantity && v.element == element &&
        v.algorithm == algorithm && v.contact == contact && v.mesh == mesh)
      return &v;
  }
  return nullptr;
}

StudyMatch StudyReference::find_value(const std::string& problem, const std::string& quantity,
                                      const std::string& element, const std::string& algorithm,
                                      const std::string& contact, const std::string& mesh) const {
  const std::string alg = study_algorithm(algorithm);
  if (alg.empty() || (contact != "ss" && contact != "ns"))
    return {};
  const std::string el = study_element(element);
  if (const auto* v = find_exact_key(problem, quantity, el, alg, contact, mesh))
    return {v, false};
  if (const auto* v = find_exact_key(problem, quantity, el, alg, "either", mesh))
    return {v, false};
  if (alg == "LMP_PLM" && contact == "ns") {
    if (const auto* v = find_exact_key(problem, quantity, el, alg, "ss", mesh))
      return {v, true};
  }
  return {};
}

const StudyGrade* StudyReference::find_grade_cell(const std::string& problem,
                                                  const std::string& study_row,
                                                  const std::string& study_element_name,
                                                  const std::string& column) const {
  for (const auto& g : grades_) {
    if (g.problem == problem && g.row == study_row && g.element == study_element_name &&
        g.column == column)
      return &g;
  }
  return nullptr;
}

const StudyGrade* StudyReference::find_grade(const std::string& problem,
                                             const std::string& study_row,
                                             const std::string& element,
                                             const std::string& algorithm,
                                             const std::string& contact) const {
  const std::string column = study_grade_column(algorithm, contact);
  if (column.empty())
    return nullptr;
  return find_grade_cell(problem, study_row, study_element(element), column);
}

std::string StudyReference::printed_exact(const std::string& problem,
                                          const std::string& quantity) const {
  for (const auto& v : values_) {
    if (v.problem == problem && v.quantity == quantity)
      return v.exact_printed;
  }
  return {};
}

StudyReference load_study_reference(const fs::path& dir) {
  if (!holds_study_data(dir)) {
    throw ReportError(fmt::format(
        "study data directory '{}' does not hold ansys_results.csv and ansys_grades.csv",
        dir.string()));
  }
  const CsvFile results(dir / "ansys_results.csv",
                        {"table", "problem", "quantity", "element", "contact", "algorithm", "mesh",
                         "value", "exact"});
  std::vector<StudyValue> values;
  values.reserve(results.size());
  for (std::size_t i = 0; i < results.size(); ++i) {
    StudyValue v;
    v.table = results.get(i, "table");
    v.problem = results.get(i, "problem");
    v.quantity = results.get(i, "quantity");
    v.element = results.get(i, "element");
    v.contact = results.get(i, "contact");
    v.algorithm = results.get(i, "algorithm");
    v.mesh = results.get(i, "mesh");
    v.printed = results.get(i, "value");
    v.value = results.number(i, "value");
    v.exact_printed = results.get(i, "exact");
    if (v.exact_printed != "inf")
      v.exact = results.number(i, "exact");
    values.push_back(std::move(v));
  }
  const CsvFile grades_csv(dir / "ansys_grades.csv",
                           {"table", "problem", "row", "element", "column", "grade", "converging"});
  std::vector<StudyGrade> grades;
  grades.reserve(grades_csv.size());
  for (std::size_t i = 0; i < grades_csv.size(); ++i) {
    StudyGrade g;
    g.table = grades_csv.get(i, "table");
    g.problem = grades_csv.get(i, "problem");
    g.row = grades_csv.get(i, "row");
    g.element = grades_csv.get(i, "element");
    g.column = grades_csv.get(i, "column");
    g.grade = grades_csv.get(i, "grade");
    g.converging = grades_csv.get(i, "converging") == "1";
    grades.push_back(std::move(g));
  }
  return StudyReference(std::move(values), std::move(grades));
}

fs::path default_study_data_dir() {
#ifdef CONTACT_SUITE_STUDY_DATA_DIR
  if (holds_study_data(CONTACT_SUITE_STUDY_DATA_DIR))
    return CONTACT_SUITE_STUDY_DATA_DIR;
#endif
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    fs::path dir = exe.parent_path();
    for (int up = 0; up < 5 && !dir.empty(); ++up) {
      if (holds_study_data(dir / "data" / "study"))
        return dir / "data" / "study";
      if (dir == dir.parent_path())
        break;
      dir = dir.parent_path();
    }
  }
  const fs::path cwd = fs::current_path(ec);
  if (!ec && holds_study_data(cwd / "data" / "study"))
    return cwd / "data" / "study";
  throw ReportError(
      "the study's data (data/study/ansys_results.csv) was not found next to the program or in "
      "the working directory; pass --study-data DIR");
}

std::string study_element(const std::string& element) {
  if (element == "Q4")
    return "4Q";
  if (element == "Q8")
    return "8Q";
  return element;
}

std::string study_algorithm(const std::string& algorithm) {
  if (algorithm == "AL" || algorithm == "PM")
    return "AL_PM";
  if (algorithm == "LMP" || algorithm == "PLM")
    return "LMP_PLM";
  if (algorithm == "MPC")
    return "IMC";
  return {};
}

std::string study_algorithm_label(const std::string& study_algorithm_key) {
  if (study_algorithm_key == "AL_PM")
    return "AL, PM";
  if (study_algorithm_key == "LMP_PLM")
    return "LMP, PLM";
  return study_algorithm_key;
}

std::string study_grade_column(const std::string& algorithm, const std::string& contact) {
  if (contact != "ss" && contact != "ns")
    return {};
  const std::string alg = study_algorithm(algorithm);
  if (alg == "AL_PM")
    return "AL_PM_" + contact;
  return alg;
}

}  // namespace cs::reports
