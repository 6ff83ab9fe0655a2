#include "schema/registered_problems.hpp"

#include <algorithm>
#include <cctype>
#include <deque>
#include <limits>
#include <mutex>
#include <string>

namespace cs::schema {
namespace {

struct RegisteredNames {
  std::string name;
  std::string label;
};

/// The table of registered names: a deque, so that the views entry() hands out stay valid as it
/// grows; element i is the problem kFirstRegisteredProblem + i.
struct Registry {
  std::mutex mutex;
  std::deque<RegisteredNames> names;
};

Registry& registry() {
  static Registry r;
  return r;
}

bool is_plain_name(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
  });
}

}  // namespace

AxisEntry registered_entry(ProblemId v) {
  const auto index = static_cast<std::size_t>(v);
  if (index < kFirstRegisteredProblem)
    return {};
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  if (index - kFirstRegisteredProblem >= r.names.size())
    return {};
  const RegisteredNames& n = r.names[index - kFirstRegisteredProblem];
  return {n.name, "", n.label};
}

std::vector<ProblemId> registered_values(ProblemId) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  std::vector<ProblemId> out;
  for (std::size_t i = 0; i < r.names.size(); ++i)
    out.push_back(static_cast<ProblemId>(kFirstRegisteredProblem + i));
  return out;
}

ProblemId register_problem_name(std::string_view name, std::string_view label) {
  if (!is_plain_name(name)) {
    throw SchemaError("register_problem: the name '" + std::string(name) +
                      "' is not a plain name (letters, digits and '_')");
  }
  const auto taken = [&name] {
    throw SchemaError("register_problem: '" + std::string(name) + "' is already a problem");
  };
  for (ProblemId id : values<ProblemId>()) {
    if (name == entry(id).name || name == entry(id).alias)
      taken();
  }
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const RegisteredNames& n : r.names) {
    if (name == n.name)
      taken();
  }
  constexpr std::size_t kCapacity =
      std::numeric_limits<std::underlying_type_t<ProblemId>>::max() - kFirstRegisteredProblem + 1;
  if (r.names.size() == kCapacity) {
    throw SchemaError("register_problem: all " + std::to_string(kCapacity) +
                      " ids of registered problems are taken ('" + std::string(name) + "')");
  }
  r.names.push_back({std::string(name), std::string(label)});
  return static_cast<ProblemId>(kFirstRegisteredProblem + r.names.size() - 1);
}

}  // namespace cs::schema
