#include "solver/contact/coulomb_friction.hpp"

#include <algorithm>

namespace cs::solver {

RowLaw TangentialPenaltyRules::stick_law(int j) const {
  // lambda_T - kt s = lambda_hat - kt s_prev.
  return RowLaw{1.0, -kt_[j], lambda_hat_[j] - kt_[j] * s_prev_[j]};
}

double TangentialPenaltyRules::trial(int j, double, double s) const {
  return lambda_hat_[j] + kt_[j] * (s - s_prev_[j]);
}

RowLaw TangentialMultiplierRules::stick_law(int j) const {
  return RowLaw{0.0, 1.0, s_prev_[j]};  // s = s_prev
}

double TangentialMultiplierRules::trial(int j, double lambda_t, double s) const {
  return lambda_t + c_[j] * (s - s_prev_[j]);
}

double coulomb_residual(double lambda_t, double trial, double bound) {
  return lambda_t - std::clamp(trial, -bound, bound);
}

}  // namespace cs::solver
