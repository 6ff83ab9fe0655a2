// The contact half-width as a graded quantity: read off the contact pressures (so any solver's
// pressures give it), halfway between the last node that carries pressure and the next. On
// the Hertz and Steuermann problems the converged Lagrange-multiplier solutions place it within
// an element of the exact a (the resolution of a nodal edge), and it converges with the mesh.

#include <cmath>

#include <gtest/gtest.h>

#include "suites/problem_executor.hpp"

namespace cs::suites {
namespace {

const QuantityResult& half_width(const CaseResult& r) {
  const QuantityResult* q = r.quantity(schema::Quantity::contact_half_width);
  if (q == nullptr)
    throw std::logic_error("no contact_half_width in " + case_id(r.spec));
  return *q;
}

CaseResult run_one(ProblemId p, MeshLevel m, ContactKind c) {
  const CaseSpec spec{.problem = p,
                      .mesh = m,
                      .element = Element::Q4,
                      .algorithm = Algorithm::LMP,
                      .contact = c,
                      .overrides = {}};
  ProblemExecutor executor(spec);
  return executor.run(spec);
}

// Requirement: within one element of the exact value (the exact a over a is 1; over b for S
// it is the oracle's a/b > 1), for every discretization.
TEST(ContactHalfWidth, WithinAnElementOfTheExactEdge) {
  for (ProblemId p : {ProblemId::H_p, ProblemId::H_a, ProblemId::S_1}) {
    for (ContactKind c : {ContactKind::ss, ContactKind::ns, ContactKind::mortar}) {
      const CaseResult r = run_one(p, MeshLevel::C, c);
      ASSERT_EQ(r.status, CaseStatus::converged) << r.reason;
      const QuantityResult& q = half_width(r);
      EXPECT_GE(q.exact, 1.0) << case_id(r.spec);
      EXPECT_LE(std::abs(q.value - q.exact), r.element_size_h) << case_id(r.spec);
    }
  }
}

// Requirement: it converges at the rate of its resolution: on H_p the error shrinks C -> M -> F
// and stays within half an element on each mesh (the edge moves by whole nodes).
TEST(ContactHalfWidth, ConvergesOnHertz) {
  double previous = INFINITY;
  for (MeshLevel m : {MeshLevel::C, MeshLevel::M, MeshLevel::F}) {
    const CaseResult r = run_one(ProblemId::H_p, m, ContactKind::ss);
    const double error = std::abs(half_width(r).value - 1.0);
    EXPECT_LE(error, previous) << schema::to_string(m);
    EXPECT_LE(error, 0.5 * r.element_size_h * (1 + 1e-9)) << schema::to_string(m);
    previous = error;
  }
}

}  // namespace
}  // namespace cs::suites
