#pragma once
// The study's accuracy grades (Eq. 46, computed by grading/accuracy.hpp), best first, and how
// a case ended.

#include <cstdint>
#include <string_view>

#include "schema/name_table.hpp"

namespace cs::schema {

/// Best first: e (excellent), g (good), s (satisfactory), u (unsatisfactory).
enum class Grade : std::uint8_t { e, g, s, u };
constexpr std::string_view axis_name(Grade) {
  return "grade";
}
constexpr AxisEntry entry(Grade v) {
  switch (v) {
    case Grade::e:
      return {"e", "", "excellent"};
    case Grade::g:
      return {"g", "", "good"};
    case Grade::s:
      return {"s", "", "satisfactory"};
    case Grade::u:
      return {"u", "", "unsatisfactory"};
  }
  return {};
}

/// True when `grade` is worse than `reference`.
constexpr bool is_worse(Grade grade, Grade reference) {
  return static_cast<int>(grade) > static_cast<int>(reference);
}

/// How a case ended.
enum class CaseStatus : std::uint8_t {
  converged,      ///< solved; contact iterations converged
  not_converged,  ///< contact iterations hit the cap or cycled; values are the last iterate
  failed,         ///< no values: singular system, bad model, the solver crashed or refused
  timeout,        ///< an external solver did not finish within its time limit; no values
};
constexpr std::string_view axis_name(CaseStatus) {
  return "case status";
}
constexpr AxisEntry entry(CaseStatus v) {
  switch (v) {
    case CaseStatus::converged:
      return {"converged", "", ""};
    case CaseStatus::not_converged:
      return {"not_converged", "", "not converged"};
    case CaseStatus::failed:
      return {"failed", "", ""};
    case CaseStatus::timeout:
      return {"timeout", "", ""};
  }
  return {};
}

}  // namespace cs::schema
