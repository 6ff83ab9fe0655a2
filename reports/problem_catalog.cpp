#include "reports/problem_catalog.hpp"

namespace cs::reports {
namespace {

QuantityInfo patch_quantity(const char* table) {
  return {"sigma_z_max",    "σ̄<sub>z</sub>",           "−σ<sub>z</sub><sup>max</sup>/p",
          "-sigma_z^max/p", "maximum vertical stress", table};
}

QuantityInfo centre_contact_quantity(const char* table) {
  return {"sigma_c",         "σ̄<sub>c</sub>",  "−σ<sub>z</sub>(0, 0)/p",
          "-sigma_z(0,0)/p", "contact stress", table};
}

QuantityInfo steuermann_quantity(const char* table) {
  return {"sigma_c",
          "σ̄<sub>c</sub>",
          "max of −σ<sub>z</sub>/p on z = 0",
          "max -sigma_z/p on z = 0",
          "contact stress",
          table};
}

QuantityInfo punch_quantity(const char* table) {
  return {"sigma_c_star",    "σ̄<sub>c</sub><sup>*</sup>",        "−σ<sub>z</sub>(a, 0)/p",
          "-sigma_z(a,0)/p", "contact stress at the punch edge", table};
}

std::vector<ProblemInfo> make_problems() {
  const QuantityInfo horizontal{"sigma_h",         "σ̄<sub>h</sub>",     "−σ<sub>x</sub>(0, 0)/p",
                                "-sigma_x(0,0)/p", "horizontal stress", "8"};
  return {
      {"P_p",
       "P<sub>p</sub>",
       "P_p",
       "plane-strain contact patch test, matched nodes",
       "3",
       "Eq. 6",
       false,
       {patch_quantity("3")}},
      {"Pprime_p",
       "P′<sub>p</sub>",
       "P'_p",
       "plane-strain contact patch test, mismatched nodes",
       "4",
       "Eq. 6",
       false,
       {patch_quantity("4")}},
      {"P_a",
       "P<sub>a</sub>",
       "P_a",
       "axisymmetric contact patch test, matched nodes",
       "5",
       "Eq. 8",
       false,
       {patch_quantity("5")}},
      {"Pprime_a",
       "P′<sub>a</sub>",
       "P'_a",
       "axisymmetric contact patch test, mismatched nodes",
       "6",
       "Eq. 8",
       false,
       {patch_quantity("6")}},
      {"H_p",
       "H<sub>p</sub>",
       "H_p",
       "plane-strain Hertzian contact",
       "7, 8",
       "Eq. 15",
       false,
       {centre_contact_quantity("7"), horizontal}},
      {"H_a",
       "H<sub>a</sub>",
       "H_a",
       "axisymmetric Hertzian contact",
       "9",
       "Eq. 22",
       false,
       {centre_contact_quantity("9")}},
      {"S_1",
       "S(1)",
       "S(1)",
       "plane-strain Steuermann contact, r_e/b = 1",
       "10",
       "Eq. 31",
       false,
       {steuermann_quantity("10")}},
      {"S_1_3",
       "S(1/3)",
       "S(1/3)",
       "plane-strain Steuermann contact, r_e/b = 1/3",
       "11",
       "Eq. 31",
       false,
       {steuermann_quantity("11")}},
      {"S_1_7",
       "S(1/7)",
       "S(1/7)",
       "plane-strain Steuermann contact, r_e/b = 1/7",
       "12",
       "Eq. 31",
       false,
       {steuermann_quantity("12")}},
      {"F_p",
       "F<sub>p</sub>",
       "F_p",
       "plane-strain flat punch",
       "13",
       "Eq. 39",
       true,
       {punch_quantity("13")}},
      {"F_a",
       "F<sub>a</sub>",
       "F_a",
       "axisymmetric flat punch",
       "14",
       "Eq. 45",
       true,
       {punch_quantity("14")}},
  };
}

}  // namespace

const std::vector<ProblemInfo>& all_problem_infos() {
  static const std::vector<ProblemInfo> problems = make_problems();
  return problems;
}

const ProblemInfo* find_problem_info(const std::string& id) {
  for (const auto& p : all_problem_infos()) {
    if (p.id == id)
      return &p;
  }
  return nullptr;
}

const QuantityInfo* find_quantity_info(const std::string& problem, const std::string& quantity) {
  const ProblemInfo* p = find_problem_info(problem);
  if (p == nullptr)
    return nullptr;
  for (const auto& q : p->quantities) {
    if (q.name == quantity)
      return &q;
  }
  return nullptr;
}

const std::vector<GradeTableRow>& grade_table_rows() {
  static const std::vector<GradeTableRow> rows{
      {"P_p", "sigma_z_max", "main", "P<sub>p</sub>"},
      {"P_a", "sigma_z_max", "main", "P<sub>a</sub>"},
      {"Pprime_p", "sigma_z_max", "main", "P′<sub>p</sub>"},
      {"Pprime_a", "sigma_z_max", "main", "P′<sub>a</sub>"},
      {"H_p", "sigma_c", "contact", "H<sub>p</sub> (contact)"},
      {"H_p", "sigma_h", "horizontal", "H<sub>p</sub> (horizontal)"},
      {"H_a", "sigma_c", "main", "H<sub>a</sub>"},
      {"S_1", "sigma_c", "main", "S(1)"},
      {"S_1_3", "sigma_c", "main", "S(1/3)"},
      {"S_1_7", "sigma_c", "main", "S(1/7)"},
  };
  return rows;
}

}  // namespace cs::reports
