// Uses the installed oracles as another project would: Hertz's plane-strain peak pressure is
// 4/pi times the mean pressure (study Eq. 15). Exit 0 when the installed library agrees.
#include <cmath>
#include <cstdio>

#include "oracles/hertz_plane.hpp"

int main() {
  const auto c = cs::oracles::hertz_plane_contact({100.0, 1000.0, 0.25, 2.0});
  const double ratio = c.p_max / c.p_mean;
  std::printf("a = %.6g, p_max/p_mean = %.15g\n", c.contact_half_width_a, ratio);
  return std::abs(ratio - 4.0 / M_PI) < 1e-12 ? 0 : 1;
}
