#include "suites/huge_pages.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace cs::suites {

bool huge_pages_on_request(std::string_view enabled_text) {
  return enabled_text.find("[madvise]") != std::string_view::npos;
}

std::optional<std::string> tunables_with_huge_pages(const char* current) {
  constexpr std::string_view kTunable = "glibc.malloc.hugetlb";
  const std::string value = current != nullptr ? current : "";
  std::istringstream items(value);
  for (std::string item; std::getline(items, item, ':');) {
    if (item.substr(0, item.find('=')) == kTunable)
      return std::nullopt;
  }
  return (value.empty() ? "" : value + ":") + std::string(kTunable) + "=1";
}

std::optional<std::string> huge_page_tunables() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string enabled;
  std::getline(in, enabled);
  if (!huge_pages_on_request(enabled))
    return std::nullopt;
  return tunables_with_huge_pages(std::getenv("GLIBC_TUNABLES"));
}

}  // namespace cs::suites
