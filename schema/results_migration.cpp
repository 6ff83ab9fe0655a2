#include "schema/results_migration.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>

#include "schema/case_spec.hpp"

namespace cs::schema {
namespace {

using nlohmann::json;

constexpr std::string_view kOldCalculix = "calculix";

bool is_old_calculix(const json& record) {
  return record.is_object() && record.contains("solver") && record["solver"].is_string() &&
         record["solver"].get<std::string>() == kOldCalculix;
}

template <class E>
std::optional<E> field(const json& record, const char* key) {
  if (!record.contains(key) || !record[key].is_string())
    return std::nullopt;
  return try_parse<E>(record[key].get<std::string>());
}

/// The CalculiX option label the adapter wrote for a study algorithm and contact.
std::string calculix_label(Algorithm algorithm, ContactKind contact) {
  const std::string where(to_string(contact));
  switch (algorithm) {
    case Algorithm::PM:
    case Algorithm::AL:
      return "linear-" + where;
    case Algorithm::LMP:
    case Algorithm::PLM:
      return "hard-" + where;
    case Algorithm::MPC:
      break;
  }
  std::string label(to_string(algorithm));
  std::transform(label.begin(), label.end(), label.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return label + "-" + where;
}

/// The spec of a migrated record (its axes, solver and overrides), or none if a field is bad.
std::optional<CaseSpec> spec_of(const json& record) {
  const auto problem = field<ProblemId>(record, "problem");
  const auto element = field<Element>(record, "element");
  const auto algorithm = field<Algorithm>(record, "algorithm");
  const auto contact = field<ContactKind>(record, "contact");
  const auto target = field<TargetKind>(record, "target");
  const auto recovery = field<Recovery>(record, "recovery");
  if (!problem || !element || !algorithm || !contact || !target || !recovery)
    return std::nullopt;
  CaseSpec spec{.problem = *problem,
                .element = *element,
                .algorithm = *algorithm,
                .contact = *contact,
                .target = *target,
                .recovery = *recovery};
  const std::string solver = record["solver"].get<std::string>();
  spec.solver = SolverKind::external;
  spec.solver_name = solver.substr(0, solver.find(':'));
  spec.solver_option = solver.substr(solver.find(':') + 1);
  if (record.contains("mesh")) {
    const auto mesh = field<MeshLevel>(record, "mesh");
    if (!mesh)
      return std::nullopt;
    spec.mesh = *mesh;
  }
  if (record.contains("overrides") && record["overrides"].is_object()) {
    for (const auto& [name, value] : record["overrides"].items()) {
      if (!value.is_number())
        return std::nullopt;
      spec.overrides[name] = value.get<double>();
    }
  }
  return spec;
}

/// Rewrites one CalculiX record (see the header); `relabel_spr`: its spr means own.
void migrate_record(json& record, bool is_case, bool relabel_spr) {
  const auto algorithm = field<Algorithm>(record, "algorithm");
  const auto contact = field<ContactKind>(record, "contact");
  if (!algorithm || !contact)
    return;
  record["solver"] = std::string(kOldCalculix) + ":" + calculix_label(*algorithm, *contact);
  if (*algorithm != Algorithm::MPC)
    record["algorithm"] = std::string(to_string(Algorithm::PM));
  if (relabel_spr && field<Recovery>(record, "recovery") == Recovery::spr)
    record["recovery"] = std::string(to_string(Recovery::own));
  const auto spec = spec_of(record);
  if (!spec)
    return;
  if (is_case) {
    record["id"] = case_id(*spec);
  } else if (record.contains("quantity") && record["quantity"].is_string()) {
    record["id"] = case_key(*spec) + "/" + record["quantity"].get<std::string>();
  }
}

json* array_of(json& doc, const char* key) {
  return doc.is_object() && doc.contains(key) && doc[key].is_array() ? &doc[key] : nullptr;
}

/// True when a CalculiX record of the file is on the `own` basis (written after the bases).
bool holds_own_calculix(json& doc) {
  for (const char* key : {"cases", "rows"}) {
    if (json* records = array_of(doc, key))
      for (const auto& r : *records)
        if (is_old_calculix(r) && field<Recovery>(r, "recovery") == Recovery::own)
          return true;
  }
  return false;
}

}  // namespace

void migrate_results_v3_to_v4(json& doc) {
  const bool relabel_spr = !holds_own_calculix(doc);
  for (const char* key : {"cases", "rows"}) {
    json* records = array_of(doc, key);
    if (records == nullptr)
      continue;
    for (auto& r : *records)
      if (is_old_calculix(r))
        migrate_record(r, key == std::string_view("cases"), relabel_spr);
  }
}

}  // namespace cs::schema
