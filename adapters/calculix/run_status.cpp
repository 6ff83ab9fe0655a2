#include "adapters/calculix/run_status.hpp"

#include <array>
#include <charconv>
#include <limits>
#include <sstream>
#include <vector>

namespace cs::adapters::calculix {
namespace {

/// ccx's messages when its increment control gives up: the analysis did not converge.
constexpr std::array<std::string_view, 6> kNonConvergence = {
    "too many cutbacks",   "increment size smaller than minimum",
    "too many iterations", "solution seems to diverge",
    "divergence",          "no convergence",
};

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    lines.push_back(text.substr(pos, end - pos));
    pos = end + 1;
  }
  return lines;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::string collapse_spaces(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c != ' ' || out.empty() || out.back() != ' ')
      out += c;
  }
  return out;
}

bool to_int(std::string_view s, int& v) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size();
}

/// A count of a .sta row (step, increment, attempt: from 1; iterations: from 0).
bool to_count(std::string_view s, int min, int& v) {
  return to_int(s, v) && v >= min;
}

bool mentions_non_convergence(std::string_view message) {
  for (std::string_view pattern : kNonConvergence) {
    if (message.find(pattern) != std::string_view::npos)
      return true;
  }
  return false;
}

std::string child_failure(const platform::ChildResult& child) {
  if (child.interrupted)
    return "ccx interrupted (signal " + std::to_string(child.signal) + ")";
  if (child.signal != 0)
    return "ccx " + child.describe();
  return "ccx " + child.describe() + " without an *ERROR message";
}

}  // namespace

const char* to_string(CalculixStatus status) {
  switch (status) {
    case CalculixStatus::Converged:
      return "converged";
    case CalculixStatus::NotConverged:
      return "not converged";
    case CalculixStatus::Failed:
      return "failed";
    case CalculixStatus::Timeout:
      return "timeout";
  }
  return "unknown";
}

StaSummary parse_sta(std::string_view text) {
  StaSummary sta;
  for (std::string_view line : split_lines(text)) {
    std::istringstream words{std::string(line)};
    std::string step, inc, att, itrs;
    int s = 0, i = 0, n = 0;
    if (!(words >> step >> inc >> att >> itrs) || !to_count(step, 1, s) || !to_count(inc, 1, i) ||
        !to_count(itrs, 0, n) || att.empty())
      continue;
    const bool unconverged = att.back() == 'U';
    int a = 0;
    if (!to_count(unconverged ? std::string_view(att).substr(0, att.size() - 1) : att, 1, a))
      continue;
    ++sta.attempts;
    sta.iterations = n > std::numeric_limits<int>::max() - sta.iterations
                         ? std::numeric_limits<int>::max()
                         : sta.iterations + n;
    if (!unconverged)
      ++sta.increments;
  }
  return sta;
}

std::string first_error_message(std::string_view ccx_output) {
  const auto lines = split_lines(ccx_output);
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::size_t at = lines[k].find("*ERROR");
    if (at == std::string_view::npos)
      continue;
    std::string message(trim(lines[k].substr(at)));
    // Continuation lines: deeper-indented text (ccx indents them by 7 or more spaces).
    for (std::size_t j = k + 1; j < lines.size(); ++j) {
      const std::string_view next = trim(lines[j]);
      if (next.empty() || next.front() == '*' || lines[j].substr(0, 3) != "   ")
        break;
      message += " ";
      message += next;
    }
    message = collapse_spaces(message);  // "element           1" -> "element 1"
    return message.size() > 300 ? message.substr(0, 297) + "..." : message;
  }
  return "";
}

RunOutcome classify_run(const platform::ChildResult& child, std::string_view ccx_output) {
  if (!child.started)
    return {CalculixStatus::Failed, child.spawn_error};
  if (child.timed_out)
    return {CalculixStatus::Timeout, "ccx " + child.describe()};
  if (child.interrupted || child.signal != 0)
    return {CalculixStatus::Failed, child_failure(child)};
  const std::string error = first_error_message(ccx_output);
  if (child.exit_code == 0 && error.empty() &&
      ccx_output.find("Job finished") != std::string_view::npos)
    return {CalculixStatus::Converged, ""};
  if (error.empty())
    return {CalculixStatus::Failed, child_failure(child)};
  if (mentions_non_convergence(error))
    return {CalculixStatus::NotConverged, error};
  return {CalculixStatus::Failed, error};
}

}  // namespace cs::adapters::calculix
