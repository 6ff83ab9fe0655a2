#include "platform/available_memory.hpp"

#include <charconv>
#include <fstream>
#include <iterator>
#include <string>

namespace cs::platform {

double parse_mem_available_mb(std::string_view meminfo) {
  constexpr std::string_view key = "MemAvailable:";
  const auto at = meminfo.find(key);
  if (at == std::string_view::npos || (at > 0 && meminfo[at - 1] != '\n'))
    return 0.0;
  std::string_view rest = meminfo.substr(at + key.size());
  const auto digits = rest.find_first_not_of(' ');
  if (digits == std::string_view::npos)
    return 0.0;
  rest.remove_prefix(digits);
  long long kib = 0;
  const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), kib);
  const std::string_view unit(end, static_cast<std::size_t>(rest.data() + rest.size() - end));
  if (ec != std::errc() || kib < 0 || unit.substr(0, 3) != " kB")
    return 0.0;
  return static_cast<double>(kib) / 1024.0;
}

double available_memory_mb() {
  std::ifstream in("/proc/meminfo");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return parse_mem_available_mb(text);
}

}  // namespace cs::platform
