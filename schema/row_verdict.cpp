#include "schema/row_verdict.hpp"

namespace cs::schema {

bool RowVerdict::is_baseline() const {
  return schema::is_baseline(spec);
}

}  // namespace cs::schema
