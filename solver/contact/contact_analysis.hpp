#pragma once
// A frictionless contact analysis: one model, one contact pair, any number of settings.
//
// Usage (a suite problem):
//   Model model = ...;                          // mesh with edge sets, materials, BCs, loads
//   LinearStaticAnalysis elastic(model);        // the FE core: DOF map, assembly
//   ContactAnalysis contact(elastic, {"block.contact", TargetSurface{"indenter.contact"}});
//   //   or a rigid target: {"block.contact", RigidCircle{{0.0, -R}, R}}
//   ContactSettings s;                          // discretization, algorithm, FKN, FTOLN, pinball
//   s.discretization = ContactDiscretization::SurfaceToSurface;
//   s.algorithm = ContactAlgorithm::LagrangeMultiplier;
//   ContactResult r = contact.solve(s);         // status, per-node pressure, displacement
//   if (r.converged()) stresses = recover_stresses(model, r.displacement);
//
// What is shared between solves of one ContactAnalysis: the assembled stiffness and load (the
// FE core's); the constraint rows of each row kind (ns; ss Gauss points for PM/AL; ss nodal
// weighted gaps for LM/MPC; mortar); per pinball, ONE sparse factorization: the condensation
// onto the contact DOFs that any row kind's candidates touch; per row kind and pinball, the
// small dense condensation onto its rows. Changing the discretization, the algorithm, FKN,
// FTOLN or the iteration caps reuses the factorization.
//
// Data flow of solve(): rows g = g0 + B u (discretization) -> candidates (the search,
// solver/contact/contact_search.hpp: |g_s| <= pinball h at first) -> condensation onto the
// contact DOFs, then onto the candidate rows (condensation.hpp) -> algorithm (one switch) ->
// displacement recovery -> review of the search -> per-node results. Rows outside the
// candidates never act; one that ends up penetrating either approached during the iterations
// (the search grows its reach and the solve starts again over the larger set) or is a true
// geometric miss (NotConverged, ContactBeyondPinball), never silently wrong (MPC, which by
// definition ties the rows found at the start, is not reviewed).
//
// Changed loads and prescribed values are picked up by the next solve (one forward solve);
// e.g. a load-controlled rigid punch (secant iterations on a support displacement) should keep
// one ContactAnalysis across its iterations instead of refactoring for each. A ContactAnalysis
// is not thread-safe (it caches); give each worker its own.

#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "solver/contact/condensation.hpp"
#include "solver/contact/constraint_rows.hpp"
#include "solver/contact/constraint_set.hpp"
#include "solver/contact/contact_options.hpp"
#include "solver/contact/contact_result.hpp"
#include "solver/contact/contact_search.hpp"
#include "solver/contact/contact_surface.hpp"
#include "solver/contact/load_step.hpp"
#include "solver/contact/target.hpp"
#include "solver/linear_static.hpp"

namespace cs::solver {

struct AlgorithmOutcome;
struct RowState;

/// The contact pair of a model: the contact surface of a deformable body (the study's contact
/// elements' side, e.g. the indented block's top edge set) and its target.
struct ContactPair {
  std::string contact_surface;  ///< edge set name, e.g. "block.top"
  TargetSpec target;            ///< TargetSurface{"indenter.bottom"} or a RigidProfile
  /// Along which normal gaps are measured (solver/contact/gap_normal.hpp): the target's by
  /// default, or the contact surface's own (the half-space theory's linearization).
  GapNormal gap_normal = GapNormal::Target;
};

/// The rows `settings` select.
ConstraintRows constraint_rows(const ContactSettings& settings);

class ContactAnalysis {
 public:
  /// Builds the contact surface and the target on `elastic.model()`. Throws ContactError for an
  /// unknown or empty contact surface or target edge set, or an invalid rigid profile.
  /// `elastic` must outlive this object; it is assembled on the first solve if it is not yet.
  ContactAnalysis(LinearStaticAnalysis& elastic, ContactPair pair);
  ~ContactAnalysis();

  /// Runs one contact analysis (with friction: one load step from the unloaded reference state,
  /// the loads applied at once). Throws ContactError for invalid settings or a target that no
  /// contact point comes within the pinball of; a failure to converge is a status.
  /// Changed loads or prescribed displacement values of the model (elastic.update_prescribed_
  /// values()) are picked up at the cost of one forward solve; a changed stiffness (materials,
  /// coordinates) needs a new ContactAnalysis.
  ContactResult solve(const ContactSettings& settings);

  /// One load step from the converged tangential state `previous` of the step before (empty:
  /// the unloaded reference state; what solve(settings) uses). Without friction (mu = 0)
  /// `previous` is not read and this is solve(settings). Throws ContactError as solve() does, or
  /// if `previous` belongs to other constraint rows.
  ContactResult solve(const ContactSettings& settings, const FrictionHistory& previous);

  /// Runs the load steps in order from the unloaded state: for each, step.apply(), the
  /// prescribed values re-read (elastic.update_prescribed_values()), then solve(settings,
  /// previous step's friction_history). Returns one result per step run; stops after the first
  /// step that does not converge (its result is the last). Without friction every step is an
  /// independent frictionless solve.
  std::vector<ContactResult> solve_steps(const ContactSettings& settings,
                                         const std::vector<LoadStep>& steps);

  const ContactSurface& surface() const { return surface_; }
  const ContactTarget& target() const { return target_; }
  /// The constraint rows of a kind (built on first use).
  const ConstraintSet& constraints(ConstraintRows rows);

  /// Later solves recover the displacement only at the DOFs of `nodes` and at every DOF a
  /// contact row of any kind reads (what the analysis itself reads): the backward solve visits
  /// only the part of the factor those entries need. The other entries are NaN and
  /// ContactResult::displacement_complete is false. Empty (the default): the whole field.
  void recover_only_at(std::vector<int> nodes);

 private:
  struct DofStage;
  struct RowStage;
  /// The stages of a row kind and search extent (pinball, reach: contact_search.hpp);
  /// `frictional`: the contact DOFs and rows include the tangential twins (a separate
  /// factorization, so that frictionless solves never change).
  struct StageKey {
    ConstraintRows rows;
    double pinball;
    double reach;
    CondensationMethod method;
    bool frictional;
    SearchExtent extent() const { return {pinball, reach}; }
    auto tie() const { return std::tie(rows, pinball, reach, method, frictional); }
    bool operator<(const StageKey& o) const { return tie() < o.tie(); }
  };
  DofStage& dof_stage(const StageKey& key, ContactResult& result);
  /// Drops the stages of grown searches other than `keep`'s (a cache: at most one grown
  /// factorization beside the pinball's is kept).
  void evict_grown_stages(const StageKey& keep);
  RowStage& row_stage(const StageKey& key, ContactResult& result);
  /// The candidate rows and their condensation, stacked with the tangential twins if frictional.
  void fill_row_stage(const StageKey& key, const ConstraintSet& set, RowStage& rs) const;
  static StageKey dof_key(const StageKey& row_key);
  /// Whether a nodal row's node cannot slip because its tangential DOFs (and its target point's)
  /// are all prescribed, e.g. a node on a symmetry line against a rigid target. Its tangential
  /// twin is left empty: the support takes the shear. (Weighted rows would otherwise constrain
  /// more slips than there are free tangential DOFs, a singular system with multipliers.)
  bool tangent_held(const ContactConstraint& row) const;
  /// One solve over the candidates of `key`; fills `result` (iteration counts and timings
  /// add up over the rounds of a growing search). Returns the review of the search.
  SearchReview solve_round(const ContactSettings& settings, const FrictionHistory& previous,
                           const StageKey& key, ContactResult& result);
  AlgorithmOutcome run_frictionless(const ContactSettings& settings, const RowStage& cd) const;
  AlgorithmOutcome run_frictional(const ContactSettings& settings, const FrictionHistory& previous,
                                  const RowStage& cd) const;
  /// Displacement, row quantities and per-node results of a solution (friction included).
  /// Returns the review of the search (converged non-MPC solves; else an empty review).
  SearchReview recover_results(const ContactSettings& settings, const FrictionHistory& previous,
                               const StageKey& key, const RowStage& cd, const DofStage& ds,
                               const AlgorithmOutcome& out, ContactResult& result);
  void recover_friction(const FrictionHistory& previous, const ConstraintSet& set,
                        const RowStage& cd, const AlgorithmOutcome& out, const RowState& rows,
                        ContactResult& result);
  /// Picks up changed loads and prescribed values (see solve()).
  void refresh_loads();
  /// The subset of `key`'s stage 1 that recover_only_at asks for (made on first use), or null.
  const RecoverySubset* recovery_subset(const StageKey& key);
  /// The free equations recover_only_at asks for: its nodes' and every contact row's.
  std::vector<int> read_equations();
  /// Rows of `set` within `extent` that can move (contact_search.hpp).
  std::vector<int> candidates(const ConstraintSet& set, const SearchExtent& extent) const;
  /// Whether row j of `set` has a free DOF.
  bool movable(const ConstraintSet& set, int j) const;

  LinearStaticAnalysis& elastic_;
  ContactPair pair_;
  ContactSurface surface_;
  ContactTarget target_;
  std::map<ConstraintRows, ConstraintSet> constraints_;
  /// Stage 1, keyed by dof_key() (extent, method, frictional: every row kind shares it).
  std::map<StageKey, std::shared_ptr<DofStage>> dof_stages_;  ///< shared: see dof_stage()
  std::map<StageKey, std::unique_ptr<RowStage>> row_stages_;  ///< stage 2, per row kind
  std::vector<int> recovered_nodes_;  ///< recover_only_at's nodes; empty: the whole field
  Eigen::VectorXd load_f_;            ///< the reduced load f_f the stages were computed for
  Eigen::VectorXd prescribed_;        ///< the prescribed values the stages were computed for
};

/// One-shot convenience: builds the FE core's analysis and a ContactAnalysis and solves once.
ContactResult solve_contact(const Model& model, const ContactPair& pair,
                            const ContactSettings& settings);

}  // namespace cs::solver
