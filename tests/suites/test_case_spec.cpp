// Names of the option axes round-trip; bad names and --set values are rejected clearly.

#include <gtest/gtest.h>

#include "schema/schema_error.hpp"
#include "suites/case_spec.hpp"
#include "suites/problem_catalog.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

TEST(CaseSpec, EveryNameRoundTrips) {
  for (auto p : values<ProblemId>())
    EXPECT_EQ(parse<ProblemId>(to_string(p)), p);
  for (auto m : values<MeshLevel>())
    EXPECT_EQ(parse<MeshLevel>(to_string(m)), m);
  for (auto e : values<Element>())
    EXPECT_EQ(parse<Element>(to_string(e)), e);
  for (auto a : values<Algorithm>())
    EXPECT_EQ(parse<Algorithm>(to_string(a)), a);
  for (auto c : values<ContactKind>())
    EXPECT_EQ(parse<ContactKind>(to_string(c)), c);
  // the study's 11, the two equal-moduli patch tests, FP_p and CM_p
  EXPECT_EQ(values<ProblemId>().size(), 15u);
  EXPECT_EQ(study_problems().size(), 11u);
  // 11 problems x 3 meshes x 2 elements x 5 algorithms x 2 discretizations: the study's 660.
  EXPECT_EQ(study_problems().size() * values<MeshLevel>().size() * values<Element>().size() *
                values<Algorithm>().size() * study_contacts().size(),
            660u);
}

TEST(CaseSpec, StudyAliasesAreAccepted) {
  EXPECT_EQ(parse<Algorithm>("IMC"), Algorithm::MPC);
  EXPECT_EQ(parse<Element>("8Q"), Element::Q8);
  EXPECT_EQ(parse<ProblemId>("P'_p"), ProblemId::Pprime_p);
}

TEST(CaseSpec, UnknownNamesListTheAcceptedOnes) {
  try {
    parse<Algorithm>("XYZ");
    FAIL() << "no exception";
  } catch (const schema::SchemaError& e) {
    EXPECT_NE(std::string(e.what()).find("AL, PM, LMP, PLM, MPC"), std::string::npos);
  }
  EXPECT_THROW(parse<ProblemId>("H_x"), schema::SchemaError);
  EXPECT_THROW(parse<ContactKind>("SS"), schema::SchemaError);
}

TEST(CaseSpec, OverridesParseNumbersAndRatios) {
  EXPECT_EQ(parse_override("nu=0.3"), (std::pair<std::string, double>{"nu", 0.3}));
  EXPECT_DOUBLE_EQ(parse_override("re_over_b=1/3").second, 1.0 / 3.0);
  EXPECT_THROW(parse_override("nu"), SuiteInputError);
  EXPECT_THROW(parse_override("nu="), SuiteInputError);
  EXPECT_THROW(parse_override("nu=abc"), SuiteInputError);
  EXPECT_THROW(parse_override("nu=1/0"), SuiteInputError);
  EXPECT_THROW(parse_override("nu=nan"), SuiteInputError);
}

TEST(CaseSpec, CaseIdNamesEveryAxis) {
  CaseSpec spec;
  spec.problem = ProblemId::H_p;
  spec.mesh = MeshLevel::F;
  spec.algorithm = Algorithm::AL;
  spec.contact = ContactKind::ns;
  EXPECT_EQ(case_id(spec), "H_p/F/Q4/AL/ns");
  spec.target = TargetKind::Rigid;
  spec.overrides["fkn"] = 10;
  EXPECT_EQ(case_id(spec), "H_p/F/Q4/AL/ns/rigid/fkn=10");
  spec.recovery = Recovery::extrapolated;
  EXPECT_EQ(case_id(spec), "H_p/F/Q4/AL/ns/rigid/extrapolated/fkn=10");
}

TEST(CaseSpec, RecoveryNamesRoundTripAndBadOnesAreRejected) {
  for (Recovery r : values<Recovery>())
    EXPECT_EQ(parse<Recovery>(to_string(r)), r);
  EXPECT_EQ(CaseSpec{}.recovery, Recovery::spr);
  EXPECT_THROW(parse<Recovery>("smoothed"), schema::SchemaError);
}

}  // namespace
}  // namespace cs::suites
