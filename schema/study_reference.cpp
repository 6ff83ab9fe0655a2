#include "schema/study_reference.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <system_error>
#include <tuple>

#include <fmt/format.h>

#include "schema/schema_error.hpp"

namespace cs::schema {
namespace {

namespace fs = std::filesystem;

/// The contact key of the study's columns that hold for node-to-surface and
/// surface-to-surface alike (data/study/README.md).
constexpr const char* kEitherContact = "either";
/// The printed exact value of a singular problem.
constexpr const char* kInfinite = "inf";

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
      throw SchemaError(fmt::format("study data file '{}' cannot be read", path_));
    std::string line;
    if (!std::getline(in, line))
      throw SchemaError(fmt::format("study data file '{}' is empty", path_));
    header_ = split_commas(line);
    for (const auto& name : required) {
      if (column(name) < 0)
        throw SchemaError(fmt::format("study data file '{}' has no column '{}'", path_, name));
    }
    int line_no = 1;
    while (std::getline(in, line)) {
      ++line_no;
      if (line.empty() || line == "\r")
        continue;
      auto fields = split_commas(line);
      if (fields.size() != header_.size()) {
        throw SchemaError(fmt::format("study data file '{}' line {}: {} fields, expected {}", path_,
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
      throw SchemaError(fmt::format("study data file '{}' line {}: '{}' is not a number ({})",
                                    path_, line_numbers_[row], text, name));
    }
    return v;
  }
  /// A name of the vocabulary (schema/name_table.hpp), names and aliases accepted.
  template <Axis E>
  E name(std::size_t row, const std::string& column_name) const {
    const std::string& text = get(row, column_name);
    if (const auto v = try_parse<E>(text))
      return *v;
    fail(row, fmt::format("unknown {} '{}' in column '{}' (expected one of: {})", axis_name(E{}),
                          text, column_name, accepted_names<E>()));
  }
  [[noreturn]] void fail(std::size_t row, const std::string& what) const {
    throw SchemaError(
        fmt::format("study data file '{}' line {}: {}", path_, line_numbers_[row], what));
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

/// The first algorithm of the study column a CSV names: by its study column key ("AL_PM") or
/// by the name the study gives an algorithm of its own column ("IMC"); nullopt if neither.
std::optional<Algorithm> study_column_named(std::string_view key) {
  for (const Algorithm a : values<Algorithm>()) {
    if (traits(a).study_column == key)
      return study_column_members(a).front();
  }
  if (const auto a = try_parse<Algorithm>(key))
    return study_column_members(*a).front();
  return std::nullopt;
}

Algorithm study_algorithm_of(const CsvFile& csv, std::size_t row, const std::string& column) {
  const std::string& key = csv.get(row, column);
  if (const auto a = study_column_named(key))
    return *a;
  csv.fail(row, fmt::format("unknown study algorithm column '{}'", key));
}

std::optional<ContactKind> study_contact_of(const CsvFile& csv, std::size_t row) {
  if (csv.get(row, "contact") == kEitherContact)
    return std::nullopt;
  const ContactKind c = csv.name<ContactKind>(row, "contact");
  if (!traits(c).in_study)
    csv.fail(row, fmt::format("contact '{}' was not in the study", to_string(c)));
  return c;
}

/// A Table 2 column: a study column key, followed by "_<contact>" where the study separates
/// the contact types (AL_PM_ss).
std::pair<Algorithm, std::optional<ContactKind>> grade_column_of(const CsvFile& csv,
                                                                 std::size_t row) {
  const std::string& key = csv.get(row, "column");
  for (const ContactKind c : values<ContactKind>()) {
    const std::string suffix = fmt::format("_{}", to_string(c));
    if (!traits(c).in_study || key.size() <= suffix.size() ||
        key.compare(key.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    if (const auto a =
            study_column_named(std::string_view(key).substr(0, key.size() - suffix.size())))
      return {*a, c};
  }
  if (const auto a = study_column_named(key))
    return {*a, std::nullopt};
  csv.fail(row, fmt::format("unknown Table 2 column '{}'", key));
}

std::vector<StudyValue> read_values(const fs::path& file) {
  const CsvFile csv(file, {"table", "problem", "quantity", "element", "contact", "algorithm",
                           "mesh", "value", "exact"});
  std::vector<StudyValue> values;
  values.reserve(csv.size());
  for (std::size_t i = 0; i < csv.size(); ++i) {
    StudyValue v;
    v.table = csv.get(i, "table");
    v.problem = csv.name<ProblemId>(i, "problem");
    v.quantity = csv.name<Quantity>(i, "quantity");
    v.element = csv.name<Element>(i, "element");
    v.contact = study_contact_of(csv, i);
    v.algorithm = study_algorithm_of(csv, i, "algorithm");
    v.mesh = csv.name<MeshLevel>(i, "mesh");
    v.printed = csv.get(i, "value");
    v.value = csv.number(i, "value");
    v.exact_printed = csv.get(i, "exact");
    if (v.exact_printed != kInfinite)
      v.exact = csv.number(i, "exact");
    values.push_back(std::move(v));
  }
  return values;
}

std::vector<StudyGrade> read_grades(const fs::path& file) {
  const CsvFile csv(file, {"table", "problem", "row", "element", "column", "grade", "converging"});
  std::vector<StudyGrade> grades;
  grades.reserve(csv.size());
  for (std::size_t i = 0; i < csv.size(); ++i) {
    StudyGrade g;
    g.table = csv.get(i, "table");
    g.problem = csv.name<ProblemId>(i, "problem");
    g.row = csv.get(i, "row");
    g.element = csv.name<Element>(i, "element");
    std::tie(g.algorithm, g.contact) = grade_column_of(csv, i);
    g.grade = csv.name<Grade>(i, "grade");
    g.converging = csv.get(i, "converging") == "1";
    grades.push_back(std::move(g));
  }
  return grades;
}

/// table1_elements.csv (the study's Table 1), when the directory has it.
std::map<std::pair<ProblemId, MeshLevel>, int> read_table1(const fs::path& file) {
  std::map<std::pair<ProblemId, MeshLevel>, int> out;
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    return out;
  const CsvFile csv(file, {"column", "problem", "mesh", "elements"});
  for (std::size_t i = 0; i < csv.size(); ++i) {
    const std::string text = csv.get(i, "elements");
    std::size_t used = 0;
    int n = 0;
    try {
      n = std::stoi(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text.size() || n <= 0) {
      throw SchemaError(fmt::format("{}: row {}: elements '{}' is not a positive integer",
                                    file.string(), i + 2, text));
    }
    out[{csv.name<ProblemId>(i, "problem"), csv.name<MeshLevel>(i, "mesh")}] = n;
  }
  return out;
}

bool holds_study_data(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / "ansys_results.csv", ec) &&
         fs::is_regular_file(dir / "ansys_grades.csv", ec);
}

}  // namespace

std::string StudyGrade::cell() const {
  return std::string(to_string(grade)) + (converging ? ", c" : "");
}

std::string StudyGrade::column_label() const {
  return study_column_label(algorithm) +
         (contact ? fmt::format(" {}", to_string(*contact)) : std::string());
}

StudyReference::StudyReference(std::vector<StudyValue> values, std::vector<StudyGrade> grades,
                               std::map<std::pair<ProblemId, MeshLevel>, int> table1)
    : values_(std::move(values)), grades_(std::move(grades)), table1_(std::move(table1)) {}

std::optional<int> StudyReference::table1_elements(ProblemId problem, MeshLevel mesh) const {
  const auto it = table1_.find({problem, mesh});
  return it == table1_.end() ? std::nullopt : std::optional<int>(it->second);
}

const StudyValue* StudyReference::find_exact_key(ProblemId problem, Quantity quantity,
                                                 Element element, Algorithm algorithm,
                                                 std::optional<ContactKind> contact,
                                                 MeshLevel mesh) const {
  for (const auto& v : values_) {
    if (v.problem == problem && v.quantity == quantity && v.element == element &&
        same_study_column(v.algorithm, algorithm) && v.contact == contact && v.mesh == mesh)
      return &v;
  }
  return nullptr;
}

StudyMatch StudyReference::find_value(ProblemId problem, Quantity quantity, Element element,
                                      Algorithm algorithm, ContactKind contact,
                                      MeshLevel mesh) const {
  if (!traits(contact).in_study)
    return {};
  if (const auto* v = find_exact_key(problem, quantity, element, algorithm, contact, mesh))
    return {v, false};
  if (const auto* v = find_exact_key(problem, quantity, element, algorithm, std::nullopt, mesh))
    return {v, false};
  // The study's node-to-surface tables that print no LMP, PLM column say "LMP, PLM have the
  // same results as for surface-to-surface elements".
  if (same_study_column(algorithm, Algorithm::LMP) && contact == ContactKind::ns) {
    if (const auto* v =
            find_exact_key(problem, quantity, element, algorithm, ContactKind::ss, mesh))
      return {v, true};
  }
  return {};
}

const StudyGrade* StudyReference::find_grade(ProblemId problem, const std::string& study_row,
                                             Element element, Algorithm algorithm,
                                             ContactKind contact) const {
  if (!traits(contact).in_study)
    return nullptr;
  for (const auto& g : grades_) {
    if (g.problem == problem && g.row == study_row && g.element == element &&
        same_study_column(g.algorithm, algorithm) && (!g.contact || *g.contact == contact))
      return &g;
  }
  return nullptr;
}

std::string StudyReference::printed_exact(ProblemId problem, Quantity quantity) const {
  for (const auto& v : values_) {
    if (v.problem == problem && v.quantity == quantity)
      return v.exact_printed;
  }
  return {};
}

bool StudyReference::separates_contacts(Algorithm a) const {
  return std::any_of(grades_.begin(), grades_.end(), [&](const StudyGrade& g) {
    return same_study_column(g.algorithm, a) && g.contact.has_value();
  });
}

std::string StudyReference::grade_table(Element element) const {
  for (const auto& g : grades_) {
    if (g.element == element)
      return g.table;
  }
  return {};
}

std::vector<std::pair<ProblemId, std::string>> StudyReference::grade_rows() const {
  std::vector<std::pair<ProblemId, std::string>> rows;
  for (const auto& g : grades_) {
    const std::pair key(g.problem, g.row);
    if (std::find(rows.begin(), rows.end(), key) == rows.end())
      rows.push_back(key);
  }
  return rows;
}

std::vector<ProblemId> StudyReference::singular_problems() const {
  std::vector<ProblemId> out;
  for (const auto id : schema::values<ProblemId>()) {
    const bool singular = std::any_of(values_.begin(), values_.end(), [&](const StudyValue& v) {
      return v.problem == id && !v.exact;
    });
    if (singular)
      out.push_back(id);
  }
  return out;
}

StudyReference load_study_reference(const fs::path& dir) {
  if (!holds_study_data(dir)) {
    throw SchemaError(fmt::format(
        "study data directory '{}' does not hold ansys_results.csv and ansys_grades.csv",
        dir.string()));
  }
  return StudyReference(read_values(dir / "ansys_results.csv"),
                        read_grades(dir / "ansys_grades.csv"),
                        read_table1(dir / "table1_elements.csv"));
}

fs::path default_study_data_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  // An installed (or unpacked) program reads its own copy, PREFIX/bin -> PREFIX/share, even
  // where the source tree it was built from still exists.
  const fs::path installed =
      exe.parent_path().parent_path() / "share" / "contact-suite" / "data" / "study";
  if (!ec && holds_study_data(installed))
    return installed;
#ifdef CONTACT_SUITE_STUDY_DATA_DIR
  if (holds_study_data(CONTACT_SUITE_STUDY_DATA_DIR))
    return CONTACT_SUITE_STUDY_DATA_DIR;
#endif
  if (!ec) {
    fs::path dir = exe.parent_path();
    for (int up = 0; up < 5 && !dir.empty(); ++up) {
      if (holds_study_data(dir / "data" / "study"))
        return dir / "data" / "study";
      const fs::path installed = dir / "share" / "contact-suite" / "data" / "study";
      if (holds_study_data(installed))  // an installed program: PREFIX/bin -> PREFIX/share
        return installed;
      if (dir == dir.parent_path())
        break;
      dir = dir.parent_path();
    }
  }
  const fs::path cwd = fs::current_path(ec);
  if (!ec && holds_study_data(cwd / "data" / "study"))
    return cwd / "data" / "study";
  throw SchemaError(
      "the study's data (data/study/ansys_results.csv) was not found next to the program or in "
      "the working directory; pass --study-data DIR");
}

bool same_study_column(Algorithm a, Algorithm b) {
  return traits(a).study_column == traits(b).study_column;
}

std::vector<Algorithm> study_column_members(Algorithm a) {
  std::vector<Algorithm> out;
  for (const Algorithm b : values<Algorithm>()) {
    if (same_study_column(a, b))
      out.push_back(b);
  }
  return out;
}

std::vector<Algorithm> study_columns() {
  std::vector<Algorithm> out;
  for (const Algorithm a : values<Algorithm>()) {
    if (study_column_members(a).front() == a)
      out.push_back(a);
  }
  return out;
}

std::string study_column_label(Algorithm a) {
  std::string out;
  for (const Algorithm b : study_column_members(a))
    out += fmt::format("{}{}", out.empty() ? "" : ", ", study_name(b));
  return out;
}

}  // namespace cs::schema
