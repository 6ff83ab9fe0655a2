// The whole report of a real run (data/battery_results.json), figures off, against gold files
// (tests/reports/gold/battery/), compared line by line with a numeric tolerance: words and
// layout must match exactly; a number may differ by one unit in the last digit the gold file
// prints (round-off of the last place) and no more. A change of the report's content shows up
// here as a diff. To accept a deliberate change:
//   CS_UPDATE_GOLD=1 build/tests/test_reports --gtest_filter='GoldReport.*'

#include <cmath>
#include <cstdlib>
#include <regex>

#include <gtest/gtest.h>

#include "report_test_support.hpp"
#include "reports/report_writer.hpp"

namespace cs::reports {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

fs::path gold_dir() {
  return testing::source_dir() / "tests" / "reports" / "gold" / "battery";
}

/// A line split into its text and its numbers ("−0.28" counts as -0.28, U+2212 being the
/// report's minus sign); `places` is each number's count of printed decimals.
struct Tokens {
  std::string text;
  std::vector<double> numbers;
  std::vector<int> places;
};

Tokens tokenize(const std::string& line) {
  static const std::regex number(R"((−|-|\+)?\d+(\.(\d+))?(e[-+]\d+)?)");
  Tokens t;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(line.begin(), line.end(), number);
       it != std::sregex_iterator(); ++it) {
    t.text += line.substr(last, it->position() - last) + "#";
    std::string s = it->str();
    const bool unicode_minus = s.rfind("−", 0) == 0;
    if (unicode_minus)
      s = "-" + s.substr(std::string("−").size());
    t.numbers.push_back(std::stod(s));
    const int exponent = (*it)[4].matched ? std::stoi((*it)[4].str().substr(1)) : 0;
    t.places.push_back(static_cast<int>((*it)[3].length()) - exponent);
    last = it->position() + it->length();
  }
  t.text += line.substr(last);
  return t;
}

/// Empty when `actual` matches `gold`, else the first differing line.
std::string compare(const std::string& gold, const std::string& actual) {
  std::istringstream g(gold), a(actual);
  std::string gl, al;
  for (int n = 1;; ++n) {
    const bool more_g = static_cast<bool>(std::getline(g, gl));
    const bool more_a = static_cast<bool>(std::getline(a, al));
    if (!more_g && !more_a)
      return {};
    if (more_g != more_a)
      return "line " + std::to_string(n) + ": one file ends first";
    const Tokens tg = tokenize(gl), ta = tokenize(al);
    bool same = tg.text == ta.text && tg.numbers.size() == ta.numbers.size();
    for (std::size_t i = 0; same && i < tg.numbers.size(); ++i) {
      const double unit = std::pow(10.0, -tg.places[i]);
      same = std::abs(tg.numbers[i] - ta.numbers[i]) <= unit * 1.0000001;
    }
    if (!same)
      return "line " + std::to_string(n) + ":\n  gold:   " + gl + "\n  actual: " + al;
  }
}

// Requirement: the report of the battery fixture matches its gold files, page by page, up to
// one unit in the last printed digit; no page is added or lost.
TEST(GoldReport, BatteryFixtureMatchesItsGoldFiles) {
  testing::TempDir tmp;
  ReportOptions o;
  o.out_dir = tmp.path() / "report";
  o.study_data = testing::study_dir();
  o.figures = false;
  auto doc = schema::read_results_file(testing::source_dir() / "tests" / "reports" / "data" /
                                       "battery_results.json");
  doc.source = "battery_results.json";  // the checkout's path is not part of the report
  const ReportOutcome outcome = write_report(doc, o);
  const bool update = std::getenv("CS_UPDATE_GOLD") != nullptr;
  if (update)
    fs::create_directories(gold_dir());
  std::vector<std::string> pages;
  for (const auto& file : outcome.files) {
    if (fs::path(file).extension() != ".md")
      continue;
    pages.push_back(file);
    const std::string actual = read_text(o.out_dir / file);
    if (update) {
      testing::write_text(gold_dir() / file, actual);
      continue;
    }
    ASSERT_TRUE(fs::exists(gold_dir() / file)) << file << " has no gold file";
    const std::string diff = compare(read_text(gold_dir() / file), actual);
    EXPECT_TRUE(diff.empty()) << file << " " << diff;
  }
  int gold_pages = 0;
  for (const auto& e : fs::directory_iterator(gold_dir()))
    gold_pages += e.path().extension() == ".md";
  EXPECT_EQ(gold_pages, static_cast<int>(pages.size())) << "a page was added or lost";
}

// Requirement: the comparison itself fails on a changed word and on a number beyond the last
// printed digit, and passes round-off of that digit.
TEST(GoldReport, TheComparisonSeesWordsAndDigits) {
  EXPECT_EQ(compare("e −0.28 % (0.01)", "e −0.29 % (0.01)"), "");
  EXPECT_NE(compare("e −0.28 %", "e −0.30 %"), "");
  EXPECT_NE(compare("e −0.28 %", "e +0.28 %"), "");
  EXPECT_NE(compare("e −0.28 %", "g −0.28 %"), "");
  EXPECT_EQ(compare("4.1e-13 %", "4.2e-13 %"), "");
  EXPECT_NE(compare("4.1e-13 %", "4.1e-12 %"), "");
  EXPECT_NE(compare("a\nb\n", "a\n"), "");
}

}  // namespace
}  // namespace cs::reports
