#pragma once
// Typed reading of one JSON object of a results or baseline file. Every field is read with its
// type checked; a missing field, a wrong type, an unknown name or a number out of range is a
// SchemaError naming the file, the field's path and the cause ("results.json: cases[3].
// quantities.sigma_c.value: is a string, expected a number or null").

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "schema/name_table.hpp"

namespace cs::schema {

class JsonFields {
 public:
  /// `path` is where the object sits ("results.json: cases[3]"); throws if it is not an object.
  JsonFields(const nlohmann::json& object, std::string path);

  [[noreturn]] void fail(std::string_view what) const;
  [[noreturn]] void fail_field(std::string_view key, std::string_view what) const;

  bool has(const char* key) const;
  /// The reader of a nested object at `key` (required).
  JsonFields object(const char* key) const;
  /// The JSON value at `key` (required), for arrays and free-form objects.
  const nlohmann::json& at(const char* key) const;
  /// The path of a member, for nested readers ("...cases[3].quantities").
  std::string path_of(std::string_view key) const;
  const std::string& path() const { return path_; }

  std::string string(const char* key) const;
  std::string optional_string(const char* key, std::string fallback = {}) const;
  bool boolean(const char* key) const;
  std::optional<bool> optional_boolean(const char* key) const;  ///< absent or null: nullopt
  /// An integer in [min, max] (a JSON integer, not 2.5 nor 4294967298 for an int field).
  long long integer(const char* key, long long min, long long max) const;
  long long optional_integer(const char* key, long long fallback, long long min,
                             long long max) const;
  /// A finite number; null or absent reads as NaN when `nullable`, else it is an error.
  double number(const char* key, bool nullable) const;
  /// A finite number, or nullopt when absent or null.
  std::optional<double> optional_number(const char* key) const;
  /// A name of axis E (schema/name_table.hpp).
  template <Axis E>
  E name(const char* key) const {
    const std::string text = string(key);
    if (const auto v = try_parse<E>(text))
      return *v;
    fail_field(key, "unknown " + std::string(axis_name(E{})) + " \"" + text +
                        "\" (expected one of: " + accepted_names<E>() + ")");
  }
  template <Axis E>
  std::optional<E> optional_name(const char* key) const {
    if (!has(key) || object_.at(key).is_null())
      return std::nullopt;
    return name<E>(key);
  }

 private:
  const nlohmann::json& object_;
  std::string path_;
};

/// A finite number as JSON, or null: JSON has no NaN or infinity.
nlohmann::json number_or_null(double v);
nlohmann::json number_or_null(const std::optional<double>& v);

}  // namespace cs::schema
