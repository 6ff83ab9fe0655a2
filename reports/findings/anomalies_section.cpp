#include "reports/findings/anomalies_section.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "grading/convergence.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/option_classes.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;
using schema::Element;

/// Every (problem, quantity, element) slot of the baseline rows.
std::vector<Slot> all_slots(const ResultsIndex& index) {
  std::vector<Slot> slots;
  for (const schema::ProblemRecord* p : index.problems()) {
    for (const auto& q : p->quantities) {
      for (const auto element : schema::values<Element>())
        slots.push_back({p->id, q.quantity, element});
    }
  }
  return slots;
}

std::string al_equals_pm(const ResultsIndex& index) {
  int rows = 0, coinciding = 0, same_iterations = 0, cases = 0;
  double largest_penetration = 0.0;
  bool any_penetration = false;
  for (const Slot& slot : all_slots(index)) {
    for (const ContactKind contact : schema::values<ContactKind>()) {
      const OptionComparison cmp =
          compare_options(index, {Algorithm::AL, contact}, {Algorithm::PM, contact}, {slot});
      rows += cmp.compared;
      coinciding += cmp.coincide() ? 1 : 0;
    }
  }
  for (const auto& c : index.results().cases) {
    if (c.spec.algorithm != Algorithm::AL || !c.is_baseline())
      continue;
    ++cases;
    if (c.interface && c.interface->max_penetration_over_h) {
      any_penetration = true;
      largest_penetration = std::max(largest_penetration, *c.interface->max_penetration_over_h);
    }
    for (const auto& d : index.results().cases) {
      schema::CaseSpec twin = c.spec;
      twin.algorithm = Algorithm::PM;
      if (d.spec == twin && d.iterations == c.iterations)
        ++same_iterations;
    }
  }
  if (coinciding == 0)
    return {};
  std::string out = fmt::format(
      "- **AL = PM.** AL and PM coincide on {} of the {} rows where both ran (values within "
      "0.01 % on every mesh), and {} of {} AL cases take exactly as many iterations as their PM "
      "twin. AL differs from PM only once it augments its multipliers, which it does when the "
      "penetration exceeds FTOLN h (0.1 h by default).",
      coinciding, rows, same_iterations, cases);
  if (any_penetration) {
    out += fmt::format(
        " The largest penetration of any AL case is {:.3g} h (interface checks): far below "
        "FTOLN, so the augmentation never starts and AL is PM at the default FKN and FTOLN.",
        largest_penetration);
  }
  return out + "\n";
}

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (const auto& part : parts)
    out += (out.empty() ? "" : "; ") + part;
  return out;
}

/// Quadrature round-off (|v| < 1e-14) printed as the 0 it is.
double round_off_to_zero(double v) {
  return std::abs(v) < 1e-14 ? 0.0 : v;
}

/// The position (x/a) of the largest -sigma_z/p of a case's surface profile.
std::optional<double> peak_position(const schema::CaseResult& c) {
  const auto& p = c.profile;
  std::optional<double> x;
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.x_over_a.size(); ++i) {
    if (std::isfinite(p.sigma_z_over_p[i]) && p.sigma_z_over_p[i] > best) {
      best = p.sigma_z_over_p[i];
      x = p.x_over_a[i];
    }
  }
  return x;
}

std::string axisymmetric_q8_penalty(const ResultsIndex& index) {
  std::vector<std::string> rows;
  int at_axis = 0, cases = 0;
  for (const schema::ProblemRecord* p : index.problems()) {
    if (!p->axisymmetric || p->singular)
      continue;
    for (const auto& q : p->quantities) {
      const schema::RowVerdict* pm =
          index.row(p->id, q.quantity, Element::Q8, {Algorithm::PM, ContactKind::ns});
      const schema::RowVerdict* lm =
          index.row(p->id, q.quantity, Element::Q8, {Algorithm::LMP, ContactKind::ns});
      const schema::RowVerdict* q4 =
          index.row(p->id, q.quantity, Element::Q4, {Algorithm::PM, ContactKind::ns});
      if (pm == nullptr || !pm->errors[2] || std::abs(*pm->errors[2]) < 5.0)
        continue;
      if (const schema::CaseResult* c = index.case_of(*pm, kFinestMesh)) {
        const auto x = peak_position(*c);
        ++cases;
        at_axis += x && *x == 0.0 ? 1 : 0;
      }
      rows.push_back(fmt::format(
          "{} {}: PM ns Q8 {} on F; LMP ns Q8 {}; PM ns Q4 {}", schema::label(p->id),
          schema::to_string(q.quantity), format_percent(*pm->errors[2]),
          lm && lm->errors[2] ? format_percent(*lm->errors[2]) : std::string(kMissing),
          q4 && q4->errors[2] ? format_percent(*q4->errors[2]) : std::string(kMissing)));
    }
  }
  if (rows.empty())
    return {};
  const std::string list = joined(rows);
  return fmt::format(
      "- **AL/PM node-to-surface with Q8 in axisymmetry.** {}. On F the largest −σ<sub>z</sub>/p "
      "sits on the axis (r = 0) in {} of {} of these cases. The consistent weight ∫N r dr of a "
      "Q8 corner node on the axis is {:.3g} h² (3-point Gauss quadrature of an edge [0, h]; "
      "midside {:.4g} h², far corner {:.4g} h²), against {:.4g} h² for the Q4 axis node: under "
      "a uniform pressure the consistent load of that node is 0. The node is not left "
      "unconstrained, though: node-to-surface scales its penalty by ∫|N| r dr = {:.4g} h² instead, "
      "so it takes a force FKN E d / h · {:.4g} h² for a penetration d that the consistent load "
      "does not call for, a point force on the axis. Lagrange multipliers enforce the node's gap "
      "and take from it whatever force equilibrium asks (0 here), which is why LMP ns Q8 is "
      "exact on the same meshes.\n",
      list, at_axis, cases, round_off_to_zero(quadratic_edge_axisymmetric_weight(0, 1.0)),
      quadratic_edge_axisymmetric_weight(2, 1.0), quadratic_edge_axisymmetric_weight(1, 1.0),
      linear_edge_axisymmetric_weight(0, 1.0), quadratic_edge_axisymmetric_abs_weight(0, 1.0),
      quadratic_edge_axisymmetric_abs_weight(0, 1.0));
}

/// The largest |force balance| of the Q8 cases with weighted rows (ss with LMP or PLM, mortar
/// with AL, PM, LMP or PLM) on axisymmetric problems, and its case id.
std::optional<std::pair<double, std::string>> weighted_q8_force_balance(const ResultsIndex& index) {
  std::optional<std::pair<double, std::string>> worst;
  for (const auto& c : index.results().cases) {
    const auto& s = c.spec;
    const bool weighted = s.contact == ContactKind::mortar ||
                          (s.contact == ContactKind::ss &&
                           (s.algorithm == Algorithm::LMP || s.algorithm == Algorithm::PLM));
    const schema::ProblemRecord* p = index.problem(s.problem);
    if (s.element != Element::Q8 || !weighted || s.algorithm == Algorithm::MPC || !p ||
        !p->axisymmetric || !c.interface || !c.interface->force_balance)
      continue;
    const double v = std::abs(*c.interface->force_balance);
    if (!worst || v > worst->first)
      worst = std::make_pair(v, schema::case_id(s));
  }
  return worst;
}

std::string weighted_q8_basis(const ResultsIndex& index) {
  const auto worst = weighted_q8_force_balance(index);
  if (!worst)
    return {};
  std::string out = fmt::format(
      "- **Q8 weighted-gap rows (ss with LMP/PLM/MPC, mortar): the multiplier basis.** A "
      "weighted row enforces ∫Φ<sub>a</sub> g (r) ds ≥ 0 and carries λ<sub>a</sub> ≥ 0. With the "
      "Lagrange shape functions as Φ, a Q8 corner function (1 − s)(1 − 2s) changes sign, and in "
      "axisymmetry that breaks both: on the axis ∫N r dr = {:.3g} h², so the axis multiplier "
      "transmits no net force while it counts as one; and beyond the end of a target, where the "
      "gap grows as g = r − r<sub>e</sub>, ∫N<sub>c</sub> g r dr = {:.4g} h³ over the outer edge "
      "(plane strain: {:.3g}), a weighted gap that reads penetration where there is none. Both "
      "sit at H<sub>a</sub> (the indenter ends at 2a) and F<sub>a</sub> (the punch edge), so the "
      "solver takes as Φ on Q8 sides the quadratic Bernstein basis (1 − s)², 2s(1 − s), s², "
      "which spans the same quadratics and sums to 1 (the patch tests hold) but is ≥ 0 (weights on "
      "the axis edge {:.4g}, {:.4g}, "
      "{:.4g} h²). The largest |force balance| of a Q8 weighted-row case (MPC aside) in "
      "axisymmetry is now {:.2g} (`{}`).",
      round_off_to_zero(quadratic_edge_axisymmetric_weight(0, 1.0)),
      corner_weighted_linear_gap(true, 1.0),
      round_off_to_zero(corner_weighted_linear_gap(false, 1.0)),
      bernstein_axisymmetric_weight(0, 1.0), bernstein_axisymmetric_weight(2, 1.0),
      bernstein_axisymmetric_weight(1, 1.0), worst->first, worst->second);
  const schema::RowVerdict* f = index.row(schema::ProblemId::F_a, schema::Quantity::sigma_c_star,
                                          Element::Q8, {Algorithm::LMP, ContactKind::ss});
  if (f && f->values[0] && f->values[1] && f->values[2]) {
    out += fmt::format(
        " The edge stress of F<sub>a</sub> Q8 LMP ss reads {} / {} / {} on C / M / F: ratios "
        "{:.3f} and {:.3f} per halving of h, against "
        "√2 = {:.3f} for the square-root singularity.",
        format_value(f->values[0]), format_value(f->values[1]), format_value(f->values[2]),
        *f->values[1] / *f->values[0], *f->values[2] / *f->values[1], std::sqrt(2.0));
  }
  return out + "\n";
}

std::string crossings(const ResultsIndex& index) {
  std::vector<std::string> rows;
  int converging = 0;
  for (const schema::RowVerdict* r : index.baseline_rows()) {
    if (!r->grade || !r->errors[2] ||
        !grading::luck_of_one_mesh(r->errors[0].value_or(0.0), r->errors[1].value_or(0.0),
                                   *r->errors[2]))
      continue;
    converging += r->converging.value_or(false) ? 1 : 0;
    rows.push_back(fmt::format(
        "{} {} {} {}: {} / {} / {}", schema::label(r->spec.problem), schema::to_string(r->quantity),
        schema::to_string(r->spec.element), Option{r->spec.algorithm, r->spec.contact}.label(),
        format_value(r->errors[0]), format_value(r->errors[1]), format_value(r->errors[2])));
  }
  if (rows.empty())
    return {};
  const std::string list = joined(rows);
  return fmt::format(
      "- **Fine-mesh grades after errors above 100 %.** {} row(s) are graded e or g on F after "
      "an error above 100 % on C or M (errors in % on C / M / F): {}. {} of them converge by "
      "the study's rule. An error that falls from above 100 % into the e or g band within two "
      "halvings of h is far faster than any order these elements deliver: the fine-mesh grade "
      "is the luck of one mesh, not evidence for the option.\n",
      rows.size(), list, converging);
}

}  // namespace

double quadratic_edge_axisymmetric_weight(int node, double h) {
  const std::array<double, 3> xi{-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const std::array<double, 3> w{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double sum = 0.0;
  for (std::size_t g = 0; g < 3; ++g) {
    const double s = xi[g];
    const std::array<double, 3> n{0.5 * s * (s - 1.0), 0.5 * s * (s + 1.0), 1.0 - s * s};
    const double r = 0.5 * h * (1.0 + s);
    sum += w[g] * n[static_cast<std::size_t>(node)] * r * 0.5 * h;
  }
  return sum;
}

double quadratic_edge_axisymmetric_abs_weight(int node, double h) {
  // |N| has a kink where N changes sign (t = 1/2 for a corner): 3-point Gauss on each half.
  const std::array<double, 3> xi{-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const std::array<double, 3> w{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double sum = 0.0;
  for (const double t0 : {0.0, 0.5}) {
    for (std::size_t g = 0; g < 3; ++g) {
      const double t = t0 + 0.25 * (1.0 + xi[g]);
      const double s = 2.0 * t - 1.0;
      const std::array<double, 3> n{0.5 * s * (s - 1.0), 0.5 * s * (s + 1.0), 1.0 - s * s};
      sum += w[g] * std::abs(n[static_cast<std::size_t>(node)]) * t * h * 0.25 * h;
    }
  }
  return sum;
}

double corner_weighted_linear_gap(bool axisymmetric, double h) {
  // Corner at t = 0, gap g = t h, r = r_e + t h: the r_e part integrates N_c t to 0, so r = t h
  // gives the whole; 3-point Gauss is exact (degree <= 4).
  const std::array<double, 3> xi{-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const std::array<double, 3> w{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double sum = 0.0;
  for (std::size_t g = 0; g < 3; ++g) {
    const double t = 0.5 * (1.0 + xi[g]);
    const double n = (1.0 - t) * (1.0 - 2.0 * t);
    const double r = axisymmetric ? t * h : 1.0;
    sum += w[g] * n * (t * h) * r * 0.5 * h;
  }
  return sum;
}

double bernstein_axisymmetric_weight(int node, double h) {
  const std::array<double, 3> xi{-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const std::array<double, 3> w{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double sum = 0.0;
  for (std::size_t g = 0; g < 3; ++g) {
    const double t = 0.5 * (1.0 + xi[g]);
    const std::array<double, 3> b{(1.0 - t) * (1.0 - t), t * t, 2.0 * t * (1.0 - t)};
    sum += w[g] * b[static_cast<std::size_t>(node)] * t * h * 0.5 * h;
  }
  return sum;
}

double linear_edge_axisymmetric_weight(int node, double h) {
  const double s0 = 1.0 / std::sqrt(3.0);
  double sum = 0.0;
  for (const double s : {-s0, s0}) {
    const std::array<double, 2> n{0.5 * (1.0 - s), 0.5 * (1.0 + s)};
    sum += n[static_cast<std::size_t>(node)] * 0.5 * h * (1.0 + s) * 0.5 * h;
  }
  return sum;
}

std::string anomalies_section(const ResultsIndex& index) {
  const std::string body = al_equals_pm(index) + axisymmetric_q8_penalty(index) +
                           weighted_q8_basis(index) + crossings(index);
  if (body.empty())
    return {};
  return "## Anomalies explained\n\n"
         "What the tables show that an analyst would ask about, each with the computation that "
         "explains it.\n\n" +
         body + "\n";
}

}  // namespace cs::reports
