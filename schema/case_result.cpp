#include "schema/case_result.hpp"

#include <cmath>

namespace cs::schema {

bool QuantityResult::singular() const {
  return std::isinf(exact);
}

const QuantityResult* CaseResult::quantity(Quantity q) const {
  for (const auto& r : quantities) {
    if (r.quantity == q)
      return &r;
  }
  return nullptr;
}

bool CaseResult::is_baseline() const {
  return schema::is_baseline(spec);
}

}  // namespace cs::schema
