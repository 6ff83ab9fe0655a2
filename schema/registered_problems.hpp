#pragma once
// The names of the problems registered at run time (see ProblemId in schema/case_axes.hpp):
// a problem defined outside the battery gets an id from kFirstRegisteredProblem up and its
// names here, so that case ids, the command line and results.json name it like any other.
// suites::register_problem is the one caller; registered_entry and registered_values (declared
// in case_axes.hpp) read the table. Safe to call from several threads.

#include <string_view>

#include "schema/case_axes.hpp"

namespace cs::schema {

/// Registers a problem named `name` (its canonical name; `label` its Markdown label, "" for the
/// name) and returns its id, the next from kFirstRegisteredProblem. Throws SchemaError when the
/// name is empty or not made of [A-Za-z0-9_], when it is already a problem's name or alias, or
/// when every id of the range is taken.
ProblemId register_problem_name(std::string_view name, std::string_view label = "");

}  // namespace cs::schema
