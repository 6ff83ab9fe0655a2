#include "suites/case_matrix.hpp"

#include <algorithm>

#include "suites/problem_catalog.hpp"

namespace cs::suites {
namespace {

template <class E, class All>
std::vector<E> or_all(const std::vector<E>& chosen, const All& all) {
  if (chosen.empty())
    return {all.begin(), all.end()};
  std::vector<E> unique;
  for (E v : chosen) {
    if (std::find(unique.begin(), unique.end(), v) == unique.end())
      unique.push_back(v);
  }
  return unique;
}

}  // namespace

std::vector<CaseSpec> make_case_matrix(const CaseSelection& sel) {
  validate_sweeps(sel.sweeps, sel.overrides, or_all(sel.problems, study_problems()));
  const auto points = sweep_points(sel.sweeps);
  std::vector<CaseSpec> cases;
  for (ProblemId p : or_all(sel.problems, study_problems())) {
    for (MeshLevel m : or_all(sel.meshes, schema::kStudyMeshes)) {
      for (Element e : or_all(sel.elements, values<Element>())) {
        for (Algorithm a : or_all(sel.algorithms, values<Algorithm>())) {
          // MPC is not defined with friction: left out unless asked for (then refused).
          if (sel.algorithms.empty() && a == Algorithm::MPC && is_frictional(p))
            continue;
          for (ContactKind c : or_all(sel.contacts, study_contacts())) {
            for (Recovery r : or_all(sel.recoveries, std::vector<Recovery>{Recovery::spr})) {
              for (const auto& point : points) {
                auto overrides = sel.overrides;
                overrides.insert(point.begin(), point.end());
                cases.push_back(CaseSpec{.problem = p,
                                         .mesh = m,
                                         .element = e,
                                         .algorithm = a,
                                         .contact = c,
                                         .target = sel.target,
                                         .recovery = r,
                                         .solver = sel.solver,
                                         .overrides = std::move(overrides)});
              }
            }
          }
        }
      }
    }
  }
  return cases;
}

}  // namespace cs::suites
