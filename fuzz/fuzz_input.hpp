#pragma once
// What every libFuzzer target here shares: the input as text, and the rule that an input error
// is an answer, not a finding.
//
// The readers are fuzzed through their text overloads (the path versions call them). An input
// they refuse must be refused with one of the errors the command line maps to exit 2 (bad
// input, apps/main.cpp): SchemaError, or std::invalid_argument, from which SuiteInputError and
// the CalculiX errors derive. Anything else escaping a reader (another exception, a crash, a
// sanitizer report, a hang or a leak) is a finding: libFuzzer stops and saves the input.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "schema/schema_error.hpp"

namespace cs::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Runs `read`; swallows the bad-input errors (exit 2) and lets everything else through.
template <class Read>
void expect_answer_or_input_error(Read&& read) {
  try {
    read();
  } catch (const schema::SchemaError&) {
  } catch (const std::invalid_argument&) {
  }
}

}  // namespace cs::fuzz
