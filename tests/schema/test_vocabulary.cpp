// Requirement: every name of the vocabulary is parsed and printed in one place; each axis
// round-trips name -> enum -> name, aliases parse to their enumerator, unknown names are rejected
// with a message listing the accepted ones, and the case id is stable.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "schema/case_axes.hpp"
#include "schema/case_spec.hpp"
#include "schema/convergence_trend.hpp"
#include "schema/grade.hpp"
#include "schema/quantity.hpp"
#include "schema/schema_error.hpp"

namespace cs::schema {
namespace {

template <class E>
void expect_round_trip(std::size_t expected_count) {
  EXPECT_EQ(count<E>(), expected_count);
  std::set<std::string_view> names;
  for (E v : values<E>()) {
    const std::string_view name = to_string(v);
    EXPECT_FALSE(name.empty());
    EXPECT_TRUE(names.insert(name).second) << "duplicate name " << name;
    EXPECT_EQ(parse<E>(name), v);
    EXPECT_FALSE(label(v).empty());
  }
}

TEST(SchemaVocabulary, EveryAxisRoundTrips) {
  expect_round_trip<ProblemId>(17);  // the study's 11, 2 E1 patch tests, FP_p, CM_p, IF_p, IF_a
  expect_round_trip<MeshLevel>(4);   // C, M, F and VF
  expect_round_trip<Element>(2);
  expect_round_trip<Algorithm>(5);
  expect_round_trip<ContactKind>(3);
  expect_round_trip<TargetKind>(2);
  expect_round_trip<Recovery>(3);
  expect_round_trip<SolverKind>(3);  // builtin, imported, external (CalculiX is external)
  expect_round_trip<Quantity>(9);
  expect_round_trip<Grade>(4);
  expect_round_trip<CaseStatus>(4);
  expect_round_trip<Trend>(3);
}

TEST(SchemaVocabulary, AliasesParseToTheirEnumerator) {
  EXPECT_EQ(parse<Algorithm>("IMC"), Algorithm::MPC);
  EXPECT_EQ(parse<Element>("8Q"), Element::Q8);
  EXPECT_EQ(parse<ProblemId>("P'_p"), ProblemId::Pprime_p);
  EXPECT_EQ(to_string(Algorithm::MPC), "MPC");  // the alias is never printed
}

TEST(SchemaVocabulary, UnknownNameIsRejectedListingTheAccepted) {
  try {
    parse<Algorithm>("ALM");
    FAIL() << "ALM parsed";
  } catch (const SchemaError& e) {
    EXPECT_STREQ(e.what(), "unknown algorithm 'ALM' (expected one of: AL, PM, LMP, PLM, MPC)");
  }
  EXPECT_FALSE(try_parse<ContactKind>("").has_value());
  EXPECT_FALSE(try_parse<ProblemId>("h_p").has_value());  // names are case-sensitive
}

TEST(SchemaVocabulary, TraitsComeFromTheTable) {
  EXPECT_EQ(traits(Algorithm::AL).study_column, traits(Algorithm::PM).study_column);
  EXPECT_EQ(traits(Algorithm::LMP).study_column, traits(Algorithm::PLM).study_column);
  EXPECT_NE(traits(Algorithm::AL).colour, traits(Algorithm::PM).colour);
  EXPECT_TRUE(traits(ContactKind::ns).in_study);
  EXPECT_FALSE(traits(ContactKind::mortar).in_study);
  EXPECT_TRUE(is_worse(Grade::u, Grade::s));
  EXPECT_FALSE(is_worse(Grade::e, Grade::e));
}

TEST(SchemaCaseSpec, CaseIdIsStableAndNamesEveryNonDefaultAxis) {
  CaseSpec s;
  s.problem = ProblemId::H_p;
  s.mesh = MeshLevel::F;
  s.element = Element::Q4;
  s.algorithm = Algorithm::LMP;
  s.contact = ContactKind::ss;
  EXPECT_EQ(case_id(s), "H_p/F/Q4/LMP/ss");
  EXPECT_EQ(case_key(s), "H_p/Q4/LMP/ss");
  EXPECT_TRUE(is_baseline(s));
  s.target = TargetKind::Rigid;
  s.recovery = Recovery::extrapolated;
  s.overrides["fkn"] = 10;
  EXPECT_EQ(case_id(s), "H_p/F/Q4/LMP/ss/rigid/extrapolated/fkn=10");
  s.solver = SolverKind::imported;
  s.solver_name = "abaqus";
  EXPECT_EQ(case_id(s), "H_p/F/Q4/LMP/ss/rigid/extrapolated/fkn=10/@abaqus");
  EXPECT_FALSE(is_baseline(s));
}

// Requirement (issue 13, import): a case id read back from a file names exactly the case that
// wrote it, and any other spelling is refused with the canonical one.
TEST(SchemaCaseSpec, CaseIdParsesBackToItsCase) {
  CaseSpec s = parse_case_id("S_1_3/M/Q8/PM/ns");
  EXPECT_EQ(case_id(s), "S_1_3/M/Q8/PM/ns");
  EXPECT_EQ(s.element, Element::Q8);
  EXPECT_EQ(s.contact, ContactKind::ns);
  s.target = TargetKind::Rigid;
  s.recovery = Recovery::extrapolated;
  s.overrides = {{"fkn", 0.1}, {"nu", 1.0 / 3.0}, {"p_over_E", 1e-6}};
  EXPECT_EQ(parse_case_id(case_id(s)), s) << case_id(s);
  s.solver = SolverKind::external;
  s.solver_name = "calculix";
  s.solver_option = "hard-ss";
  EXPECT_EQ(case_id(s).substr(case_id(s).rfind('/')), "/@calculix:hard-ss");
  EXPECT_EQ(parse_case_id(case_id(s)), s);
  s.solver_option.clear();
  s.solver = SolverKind::imported;
  s.solver_name = "abaqus-2024.1";
  EXPECT_EQ(parse_case_id(case_id(s)), s) << case_id(s);
  for (const auto& cp : values<ProblemId>()) {  // every problem, mesh, element, ...
    CaseSpec c;
    c.problem = cp;
    EXPECT_EQ(parse_case_id(case_id(c)), c);
  }
}

TEST(SchemaCaseSpec, MalformedCaseIdsAreRefusedNamingTheField) {
  const std::vector<std::pair<std::string, std::string>> bad{
      {"", "expected problem/mesh"},
      {"H_p/C/Q4/PM", "expected problem/mesh"},
      {"H_x/C/Q4/PM/ss", "unknown problem 'H_x'"},
      {"H_p/X/Q4/PM/ss", "unknown mesh level 'X'"},
      {"H_p/C/Q4/PM/ss/", "unexpected field ''"},
      {"H_p/C/Q4/PM/ss/fkn=abc", "'fkn=abc' is not a parameter"},
      {"H_p/C/Q4/PM/ss/fkn=inf", "'fkn=inf' is not a parameter"},
      {"H_p/C/Q4/PM/ss/fkn=1/fkn=2", "given twice"},
      {"H_p/C/Q4/PM/ss/@", "not a solver suffix"},
      {"H_p/C/Q4/PM/ss/@builtin", "not a solver suffix"},
      {"H_p/C/Q4/PM/ss/@calculix", "names CalculiX without its option"},
      {"H_p/C/Q4/PM/ss/@a/@b", "unexpected field '@b'"},
      {"H_p/C/Q4/PM/ss/extrapolated/rigid", "unexpected field 'rigid'"},
      {"H_p/C/Q4/PM/ss/fkn=10.0", "'H_p/C/Q4/PM/ss/fkn=10'"},
      {"P'_p/C/Q4/PM/ss", "'Pprime_p/C/Q4/PM/ss'"},
      {"H_p/C/Q4/IMC/ss", "'H_p/C/Q4/MPC/ss'"},
      {"H_p/C/Q4/PM/ss/spr", "'H_p/C/Q4/PM/ss'"},
  };
  for (const auto& [id, expected] : bad) {
    try {
      parse_case_id(id);
      ADD_FAILURE() << "accepted: " << id;
    } catch (const SchemaError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << id << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace cs::schema
