#pragma once
// The noise-aware convergence verdict of a C/M/F error sequence (grading/convergence.hpp
// computes it): the vocabulary, so that results and reports name it one way.

#include <cstdint>
#include <string_view>

#include "schema/name_table.hpp"

namespace cs::schema {

/// What the errors on C, M, F do once changes below a stated floor count as noise.
enum class Trend : std::uint8_t {
  converging,      ///< the error falls by more than the floor and never grows beyond it
  settled,         ///< both successive changes are below the floor: a plateau
  not_converging,  ///< the error grows beyond the floor, or does not fall by more than it
};
constexpr std::string_view axis_name(Trend) {
  return "convergence trend";
}
constexpr AxisEntry entry(Trend v) {
  switch (v) {
    case Trend::converging:
      return {"converging", "", ""};
    case Trend::settled:
      return {"settled", "", ""};
    case Trend::not_converging:
      return {"not_converging", "", "not converging"};
  }
  return {};
}

}  // namespace cs::schema
