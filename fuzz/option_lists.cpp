// Fuzzes the comma-separated list options of `run` (`--problems H_p,S_1 --meshes C,M ...`):
// suites::split_list_option, then the name tables' try_parse/parse (schema/name_table.hpp) of
// every axis, quantity, grade and status. The input is the arguments of repeated options, one
// per line. Seeds: fuzz/corpus/option_lists/.

#include <cstdlib>
#include <string>
#include <vector>

#include "fuzz/fuzz_input.hpp"
#include "schema/case_axes.hpp"
#include "schema/grade.hpp"
#include "schema/quantity.hpp"
#include "suites/case_spec.hpp"

namespace {

/// parse<E> and try_parse<E> agree, and a parsed name prints back to a name that parses to it.
template <class E>
void parse_as(const std::string& name) {
  const auto v = cs::schema::try_parse<E>(name);
  cs::fuzz::expect_answer_or_input_error([&] {
    if (cs::schema::parse<E>(name) != v)
      std::abort();
  });
  if (v && cs::schema::try_parse<E>(cs::schema::to_string(*v)) != v)
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = cs::fuzz::as_text(data, size);
  std::vector<std::string> raw;
  for (std::size_t start = 0; start <= text.size();) {
    const auto end = std::min(text.find('\n', start), text.size());
    raw.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  cs::fuzz::expect_answer_or_input_error([&] {
    for (const auto& name : cs::suites::split_list_option(raw, "--fuzz")) {
      if (name.empty() || name.find(',') != std::string::npos)
        std::abort();
      using namespace cs::schema;
      parse_as<ProblemId>(name);
      parse_as<MeshLevel>(name);
      parse_as<Element>(name);
      parse_as<Algorithm>(name);
      parse_as<ContactKind>(name);
      parse_as<TargetKind>(name);
      parse_as<Recovery>(name);
      parse_as<SolverKind>(name);
      parse_as<Quantity>(name);
      parse_as<Grade>(name);
      parse_as<CaseStatus>(name);
    }
  });
  return 0;
}
