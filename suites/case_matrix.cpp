#include "suites/case_matrix.hpp"

#include <algorithm>

namespace cs::suites {
namespace {

template <class E>
std::vector<E> or_all(const std::vector<E>& chosen, const std::vector<E>& all) {
  if (chosen.empty())
    return all;
  std::vector<E> unique;
  for (E v : chosen) {
    if (std::find(unique.begin(), unique.end(), v) == unique.end())
      unique.push_back(v);
  }
  return unique;
}

}  // namespace

std::vector<CaseSpec> make_case_matrix(const CaseSelection& sel) {
  std::vector<CaseSpec> cases;
  for (ProblemId p : or_all(sel.problems, all_problems())) {
    for (MeshLevel m : or_all(sel.meshes, all_mesh_levels())) {
      for (ElementType e : or_all(sel.elements, all_elements())) {
        for (Algorithm a : or_all(sel.algorithms, all_algorithms())) {
          for (ContactKind c : or_all(sel.contacts, study_contacts())) {
            for (Recovery r : or_all(sel.recoveries, {Recovery::spr}))
              cases.push_back(CaseSpec{p, m, e, a, c, sel.target, r, sel.overrides});
          }
        }
      }
    }
  }
  return cases;
}

}  // namespace cs::suites
