#pragma once
// Deterministic slices of a case list, for runs spread over machines (`run --shard K/N`, a Slurm
// job array) and merged afterwards (`merge`, suites/results_merge.hpp).
//
// Cases that share a model (runner.hpp: model_key) stay in one slice, so a slice builds and
// factors each of its models once. Groups are dealt largest first to the least-loaded slice by
// an estimated cost (longest-processing-time scheduling), ties broken by slice index and the
// group's key, so every machine computes the same partition from the same case list.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "suites/case_spec.hpp"

namespace cs::suites {

/// Slice K of N (1-based).
struct ShardSpec {
  int index = 1;
  int count = 1;
};

/// Parses "K/N" with 1 <= K <= N <= kMaxShards; throws SuiteInputError otherwise
/// ("--shard 4/3: K must be between 1 and N").
ShardSpec parse_shard(std::string_view text);
inline constexpr int kMaxShards = 10000;

/// The cases of slice `shard`, in their original order.
std::vector<CaseSpec> shard_cases(const std::vector<CaseSpec>& cases, const ShardSpec& shard,
                                  const std::function<double(const CaseSpec&)>& group_cost);

/// A key that every slice of one run shares and slices of different runs do not: a hash of the
/// whole case list (before slicing), the build's version and the shard count.
std::string run_key(const std::vector<CaseSpec>& cases, std::string_view version, int count);

}  // namespace cs::suites
