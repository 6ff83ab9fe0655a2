#include "suites/case_spec.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

double parse_number(const std::string& name, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
    throw SuiteInputError(fmt::format("--set {}: '{}' is not a finite number", name, text));
  }
  return value;
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
  const double value = slash == std::string::npos
                           ? parse_number(name, value_text)
                           : parse_number(name, value_text.substr(0, slash)) /
                                 parse_number(name, value_text.substr(slash + 1));
  if (!std::isfinite(value)) {
    throw SuiteInputError(fmt::format("--set {}: '{}' is not a finite number", name, value_text));
  }
  return {name, value};
}

}  // namespace cs::suites
