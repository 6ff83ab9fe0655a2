#pragma once
// CalculiX as a registered code: its manifest, declared here in C++ because its adapter is C++
// (suites/calculix_executor.hpp runs it in-process), and the one table of its contact options.
// Everything else (`list`, `run --solver calculix`, case ids, the report's option mapping)
// reads this table, as it reads an external code's manifest.json (docs/solver-protocol.md).
//
// CalculiX's options, by its own names (case ids end in /@calculix:<label>):
//
//   label      family   discretization  deck
//   linear-ns  penalty  ns  *CONTACT PAIR, TYPE=NODE TO SURFACE, SMALL SLIDING;
//                           PRESSURE-OVERCLOSURE=LINEAR, K = FKN E / h (our penalty law),
//                           sigma_inf = 0.25 % p, c0 = 0.1
//   linear-ss  penalty  ss  TYPE=SURFACE TO SURFACE; LINEAR, K = FKN E / h
//   hard-ns    penalty  ns  TYPE=NODE TO SURFACE, SMALL SLIDING; PRESSURE-OVERCLOSURE=HARD,
//                           which ccx reduces to a penalty with K = 50 E (its default)
//   hard-ss    penalty  ss  TYPE=SURFACE TO SURFACE; HARD (K = 50 E)
//
// Every option is a penalty: CalculiX has no augmented Lagrangian, its Lagrange-multiplier
// contact is mortar, which ccx 2.20 rejects on 2D elements, and it has no frictionless bonded
// (MPC) contact. Its rows therefore sit in the study's AL_PM column. It takes a meshed target
// only (the adapter writes meshed surfaces), plane strain or axisymmetric, Q4 or Q8.

#include <string_view>

#include "adapters/calculix/calculix_options.hpp"
#include "adapters/protocol/solver_manifest.hpp"

namespace cs::adapters::calculix {

/// The code's name in case ids and results ("calculix").
inline constexpr std::string_view kCalculixName = "calculix";

/// CalculiX's manifest: name, description, command {"ccx"} (the program; the adapter builds
/// its arguments), version command, the four options above, what it supports, and the time
/// limit of one case (600 s).
const protocol::SolverManifest& calculix_manifest();

/// The deck options of CalculiX's option `label` for a penalty factor `fkn` (LINEAR:
/// K = fkn E / h) on `scale`: pair type, behaviour, K and sigma_inf = 0.25 % p. Throws
/// protocol::ManifestError naming CalculiX's options for an unknown label, CalculixError for a
/// non-positive or non-finite E, h, p or fkn.
CalculixOptions options_for(std::string_view label, double fkn, const PenaltyScale& scale);

}  // namespace cs::adapters::calculix
