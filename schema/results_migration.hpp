#pragma once
// Reading an older results.json: the changes of each schema version that a reader can make
// good without rerunning anything (docs/results-schema.md, "What changed from version 3").
//
// Version 3 -> 4: CalculiX became a registered code with its own option labels
// (adapters/calculix/calculix_manifest.hpp). A version-3 case or row of solver "calculix" is
// rewritten as follows:
//   - its solver becomes "calculix:<label>", the CalculiX option the adapter wrote for the
//     study option it was run under: PM and AL (a LINEAR penalty, K = FKN E / h) -> linear-ns
//     or linear-ss, LMP and PLM (HARD, which ccx reduces to a penalty with K = 50 E) ->
//     hard-ns or hard-ss; its algorithm becomes PM, the penalty family's column (the study
//     options CalculiX does not offer, MPC and mortar, keep their fields and get the label
//     "<algorithm>-<contact>" in lower case: such cases only ever failed as not supported);
//   - its recovery `spr` becomes `own`: version-3 builds before the two stress bases graded
//     CalculiX's own extrapolated nodal stresses and labelled them spr. A file that already
//     holds a CalculiX case or row on `own` was written after the two bases existed; its spr
//     cases are the common basis and keep it;
//   - its id follows from the new fields.
// Every other record is left as it is. Two old cases that become one (PM and AL, LMP and PLM
// ran the same deck) are then a duplicate id, refused by the reader as any duplicate is.

#include <nlohmann/json.hpp>

namespace cs::schema {

/// Rewrites the version-3 document `doc` (its "cases" and "rows" arrays) as version 4, in
/// place; records that are not objects or lack the fields are left for the reader to refuse.
void migrate_results_v3_to_v4(nlohmann::json& doc);

}  // namespace cs::schema
