#pragma once
// The machinery of the vocabulary: every axis of a case, every quantity, grade and status is an
// `enum class` whose names live in ONE constexpr function per enum, `entry(E)`, a switch with no
// default. The project compiles with -Werror=switch, so an enumerator without a name is a
// compile error, not a run-time surprise.
//
// An axis E declares, next to its enum (found by argument-dependent lookup):
//   constexpr AxisEntry entry(E v);          // its names; {} for a value that is not an enumerator
//   constexpr std::string_view axis_name(E); // what it is called in messages ("algorithm")
// and gets from here: to_string(v), label(v), parse<E>(text), try_parse<E>(text),
// values<E>(), count<E>(), accepted_names<E>().
//
// Enumerators are numbered 0, 1, 2, ... in table order (the study's order); values<E>() walks
// them until entry() returns an empty name.
//
// An axis may also have values registered at run time (ProblemId, for problems defined outside
// the battery): it then declares `std::vector<E> registered_values(E)`, and try_parse, parse and
// accepted_names know those values too (values<E>() and count<E>() stay the enumerators).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "schema/schema_error.hpp"

namespace cs::schema {

/// The names of one enumerator.
struct AxisEntry {
  std::string_view name;   ///< canonical: command line, case ids, results.json
  std::string_view alias;  ///< also accepted when parsing ("" for none), e.g. IMC for MPC
  std::string_view label;  ///< for Markdown, e.g. "P′<sub>p</sub>" ("" = the name)
};

template <class E>
concept Axis = requires(E v) {
  { entry(v) } -> std::convertible_to<AxisEntry>;
  { axis_name(v) } -> std::convertible_to<std::string_view>;
};

/// The number of enumerators of E.
template <Axis E>
constexpr std::size_t count() {
  std::size_t n = 0;
  while (!entry(static_cast<E>(n)).name.empty())
    ++n;
  return n;
}

/// Every enumerator of E in table order.
template <Axis E>
constexpr std::array<E, count<E>()> values() {
  std::array<E, count<E>()> out{};
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<E>(i);
  return out;
}

/// The canonical name.
template <Axis E>
constexpr std::string_view to_string(E v) {
  return entry(v).name;
}

/// The Markdown display label (the name where no label is given).
template <Axis E>
constexpr std::string_view label(E v) {
  const AxisEntry e = entry(v);
  return e.label.empty() ? e.name : e.label;
}

/// The enumerator named or aliased `text`, or nullopt.
template <Axis E>
constexpr std::optional<E> try_parse(std::string_view text) {
  const auto names = [text](E v) {
    const AxisEntry e = entry(v);
    return text == e.name || (!e.alias.empty() && text == e.alias);
  };
  for (E v : values<E>()) {
    if (names(v))
      return v;
  }
  if constexpr (requires { registered_values(E{}); }) {
    if (!std::is_constant_evaluated()) {
      for (E v : registered_values(E{})) {
        if (names(v))
          return v;
      }
    }
  }
  return std::nullopt;
}

/// "AL, PM, LMP, PLM, MPC": the canonical names (registered values last), for messages.
template <Axis E>
std::string accepted_names() {
  std::string out;
  const auto add = [&out](E v) {
    out += out.empty() ? "" : ", ";
    out += to_string(v);
  };
  for (E v : values<E>())
    add(v);
  if constexpr (requires { registered_values(E{}); }) {
    for (E v : registered_values(E{}))
      add(v);
  }
  return out;
}

/// The enumerator named or aliased `text`; throws SchemaError "unknown algorithm 'X' (expected
/// one of: AL, PM, LMP, PLM, MPC)".
template <Axis E>
E parse(std::string_view text) {
  if (const auto v = try_parse<E>(text))
    return *v;
  throw SchemaError("unknown " + std::string(axis_name(E{})) + " '" + std::string(text) +
                    "' (expected one of: " + accepted_names<E>() + ")");
}

}  // namespace cs::schema
