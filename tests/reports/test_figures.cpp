// Figures: PNG files drawn by gnuplot (skipped when it is not installed), the observed order
// of convergence, and a report that says so when no figure could be drawn.

#include <cmath>

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/figures/figures.hpp"
#include "reports/figures/gnuplot.hpp"
#include "reports/figures/observed_order.hpp"
#include "reports/figures/plain_label.hpp"
#include "support/tolerance.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;
using testing::Loaded;
using testing::sample_json;
using testing::TempDir;

TEST(ObservedOrder, LeastSquaresSlopeOfLogErrorOverLogH) {
  // |e| = 3 h^2 exactly: slope 2 to round-off.
  EXPECT_TRUE(cs::testing::Near(
      *observed_order({{0.25, 0.1875}, {0.125, 0.046875}, {0.0625, 0.01171875}}), 2.0, {1e-12, 0}));
  // Three points off a line: the least-squares slope of (ln h, ln e) = (0,0), (1,1), (2,3):
  // 1.5, whatever the base of the logarithm.
  const double e = std::exp(1.0);
  EXPECT_TRUE(
      cs::testing::Near(*observed_order({{1, 1}, {e, e}, {e * e, e * e * e}}), 1.5, {1e-12, 0}));
  // A singular stress growing as h^-1/2: slope -0.5.
  EXPECT_TRUE(cs::testing::Near(*observed_order({{0.25, 2.0}, {0.0625, 4.0}}), -0.5, {1e-12, 0}));
  // Zero errors (exact results) and single points carry no order.
  EXPECT_FALSE(observed_order({{0.25, 0.0}, {0.125, 0.0}, {0.0625, 1e-3}}).has_value());
  EXPECT_FALSE(observed_order({{0.25, 1.0}, {0.25, 2.0}}).has_value());
}

TEST(Figures, ObservedOrdersOfTheSample) {
  const Loaded data(sample_json());
  const auto orders = observed_orders(data.index);
  bool found = false;
  for (const auto& o : orders) {
    if (o.problem == schema::ProblemId::F_p && o.element == schema::Element::Q4 &&
        o.option_label == "AL (ss)") {
      found = true;
      EXPECT_TRUE(o.singular);
      ASSERT_TRUE(o.order.has_value());
      EXPECT_LT(*o.order, -0.4);  // 2.13, 3.02, 4.27 on h, h/2, h/4: grows about as h^-1/2
      EXPECT_GT(*o.order, -0.6);
    }
    if (o.problem == schema::ProblemId::P_p && o.option_label == "AL (ss)") {
      EXPECT_FALSE(o.order.has_value());  // exact
      EXPECT_FALSE(o.singular);
    }
  }
  EXPECT_TRUE(found);
}

bool is_png(const fs::path& p) {
  const std::string bytes = testing::read_text(p);
  return bytes.size() > 1000 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

TEST(Figures, DrawsNonEmptyPngFiles) {
  if (!find_gnuplot())
    GTEST_SKIP() << "gnuplot with a PNG terminal is not installed";
  const Loaded data(sample_json());
  TempDir tmp;
  const FigureSet set = render_figures(data.index, tmp.path());
  EXPECT_TRUE(set.unavailable.empty());
  std::vector<std::string> files;
  for (const auto& f : set.figures) {
    EXPECT_TRUE(f.produced) << f.file << ": " << f.error;
    EXPECT_TRUE(is_png(tmp.path() / f.file)) << f.file;
    files.push_back(f.file);
  }
  for (const char* expected :
       {"figures/profile_H_p_Q4.png", "figures/profile_H_p_Q8.png", "figures/profile_S_1_3_Q4.png",
        "figures/convergence_H_p_sigma_c.png", "figures/convergence_H_p_sigma_h.png",
        "figures/convergence_F_p_sigma_c_star.png"}) {
    EXPECT_NE(std::find(files.begin(), files.end(), expected), files.end()) << expected;
  }
  const std::string md = figures_section(set);
  EXPECT_NE(md.find("![H_p sigma_c](figures/profile_H_p_Q4.png)"), std::string::npos);
  EXPECT_NE(md.find("Q4 AL (ss): slope −"), std::string::npos);
}

// Requirement: figure titles name problems and quantities in plain text, from the vocabulary's
// Markdown labels.
TEST(Figures, PlainTextOfTheVocabularysLabels) {
  EXPECT_EQ(plain_label(schema::label(schema::ProblemId::Pprime_p)), "P'_p");
  EXPECT_EQ(plain_label(schema::label(schema::ProblemId::S_1_3)), "S(1/3)");
  EXPECT_EQ(plain_label(schema::label(schema::ProblemId::H_a)), "H_a");
  EXPECT_EQ(plain_label("σ̄<sub>c</sub><sup>*</sup>"), "σ̄_c^*");
  EXPECT_EQ(plain_label("a <b>bold</b> word"), "a bold word");
}

TEST(Figures, WithoutGnuplotTheReportSaysSo) {
  const Loaded data(sample_json());
  TempDir tmp;
  const FigureSet set = render_figures(data.index, tmp.path(), {"/nonexistent/gnuplot"});
  EXPECT_FALSE(set.unavailable.empty());
  EXPECT_FALSE(fs::exists(tmp.path() / "figures"));
  EXPECT_NE(figures_section(set).find("**No figures:**"), std::string::npos);
}

TEST(Figures, ProfileCaptionSaysWhenTheExactCurveIsMissing) {
  auto doc = sample_json();
  for (auto& c : doc["cases"])
    c.erase("exact_profile");
  const Loaded data(doc);
  TempDir tmp;
  const FigureSet set = render_figures(data.index, tmp.path(), {"/nonexistent/gnuplot"});
  bool noted = false;
  for (const auto& f : set.figures) {
    for (const auto& n : f.notes)
      noted = noted || n.find("no exact curve") != std::string::npos;
  }
  EXPECT_TRUE(noted);
}

}  // namespace
}  // namespace cs::reports
