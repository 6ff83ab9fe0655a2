// Fuzzes the CalculiX result-file reader (adapters/calculix/frd_reader.hpp: parse_frd, which
// read_frd calls) and the lookups the result mapping makes on what it returns.
// Seeds: fuzz/corpus/frd_reader/.

#include <cstdlib>

#include "adapters/calculix/frd_reader.hpp"
#include "fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cs::fuzz::expect_answer_or_input_error([&] {
    const auto frd = cs::adapters::calculix::parse_frd(cs::fuzz::as_text(data, size), "fuzz");
    if (frd.nodes.coordinates.size() != 3 * frd.nodes.ids.size())
      std::abort();
    for (const auto& block : frd.blocks) {
      // Every block is rectangular: value(row, c) stays inside `values`.
      if (block.values.size() != block.node_ids.size() * block.components.size())
        std::abort();
      if (frd.last_block(block.name) == nullptr)
        std::abort();
      for (const auto& c : block.components) {
        if (block.component(c) < 0)
          std::abort();
      }
    }
  });
  return 0;
}
