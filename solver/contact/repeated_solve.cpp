#include "solver/contact/repeated_solve.hpp"

namespace cs::solver {

bool repeats_solve(const ContactSettings& settings, const ContactResult& earlier) {
  ContactSettings wanted = settings;
  const ContactSettings& ran = earlier.settings;
  if (!wanted.frictional())
    wanted.tangential = ran.tangential;  // not read without friction
  if (wanted.algorithm == ContactAlgorithm::Penalty &&
      ran.algorithm == ContactAlgorithm::AugmentedLagrangian) {
    if (!earlier.converged() || earlier.augmentations != 0)
      return false;
    wanted.algorithm = ran.algorithm;  // AL's first pass is PM's solve
    wanted.ftoln = ran.ftoln;          // which reads neither
    wanted.max_augmentations = ran.max_augmentations;
  }
  return wanted == ran;
}

}  // namespace cs::solver
