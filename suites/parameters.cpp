#include "suites/parameters.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

std::vector<ParameterSpec> common_parameters(double default_p_over_E) {
  return {
      {"nu", 0.25, 0.0, 0.5, true, false, "Poisson's ratio of the indented body"},
      // Below 1e-21 the indentation drowns in the round-off of the coordinates (H_p gives
      // +22 % at 1e-22, -100 % at 1e-300); every graded value is the same from 1e-20 to 1e-3,
      // so 1e-12 leaves a wide margin. Above 0.1 the small-strain model no longer holds.
      {"p_over_E", default_p_over_E, 1e-12, 0.1, true, true,
       "applied pressure p over Young's modulus E of the indented body (the answers are linear "
       "in it; below 1e-12 round-off takes over)"},
      {"E_ratio", 1e6, 1.0, 1e12, true, true,
       "Young's modulus of the meshed indenter over that of the indented body"},
      // From 1e5 up the penalty's condensed system is too ill-conditioned for the active set
      // to settle (H_p C: cycling, reported as not converged, up to 1e200; at 1e300 it
      // "converged" 31 % off). Below 1e-6 the penetration is the whole answer.
      // Default 100 (it was 1), from the sweeps of ci/sweeps.sh (issue 14; the report's
      // "Parameter sweeps" section prints the numbers): the penalty is k = FKN E / h per
      // contact point, so FKN already scales with the modulus and the element size, and FKN
      // = 100 is the smallest decade at which every smooth AL/PM row (P, P', H, S; Q4 and Q8;
      // ss, ns and mortar) is e or g on the F mesh: at 1, H_a is s (-6 %, Q4 and Q8 ss) and u
      // with Q8 mortar (-24 %) and Q8 ns (+25 %), P_a Q8 ns u (+34 %). Iterations rise from
      // 5-8 to 5-23 (LMP: 5-12) and saturate above 100; the first case that cycles is at 1e4.
      {"fkn", 100.0, 1e-6, 1e4, true, true,
       "normal penalty stiffness factor FKN (PM, AL): multiplies the element stiffness scale; "
       "above 1e4 the penalty system is too ill-conditioned to settle"},
      {"ftoln", 0.1, 0.0, 1.0, false, true,
       "penetration tolerance FTOLN (AL), as a fraction of the underlying element depth (more "
       "than one element's depth is not a tolerance)"},
      {"pinball", 1.0, 1e-3, 1e3, true, true,
       "pinball radius (candidate search, MPC ties), as a multiple of the underlying element "
       "depth"},
  };
}

Parameters::Parameters(const std::vector<ParameterSpec>& specs,
                       const std::map<std::string, double>& overrides,
                       std::string_view problem_name) {
  for (const auto& s : specs) {
    values_[s.name] = s.default_value;
    overridden_[s.name] = false;
  }
  for (const auto& [name, value] : overrides) {
    const ParameterSpec* spec = nullptr;
    for (const auto& s : specs) {
      if (s.name == name)
        spec = &s;
    }
    if (spec == nullptr) {
      std::string known;
      for (const auto& s : specs)
        known += (known.empty() ? "" : ", ") + s.name;
      throw SuiteInputError(
          fmt::format("problem {} has no parameter '{}' (it has: {})", problem_name, name, known));
    }
    if (!accepts(*spec, value)) {
      throw SuiteInputError(fmt::format("--set {}={}: out of range {} for problem {}", name, value,
                                        range_text(*spec), problem_name));
    }
    values_[name] = value;
    overridden_[name] = true;
  }
}

double Parameters::get(std::string_view name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) {
    throw std::logic_error(fmt::format("parameter '{}' is not declared", name));
  }
  return it->second;
}

bool Parameters::overridden(std::string_view name) const {
  const auto it = overridden_.find(name);
  return it != overridden_.end() && it->second;
}

bool accepts(const ParameterSpec& s, double v) {
  const bool above = s.min_inclusive ? v >= s.min : v > s.min;
  const bool below = s.max_inclusive ? v <= s.max : v < s.max;
  return std::isfinite(v) && above && below && (!s.whole || v == std::round(v));
}

std::string range_text(const ParameterSpec& s) {
  auto bound = [](double v) { return std::isinf(v) ? std::string("inf") : fmt::format("{:g}", v); };
  return fmt::format("{}{}, {}{}{}", s.min_inclusive ? "[" : "(", bound(s.min), bound(s.max),
                     s.max_inclusive ? "]" : ")", s.whole ? ", a whole number" : "");
}

}  // namespace cs::suites
