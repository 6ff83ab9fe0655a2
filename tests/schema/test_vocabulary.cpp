// Requirement: every name of the vocabulary is parsed and printed in one place; each axis
// round-trips name -> enum -> name, aliases parse to their enumerator, unknown names are rejected
// with a message listing the accepted ones, and the case id is stable.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "schema/case_axes.hpp"
#include "schema/case_spec.hpp"
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
  expect_round_trip<ProblemId>(15);
  expect_round_trip<MeshLevel>(3);
  expect_round_trip<Element>(2);
  expect_round_trip<Algorithm>(5);
  expect_round_trip<ContactKind>(3);
  expect_round_trip<TargetKind>(2);
  expect_round_trip<Recovery>(2);
  expect_round_trip<SolverKind>(3);
  expect_round_trip<Quantity>(6);
  expect_round_trip<Grade>(4);
  expect_round_trip<CaseStatus>(4);
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

}  // namespace
}  // namespace cs::schema
