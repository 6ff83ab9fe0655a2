// Fuzzes the gate's baseline reader (schema/baseline_file.hpp: parse_baseline_text, which
// read_baseline_file calls, and tolerances_from_json, which `gate --update` calls on a
// baseline of any version). Seeds: fuzz/corpus/baseline_file/.

#include "schema/baseline_file.hpp"
#include "fuzz/fuzz_input.hpp"
#include "schema/json_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = cs::fuzz::as_text(data, size);
  cs::fuzz::expect_answer_or_input_error([&] {
    const auto baseline = cs::schema::parse_baseline_text(text, "fuzz");
    (void)cs::schema::to_json(baseline).dump();
  });
  cs::fuzz::expect_answer_or_input_error([&] {
    const auto doc = cs::schema::parse_json_text(text, "baseline", "fuzz");
    const auto tolerances = cs::schema::tolerances_from_json(doc, "fuzz");
    (void)tolerances.of(cs::schema::Quantity{});
  });
  return 0;
}
