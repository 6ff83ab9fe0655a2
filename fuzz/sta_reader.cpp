// Fuzzes what the CalculiX adapter reads of a run's end (adapters/calculix/run_status.hpp):
// the .sta parser and the search for ccx's first *ERROR message in its output.
// Seeds: fuzz/corpus/sta_reader/.

#include <cstdlib>

#include "adapters/calculix/run_status.hpp"
#include "fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = cs::fuzz::as_text(data, size);
  cs::fuzz::expect_answer_or_input_error([&] {
    const auto sta = cs::adapters::calculix::parse_sta(text);
    if (sta.attempts < 0 || sta.increments < 0 || sta.increments > sta.attempts ||
        sta.iterations < 0)
      std::abort();
  });
  cs::fuzz::expect_answer_or_input_error([&] {
    if (cs::adapters::calculix::first_error_message(text).size() > 300)
      std::abort();
  });
  return 0;
}
