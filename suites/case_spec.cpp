#include "suites/case_spec.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

double parse_number(const std::string& name, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
    throw SuiteInputError(fmt::format("--set {}: '{}' is not a finite number", name, text));
  }
  if (errno == ERANGE && value != 0.0 && std::abs(value) < 1.0)
    errno = 0;  // a subnormal result is still the number written
  if (errno == ERANGE) {
    throw SuiteInputError(fmt::format(
        "--set {}: '{}' is out of the range of a double (it would read as {})", name, text, value));
  }
  return value == 0.0 ? 0.0 : value;  // -0 is 0: one case id
}

}  // namespace

const std::vector<ContactKind>& study_contacts() {
  static const std::vector<ContactKind> v{ContactKind::ss, ContactKind::ns};
  return v;
}

std::pair<std::string, double> parse_override(std::string_view text) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0 || eq + 1 == text.size()) {
    throw SuiteInputError(fmt::format("malformed --set '{}' (expected name=value)", text));
  }
  const std::string name(text.substr(0, eq));
  const std::string value_text(text.substr(eq + 1));
  // A value is a number or a ratio of two numbers (re_over_b=1/3).
  const auto slash = value_text.find('/');
  if (slash == std::string::npos)
    return {name, parse_number(name, value_text)};
  const double numerator = parse_number(name, value_text.substr(0, slash));
  const double value = numerator / parse_number(name, value_text.substr(slash + 1));
  if (!std::isfinite(value)) {
    throw SuiteInputError(fmt::format("--set {}: '{}' is not a finite number", name, value_text));
  }
  if (value == 0.0 && numerator != 0.0) {
    throw SuiteInputError(fmt::format(
        "--set {}: '{}' is out of the range of a double (it would read as 0)", name, value_text));
  }
  return {name, value == 0.0 ? 0.0 : value};  // 0/-4 is 0, as -0 is: one case id
}

std::map<std::string, double> parse_overrides(const std::vector<std::string>& texts) {
  std::map<std::string, double> out;
  for (const auto& text : texts) {
    const auto [name, value] = parse_override(text);
    if (!out.emplace(name, value).second)
      throw SuiteInputError(fmt::format("--set {} is given twice", name));
  }
  return out;
}

std::string plain_file_name(std::string_view text) {
  std::string name(text);
  for (char& c : name) {
    const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                       c == '.' || c == '=' || c == '@' || c == '-';
    if (!plain)
      c = '_';
  }
  return name;
}

void require_no_empty_items(const std::vector<std::string>& items, std::string_view option) {
  for (const auto& item : items) {
    if (item.empty())
      throw SuiteInputError(fmt::format("{}: empty item in the list (two commas?)", option));
  }
}

std::vector<std::string> split_list_option(const std::vector<std::string>& raw,
                                           std::string_view option) {
  std::vector<std::string> items;
  for (const auto& text : raw) {
    std::size_t start = 0;
    while (true) {
      const auto comma = text.find(',', start);
      items.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
      if (comma == std::string::npos)
        break;
      start = comma + 1;
    }
  }
  require_no_empty_items(items, option);
  return items;
}

}  // namespace cs::suites
