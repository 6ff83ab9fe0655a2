#include "suites/parameter_sweep.hpp"

#include <fmt/format.h>

#include "suites/parameters.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

SweepAxis parse_sweep(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw SuiteInputError(fmt::format("malformed --sweep '{}' (expected key=v1,v2,...)", text));
  SweepAxis axis{text.substr(0, eq), {}};
  const std::string list = text.substr(eq + 1);
  if (list.empty())
    throw SuiteInputError(fmt::format("--sweep {}: empty value list", axis.key));
  const auto items = split_list_option({list}, fmt::format("--sweep {}", axis.key));
  for (const auto& item : items) {
    const double value = parse_override(axis.key + "=" + item).second;
    for (double earlier : axis.values) {
      if (earlier == value)
        throw SuiteInputError(fmt::format("--sweep {}: value {} is given twice", axis.key, item));
    }
    axis.values.push_back(value);
  }
  return axis;
}

const ParameterSpec* find_spec(const std::vector<ParameterSpec>& specs, const std::string& key) {
  for (const auto& s : specs) {
    if (s.name == key)
      return &s;
  }
  return nullptr;
}

}  // namespace

std::vector<SweepAxis> parse_sweeps(const std::vector<std::string>& texts) {
  std::vector<SweepAxis> axes;
  for (const auto& text : texts) {
    SweepAxis axis = parse_sweep(text);
    for (const auto& earlier : axes) {
      if (earlier.key == axis.key)
        throw SuiteInputError(fmt::format("--sweep {} is given twice", axis.key));
    }
    axes.push_back(std::move(axis));
  }
  return axes;
}

void validate_sweeps(const std::vector<SweepAxis>& sweeps,
                     const std::map<std::string, double>& overrides,
                     const std::vector<ProblemId>& problems) {
  for (const auto& axis : sweeps) {
    if (overrides.contains(axis.key)) {
      throw SuiteInputError(
          fmt::format("{} is both swept (--sweep) and set (--set): give it one way", axis.key));
    }
    for (ProblemId p : problems) {
      const auto& specs = problem_descriptor(p).parameters;
      const ParameterSpec* spec = find_spec(specs, axis.key);
      if (spec == nullptr) {
        std::string known;
        for (const auto& s : specs)
          known += (known.empty() ? "" : ", ") + s.name;
        throw SuiteInputError(
            fmt::format("--sweep {}: problem {} has no such parameter (it has: {})", axis.key,
                        to_string(p), known));
      }
      for (double v : axis.values) {
        if (!accepts(*spec, v)) {
          throw SuiteInputError(fmt::format("--sweep {}={:g}: out of range {} for problem {}",
                                            axis.key, v, range_text(*spec), to_string(p)));
        }
      }
    }
  }
}

std::vector<std::map<std::string, double>> sweep_points(const std::vector<SweepAxis>& sweeps) {
  std::vector<std::map<std::string, double>> points{{}};
  for (const auto& axis : sweeps) {
    std::vector<std::map<std::string, double>> next;
    for (const auto& point : points) {
      for (double v : axis.values) {
        auto p = point;
        p[axis.key] = v;
        next.push_back(std::move(p));
      }
    }
    points = std::move(next);
  }
  return points;
}

}  // namespace cs::suites
