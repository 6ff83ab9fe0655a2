#pragma once
// The parameters a problem fixes (as the study fixes them) and that `--set name=value`
// overrides: declared once per problem with default, range and meaning; validated once.

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace cs::suites {

/// One settable parameter of a problem.
struct ParameterSpec {
  std::string name;         ///< the `--set` key, e.g. "nu"
  double default_value;     ///< the study's value
  double min;               ///< smallest accepted value
  double max;               ///< largest accepted value
  bool min_inclusive;       ///< whether `min` itself is accepted
  bool max_inclusive;       ///< whether `max` itself is accepted
  std::string description;  ///< one line for `contact-suite list`
  bool whole = false;       ///< a count: whole numbers only
};

/// The default FKN of the friction problems (FP_p, CM_p), which keep the FKN of before issue
/// 14: their tangential penalty is FKT x FKN, and with the frictionless default (100) their
/// frictional active set cycles (CM_p C AL/PM ss) or loses every sticking row (mortar). The
/// sweeps of issue 14 cover the frictionless battery only.
inline constexpr double kFrictionalDefaultFkn = 1.0;

/// The parameters shared by every problem: material, indenter stiffness, contact settings.
std::vector<ParameterSpec> common_parameters(double default_p_over_E);

/// Resolved parameter values of one case: defaults with the overrides applied.
class Parameters {
 public:
  /// Applies `overrides` to the defaults of `specs`. Throws SuiteInputError naming the key
  /// for a key the problem does not have (listing those it has) or a value out of range.
  Parameters(const std::vector<ParameterSpec>& specs,
             const std::map<std::string, double>& overrides, std::string_view problem_name);

  /// The value of a declared parameter; throws std::logic_error for an undeclared name
  /// (a programming error, not an input error).
  double get(std::string_view name) const;
  /// True when the problem has a parameter called `name`.
  bool declares(std::string_view name) const { return values_.find(name) != values_.end(); }
  /// True when `name` was set by an override (not its default).
  bool overridden(std::string_view name) const;

 private:
  std::map<std::string, double, std::less<>> values_;
  std::map<std::string, bool, std::less<>> overridden_;
};

/// True when `value` is finite and within the parameter's range (and whole, for a count).
bool accepts(const ParameterSpec& spec, double value);

/// "[0, 0.5)"-style text of a parameter's range, for listings and error messages.
std::string range_text(const ParameterSpec& spec);

}  // namespace cs::suites
