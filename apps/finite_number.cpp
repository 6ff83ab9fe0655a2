#include "apps/finite_number.hpp"

#include <cstdlib>
#include <string>

#include <fmt/core.h>

namespace cs::apps {

CLI::Validator finite_number(double lo, bool lo_open, double hi) {
  std::string range;
  if (std::isfinite(lo) && std::isfinite(hi))
    range = fmt::format(" from {:g} to {:g}", lo, hi);
  else if (std::isfinite(lo))
    range = fmt::format(" {} {:g}", lo_open ? "above" : "from", lo);
  else if (std::isfinite(hi))
    range = fmt::format(" up to {:g}", hi);
  return CLI::Validator(
      [=](const std::string& text) {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        const bool ok = end != text.c_str() && *end == '\0' && std::isfinite(v) &&
                        (lo_open ? v > lo : v >= lo) && v <= hi;
        return ok ? std::string() : fmt::format("'{}' is not a finite number{}", text, range);
      },
      "NUMBER");
}

}  // namespace cs::apps
