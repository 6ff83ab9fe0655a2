// Figures: the plot models of the profile and convergence figures (checked on numbers, without
// gnuplot), the PNG files gnuplot draws from them (skipped when it is not installed), and a
// figure set that says so when no figure could be drawn.

#include <cmath>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "grading/convergence.hpp"
#include "report_test_support.hpp"
#include "reports/figures/figures.hpp"
#include "reports/figures/gnuplot.hpp"

// A namespace of its own: the file-local names stay apart from the program's others (unity build).
namespace cs::reports::test_figures {
namespace {

namespace fs = std::filesystem;
using schema::Element;
using schema::ProblemId;
using testing::Loaded;
using testing::sample_json;
using testing::TempDir;

const PlotSeries* series_titled(const PlotPanel& panel, const std::string& prefix) {
  for (const auto& s : panel.series) {
    if (s.title.rfind(prefix, 0) == 0)
      return &s;
  }
  return nullptr;
}

Plot sample_convergence(const Loaded& data, ProblemId id, Figure& figure) {
  const schema::ProblemRecord& p = *data.index.problem(id);
  return convergence_plot(data.index, row_facts(data.index), divergence_facts(data.index), p,
                          p.quantities.front(), figure);
}

// Requirement: the legend gives grading::observed_order's guarded order (never a fitted
// slope), says why there is none for a non-monotone sequence, and gives a singular row's
// divergence exponent.
TEST(ConvergenceFigure, LegendGivesTheGuardedObservedOrder) {
  const Loaded data(sample_json());
  Figure figure;
  const Plot plot = sample_convergence(data, ProblemId::H_p, figure);
  ASSERT_FALSE(plot.panels.empty());
  const PlotPanel& q4 = plot.panels.front();
  // LMP = PLM (ss): 1.31, 1.29, 1.279 against 4/pi; its order is the grading layer's.
  const double exact = 4.0 / M_PI;
  const auto order = grading::observed_order(100 * (1.31 / exact - 1), 100 * (1.29 / exact - 1),
                                             100 * (1.279 / exact - 1));
  ASSERT_TRUE(order.order.has_value()) << order.note;
  const PlotSeries* lmp = series_titled(q4, "LMP = PLM (ss)");
  ASSERT_NE(lmp, nullptr);
  EXPECT_EQ(lmp->title, fmt::format("LMP = PLM (ss): order {:.2f}", *order.order));
  // MPC ss: 1.44, 1.47, 1.52, the error grows: no order, and the legend says why.
  const PlotSeries* mpc = series_titled(q4, "MPC");
  ASSERT_NE(mpc, nullptr);
  EXPECT_NE(mpc->title.find("no order: "), std::string::npos) << mpc->title;
  // Three meshes drawn at their element sizes, |error| in percent.
  ASSERT_EQ(lmp->xy.size(), 3u);
  EXPECT_DOUBLE_EQ(lmp->xy[0].first, 0.125);
  EXPECT_NEAR(lmp->xy[2].second, 100 * std::abs(1.279 / exact - 1), 1e-3);  // 4 printed digits

  const Plot punch = sample_convergence(data, ProblemId::F_p, figure);
  const PlotSeries* al = series_titled(punch.panels.front(), "AL");
  ASSERT_NE(al, nullptr);
  EXPECT_NE(al->title.find("exponent 0."), std::string::npos) << al->title;
}

// Requirement: an exact-to-round-off error is left out of the log plot, and the figure says so.
TEST(ConvergenceFigure, RoundOffErrorsAreLeftOutAndNoted) {
  const Loaded data(sample_json());
  Figure figure;
  const Plot plot = sample_convergence(data, ProblemId::P_p, figure);  // AL ss: exact on every mesh
  const PlotSeries* al = series_titled(plot.panels.front(), "AL");
  ASSERT_NE(al, nullptr);
  EXPECT_TRUE(al->xy.empty());
  ASSERT_EQ(figure.notes.size(), 1u);
  EXPECT_NE(figure.notes[0].find("round-off"), std::string::npos);
}

// Requirement: every problem with surface profiles gets a profile figure per element; each
// option set has one colour in every panel, distinct from the others; the zoom shows C, M and
// F of every option set.
TEST(ProfileFigure, OneColourPerOptionSetAndAZoomWithEveryMesh) {
  const Loaded data(sample_json());
  Figure figure;
  const Plot plot = profile_plot(data.index, ProblemId::S_1_3, Element::Q4, figure);
  ASSERT_EQ(plot.panels.size(), 3u);  // AL ss, LMP ss, the zoom
  std::set<std::string> colours;
  for (std::size_t i = 0; i + 1 < plot.panels.size(); ++i) {
    std::set<std::string> own;
    for (const auto& s : plot.panels[i].series) {
      if (s.title != "exact")
        own.insert(s.colour);
    }
    ASSERT_EQ(own.size(), 1u) << plot.panels[i].title;
    colours.insert(*own.begin());
  }
  EXPECT_EQ(colours.size(), 2u);
  const PlotPanel& zoom = plot.panels.back();
  std::map<std::string, std::set<int>> dashes_by_colour;
  for (const auto& s : zoom.series)
    dashes_by_colour[s.colour].insert(s.dash);
  for (const auto& c : colours)
    EXPECT_EQ(dashes_by_colour[c], (std::set<int>{1, 2, 3})) << c;  // F solid, M dashed, C dotted
  ASSERT_TRUE(zoom.x.range && zoom.y.range);

  Figure none;
  EXPECT_TRUE(profile_plot(data.index, ProblemId::P_p, Element::Q4, none).panels.empty());
  Figure hertz;
  EXPECT_FALSE(profile_plot(data.index, ProblemId::H_p, Element::Q8, hertz).panels.empty());
}

bool is_png(const fs::path& p) {
  const std::string bytes = testing::read_text(p);
  return bytes.size() > 1000 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

// Requirement: the figures are PNG files, each tied to its problem's page.
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
    EXPECT_TRUE(f.problem.has_value()) << f.file;
    files.push_back(f.file);
  }
  for (const char* expected :
       {"figures/profile_H_p_Q4.png", "figures/profile_H_p_Q8.png", "figures/profile_S_1_3_Q4.png",
        "figures/convergence_H_p_sigma_c.png", "figures/convergence_H_p_sigma_h.png",
        "figures/convergence_F_p_sigma_c_star.png"}) {
    EXPECT_NE(std::find(files.begin(), files.end(), expected), files.end()) << expected;
  }
}

// Requirement (issue 27): draw_all shares the figures among threads and gives each the outcome
// and the file that draw() gives it alone. Fails if a figure gets another's image or outcome
// (an empty plot's or a refused label's error), or a file differs from the one-by-one drawing.
TEST(Figures, DrawingAtOnceGivesEachFigureItsOwnOutcome) {
  if (!find_gnuplot())
    GTEST_SKIP() << "gnuplot with a PNG terminal is not installed";
  const Loaded data(sample_json());
  std::vector<Plot> plots;
  std::vector<Figure> figures;
  for (const schema::ProblemRecord* p : data.index.problems()) {
    Figure f(FigureKind::convergence, fmt::format("figures/c_{}.png", schema::to_string(p->id)),
             p->id);
    plots.push_back(sample_convergence(data, p->id, f));
    figures.push_back(f);
  }
  ASSERT_GE(plots.size(), 4u);
  plots[1].panels.clear();          // nothing to plot
  plots[2].title = "bad\x01title";  // a control character: refused
  TempDir at_once, one_by_one;
  const GnuplotWriter writer;
  std::vector<Figure> drawn = figures;
  writer.draw_all(plots, at_once.path(), drawn);
  for (std::size_t i = 0; i < plots.size(); ++i) {
    Figure alone = figures[i];
    writer.draw(plots[i], one_by_one.path(), alone);
    EXPECT_EQ(drawn[i].produced, alone.produced) << alone.file;
    EXPECT_EQ(drawn[i].error, alone.error) << alone.file;
    if (alone.produced) {
      EXPECT_EQ(testing::read_text(at_once.path() / alone.file),
                testing::read_text(one_by_one.path() / alone.file))
          << alone.file;
    }
  }
  EXPECT_FALSE(drawn[1].produced);
  EXPECT_FALSE(drawn[2].produced);
  EXPECT_NE(drawn[1].error, drawn[2].error);
  EXPECT_TRUE(drawn[0].produced && drawn[3].produced);
}

// Requirement: figure titles name problems and quantities in plain text, from the vocabulary's
// Markdown labels.
TEST(Figures, PlainTextOfTheVocabularysLabels) {
  EXPECT_EQ(plain_label(schema::label(ProblemId::Pprime_p)), "P'_p");
  EXPECT_EQ(plain_label(schema::label(ProblemId::S_1_3)), "S(1/3)");
  EXPECT_EQ(plain_label(schema::label(ProblemId::H_a)), "H_a");
  EXPECT_EQ(plain_label("σ̄<sub>c</sub><sup>*</sup>"), "σ̄_c^*");
  EXPECT_EQ(plain_label("a <b>bold</b> word"), "a bold word");
}

// Requirement: a conformal fit, whose contact is an arc, has no profile along z = 0 (it once
// drew -sigma_z against a step, captioned as the study's Figure 4); its convergence figures stay.
TEST(Figures, AConformalFitHasNoProfileFigure) {
  auto doc = sample_json();
  for (auto& p : doc["problems"]) {
    if (p["id"] == "H_p")
      p["situation"] = "conformal_fit";
  }
  const Loaded data(doc);
  TempDir tmp;
  const FigureSet set = render_figures(data.index, tmp.path());
  bool convergence = false;
  for (const auto& f : set.figures) {
    if (f.problem == ProblemId::H_p) {
      EXPECT_NE(f.kind, FigureKind::profile) << f.file;
      convergence = convergence || f.kind == FigureKind::convergence;
    }
  }
  EXPECT_TRUE(convergence);
}

TEST(Figures, WithoutGnuplotTheSetSaysSo) {
  const Loaded data(sample_json());
  TempDir tmp;
  const FigureSet set = render_figures(data.index, tmp.path(), {"/nonexistent/gnuplot"});
  EXPECT_FALSE(set.unavailable.empty());
  EXPECT_FALSE(fs::exists(tmp.path() / "figures"));
  for (const auto& f : set.figures)
    EXPECT_EQ(f.error, set.unavailable);
}

TEST(Figures, ProfileNotesSayWhenTheExactCurveIsMissing) {
  auto doc = sample_json();
  for (auto& c : doc["cases"])
    c.erase("exact_profile");
  const Loaded data(doc);
  Figure figure;
  const Plot plot = profile_plot(data.index, ProblemId::H_p, Element::Q4, figure);
  ASSERT_FALSE(plot.panels.empty());
  EXPECT_EQ(plot.panels.back().title.rfind("zoom", 0), std::string::npos);  // nothing to zoom at
  ASSERT_EQ(figure.notes.size(), 1u);
  EXPECT_NE(figure.notes[0].find("no exact curve"), std::string::npos);
}

}  // namespace
}  // namespace cs::reports::test_figures
