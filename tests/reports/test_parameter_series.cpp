// Requirement: the one series model of the sweep and extent sections groups points
// by series in the order of their first point, orders each series by its parameter, finds a
// point by its parameter, ranges only converged errors, and prints a run of parameter values
// as a window only when it is contiguous among the values swept.

#include <gtest/gtest.h>

#include "reports/findings/parameter_series.hpp"

namespace cs::reports {
namespace {

SeriesPoint point(double parameter, double error, bool converged = true) {
  return {parameter, 1.0 + error / 100.0,
          error,     converged ? schema::CaseStatus::converged : schema::CaseStatus::not_converged,
          3,         nullptr,
          nullptr};
}

TEST(ParameterSeries, GroupsInFirstPointOrderAndSortsByParameter) {
  SeriesGroups groups;
  ParameterSeries lmp{{}, schema::Quantity::sigma_c, {}};
  ParameterSeries al = lmp;
  al.spec.algorithm = schema::Algorithm::AL;
  groups.of("LMP", lmp).points.push_back(point(10, -1.0));
  groups.of("AL", al).points.push_back(point(100, -0.5));
  groups.of("LMP", lmp).points.push_back(point(1, -2.0));
  groups.of("AL", al).points.push_back(point(1, -7.0, false));
  const std::vector<ParameterSeries> series = std::move(groups).sorted();
  ASSERT_EQ(series.size(), 2u);
  EXPECT_EQ(series[0].spec.algorithm, schema::Algorithm::LMP);
  EXPECT_EQ(series[0].points.front().parameter, 1.0);
  EXPECT_EQ(series[0].at(10)->error, -1.0);
  EXPECT_EQ(series[0].at(100), nullptr);
  EXPECT_EQ(parameter_values({&series[0], &series[1]}), (std::vector<double>{1, 10, 100}));
  // exact: the not-converged point at 1 is no evidence of the range
  EXPECT_EQ(series[1].error_range(), std::make_pair(-0.5, -0.5));
  EXPECT_EQ(series[1].label(), "P_p sigma_c C Q4 AL ss");
}

TEST(ParameterSeries, WindowOnlyForAContiguousRun) {
  const std::vector<double> all{0.01, 1, 100, 10000};
  EXPECT_EQ(parameter_window({1, 100, 10000}, all), "1 to 10000");
  EXPECT_EQ(parameter_window({0.01, 100}, all), "0.01, 100");
  EXPECT_EQ(parameter_window({100}, all), "100");
  EXPECT_EQ(parameter_window({}, all), "none");
}

}  // namespace
}  // namespace cs::reports
