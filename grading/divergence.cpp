#include "grading/divergence.hpp"

#include <cmath>

namespace cs::grading {

bool eq47_diverging(double s_c, double s_m, double s_f) {
  return std::abs(s_c - s_m) < std::abs(s_m - s_f);
}

schema::DivergenceVerdict divergence_verdict(double s_c, double s_m, double s_f) {
  schema::DivergenceVerdict d;
  d.eq47 = eq47_diverging(s_c, s_m, s_f);
  const bool one_sign = (s_c > 0 && s_m > 0 && s_f > 0) || (s_c < 0 && s_m < 0 && s_f < 0);
  d.monotone = one_sign && std::abs(s_c) < std::abs(s_m) && std::abs(s_m) < std::abs(s_f);
  if (one_sign)
    d.exponent = 0.5 * (std::log2(s_m / s_c) + std::log2(s_f / s_m));
  d.diverges = d.monotone && d.exponent && *d.exponent >= kDivergenceExponentMin &&
               *d.exponent <= kDivergenceExponentMax;
  return d;
}

}  // namespace cs::grading
