#include "reports/figures/plain_label.hpp"

namespace cs::reports {

std::string plain_label(std::string_view markdown) {
  constexpr std::string_view kPrime = "′";
  std::string out;
  for (std::size_t i = 0; i < markdown.size();) {
    if (markdown.substr(i, kPrime.size()) == kPrime) {
      out += '\'';
      i += kPrime.size();
      continue;
    }
    if (markdown[i] != '<') {
      out += markdown[i++];
      continue;
    }
    const std::size_t close = markdown.find('>', i);
    if (close == std::string_view::npos) {
      out += markdown.substr(i);
      break;
    }
    const std::string_view tag = markdown.substr(i + 1, close - i - 1);
    if (tag == "sub")
      out += '_';
    else if (tag == "sup")
      out += '^';
    i = close + 1;
  }
  return out;
}

}  // namespace cs::reports
