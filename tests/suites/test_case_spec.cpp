// Names of the option axes round-trip; bad names and --set values are rejected clearly.

#include <gtest/gtest.h>

#include "suites/case_spec.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

TEST(CaseSpec, EveryNameRoundTrips) {
  for (auto p : all_problems())
    EXPECT_EQ(parse_problem(to_string(p)), p);
  for (auto m : all_mesh_levels())
    EXPECT_EQ(parse_mesh_level(to_string(m)), m);
  for (auto e : all_elements())
    EXPECT_EQ(parse_element(to_string(e)), e);
  for (auto a : all_algorithms())
    EXPECT_EQ(parse_algorithm(to_string(a)), a);
  for (auto c : all_contacts())
    EXPECT_EQ(parse_contact(to_string(c)), c);
  EXPECT_EQ(all_problems().size(), 11u);
  // 11 problems x 3 meshes x 2 elements x 5 algorithms x 2 discretizations: the study's 660.
  EXPECT_EQ(all_problems().size() * all_mesh_levels().size() * all_elements().size() *
                all_algorithms().size() * study_contacts().size(),
            660u);
}

TEST(CaseSpec, StudyAliasesAreAccepted) {
  EXPECT_EQ(parse_algorithm("IMC"), Algorithm::MPC);
  EXPECT_EQ(parse_element("8Q"), ElementType::Q8);
  EXPECT_EQ(parse_problem("P'_p"), ProblemId::Pprime_p);
}

TEST(CaseSpec, UnknownNamesListTheAcceptedOnes) {
  try {
    parse_algorithm("XYZ");
    FAIL() << "no exception";
  } catch (const SuiteInputError& e) {
    EXPECT_NE(std::string(e.what()).find("AL, PM, LMP, PLM, MPC"), std::string::npos);
  }
  EXPECT_THROW(parse_problem("H_x"), SuiteInputError);
  EXPECT_THROW(parse_contact("SS"), SuiteInputError);
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
  for (Recovery r : all_recoveries())
    EXPECT_EQ(parse_recovery(to_string(r)), r);
  EXPECT_EQ(CaseSpec{}.recovery, Recovery::spr);
  EXPECT_THROW(parse_recovery("smoothed"), SuiteInputError);
}

}  // namespace
}  // namespace cs::suites
