// Fuzzes the reader of CalculiX's record of its 2D-to-3D element expansion (.12d;
// adapters/calculix/expansion_map.hpp: parse_expansion, which read_expansion calls).
// Seeds: fuzz/corpus/expansion_map/.

#include "adapters/calculix/expansion_map.hpp"
#include "fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cs::fuzz::expect_answer_or_input_error([&] {
    const auto map = cs::adapters::calculix::parse_expansion(cs::fuzz::as_text(data, size), "fuzz");
    for (const auto& [expanded, deck] : map)
      (void)cs::adapters::calculix::deck_node(map, expanded);
  });
  return 0;
}
