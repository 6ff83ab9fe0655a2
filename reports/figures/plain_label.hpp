#pragma once
// The plain text of a Markdown display label (schema's label()), for gnuplot titles, which
// print neither HTML nor Unicode primes reliably: "P′<sub>p</sub>" -> "P'_p",
// "σ̄<sub>c</sub><sup>*</sup>" -> "σ̄_c^*", "S(1/3)" unchanged.

#include <string>
#include <string_view>

namespace cs::reports {

/// <sub>x</sub> -> _x, <sup>x</sup> -> ^x, ′ -> ', any other tag dropped.
std::string plain_label(std::string_view markdown);

}  // namespace cs::reports
