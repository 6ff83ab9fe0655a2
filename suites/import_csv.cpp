#include "suites/import_csv.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <system_error>
#include <type_traits>

#include <fmt/format.h>

namespace cs::suites {
namespace {

enum Column {
  kCaseId,
  kX,
  kSigmaZ,
  kSigmaX,
  kContactPressure,
  kRequired,  // the columns above are required, the ones below optional
  kOption = kRequired,
  kWallSeconds,
  kIterations,
  kEquations,
  kPeakRss,
  kColumns
};
constexpr std::array<std::string_view, kColumns> kNames{
    "case_id",      "x",          "sigma_z",     "sigma_x",    "contact_pressure", "option",
    "wall_seconds", "iterations", "n_equations", "peak_rss_mb"};

/// Where an error is: the file, the line and (0: none) the 1-based column with its name.
struct Place {
  std::string_view source;
  int line = 0;
  int column = 0;
  std::string_view name;
};

[[noreturn]] void fail(const Place& at, const std::string& what) {
  if (at.column > 0)
    throw ImportError(
        fmt::format("{}:{}: column {} ({}): {}", at.source, at.line, at.column, at.name, what));
  if (at.line > 0)
    throw ImportError(fmt::format("{}:{}: {}", at.source, at.line, what));
  throw ImportError(fmt::format("{}: {}", at.source, what));
}

/// A field as a message shows it: printable ASCII, at most 40 characters.
std::string shown(std::string_view text) {
  std::string out;
  for (char c : text.substr(0, 40))
    out += c >= 0x20 && c < 0x7f ? c : '?';
  return text.size() > 40 ? out + "..." : out;
}

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  return first == std::string_view::npos ? std::string_view{}
                                         : s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

/// The trimmed comma-separated fields of a line.
std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  while (true) {
    const auto comma = line.find(',');
    fields.push_back(trimmed(line.substr(0, comma)));
    if (comma == std::string_view::npos)
      return fields;
    line.remove_prefix(comma + 1);
  }
}

/// A finite double written in full (an optional leading '+').
double parse_number(std::string_view text, const Place& at) {
  if (text.empty())
    fail(at, "empty value (expected a number)");
  std::string_view digits = text;
  if (digits.starts_with('+'))
    digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range)
    fail(at, fmt::format("'{}' is out of the range of a double", shown(text)));
  if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty() ||
      digits.starts_with('-') != text.starts_with('-') || digits.starts_with('+'))
    fail(at, fmt::format("'{}' is not a number", shown(text)));
  if (!std::isfinite(value))
    fail(at, fmt::format("'{}' is not a finite number", shown(text)));
  return value == 0.0 ? 0.0 : value;  // -0 is 0: one node
}

/// The file position of each of the five columns, from the header line.
std::array<int, kColumns> read_header(std::string_view line, const Place& at) {
  std::array<int, kColumns> index;
  index.fill(-1);
  const auto fields = split_fields(line);
  for (int k = 0; k < static_cast<int>(fields.size()); ++k) {
    const Place here{at.source, at.line, k + 1, "header"};
    int c = 0;
    while (c < kColumns && kNames[c] != fields[k])
      ++c;
    if (c == kColumns)
      fail(here,
           fmt::format("unknown column '{}' (expected {}, and optionally {})", shown(fields[k]),
                       std::string(kImportHeader), std::string(kImportOptionalColumns)));
    if (index[c] >= 0)
      fail(here,
           fmt::format("column '{}' is given twice (also column {})", kNames[c], index[c] + 1));
    index[c] = k;
  }
  for (int c = 0; c < kRequired; ++c) {
    if (index[c] < 0)
      fail(at, fmt::format("missing column '{}' in the header (expected {})", kNames[c],
                           std::string(kImportHeader)));
  }
  return index;
}

/// `value` into a case's `slot` (the first row that gives it), or an error if an earlier row
/// of the case gave another value.
template <class T>
void merge_case_value(std::optional<T>& slot, const std::optional<T>& value, std::string_view id,
                      const Place& at) {
  if (!value)
    return;
  if (slot && *slot != *value)
    fail(at,
         fmt::format("case '{}': {} differs from an earlier row of the case", shown(id), at.name));
  slot = value;
}

/// Collects the rows by case id and refuses a node given twice.
class CaseCollector {
 public:
  explicit CaseCollector(std::string_view source) : source_(source) {}

  void add(std::string_view id, const ImportRow& row, const ImportedCaseValues& values,
           const std::array<Place, kColumns>& places) {
    // A case is its id and its option: two options of a code share the id's study fields.
    const std::string key = std::string(id) + '\n' + values.option.value_or("");
    auto [it, inserted] = slot_.try_emplace(key, cases_.size());
    if (inserted) {
      cases_.push_back({std::string(id), row.line, {}, {}});
      cases_.back().values.option = values.option;
    }
    ImportedCase& c = cases_[it->second];
    merge_case_value(c.values.wall_seconds, values.wall_seconds, id, places[kWallSeconds]);
    merge_case_value(c.values.iterations, values.iterations, id, places[kIterations]);
    merge_case_value(c.values.n_equations, values.n_equations, id, places[kEquations]);
    merge_case_value(c.values.peak_rss_mb, values.peak_rss_mb, id, places[kPeakRss]);
    const auto [seen, fresh] = lines_[it->second].try_emplace(row.x, row.line);
    if (!fresh)
      fail({source_, row.line, 0, {}},
           fmt::format("duplicate node: case '{}'{} already has x = {} on line {}", shown(id),
                       values.option ? " (option " + *values.option + ")" : std::string(), row.x,
                       seen->second));
    c.rows.push_back(row);
  }

  std::vector<ImportedCase> take() { return std::move(cases_); }

 private:
  std::string_view source_;
  std::vector<ImportedCase> cases_;
  std::map<std::string, std::size_t> slot_;
  std::map<std::size_t, std::map<double, int>> lines_;  ///< per case: x -> line
};

/// A count (iterations, equations): a whole number from 0 to 2^31 - 1.
int parse_count(std::string_view text, const Place& at) {
  const double v = parse_number(text, at);
  if (v < 0 || v != std::floor(v) || v > 2147483647.0)
    fail(at, fmt::format("'{}' is not a whole number >= 0", shown(text)));
  return static_cast<int>(v);
}

/// A time or memory: a number >= 0.
double parse_amount(std::string_view text, const Place& at) {
  const double v = parse_number(text, at);
  if (v < 0)
    fail(at, fmt::format("'{}' is negative", shown(text)));
  return v;
}

/// The optional per-case columns of one row (an empty or absent field gives nothing).
ImportedCaseValues read_case_values(const std::vector<std::string_view>& fields,
                                    const std::array<int, kColumns>& index,
                                    const std::array<Place, kColumns>& places) {
  const auto given = [&](Column c) { return index[c] >= 0 && !fields[index[c]].empty(); };
  ImportedCaseValues v;
  if (given(kOption)) {
    const std::string_view label = fields[index[kOption]];
    const bool plain =
        label.size() <= 64 && std::all_of(label.begin(), label.end(), [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
        });
    if (!plain)
      fail(places[kOption],
           fmt::format("'{}' is not an option label (1-64 of [A-Za-z0-9._-])", shown(label)));
    v.option = std::string(label);
  }
  if (given(kWallSeconds))
    v.wall_seconds = parse_amount(fields[index[kWallSeconds]], places[kWallSeconds]);
  if (given(kIterations))
    v.iterations = parse_count(fields[index[kIterations]], places[kIterations]);
  if (given(kEquations))
    v.n_equations = parse_count(fields[index[kEquations]], places[kEquations]);
  if (given(kPeakRss))
    v.peak_rss_mb = parse_amount(fields[index[kPeakRss]], places[kPeakRss]);
  return v;
}

/// One data row into `collector`.
void read_row(std::string_view line, const std::array<int, kColumns>& index, const Place& at,
              CaseCollector& collector) {
  const auto fields = split_fields(line);
  const auto n_columns = static_cast<std::size_t>(
      std::count_if(index.begin(), index.end(), [](int i) { return i >= 0; }));
  if (fields.size() != n_columns)
    fail(at, fmt::format("{} fields, the header has {}", fields.size(), n_columns));
  std::array<Place, kColumns> places;
  for (int c = 0; c < kColumns; ++c)
    places[c] = Place{at.source, at.line, index[c] + 1, kNames[c]};
  auto place = [&](Column c) { return places[c]; };
  const std::string_view id = fields[index[kCaseId]];
  if (id.empty())
    fail(place(kCaseId), "empty case id");
  for (const auto& f : fields) {
    if (f.find('"') != std::string_view::npos)
      fail(at, "quoted fields are not supported (no field of the layout needs quotes)");
  }
  ImportRow row;
  row.line = at.line;
  row.x = parse_number(fields[index[kX]], place(kX));
  row.sigma_z = parse_number(fields[index[kSigmaZ]], place(kSigmaZ));
  row.sigma_x = parse_number(fields[index[kSigmaX]], place(kSigmaX));
  if (const auto p = fields[index[kContactPressure]]; !p.empty())
    row.contact_pressure = parse_number(p, place(kContactPressure));
  collector.add(id, row, read_case_values(fields, index, places), places);
}

}  // namespace

std::vector<ImportedCase> parse_import_csv(std::string_view text, std::string_view source_name) {
  if (text.starts_with("\xEF\xBB\xBF"))
    text.remove_prefix(3);  // a UTF-8 byte-order mark, as spreadsheets write
  std::optional<std::array<int, kColumns>> index;
  int header_line = 0;
  CaseCollector collector(source_name);
  int line_number = 0;
  bool any_row = false;
  while (!text.empty()) {
    const auto end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++line_number;
    if (line.ends_with('\r'))
      line.remove_suffix(1);
    const std::string_view content = trimmed(line);
    if (content.empty() || content.starts_with('#'))
      continue;
    const Place at{source_name, line_number, 0, {}};
    if (!index) {
      index = read_header(line, at);
      header_line = line_number;
      continue;
    }
    read_row(line, *index, at, collector);
    any_row = true;
  }
  if (!index)
    fail({source_name, 0, 0, {}},
         fmt::format("empty file (expected the header {})", std::string(kImportHeader)));
  if (!any_row)
    fail({source_name, header_line, 0, {}}, "no data rows after the header");
  return collector.take();
}

namespace {

template <class T>
std::string field_text(const std::optional<T>& v) {
  if (!v)
    return {};
  if constexpr (std::is_same_v<T, std::string>)
    return *v;
  else
    return fmt::format("{:.17g}", static_cast<double>(*v));
}

}  // namespace

std::string import_csv_text(const std::vector<ImportedCase>& cases) {
  const bool values = std::any_of(cases.begin(), cases.end(), [](const ImportedCase& c) {
    return c.values != ImportedCaseValues{};
  });
  std::string out = std::string(kImportHeader);
  if (values)
    out += "," + std::string(kImportOptionalColumns);
  out += "\n";
  for (const auto& c : cases) {
    // The option on every row (it is part of the case), the other values on its first row only.
    bool first = true;
    for (const auto& r : c.rows) {
      out += fmt::format("{},{:.17g},{:.17g},{:.17g},", c.case_id, r.x, r.sigma_z, r.sigma_x);
      if (r.contact_pressure)
        out += fmt::format("{:.17g}", *r.contact_pressure);
      if (values) {
        const ImportedCaseValues none;
        const ImportedCaseValues& v = first ? c.values : none;
        out += fmt::format(",{},{},{},{},{}", field_text(c.values.option),
                           field_text(v.wall_seconds), field_text(v.iterations),
                           field_text(v.n_equations), field_text(v.peak_rss_mb));
      }
      out += '\n';
      first = false;
    }
  }
  return out;
}

}  // namespace cs::suites
