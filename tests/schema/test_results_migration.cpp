// Reading a version-3 results file (schema/results_migration.hpp): CalculiX's cases, which
// version-3 builds graded on CalculiX's own extrapolated nodal stresses but labelled spr, are
// read as recovery own under CalculiX's own option label, with ids that follow; the values are
// untouched; and version 4 names CalculiX only with its option.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "schema/json_file.hpp"
#include "schema/results_file.hpp"
#include "schema/schema_error.hpp"

namespace cs::schema {
namespace {

/// The committed version-3 CalculiX results (P_p C Q4 PM ns; its value is CalculiX's own).
const std::filesystem::path kOldCalculix = std::filesystem::path(CONTACT_SUITE_SOURCE_DIR) /
                                           "fuzz/corpus/results_file/run_calculix_P_p.json";

nlohmann::json old_file() {
  return read_json_file(kOldCalculix, "results");
}

/// `file` with every case and row copied once under another algorithm and contact.
nlohmann::json with_copy(nlohmann::json file, const std::string& algorithm,
                         const std::string& contact, const std::string& recovery) {
  for (const char* key : {"cases", "rows"}) {
    auto copy = file[key][0];
    copy["algorithm"] = algorithm;
    copy["contact"] = contact;
    copy["recovery"] = recovery;
    const std::string old_id = copy["id"];
    copy["id"] = std::string(key) == "cases"
                     ? "P_p/C/Q4/" + algorithm + "/" + contact +
                           (recovery == "spr" ? "" : "/" + recovery) + "/@calculix"
                     : "P_p/Q4/" + algorithm + "/" + contact +
                           (recovery == "spr" ? "" : "/" + recovery) + "/@calculix/sigma_z_max";
    file[key].push_back(copy);
  }
  return file;
}

// Requirement: the committed version-3 CalculiX case is read as CalculiX's option linear-ns on
// the own basis, with the id and row id that follow, and its value unchanged (bit for bit).
TEST(ResultsMigration, OldCalculixSprIsOwnUnderItsOptionLabel) {
  const auto raw = old_file();
  ASSERT_EQ(raw["schema_version"], 3);
  const ResultsDocument doc = read_results_file(kOldCalculix);
  ASSERT_EQ(doc.cases.size(), 1u);
  const CaseSpec& spec = doc.cases[0].spec;
  EXPECT_EQ(spec.solver, SolverKind::external);
  EXPECT_EQ(spec.solver_name, "calculix");
  EXPECT_EQ(spec.solver_option, "linear-ns");
  EXPECT_EQ(spec.algorithm, Algorithm::PM);
  EXPECT_EQ(spec.recovery, Recovery::own);
  EXPECT_EQ(case_id(spec), "P_p/C/Q4/PM/ns/own/@calculix:linear-ns");
  ASSERT_EQ(doc.rows.size(), 1u);
  EXPECT_EQ(doc.rows[0].id, "P_p/Q4/PM/ns/own/@calculix:linear-ns/sigma_z_max");
  EXPECT_EQ(doc.cases[0].quantities.at(0).value,
            raw["cases"][0]["quantities"]["sigma_z_max"]["value"].get<double>());
  // Written again, the file is version 4 and reads back the same.
  const ResultsDocument again = parse_results_text(to_json(doc).dump(), "again");
  EXPECT_EQ(to_json(doc)["schema_version"], kResultsSchemaVersion);
  EXPECT_EQ(case_id(again.cases[0].spec), case_id(spec));
}

// Requirement: HARD contact (run under the study's LMP) is CalculiX's penalty option hard-ss,
// in the penalty family's column (PM), never LMP.
TEST(ResultsMigration, HardContactIsAPenaltyNotLmp) {
  const ResultsDocument doc =
      parse_results_text(with_copy(old_file(), "LMP", "ss", "spr").dump(), "old-with-lmp");
  ASSERT_EQ(doc.cases.size(), 2u);
  EXPECT_EQ(case_id(doc.cases[1].spec), "P_p/C/Q4/PM/ss/own/@calculix:hard-ss");
  EXPECT_EQ(doc.rows[1].id, "P_p/Q4/PM/ss/own/@calculix:hard-ss/sigma_z_max");
}

// Requirement: a version-3 file that already holds CalculiX on the own basis was written with
// both bases: its spr cases are the common basis and keep it (only the option label changes).
TEST(ResultsMigration, FilesWithBothBasesKeepSpr) {
  const ResultsDocument doc =
      parse_results_text(with_copy(old_file(), "PM", "ns", "own").dump(), "both-bases");
  ASSERT_EQ(doc.cases.size(), 2u);
  EXPECT_EQ(case_id(doc.cases[0].spec), "P_p/C/Q4/PM/ns/@calculix:linear-ns");
  EXPECT_EQ(case_id(doc.cases[1].spec), "P_p/C/Q4/PM/ns/own/@calculix:linear-ns");
}

// Requirement: two old cases that are one CalculiX option (PM and AL ran the same deck) are a
// duplicate, refused with the id; version 4 does not accept CalculiX without its option, nor
// an unknown version.
TEST(ResultsMigration, RefusesWhatCannotBeMigrated) {
  EXPECT_THROW(
      {
        try {
          parse_results_text(with_copy(old_file(), "AL", "ns", "spr").dump(), "pm-and-al");
        } catch (const SchemaError& e) {
          EXPECT_NE(std::string(e.what()).find("duplicate case id"), std::string::npos);
          throw;
        }
      },
      SchemaError);
  auto v4 = old_file();
  v4["schema_version"] = 4;
  EXPECT_THROW(
      {
        try {
          parse_results_text(v4.dump(), "v4");
        } catch (const SchemaError& e) {
          EXPECT_NE(std::string(e.what()).find("without its option"), std::string::npos);
          throw;
        }
      },
      SchemaError);
  auto v2 = old_file();
  v2["schema_version"] = 2;
  EXPECT_THROW(parse_results_text(v2.dump(), "v2"), SchemaError);
}

}  // namespace
}  // namespace cs::schema
