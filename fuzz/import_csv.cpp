// Fuzzes the import layout's reader (suites/import_csv.hpp: parse_import_csv), the file another
// code's results arrive in. What it accepts must be what it promises: finite numbers, no
// duplicate node within a case, a non-empty case id; and writing the accepted cases back
// (import_csv_text, 17 digits) and reading them again gives the same doubles. Seeds:
// fuzz/corpus/import_csv/.

#include <cmath>
#include <cstdlib>
#include <set>

#include "fuzz/fuzz_input.hpp"
#include "suites/import_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = cs::fuzz::as_text(data, size);
  cs::fuzz::expect_answer_or_input_error([&] {
    const auto cases = cs::suites::parse_import_csv(text, "fuzz");
    for (const auto& c : cases) {
      std::set<double> xs;
      if (c.case_id.empty() || c.rows.empty())
        std::abort();
      for (const auto& r : c.rows) {
        if (!std::isfinite(r.x) || !std::isfinite(r.sigma_z) || !std::isfinite(r.sigma_x) ||
            (r.contact_pressure && !std::isfinite(*r.contact_pressure)) || !xs.insert(r.x).second)
          std::abort();
      }
    }
    const auto again = cs::suites::parse_import_csv(cs::suites::import_csv_text(cases), "again");
    if (again.size() != cases.size())
      std::abort();
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (again[i].case_id != cases[i].case_id || again[i].rows.size() != cases[i].rows.size())
        std::abort();
      for (std::size_t k = 0; k < cases[i].rows.size(); ++k) {
        const auto &a = again[i].rows[k], &b = cases[i].rows[k];
        if (a.x != b.x || a.sigma_z != b.sigma_z || a.sigma_x != b.sigma_x ||
            a.contact_pressure != b.contact_pressure)
          std::abort();
      }
    }
  });
  return 0;
}
