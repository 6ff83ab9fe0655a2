#pragma once
// A study problem built for one case: the solver's model and contact pair, and what the
// grading needs (the normalizing pressure, the exact values, where each quantity is sampled).
//
// Units: every problem is built with p = 1 (the normalizing pressure), its length unit (a, or
// b for S) = 1 and E = 1 / (p/E); so normalized results are read off directly.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "schema/quantity.hpp"
#include "solver/contact/contact_analysis.hpp"
#include "solver/model.hpp"
#include "suites/case_spec.hpp"
#include "suites/parameters.hpp"
#include "suites/study_meshes.hpp"

namespace cs::suites {

/// Where on the indented body's contact surface a quantity is read.
enum class SamplePoint {
  MaxOnSurface,           ///< the largest value over the surface nodes (P: sigma_z_max; S: sigma_c)
  AtAxis,                 ///< the node at x = 0 (H: sigma_c, sigma_h)
  AtEdge,                 ///< the node at x = a, the contact edge (F: sigma_c_star)
  StickZoneEdge,          ///< c/a from the contact's stick/slip states (CM), not the stresses
  ContactPeakShear,       ///< the contact solution's largest |shear| (CM: the traction has a cusp
                          ///< at c that nodal stress recovery smooths); see friction_sampling.hpp
  InterfaceMeanPressure,  ///< the contact's resultant normal force over the exact one (IF):
                          ///< the mean pressure over p; see arc_sampling.hpp
  ArcPressureExtreme,     ///< the nodal contact pressure over p farthest from the exact one
                          ///< along the contact surface (IF); see arc_sampling.hpp
  ContactEdge,            ///< the contact half-width from the contact pressures (H, S): halfway
                          ///< between the last node that carries pressure and the next one, over
                          ///< the problem's length unit (a; b for S)
};

/// Which stress a quantity normalizes: -sigma_z/p, -sigma_x/p or -tau_xz/p (the shear traction
/// the target exerts on the indented body along +x, friction problems).
enum class StressComponent { SigmaZ, SigmaX, TauXZ };

/// One graded quantity of a problem.
struct QuantityRule {
  schema::Quantity quantity = schema::Quantity::sigma_c;
  SamplePoint where = SamplePoint::MaxOnSurface;
  StressComponent component = StressComponent::SigmaZ;
  double exact = 0.0;                 ///< the physically consistent exact value (inf: singular)
  std::optional<double> study_exact;  ///< the value under the study's convention, if different
};

/// Load control for a rigid target (S with a rigid punch: the study loads the punch, so its
/// depth is an unknown). The punch stays where it touches the block, and the block's support
/// face is advanced by `delta` towards it instead (the same relative motion); delta is found by
/// secant iterations so that the support carries the punch's load. The answer is linear in
/// delta for a fixed active set, so a few iterations suffice.
struct RigidLoadControl {
  std::shared_ptr<double> delta;  ///< read by the support face's prescribed displacement
  double target_load = 0.0;       ///< per unit thickness, on the half model
  std::string reaction_set;       ///< the support face whose z reactions carry the load
  double delta_guess = 0.0;       ///< first guess of delta (its scale matters only)
};

/// Everything one problem hands to the executor.
struct ProblemSetup {
  solver::Model model;
  solver::ContactPair pair;  ///< used unless load_control is set
  std::optional<RigidLoadControl> load_control;
  StudyMeshInfo mesh_info;
  double p = 1.0;                     ///< the normalizing pressure
  double length_unit = 1.0;           ///< a (b for S): element sizes are reported over it
  double contact_half_width_a = 1.0;  ///< exact contact half-width: profiles are x / a
  std::vector<QuantityRule> quantities;
  /// The exact contact pressure over p at x on z = 0 (zero outside contact; inf at a
  /// singular edge), for the exact curve of the profile figures.
  std::function<double(double x)> exact_pressure_over_p;
  /// Friction problems (path dependent): the load steps every case runs, in order, from the
  /// unloaded state (suites/friction_cases.hpp); empty: one solve under the model's loads.
  std::vector<solver::LoadStep> load_steps;
  /// Conformal contact (IF): the exact resultant normal force of the contact over the modelled
  /// surface (per unit thickness, per radian in axisymmetry); 0: not defined.
  double exact_interface_force = 0.0;
};

/// Builds the setup of a case (one switch over the problems, in problem_setup.cpp).
/// Throws SuiteInputError for bad parameters, and lets solver errors through.
ProblemSetup build_problem(const CaseSpec& spec);

/// Validates a case before anything runs: its --set keys and values (Parameters) and, for a
/// friction problem, its algorithm (MPC is refused). Throws SuiteInputError with one line.
void validate_case(const CaseSpec& spec);

/// The edge set of the indented body where contact happens and quantities are sampled.
inline constexpr const char* kSampledSurface = study_sets::kBlockContact;

}  // namespace cs::suites
