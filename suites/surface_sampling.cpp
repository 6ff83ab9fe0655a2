#include "suites/surface_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "grading/accuracy.hpp"
#include "suites/arc_sampling.hpp"
#include "suites/friction_sampling.hpp"

namespace cs::suites {
namespace {

/// -sigma/p of one stress component.
double normalized(const solver::Stress& s, StressComponent c, double p) {
  switch (c) {
    case StressComponent::SigmaZ:
      return -s.sigma_z / p;
    case StressComponent::SigmaX:
      return -s.sigma_x / p;
    case StressComponent::TauXZ:
      return -s.tau_xz / p;
  }
  return std::nan("");
}

/// The index of the sample of `positions` that a rule reads, or -1 when there is none.
int sample_index(const std::vector<double>& x, const std::vector<double>& values, SamplePoint where,
                 double a) {
  if (x.empty())
    return -1;
  int best = 0;
  for (int i = 1; i < static_cast<int>(x.size()); ++i) {
    switch (where) {
      case SamplePoint::MaxOnSurface:
        if (values[i] > values[best])
          best = i;
        break;
      case SamplePoint::AtAxis:
        if (std::abs(x[i]) < std::abs(x[best]))
          best = i;
        break;
      case SamplePoint::AtEdge:
        if (std::abs(x[i] - a) < std::abs(x[best] - a))
          best = i;
        break;
      case SamplePoint::StickZoneEdge:  // read off the contact (friction_sampling.hpp)
      case SamplePoint::ContactPeakShear:
      case SamplePoint::ContactEdge:            // from the pressures (contact_edge)
      case SamplePoint::InterfaceMeanPressure:  // from the contact (arc_sampling.hpp)
      case SamplePoint::ArcPressureExtreme:
        return -1;
    }
  }
  return best;
}

/// The edge of contact from the pressures reported along the surface: halfway between the
/// last sample (outwards from the axis) that carries pressure and the next one (the discrete
/// edge lies somewhere between them: half an element is the resolution); the last sample's x
/// when contact reaches the end of the surface; NaN when nothing is in contact. A pressure
/// counts when it exceeds 1e-9 of the largest (a penalty's open nodes carry none).
double contact_edge(const std::vector<ContactPressureSample>& contact) {
  std::vector<ContactPressureSample> sorted(contact);
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& u, const auto& v) { return std::abs(u.x) < std::abs(v.x); });
  double peak = 0.0;
  for (const auto& c : sorted)
    peak = std::max(peak, c.pressure);
  if (!(peak > 0.0))
    return std::nan("");
  std::optional<std::size_t> last;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (sorted[i].pressure > 1e-9 * peak)
      last = i;
  }
  if (*last + 1 == sorted.size())
    return std::abs(sorted[*last].x);
  return 0.5 * (std::abs(sorted[*last].x) + std::abs(sorted[*last + 1].x));
}

/// The profile of the study's Figure 4 (nodal -sigma_z/p and the contact pressure over p, by
/// x / a) and the surface's unnormalized nodal values (what the import layout holds). A contact
/// pressure belongs to a surface node when it is reported within 1e-9 a of it.
void fill_profile(const std::vector<solver::SurfaceStressSample>& surface,
                  const std::vector<ContactPressureSample>& contact, double p, double a,
                  CaseResult& result) {
  for (const auto& s : surface) {
    result.profile.x_over_a.push_back(s.position.x() / a);
    result.profile.sigma_z_over_p.push_back(-s.stress.sigma_z / p);
    const ContactPressureSample* nearest = nullptr;
    double distance = std::numeric_limits<double>::infinity();
    for (const auto& c : contact) {
      const double d = std::abs(c.x - s.position.x());
      if (d < distance)
        distance = d, nearest = &c;
    }
    const bool at_node = nearest != nullptr && distance < 1e-9 * a;
    result.profile.pressure_over_p.push_back(at_node ? nearest->pressure / p : std::nan(""));
    if (s.node >= 0) {
      result.surface_nodes.push_back(
          {s.position.x(), s.stress.sigma_z, s.stress.sigma_x,
           at_node ? std::optional<double>(nearest->pressure) : std::nullopt});
    }
  }
}

}  // namespace

std::vector<solver::SurfaceStressSample> surface_of_nodal_stresses(
    const ProblemSetup& setup, const std::vector<solver::Stress>& nodal_stress) {
  const solver::Mesh& mesh = setup.model.mesh;
  solver::StressField field;
  field.method = solver::StressRecoveryMethod::ExtrapolatedAveraged;
  const std::size_t n_bodies = mesh.body_names.size();
  const auto n = static_cast<std::size_t>(mesh.n_nodes());
  field.nodal.assign(n_bodies, std::vector<solver::Stress>(n));
  field.nodal_count.assign(n_bodies, std::vector<int>(n, 0));
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const auto body = static_cast<std::size_t>(mesh.element_body[e]);
    for (int k = 0; k < mesh.n_element_nodes(); ++k) {
      const auto node = static_cast<std::size_t>(mesh.elements[e][k]);
      field.nodal[body][node] = nodal_stress.at(node);
      field.nodal_count[body][node] = 1;
    }
  }
  return solver::surface_stresses(setup.model, field, kSampledSurface);
}

/// Fills value, error and grade of each quantity, the contact-pressure version, and the profile.
void sample_quantities(const ProblemSetup& setup,
                       const std::vector<solver::SurfaceStressSample>& surface,
                       const std::vector<ContactPressureSample>& contact, CaseResult& result,
                       const solver::ContactResult* solution,
                       const solver::ContactResult* interface) {
  const double p = setup.p, a = setup.contact_half_width_a;
  std::vector<double> x_nodal, x_contact, pressure;
  for (const auto& s : surface)
    x_nodal.push_back(s.position.x());
  for (const auto& n : contact) {
    x_contact.push_back(n.x);
    pressure.push_back(n.pressure / p);
  }
  for (const QuantityRule& rule : setup.quantities) {
    if (sampled_from_contact(rule.where) || sampled_along_arc(rule.where)) {
      const solver::ContactResult* arc = solution != nullptr ? solution : interface;
      if (sampled_along_arc(rule.where) && arc != nullptr) {
        result.quantities.push_back(arc_quantity(rule, *arc, setup));
      } else if (solution != nullptr) {
        result.quantities.push_back(contact_quantity(rule, *solution, a, p));
      } else {  // a solver that reports no friction states: the quantity has no value
        QuantityResult q;
        q.quantity = rule.quantity;
        q.exact = rule.exact;
        q.value = q.error_percent = std::nan("");
        result.quantities.push_back(q);
      }
      continue;
    }
    if (rule.where == SamplePoint::ContactEdge) {
      QuantityResult q;
      q.quantity = rule.quantity;
      q.exact = rule.exact;
      q.value = contact_edge(contact) / setup.length_unit;
      q.error_percent = grading::error_percent(q.value, rule.exact);
      q.grade = grading::grade_of_error(q.error_percent);
      result.quantities.push_back(q);
      continue;
    }
    std::vector<double> values;
    for (const auto& s : surface)
      values.push_back(normalized(s.stress, rule.component, p));
    QuantityResult q;
    q.quantity = rule.quantity;
    q.exact = rule.exact;
    q.study_exact = rule.study_exact;
    const int i = sample_index(x_nodal, values, rule.where, a);
    q.value = i >= 0 ? values[i] : std::nan("");
    if (std::isfinite(rule.exact)) {
      q.error_percent = grading::error_percent(q.value, rule.exact);
      q.grade = grading::grade_of_error(q.error_percent);
    } else {
      q.error_percent = std::nan("");  // singular: no error to give (null in results.json)
    }
    if (rule.component == StressComponent::TauXZ && solution != nullptr)
      q.contact_pressure = solution->peak_shear / p;  // the contact's own peak shear
    if (rule.component == StressComponent::SigmaZ) {
      const int j = sample_index(x_contact, pressure, rule.where, a);
      if (j >= 0 && std::isfinite(pressure[j]))
        q.contact_pressure = pressure[j];
    }
    result.quantities.push_back(q);
  }
  fill_profile(surface, contact, p, a, result);
}

/// The exact -sigma_z/p on z = 0 at 301 points of 0 <= x <= 1.5 a (within the block).
ExactProfile exact_profile(const ProblemSetup& setup) {
  ExactProfile out;
  if (!setup.exact_pressure_over_p)
    return out;
  const double a = setup.contact_half_width_a;
  const double x_max = std::min(1.5 * a, setup.mesh_info.block_width);
  constexpr int kPoints = 301;
  for (int i = 0; i < kPoints; ++i) {
    const double x = x_max * i / (kPoints - 1);
    double value = std::nan("");
    try {
      value = setup.exact_pressure_over_p(x);
    } catch (const std::invalid_argument&) {
      continue;  // the singular edge of a flat punch
    }
    if (!std::isfinite(value))
      continue;
    out.x_over_a.push_back(x / a);
    out.sigma_z_over_p.push_back(value);
  }
  return out;
}

/// Every quantity of the problem with no value: a failed case still names what it lacks.
void mark_missing(const ProblemSetup& setup, CaseResult& result) {
  for (const QuantityRule& rule : setup.quantities) {
    QuantityResult q;
    q.quantity = rule.quantity;
    q.exact = rule.exact;
    q.study_exact = rule.study_exact;
    q.value = std::nan("");
    q.error_percent = std::nan("");
    result.quantities.push_back(q);
  }
}

}  // namespace cs::suites
