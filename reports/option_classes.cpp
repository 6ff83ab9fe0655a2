#include "reports/option_classes.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace cs::reports {
namespace {

std::vector<std::string> unique_in_order(std::vector<std::string> names,
                                         int (*order)(const std::string&)) {
  std::sort(names.begin(), names.end(),
            [order](const std::string& a, const std::string& b) { return order(a) < order(b); });
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string out;
  for (const auto& p : parts) {
    if (!out.empty())
      out += sep;
    out += p;
  }
  return out;
}

bool has_rows(const ResultsIndex& index, const Option& o, const std::vector<Slot>& slots) {
  return std::any_of(slots.begin(), slots.end(), [&](const Slot& s) {
    return index.row(s.problem, s.quantity, s.element, o) != nullptr;
  });
}

}  // namespace

OptionComparison compare_options(const ResultsIndex& index, const Option& a, const Option& b,
                                 const std::vector<Slot>& slots) {
  OptionComparison out;
  for (const auto& s : slots) {
    const RowRecord* ra = index.row(s.problem, s.quantity, s.element, a);
    const RowRecord* rb = index.row(s.problem, s.quantity, s.element, b);
    if (ra == nullptr && rb == nullptr)
      continue;
    if (ra == nullptr || rb == nullptr) {
      ++out.only_one;
      continue;
    }
    ++out.compared;
    bool differ = false, states = false;
    for (std::size_t m = 0; m < kMeshLevels.size(); ++m) {
      const auto& va = ra->values[m];
      const auto& vb = rb->values[m];
      if (va.has_value() != vb.has_value() || index.state(*ra, m) != index.state(*rb, m)) {
        differ = true;
        states = true;
        continue;
      }
      if (!va)
        continue;
      const double scale = std::max(std::abs(*va), std::abs(*vb));
      const double rel = scale > 0 ? std::abs(*va - *vb) / scale : 0.0;
      if (rel > kCoincidenceRelative)
        differ = true;
      if (rel > out.max_relative) {
        out.max_relative = rel;
        out.where_max =
            fmt::format("{} {} {} {}", s.problem, s.quantity, s.element, kMeshLevels[m]);
      }
    }
    if (differ)
      ++out.differing;
    if (states)
      ++out.states_differ;
  }
  return out;
}

std::string OptionClass::label() const {
  std::vector<std::string> algorithms, contacts;
  for (const auto& m : members) {
    algorithms.push_back(m.algorithm);
    contacts.push_back(m.contact);
  }
  algorithms = unique_in_order(algorithms, algorithm_order);
  contacts = unique_in_order(contacts, contact_order);
  if (algorithms.size() * contacts.size() == members.size()) {
    return fmt::format("{} ({})", join(algorithms, " = "), join(contacts, " = "));
  }
  std::vector<std::string> labels;
  for (const auto& m : members)
    labels.push_back(m.label());
  return join(labels, " = ");
}

std::vector<OptionClass> coincidence_classes(const ResultsIndex& index,
                                             const std::vector<Option>& candidates,
                                             const std::vector<Slot>& slots) {
  std::vector<OptionClass> classes;
  for (const auto& candidate : candidates) {
    if (!has_rows(index, candidate, slots))
      continue;
    auto joins = [&](const OptionClass& cls) {
      return std::all_of(cls.members.begin(), cls.members.end(), [&](const Option& m) {
        return compare_options(index, m, candidate, slots).coincide();
      });
    };
    auto it = std::find_if(classes.begin(), classes.end(), joins);
    if (it != classes.end()) {
      it->members.push_back(candidate);
    } else {
      classes.push_back(OptionClass{{candidate}});
    }
  }
  return classes;
}

const RowRecord* class_row(const ResultsIndex& index, const OptionClass& cls, const Slot& slot) {
  for (const auto& m : cls.members) {
    if (const RowRecord* r = index.row(slot.problem, slot.quantity, slot.element, m))
      return r;
  }
  return nullptr;
}

}  // namespace cs::reports
