#include "schema/json_fields.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "schema/schema_error.hpp"

namespace cs::schema {

using nlohmann::json;

namespace {

std::string_view type_name(const json& v) {
  if (v.is_null())
    return "null";
  if (v.is_boolean())
    return "a boolean";
  if (v.is_number())
    return "a number";
  if (v.is_string())
    return "a string";
  if (v.is_array())
    return "an array";
  return "an object";
}

}  // namespace

JsonFields::JsonFields(const json& object, std::string path)
    : object_(object), path_(std::move(path)) {
  if (!object_.is_object())
    fail(fmt::format("is {}, expected an object", type_name(object_)));
}

void JsonFields::fail(std::string_view what) const {
  throw SchemaError(fmt::format("{}: {}", path_, what));
}

void JsonFields::fail_field(std::string_view key, std::string_view what) const {
  throw SchemaError(fmt::format("{}: {}", path_of(key), what));
}

bool JsonFields::has(const char* key) const {
  return object_.contains(key);
}

std::string JsonFields::path_of(std::string_view key) const {
  return fmt::format("{}.{}", path_, key);
}

const json& JsonFields::at(const char* key) const {
  if (!has(key))
    fail(fmt::format("missing '{}'", key));
  return object_.at(key);
}

JsonFields JsonFields::object(const char* key) const {
  return JsonFields(at(key), path_of(key));
}

std::string JsonFields::string(const char* key) const {
  const json& v = at(key);
  if (!v.is_string())
    fail_field(key, fmt::format("is {}, expected a string", type_name(v)));
  return v.get<std::string>();
}

std::string JsonFields::optional_string(const char* key, std::string fallback) const {
  if (!has(key) || object_.at(key).is_null())
    return fallback;
  return string(key);
}

bool JsonFields::boolean(const char* key) const {
  const json& v = at(key);
  if (!v.is_boolean())
    fail_field(key, fmt::format("is {}, expected true or false", type_name(v)));
  return v.get<bool>();
}

std::optional<bool> JsonFields::optional_boolean(const char* key) const {
  if (!has(key) || object_.at(key).is_null())
    return std::nullopt;
  return boolean(key);
}

long long JsonFields::integer(const char* key, long long min, long long max) const {
  const json& v = at(key);
  long long value = 0;
  if (v.is_number_unsigned()) {
    const auto u = v.get<unsigned long long>();
    if (u > static_cast<unsigned long long>(std::numeric_limits<long long>::max()))
      fail_field(key, fmt::format("{} is out of range [{}, {}]", u, min, max));
    value = static_cast<long long>(u);
  } else if (v.is_number_integer()) {
    value = v.get<long long>();
  } else {
    fail_field(key, fmt::format("is {}, expected an integer", type_name(v)));
  }
  if (value < min || value > max)
    fail_field(key, fmt::format("{} is out of range [{}, {}]", value, min, max));
  return value;
}

long long JsonFields::optional_integer(const char* key, long long fallback, long long min,
                                       long long max) const {
  if (!has(key) || object_.at(key).is_null())
    return fallback;
  return integer(key, min, max);
}

double JsonFields::number(const char* key, bool nullable) const {
  if (!has(key) || object_.at(key).is_null()) {
    if (nullable)
      return std::nan("");
    fail(fmt::format("missing '{}'", key));
  }
  const json& v = object_.at(key);
  if (!v.is_number())
    fail_field(key,
               fmt::format("is {}, expected a number{}", type_name(v), nullable ? " or null" : ""));
  const double d = v.get<double>();
  if (!std::isfinite(d))
    fail_field(key, "is not a finite number");
  return d;
}

std::optional<double> JsonFields::optional_number(const char* key) const {
  if (!has(key) || object_.at(key).is_null())
    return std::nullopt;
  return number(key, false);
}

json number_or_null(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

json number_or_null(const std::optional<double>& v) {
  return v ? number_or_null(*v) : json(nullptr);
}

}  // namespace cs::schema
