#include "reports/pages/claims_ledger.hpp"

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

TemplateData claim_data(const ClaimEvidence& c) {
  TemplateData d;
  d.set("verdict", to_string(c.verdict));
  d.set("testable", c.verdict != ClaimVerdict::not_testable);
  d.set("part_not_testable", c.part_not_testable);
  d.set("resolution", fmt::format("{:g} %", grading::kCoincidenceRelative * 100));
  d.set("n", std::to_string(c.n));
  d.set("n_hold", std::to_string(c.n_hold));
  d.set("has_n", c.n > 0);
  d.set("n_fail", std::to_string(c.n - c.n_hold));
  d.set("n_excluded", std::to_string(c.n_excluded));
  d.set("has_excluded", c.n_excluded > 0);
  d.set("n2", std::to_string(c.n2));
  d.set("n2_hold", std::to_string(c.n2_hold));
  d.set("has_n2", c.n2 > 0);
  d.set("n2_exact", std::to_string(c.n2_exact));
  d.set("has_n2_exact", c.n2_exact > 0);
  d.set("has_figure", c.figure.has_value());
  d.set("figure", c.figure ? fmt::format("{:.3g}", *c.figure) : std::string());
  d.set("figure2", c.figure2 ? fmt::format("{:.3g}", *c.figure2) : std::string());
  d.set("has_examples", !c.examples.empty());
  d.set("examples", c.examples);
  d.set("examples_more", count_or_false(c.examples_more));
  d.set("has_examples2", !c.examples2.empty());
  d.set("examples2", c.examples2);
  d.set("examples2_more", count_or_false(c.examples2_more));
  d.set("members", c.members);
  d.set("members2", c.members2);
  d.set("part2_run", c.part2_run);
  d.set("verdict1", to_string(c.verdict1));
  d.set("verdict2", to_string(c.verdict2));
  d.set("has_exception", c.n_exception > 0);
  d.set("n_exception", std::to_string(c.n_exception));
  d.set("n_exception_holds", std::to_string(c.n_exception_holds));
  d.set("has_exception_examples", !c.exception_examples.empty());
  d.set("exception_examples", c.exception_examples);
  d.set("exception_examples_more", count_or_false(c.exception_examples_more));
  d.set("order_biased", c.n_order_pairs > 0 && c.verdict == ClaimVerdict::not_testable);
  d.set("noise_unknown", c.n > 0 && c.n_order_pairs == 0);
  // claim 7: the contact phase, and whether it alone makes the claim refined
  d.set("n3", std::to_string(c.n3));
  d.set("n3_hold", std::to_string(c.n3_hold));
  d.set("figure3", c.figure3 ? fmt::format("{:.3g}", *c.figure3) : std::string());
  d.set("range_low", c.range_low ? fmt::format("{:.2g}", *c.range_low) : std::string());
  d.set("range_high", c.range_high ? fmt::format("{:.2g}", *c.range_high) : std::string());
  d.set("has_phase", c.n3 > 0);
  d.set("phase_only", c.verdict == ClaimVerdict::refined && c.verdict1 > ClaimVerdict::refined);
  d.set("n_order_pairs", std::to_string(c.n_order_pairs));
  d.set("n_later_faster", std::to_string(c.n_later_faster));
  d.set("order_bias_z", fmt::format("{:.1f}", c.order_bias_z));
  d.set("has_not_run", !c.not_run.empty());
  d.set("not_run", c.not_run);
  d.set("n_plateau", std::to_string(c.n_plateau));
  d.set("has_plateau", c.n_plateau > 0);
  d.set("n_round_off", std::to_string(c.n_round_off));
  d.set("has_round_off", c.n_round_off > 0);
  d.set("n_unsound", std::to_string(c.n_unsound));
  d.set("has_unsound", c.n_unsound > 0);
  d.set("n_graded_unsatisfactory", std::to_string(c.n_hold - c.n_unsound));
  d.set("n_not_closer", std::to_string(c.n - c.n_hold - c.n_plateau));
  return d;
}

}  // namespace

std::string claims_ledger(const std::vector<ClaimEvidence>& claims) {
  TemplateData d;
  for (const auto& c : claims) {
    d.set(c.key, claim_data(c));
  }
  return render_template(templates::claims_ledger, d);
}

}  // namespace cs::reports
