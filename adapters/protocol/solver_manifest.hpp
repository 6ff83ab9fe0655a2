#pragma once
// An external code's manifest: adapters/<name>/manifest.json (or a team's own folder), the one
// file that registers a code with the solver protocol (docs/solver-protocol.md). It names the
// code, the command that solves one case directory, the options the code offers (each with its
// own label, its family and its contact discretization), what it supports, and the command that
// prints its version.
//
// The command is an argument vector run without a shell; these placeholders are replaced in
// every argument: {adapter_dir} (the manifest's folder), {case_dir} (the case directory, also
// the working directory) and {option} (the option's label).
//
// An option may narrow the code's `supports` with its own (a subset of the code's).
//
// Unknown keys, an unknown family, support or discretization, a missing or mistyped field: a
// ManifestError (a std::invalid_argument, the command line's exit 2) of one line naming the
// file and the key.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cs::adapters::protocol {

class ManifestError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// The family of an option: how the code enforces contact. Rows are matched to the study's
/// columns by family (penalty and augmented Lagrangian: AL_PM; Lagrange multiplier: LMP_PLM;
/// mpc: MPC; Nitsche, which has no column of its own in the study, sits with the penalty-based
/// AL_PM: its enforcement too depends on a stiffness-like parameter).
enum class OptionFamily { penalty, augmented_lagrangian, lagrange_multiplier, nitsche, mpc };

/// What a code can solve.
enum class Support { plane_strain, axisymmetric, rigid_target, meshed_target, Q4, Q8 };

/// One option of a code.
struct SolverOption {
  std::string label;  ///< the code's own name, e.g. "nitsche" ([A-Za-z0-9._-]+)
  OptionFamily family = OptionFamily::penalty;
  std::string discretization;  ///< "ns", "ss" or "mortar": where contact is enforced
  std::string description;  ///< one line for `list` and the report, e.g. "penalty (HARD, K = 50 E)"
  /// What this option supports where it is less than the code (GetFEM's Nitsche: no meshed
  /// target); empty: the code's `supports`.
  std::vector<Support> supports;
};

struct SolverManifest {
  std::filesystem::path folder;              ///< where manifest.json is
  std::string name;                          ///< e.g. "getfem" ([a-z0-9_-]+)
  std::string description;                   ///< one line
  std::vector<std::string> command;          ///< argv with placeholders
  std::vector<std::string> version_command;  ///< argv printing the version on its first line
  std::vector<SolverOption> options;
  std::vector<Support> supports;
  double time_limit_seconds = 600.0;  ///< per case, unless the command line says otherwise

  /// Whether the code (and, given one, its `option`) supports everything `wanted`.
  bool supports_all(std::initializer_list<Support> wanted,
                    const SolverOption* option = nullptr) const;
  /// The option called `label`; throws ManifestError naming the code's options if none is.
  const SolverOption& option(std::string_view label) const;
};

std::string_view to_string(OptionFamily f);
std::string_view to_string(Support s);

/// Parses manifest text; `source` names it in messages. Throws ManifestError.
SolverManifest parse_manifest(std::string_view text, const std::filesystem::path& source);

/// Reads and parses `folder`/manifest.json. Throws ManifestError.
SolverManifest read_manifest(const std::filesystem::path& folder);

/// `argv` with the placeholders replaced.
std::vector<std::string> expand_command(const std::vector<std::string>& argv,
                                        const std::filesystem::path& adapter_dir,
                                        const std::filesystem::path& case_dir,
                                        std::string_view option);

}  // namespace cs::adapters::protocol
