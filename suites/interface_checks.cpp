#include "suites/interface_checks.hpp"

#include <algorithm>
#include <cmath>

namespace cs::suites {
namespace {

/// A node lies outside the exact patch when it is more than one element beyond the exact
/// contact half-width: the discrete edge of contact cannot be placed finer than an element.
bool outside_patch(const ProblemSetup& setup, double x, double h) {
  return x > setup.contact_half_width_a + h * (1.0 + 1e-9);
}

}  // namespace

schema::InterfaceChecks check_interface(const ProblemSetup& setup,
                                        const solver::ContactResult& contact, double applied_load) {
  schema::InterfaceChecks checks;
  if (contact.nodes.empty() || !(setup.p > 0.0))
    return checks;
  if (applied_load > 0.0 && std::isfinite(applied_load))
    checks.force_balance = (contact.total_normal_force - applied_load) / applied_load;
  const double h = setup.mesh_info.h_contact;
  double tensile = 0.0, outside = 0.0, penetration = 0.0;
  for (const auto& n : contact.nodes) {
    tensile = std::max(tensile, -n.pressure);
    penetration = std::max(penetration, n.penetration);
    if (outside_patch(setup, n.position.x(), h))
      outside = std::max(outside, n.pressure);
  }
  checks.max_tensile_over_p = tensile / setup.p;
  checks.max_outside_over_p = outside / setup.p;
  if (h > 0.0)
    checks.max_penetration_over_h = penetration / h;
  return checks;
}

}  // namespace cs::suites
