#include "reports/tables/option_classes.hpp"

#include <algorithm>
#include <cmath>
#include <ranges>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "grading/accuracy.hpp"
#include "reports/tables/markdown_table.hpp"

namespace cs::reports {
namespace {

/// The distinct names of the `axis` values of `options`, in the vocabulary's order.
template <class E>
std::vector<std::string> unique_in_order(const std::vector<Option>& options, E Option::*axis) {
  std::vector<E> values;
  for (const Option& o : options)
    values.push_back(o.*axis);
  std::ranges::sort(values);
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return names_of(values);
}

bool has_rows(const ResultsIndex& index, const Option& o, const std::vector<Slot>& slots) {
  return std::ranges::any_of(slots, [&](const Slot& s) {
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
      differ = differ || !grading::values_coincide(*va, *vb);
      if (rel > out.max_relative) {
        out.max_relative = rel;
        out.where_max =
            fmt::format("{} {} {} {}", schema::to_string(s.problem), schema::to_string(s.quantity),
                        schema::to_string(s.element), schema::to_string(mesh));
      }
    }
    out.differing += differ ? 1 : 0;
    out.states_differ += states ? 1 : 0;
  }
  return out;
}

std::string OptionClass::label() const {
  const auto algorithms = unique_in_order(members, &Option::algorithm);
  const auto contacts = unique_in_order(members, &Option::contact);
  if (algorithms.size() * contacts.size() == members.size())
    return fmt::format("{} ({})", fmt::join(algorithms, " = "), fmt::join(contacts, " = "));
  return fmt::format("{}", fmt::join(members | std::views::transform(&Option::label), " = "));
}

std::vector<OptionClass> coincidence_classes(const ResultsIndex& index,
                                             const std::vector<Option>& candidates,
                                             const std::vector<Slot>& slots) {
  std::vector<OptionClass> classes;
  for (const auto& candidate : candidates) {
    if (!has_rows(index, candidate, slots))
      continue;
    const auto joins = [&](const OptionClass& cls) {
      return std::ranges::all_of(cls.members, [&](const Option& m) {
        return compare_options(index, m, candidate, slots).coincide();
      });
    };
    if (const auto it = std::ranges::find_if(classes, joins); it != classes.end())
      it->members.push_back(candidate);
    else
      classes.push_back(OptionClass{{candidate}});
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
