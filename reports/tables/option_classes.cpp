#include "reports/tables/option_classes.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "grading/accuracy.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

/// The distinct names of `values` in the vocabulary's order.
template <class E>
std::vector<std::string> unique_in_order(std::vector<E> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return names_of(values);
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
    const schema::RowVerdict* ra = index.row(s.problem, s.quantity, s.element, a);
    const schema::RowVerdict* rb = index.row(s.problem, s.quantity, s.element, b);
    if (ra == nullptr && rb == nullptr)
      continue;
    if (ra == nullptr || rb == nullptr) {
      ++out.only_one;
      continue;
    }
    ++out.compared;
    bool differ = false, states = false;
    for (const auto mesh : kMeshes) {
      const auto& va = ra->values[mesh_index(mesh)];
      const auto& vb = rb->values[mesh_index(mesh)];
      if (va.has_value() != vb.has_value() || index.state(*ra, mesh) != index.state(*rb, mesh)) {
        differ = true;
        states = true;
        continue;
      }
      if (!va)
        continue;
      const double scale = std::max(std::abs(*va), std::abs(*vb));
      const double rel = scale > 0 ? std::abs(*va - *vb) / scale : 0.0;
      if (!grading::values_coincide(*va, *vb))
        differ = true;
      if (rel > out.max_relative) {
        out.max_relative = rel;
        out.where_max =
            fmt::format("{} {} {} {}", schema::to_string(s.problem), schema::to_string(s.quantity),
                        schema::to_string(s.element), schema::to_string(mesh));
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
  std::vector<schema::Algorithm> member_algorithms;
  std::vector<schema::ContactKind> member_contacts;
  std::vector<std::string> labels;
  for (const auto& m : members) {
    member_algorithms.push_back(m.algorithm);
    member_contacts.push_back(m.contact);
    labels.push_back(m.label());
  }
  const auto algorithms = unique_in_order(member_algorithms);
  const auto contacts = unique_in_order(member_contacts);
  if (algorithms.size() * contacts.size() == members.size())
    return fmt::format("{} ({})", fmt::join(algorithms, " = "), fmt::join(contacts, " = "));
  return fmt::format("{}", fmt::join(labels, " = "));
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

const schema::RowVerdict* class_row(const ResultsIndex& index, const OptionClass& cls,
                                    const Slot& slot) {
  for (const auto& m : cls.members) {
    if (const schema::RowVerdict* r = index.row(slot.problem, slot.quantity, slot.element, m))
      return r;
  }
  return nullptr;
}

}  // namespace cs::reports
