#include "suites/shard.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <map>

#include <fmt/format.h>

#include "suites/runner.hpp"
#include "suites/suite_error.hpp"

namespace cs::suites {
namespace {

int parse_positive(std::string_view text, std::string_view whole) {
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
    throw SuiteInputError(
        fmt::format("--shard {}: expected K/N with whole numbers, e.g. 2/8", whole));
  }
  return v;
}

struct GroupLoad {
  std::string key;
  double cost = 0.0;
};

}  // namespace

ShardSpec parse_shard(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos)
    throw SuiteInputError(fmt::format("--shard {}: expected K/N, e.g. 2/8", text));
  const ShardSpec s{parse_positive(text.substr(0, slash), text),
                    parse_positive(text.substr(slash + 1), text)};
  if (s.count < 1 || s.count > kMaxShards)
    throw SuiteInputError(fmt::format("--shard {}: N must be between 1 and {}", text, kMaxShards));
  if (s.index < 1 || s.index > s.count)
    throw SuiteInputError(fmt::format("--shard {}: K must be between 1 and N = {}", text, s.count));
  return s;
}

std::vector<CaseSpec> shard_cases(const std::vector<CaseSpec>& cases, const ShardSpec& shard,
                                  const std::function<double(const CaseSpec&)>& group_cost) {
  std::map<std::string, GroupLoad> groups;
  for (const auto& c : cases) {
    auto [it, inserted] = groups.try_emplace(model_key(c));
    if (inserted)
      it->second = {it->first, group_cost ? group_cost(c) : 1.0};
  }
  std::vector<GroupLoad> order;
  for (const auto& [key, g] : groups)
    order.push_back(g);
  std::stable_sort(order.begin(), order.end(),
                   [](const GroupLoad& a, const GroupLoad& b) { return a.cost > b.cost; });
  std::vector<double> load(static_cast<std::size_t>(shard.count), 0.0);
  std::map<std::string, int> slice_of;
  for (const auto& g : order) {
    const auto least = std::min_element(load.begin(), load.end()) - load.begin();
    load[static_cast<std::size_t>(least)] += g.cost;
    slice_of[g.key] = static_cast<int>(least) + 1;
  }
  std::vector<CaseSpec> out;
  for (const auto& c : cases) {
    if (slice_of.at(model_key(c)) == shard.index)
      out.push_back(c);
  }
  return out;
}

std::string run_key(const std::vector<CaseSpec>& cases, std::string_view version, int count) {
  // FNV-1a over the case ids, the version and the count: stable across machines and builds.
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](std::string_view text) {
    for (unsigned char c : text) {
      h ^= c;
      h *= 1099511628211ull;
    }
    h ^= 0xff;
    h *= 1099511628211ull;
  };
  for (const auto& c : cases)
    mix(case_id(c));
  mix(version);
  mix(std::to_string(count));
  return fmt::format("{:016x}", h);
}

}  // namespace cs::suites
