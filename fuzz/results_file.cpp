// Fuzzes the results.json reader (schema/results_file.hpp: parse_results_text, which
// read_results_file calls): JSON parsing, then every field's type, range and name.
// Seeds: fuzz/corpus/results_file/.

#include "schema/results_file.hpp"
#include "fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cs::fuzz::expect_answer_or_input_error([&] {
    const auto doc = cs::schema::parse_results_text(cs::fuzz::as_text(data, size), "fuzz");
    // What is read must write back: the writer sees only validated values.
    (void)cs::schema::to_json(doc).dump();
  });
  return 0;
}
