#include "reports/findings/anomalies_section.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "grading/accuracy.hpp"
#include "reports/render/template_text.hpp"
#include "reports/tables/markdown_table.hpp"
#include "reports/tables/section_support.hpp"

namespace cs::reports {
namespace {

using schema::Algorithm;
using schema::ContactKind;
using schema::Element;
using Fields = kainjow::mustache::object;

/// 3-point Gauss-Legendre quadrature of f over [a, b]: exact for polynomials of degree <= 5.
template <typename F>
double gauss3(F f, double a, double b) {
  const double x = std::sqrt(0.6), mid = 0.5 * (a + b), half = 0.5 * (b - a);
  return half *
         (5.0 / 9.0 * f(mid - half * x) + 8.0 / 9.0 * f(mid) + 5.0 / 9.0 * f(mid + half * x));
}

/// The quadratic Lagrange shape function of node 0 (t = 0), 1 (t = 1) or 2 (t = 1/2).
double lagrange2(int node, double t) {
  const double s = 2.0 * t - 1.0;
  const std::array<double, 3> n{0.5 * s * (s - 1.0), 0.5 * s * (s + 1.0), 1.0 - s * s};
  return n[static_cast<std::size_t>(node)];
}

/// Quadrature round-off (|v| < 1e-14) printed as the 0 it is.
double clean(double v) {
  return std::abs(v) < 1e-14 ? 0.0 : v;
}

const RowFacts* find(const std::vector<RowFacts>& rows, const RowFacts& like, Element element,
                     Algorithm algorithm) {
  for (const auto& f : rows) {
    if (f.problem == like.problem && f.quantity == like.quantity && f.element == element &&
        f.option == Option{algorithm, like.option.contact})
      return &f;
  }
  return nullptr;
}

AlPmFacts al_pm(const ResultsIndex& index, const std::vector<RowFacts>& rows) {
  AlPmFacts out;
  const auto frictional = [&](schema::ProblemId p) {
    const schema::ProblemRecord* r = index.problem(p);
    return r && r->situation == schema::Situation::frictional;
  };
  for (const auto& f : rows) {
    const RowFacts* pm =
        f.option.algorithm == Algorithm::AL ? find(rows, f, f.element, Algorithm::PM) : nullptr;
    const int both = pm ? 1 : 0, alike = pm && coincide(*f.row, *pm->row) ? 1 : 0;
    (frictional(f.problem) ? out.frictional_rows : out.rows) += both;
    (frictional(f.problem) ? out.frictional_coinciding : out.coinciding) += alike;
  }
  for (const auto& c : index.results().cases) {
    if (c.spec.algorithm != Algorithm::AL || !c.is_baseline() || frictional(c.spec.problem))
      continue;
    ++out.cases;
    if (c.interface && c.interface->max_penetration_over_h)
      out.largest_penetration =
          std::max(out.largest_penetration.value_or(0.0), *c.interface->max_penetration_over_h);
    schema::CaseSpec twin = c.spec;
    twin.algorithm = Algorithm::PM;
    out.same_iterations += std::ranges::any_of(index.results().cases, [&](const auto& d) {
      return d.spec == twin && d.iterations == c.iterations;
    });
  }
  return out;
}

/// Whether the largest -sigma_z/p of a case's surface profile sits on the axis (x/a = 0).
std::optional<bool> peak_on_axis(const schema::CaseResult* c) {
  if (c == nullptr || c->profile.x_over_a.empty())
    return std::nullopt;
  const auto& p = c->profile;
  std::size_t best = 0;
  for (std::size_t i = 0; i < p.x_over_a.size(); ++i) {
    if (std::isfinite(p.sigma_z_over_p[i]) && !(p.sigma_z_over_p[i] <= p.sigma_z_over_p[best]))
      best = i;
  }
  return p.x_over_a[best] == 0.0;
}

std::optional<std::pair<double, std::string>> weighted_force_balance(const ResultsIndex& index) {
  std::optional<std::pair<double, std::string>> worst;
  for (const auto& c : index.results().cases) {
    const auto& s = c.spec;
    const bool weighted = s.contact == ContactKind::mortar ||
                          (s.contact == ContactKind::ss &&
                           (s.algorithm == Algorithm::LMP || s.algorithm == Algorithm::PLM));
    const schema::ProblemRecord* p = index.problem(s.problem);
    if (s.element != Element::Q8 || !weighted || s.algorithm == Algorithm::MPC || !p ||
        !p->axisymmetric || !c.is_baseline() || !c.interface || !c.interface->force_balance)
      continue;
    const double v = std::abs(*c.interface->force_balance);
    if (!worst || v > worst->first)
      worst = std::make_pair(v, schema::case_id(s));
  }
  return worst;
}

std::string errors_text(const RowFacts& f) {
  return join_meshes({format_error_resolved(f.errors[0]), format_error_resolved(f.errors[1]),
                      format_error_resolved(f.errors[2])});
}

std::string row_name(const RowFacts& f) {
  return fmt::format("{} {} {} {}", schema::label(f.problem), schema::label(f.quantity),
                     schema::to_string(f.element), f.option.label());
}

}  // namespace

double quadratic_edge_axisymmetric_weight(int node, double h) {
  return h * h * gauss3([&](double t) { return lagrange2(node, t) * t; }, 0.0, 1.0);
}

double quadratic_edge_axisymmetric_abs_weight(int node, double h) {
  const auto f = [&](double t) { return std::abs(lagrange2(node, t)) * t; };
  return h * h * (gauss3(f, 0.0, 0.5) + gauss3(f, 0.5, 1.0));  // |N| kinks at t = 1/2
}

double corner_weighted_linear_gap(bool axisymmetric, double h) {
  // r = r_e + t h: the r_e part integrates N_c t to 0, so r = t h gives the whole.
  return h *
         gauss3([&](double t) { return lagrange2(0, t) * t * h * (axisymmetric ? t * h : 1.0); },
                0.0, 1.0);
}

double bernstein_axisymmetric_weight(int node, double h) {
  return h * h *
         gauss3(
             [&](double t) {
               const std::array<double, 3> b{(1.0 - t) * (1.0 - t), t * t, 2.0 * t * (1.0 - t)};
               return b[static_cast<std::size_t>(node)] * t;
             },
             0.0, 1.0);
}

double linear_edge_axisymmetric_weight(int node, double h) {
  return h * h * gauss3([&](double t) { return (node == 0 ? 1.0 - t : t) * t; }, 0.0, 1.0);
}

AnomalyFacts anomaly_facts(const ResultsIndex& index, const std::vector<RowFacts>& rows) {
  AnomalyFacts out;
  out.al_pm = al_pm(index, rows);
  for (const auto& f : rows) {
    const schema::ProblemRecord* p = index.problem(f.problem);
    if (f.luck)
      out.luck.push_back(&f);
    if (!p || !p->axisymmetric || f.element != Element::Q8 ||
        f.option != Option{Algorithm::PM, ContactKind::ns} || std::abs(*f.errors[2]) < 5.0)
      continue;
    const RowFacts* lmp = find(rows, f, Element::Q8, Algorithm::LMP);
    const RowFacts* q4 = find(rows, f, Element::Q4, Algorithm::PM);
    out.axis_rows.push_back({&f, lmp ? lmp->errors[2] : std::nullopt,
                             q4 ? q4->errors[2] : std::nullopt,
                             peak_on_axis(index.case_of(*f.row, kFinestMesh))});
  }
  out.weighted_force_balance = weighted_force_balance(index);
  const schema::RowVerdict* fa = index.row(schema::ProblemId::F_a, schema::Quantity::sigma_c_star,
                                           Element::Q8, {Algorithm::LMP, ContactKind::ss});
  if (fa && ResultsIndex::complete(*fa))
    out.fa_q8_lmp_ss = std::array<double, 3>{*fa->values[0], *fa->values[1], *fa->values[2]};
  return out;
}

std::string anomalies_section(const ResultsIndex& index) {
  const std::vector<RowFacts> rows = row_facts(index);
  const AnomalyFacts a = anomaly_facts(index, rows);
  if (a.al_pm.coinciding == 0 && a.axis_rows.empty() && !a.weighted_force_balance && a.luck.empty())
    return {};
  const auto g = [](const char* format, double v) { return fmt::format(fmt::runtime(format), v); };
  // The axis weights at h = 1, in units of h^2 (h^3 for the gap).
  Fields d{{"w_axis", g("{:.3g}", clean(quadratic_edge_axisymmetric_weight(0, 1.0)))},
           {"w_mid", g("{:.4g}", quadratic_edge_axisymmetric_weight(2, 1.0))},
           {"w_far", g("{:.4g}", quadratic_edge_axisymmetric_weight(1, 1.0))},
           {"w_q4", g("{:.4g}", linear_edge_axisymmetric_weight(0, 1.0))},
           {"w_abs", g("{:.4g}", quadratic_edge_axisymmetric_abs_weight(0, 1.0))},
           {"gap_axi", g("{:.4g}", corner_weighted_linear_gap(true, 1.0))},
           {"gap_plane", g("{:.3g}", clean(corner_weighted_linear_gap(false, 1.0)))},
           {"b0", g("{:.4g}", bernstein_axisymmetric_weight(0, 1.0))},
           {"b1", g("{:.4g}", bernstein_axisymmetric_weight(1, 1.0))},
           {"b2", g("{:.4g}", bernstein_axisymmetric_weight(2, 1.0))}};
  if (a.al_pm.coinciding > 0) {
    Fields p{{"rows", std::to_string(a.al_pm.rows)},
             {"coinciding", std::to_string(a.al_pm.coinciding)},
             {"cases", std::to_string(a.al_pm.cases)},
             {"same_iterations", std::to_string(a.al_pm.same_iterations)},
             {"resolution", fmt::format("{:g} %", grading::kCoincidenceRelative * 100)},
             {"frictional_rows", count_or_false(a.al_pm.frictional_rows)},
             {"frictional_coinciding", std::to_string(a.al_pm.frictional_coinciding)}};
    if (a.al_pm.largest_penetration)
      p["penetration"] = g("{:.3g}", *a.al_pm.largest_penetration);
    d["al_pm"] = p;
  }
  int on_axis = 0, profiles = 0;
  for (const auto& r : a.axis_rows) {
    profiles += r.peak_on_axis ? 1 : 0;
    on_axis += r.peak_on_axis.value_or(false) ? 1 : 0;
  }
  d["axis_rows"] = template_list(a.axis_rows, [](const AxisPenaltyRow& r) -> TemplateData {
    return Fields{{"row", fmt::format("{} {}", schema::label(r.pm_q8->problem),
                                      schema::label(r.pm_q8->quantity))},
                  {"pm_q8", format_error_resolved(*r.pm_q8->errors[2])},
                  {"lmp_q8", format_error_resolved(r.lmp_q8)},
                  {"pm_q4", format_error_resolved(r.pm_q4)}};
  });
  d["on_axis"] = fmt::format("{} of {}", on_axis, profiles);
  d["has_axis"] = !a.axis_rows.empty();
  if (const auto& w = a.weighted_force_balance)
    d["basis"] = Fields{{"force_balance", g("{:.2g}", w->first)}, {"case", w->second}};
  if (const auto& v = a.fa_q8_lmp_ss)
    d["fa"] =
        Fields{{"values",
                join_meshes({format_value((*v)[0]), format_value((*v)[1]), format_value((*v)[2])})},
               {"ratios", fmt::format("{:.3f} and {:.3f}", (*v)[1] / (*v)[0], (*v)[2] / (*v)[1])},
               {"sqrt2", g("{:.3f}", std::sqrt(2.0))}};
  d["n_luck"] = count_or_false(a.luck.size());
  d["n_luck_c"] = std::to_string(std::ranges::count_if(a.luck, &RowFacts::study_c));
  const auto luck_cells = [](const RowFacts* f) -> std::vector<std::string> {
    return {row_name(*f), errors_text(*f), f->grade ? name_of(*f->grade) : kMissing,
            f->study_c ? "c" : "", f->credible ? "yes" : "no"};
  };
  d["luck"] = table_of({"Row", "Error C / M / F", "Grade", "c", "Credible"}, a.luck, luck_cells,
                       {Align::left, Align::left, Align::center, Align::center, Align::center})
                  .render();
  return render_template(templates::anomalies_section, d);
}

}  // namespace cs::reports
