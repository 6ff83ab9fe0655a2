#include "suites/problem_catalog.hpp"

#include <map>

namespace cs::suites {
namespace {

// The study fixes p/E = 1e-3 for the Steuermann problems; it gives no value for the others,
// where the normalized answers do not depend on it (linear elasticity, small strains). We
// use 1e-3 throughout so that every indentation is small.
constexpr double kPOverE = 1e-3;

std::vector<ParameterSpec> with(std::vector<ParameterSpec> extra) {
  auto params = common_parameters(kPOverE);
  params.insert(params.end(), extra.begin(), extra.end());
  return params;
}

ProblemInfo patch(ProblemId id, const char* title, bool axi, const char* tables) {
  return {id, title, axi, {"sigma_z_max"}, with({}), tables};
}

ProblemInfo steuermann(ProblemId id, double re_over_b, const char* title, const char* tables) {
  return {id,
          title,
          false,
          {"sigma_c"},
          with({{"re_over_b", re_over_b, 0.0, 10.0, false, true,
                 "edge radius r_e over the half-width b of the punch's flat face"}}),
          tables};
}

std::map<ProblemId, ProblemInfo> make_catalog() {
  std::map<ProblemId, ProblemInfo> c;
  c.emplace(
      ProblemId::P_p,
      patch(ProblemId::P_p, "contact patch test, matching nodes (plane strain)", false, "3a, 3b"));
  c.emplace(
      ProblemId::P_a,
      patch(ProblemId::P_a, "contact patch test, matching nodes (axisymmetric)", true, "5a-5c"));
  c.emplace(ProblemId::Pprime_p,
            patch(ProblemId::Pprime_p, "contact patch test, non-matching nodes (plane strain)",
                  false, "4a-4c"));
  c.emplace(ProblemId::Pprime_a,
            patch(ProblemId::Pprime_a, "contact patch test, non-matching nodes (axisymmetric)",
                  true, "6a-6c"));
  c.emplace(ProblemId::H_p, ProblemInfo{ProblemId::H_p,
                                        "Hertz contact of a cylinder (plane strain)",
                                        false,
                                        {"sigma_c", "sigma_h"},
                                        with({}),
                                        "7a-7d, 8a-8d"});
  c.emplace(ProblemId::H_a, ProblemInfo{ProblemId::H_a,
                                        "Hertz contact of a sphere (axisymmetric)",
                                        true,
                                        {"sigma_c"},
                                        with({}),
                                        "9a-9d"});
  c.emplace(ProblemId::S_1,
            steuermann(ProblemId::S_1, 1.0, "Steuermann rounded punch, r_e/b = 1 (plane strain)",
                       "10a-10d"));
  c.emplace(ProblemId::S_1_3,
            steuermann(ProblemId::S_1_3, 1.0 / 3.0,
                       "Steuermann rounded punch, r_e/b = 1/3 (plane strain)", "11a-11d"));
  c.emplace(ProblemId::S_1_7,
            steuermann(ProblemId::S_1_7, 1.0 / 7.0,
                       "Steuermann rounded punch, r_e/b = 1/7 (plane strain)", "12a-12d"));
  c.emplace(ProblemId::F_p, ProblemInfo{ProblemId::F_p,
                                        "Sadowsky flat punch, singular (plane strain)",
                                        false,
                                        {"sigma_c_star"},
                                        with({}),
                                        "13a-13d"});
  c.emplace(ProblemId::F_a, ProblemInfo{ProblemId::F_a,
                                        "Harding-Sneddon flat punch, singular (axisymmetric)",
                                        true,
                                        {"sigma_c_star"},
                                        with({}),
                                        "14a-14d"});
  return c;
}

}  // namespace

const ProblemInfo& problem_info(ProblemId id) {
  static const auto catalog = make_catalog();
  return catalog.at(id);
}

}  // namespace cs::suites
