// Fuzzes the `--set name=value` parser (suites/case_spec.hpp: parse_overrides). The input is
// the arguments of repeated --set options, one per line. Seeds: fuzz/corpus/set_overrides/.

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "fuzz/fuzz_input.hpp"
#include "suites/case_spec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = cs::fuzz::as_text(data, size);
  std::vector<std::string> sets;
  for (std::size_t start = 0; start <= text.size();) {
    const auto end = std::min(text.find('\n', start), text.size());
    sets.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  cs::fuzz::expect_answer_or_input_error([&] {
    for (const auto& [name, value] : cs::suites::parse_overrides(sets)) {
      // What is accepted is a named, finite value; -0 is read as 0 (one case id).
      if (name.empty() || !std::isfinite(value) || (std::signbit(value) && value == 0.0))
        std::abort();
    }
  });
  return 0;
}
