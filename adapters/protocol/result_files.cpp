#include "adapters/protocol/result_files.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "schema/json_file.hpp"
#include "schema/schema_error.hpp"

namespace cs::adapters::protocol {
namespace {

/// A failure while reading one file: its message is the case's reason.
struct ReadFailure {
  std::string message;
};

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ','))
    out.push_back(field);
  if (!line.empty() && line.back() == ',')
    out.emplace_back();
  return out;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\r' || s.back() == ' '))
    s.pop_back();
  std::size_t start = 0;
  while (start < s.size() && s[start] == ' ')
    ++start;
  return s.substr(start);
}

double parse_number(const std::string& text, const std::string& where) {
  const std::string t = trimmed(text);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size())
    throw ReadFailure{fmt::format("{}: '{}' is not a number", where, t)};
  if (!std::isfinite(v))
    throw ReadFailure{fmt::format("{}: value {} is not finite", where, t)};
  return v;
}

/// Reads a CSV with the exact header `header`; calls row(node, values) per data line,
/// `node` the index (id - 1, checked against n_nodes; a node given twice is a failure). Returns
/// which nodes the file gave.
template <class Row>
std::vector<bool> read_node_csv(const std::filesystem::path& file, const std::string& header,
                                int n_nodes, Row row) {
  std::ifstream in(file);
  if (!in)
    throw ReadFailure{fmt::format("{} is missing", file.filename().string())};
  std::string line;
  const std::string name = file.filename().string();
  if (!std::getline(in, line) || trimmed(line) != header)
    throw ReadFailure{fmt::format("{}: the header is not '{}'", name, header)};
  const std::size_t n_columns = split_csv_line(header).size();
  std::vector<bool> seen(static_cast<std::size_t>(n_nodes), false);
  for (int number = 2; std::getline(in, line); ++number) {
    if (trimmed(line).empty())
      continue;
    const std::string where = fmt::format("{} line {}", name, number);
    const auto fields = split_csv_line(trimmed(line));
    if (fields.size() != n_columns)
      throw ReadFailure{fmt::format("{}: {} values, expected {}", where, fields.size(), n_columns)};
    const double id = parse_number(fields[0], where);
    if (id != std::floor(id) || id < 1 || id > n_nodes)
      throw ReadFailure{fmt::format("{}: node id {} is not in 1..{}", where, fields[0], n_nodes)};
    const auto node = static_cast<std::size_t>(id) - 1;
    if (seen[node])
      throw ReadFailure{fmt::format("{}: node {} is given twice", where, fields[0])};
    seen[node] = true;
    std::vector<double> values;
    for (std::size_t k = 1; k < fields.size(); ++k)
      values.push_back(parse_number(fields[k], where));
    row(static_cast<int>(node), values);
  }
  return seen;
}

/// status.json's count `key` (0 when absent): a whole number in [0, most], else a ReadFailure.
long long count(const nlohmann::json& j, const char* key, long long most) {
  if (!j.contains(key))
    return 0;
  const nlohmann::json& v = j.at(key);
  const double d = v.is_number() ? v.get<double>() : -1.0;  // NaN and inf cannot be JSON
  if (!(d >= 0.0 && d <= static_cast<double>(most) && d == std::floor(d)))
    throw ReadFailure{
        fmt::format("status.json: {} is {}, not a count from 0 to {}", key, v.dump(), most)};
  return static_cast<long long>(d);
}

void read_status(const std::filesystem::path& file, ResultFiles& out) {
  std::ifstream in(file);
  if (!in)
    return;
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  nlohmann::json j;
  try {  // as results files are read: nesting bounded, no key twice
    j = schema::parse_json_text(text, "status", "status.json");
  } catch (const schema::SchemaError& e) {
    throw ReadFailure{e.what()};
  }
  try {
    if (j.contains("converged"))
      out.converged = j.at("converged").get<bool>();
    out.iterations = static_cast<int>(count(j, "iterations", std::numeric_limits<int>::max()));
    out.n_equations = count(j, "n_equations", std::numeric_limits<long long>::max() / 2);
    out.reason = j.value("reason", std::string());
    // One line: the reason goes into progress lines, Markdown tables and one-line messages.
    std::replace_if(
        out.reason.begin(), out.reason.end(),
        [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }, ' ');
    out.solver_version = j.value("solver_version", std::string());
  } catch (const nlohmann::json::exception& e) {
    throw ReadFailure{fmt::format("status.json: a value of the wrong type ({})", e.what())};
  }
}

void read_all(const std::filesystem::path& dir, int n_nodes, const std::vector<int>& required,
              ResultFiles& out) {
  read_status(dir / "status.json", out);
  out.displacement = Eigen::VectorXd::Zero(2 * n_nodes);
  const std::vector<bool> seen = read_node_csv(dir / "displacements.csv", "node_id,ux,uz", n_nodes,
                                               [&](int n, const std::vector<double>& v) {
                                                 out.displacement[2 * n] = v[0];
                                                 out.displacement[2 * n + 1] = v[1];
                                               });
  for (int n : required)
    if (!seen[n])
      throw ReadFailure{fmt::format("displacements.csv: node {} is missing", n + 1)};
  if (std::filesystem::exists(dir / "stresses.csv")) {
    out.stresses_given = true;
    out.stress.assign(n_nodes, Eigen::Vector4d::Zero());
    out.has_stress =
        read_node_csv(dir / "stresses.csv", "node_id,sigma_x,sigma_z,tau_xz,sigma_out_of_plane",
                      n_nodes, [&](int n, const std::vector<double>& v) {
                        out.stress[n] = {v[0], v[1], v[2], v[3]};
                      });
  }
  if (std::filesystem::exists(dir / "contact_pressure.csv")) {
    out.contact_pressure_given = true;
    read_node_csv(dir / "contact_pressure.csv", "node_id,pressure", n_nodes,
                  [&](int n, const std::vector<double>& v) {
                    out.contact_pressure.push_back({n, v[0]});
                  });
  }
}

}  // namespace

ResultFiles read_result_files(const std::filesystem::path& case_dir, int n_nodes,
                              const std::vector<int>& required_nodes) {
  ResultFiles out;
  try {
    read_all(case_dir, n_nodes, required_nodes, out);
  } catch (const ReadFailure& f) {
    out.error = f.message;
  }
  return out;
}

}  // namespace cs::adapters::protocol
