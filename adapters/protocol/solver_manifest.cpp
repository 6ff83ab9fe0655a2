#include "adapters/protocol/solver_manifest.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "platform/child_process.hpp"
#include "schema/json_file.hpp"
#include "schema/schema_error.hpp"

namespace cs::adapters::protocol {
namespace {

using nlohmann::json;

constexpr std::array kFamilies{OptionFamily::penalty, OptionFamily::augmented_lagrangian,
                               OptionFamily::lagrange_multiplier, OptionFamily::nitsche,
                               OptionFamily::mpc};
constexpr std::array kSupports{Support::plane_strain,  Support::axisymmetric, Support::rigid_target,
                               Support::meshed_target, Support::Q4,           Support::Q8};

template <class E, std::size_t N>
std::optional<E> find_name(const std::array<E, N>& all, std::string_view name) {
  for (E e : all)
    if (to_string(e) == name)
      return e;
  return std::nullopt;
}

template <class E, std::size_t N>
std::string names(const std::array<E, N>& all) {
  std::string out;
  for (E e : all)
    out += (out.empty() ? "" : ", ") + std::string(to_string(e));
  return out;
}

/// Reads one JSON object, refusing keys outside `allowed`.
class Fields {
 public:
  Fields(const json& j, std::string where, const std::filesystem::path& source,
         std::set<std::string> allowed)
      : j_(j), where_(std::move(where)), source_(source) {
    if (!j_.is_object())
      fail("", "is not a JSON object");
    for (const auto& item : j_.items())
      if (!allowed.contains(item.key()))
        fail(item.key(), fmt::format("is not a manifest key (known: {})", join(allowed)));
  }

  [[noreturn]] void fail(std::string_view key, std::string_view what) const {
    throw ManifestError(fmt::format("{}: {}{}{} {}", source_.string(), where_,
                                    key.empty() || where_.empty() ? "" : ".", key, what));
  }

  std::string string(const char* key, bool required = true) const {
    if (!j_.contains(key)) {
      if (required)
        fail(key, "is missing");
      return {};
    }
    if (!j_[key].is_string() || j_[key].get<std::string>().empty())
      fail(key, "must be a non-empty string");
    return j_[key].get<std::string>();
  }

  std::vector<std::string> strings(const char* key) const {
    if (!j_.contains(key))
      fail(key, "is missing");
    const json& a = j_[key];
    if (!a.is_array() || a.empty())
      fail(key, "must be a non-empty array of strings");
    std::vector<std::string> out;
    for (const auto& v : a) {
      if (!v.is_string())
        fail(key, "must be a non-empty array of strings");
      out.push_back(v.get<std::string>());
    }
    return out;
  }

  /// The "supports" list, each a known capability.
  std::vector<Support> supports() const {
    std::vector<Support> out;
    for (const std::string& s : strings("supports")) {
      const auto support = find_name(kSupports, s);
      if (!support)
        fail("supports", fmt::format("'{}' is not a capability (known: {})", s, names(kSupports)));
      out.push_back(*support);
    }
    return out;
  }

  const json& array(const char* key) const {
    if (!j_.contains(key) || !j_[key].is_array() || j_[key].empty())
      fail(key, "must be a non-empty array");
    return j_[key];
  }

  std::optional<double> number(const char* key) const {
    if (!j_.contains(key))
      return std::nullopt;
    if (!j_[key].is_number() || !std::isfinite(j_[key].get<double>()) ||
        j_[key].get<double>() <= 0.0)
      fail(key, "must be a positive number");
    return j_[key].get<double>();
  }

 private:
  static std::string join(const std::set<std::string>& s) {
    std::string out;
    for (const auto& k : s)
      out += (out.empty() ? "" : ", ") + k;
    return out;
  }
  const json& j_;
  std::string where_;
  const std::filesystem::path& source_;
};

bool plain_label(std::string_view s) {
  return !s.empty() && s.size() <= 64 && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
  });
}

SolverOption parse_option(const json& j, std::size_t index, const std::filesystem::path& source) {
  const Fields f(j, fmt::format("options[{}]", index), source,
                 {"label", "family", "discretization", "description", "supports"});
  SolverOption o;
  o.label = f.string("label");
  if (!plain_label(o.label))
    f.fail("label", fmt::format("'{}' must be 1-64 characters of [A-Za-z0-9._-]", o.label));
  const std::string family = f.string("family");
  const auto fam = find_name(kFamilies, family);
  if (!fam)
    f.fail("family", fmt::format("'{}' is not a family (known: {})", family, names(kFamilies)));
  o.family = *fam;
  o.discretization = f.string("discretization");
  if (o.discretization != "ns" && o.discretization != "ss" && o.discretization != "mortar")
    f.fail("discretization",
           fmt::format("'{}' is not a discretization (known: ns, ss, mortar)", o.discretization));
  o.description = f.string("description", false);
  if (j.contains("supports"))
    o.supports = f.supports();
  return o;
}

}  // namespace

std::string_view to_string(OptionFamily f) {
  switch (f) {
    case OptionFamily::penalty:
      return "penalty";
    case OptionFamily::augmented_lagrangian:
      return "augmented_lagrangian";
    case OptionFamily::lagrange_multiplier:
      return "lagrange_multiplier";
    case OptionFamily::nitsche:
      return "nitsche";
    case OptionFamily::mpc:
      return "mpc";
  }
  return "";
}

std::string_view to_string(Support s) {
  switch (s) {
    case Support::plane_strain:
      return "plane_strain";
    case Support::axisymmetric:
      return "axisymmetric";
    case Support::rigid_target:
      return "rigid_target";
    case Support::meshed_target:
      return "meshed_target";
    case Support::Q4:
      return "Q4";
    case Support::Q8:
      return "Q8";
  }
  return "";
}

bool SolverManifest::supports_all(std::initializer_list<Support> wanted,
                                  const SolverOption* option) const {
  const std::vector<Support>& have =
      option != nullptr && !option->supports.empty() ? option->supports : supports;
  return std::all_of(wanted.begin(), wanted.end(), [&have](Support s) {
    return std::find(have.begin(), have.end(), s) != have.end();
  });
}

const SolverOption& SolverManifest::option(std::string_view label) const {
  for (const auto& o : options)
    if (o.label == label)
      return o;
  std::string known;
  for (const auto& o : options)
    known += (known.empty() ? "" : ", ") + o.label;
  throw ManifestError(fmt::format("{} has no option '{}' (its options: {})", name, label, known));
}

SolverManifest parse_manifest(std::string_view text, const std::filesystem::path& source) {
  json j;
  try {  // a syntax error, a number out of range (1e999), deep nesting, a key given twice
    j = schema::parse_json_text(text, "manifest", source.string());
  } catch (const schema::SchemaError& e) {
    throw ManifestError(e.what());
  }
  const Fields f(j, "", source,
                 {"name", "description", "command", "version_command", "options", "supports",
                  "time_limit_seconds"});
  SolverManifest m;
  m.folder = source.parent_path();
  m.name = f.string("name");
  const bool lower = std::all_of(m.name.begin(), m.name.end(), [](char c) {
    return std::islower(static_cast<unsigned char>(c)) || std::isdigit(c) || c == '_' || c == '-';
  });
  if (!plain_label(m.name) || !lower || m.name == "builtin" || m.name == "calculix" ||
      m.name == "imported" || m.name == "external")
    f.fail("name",
           fmt::format("'{}' must be [a-z0-9_-]+ and not a built-in solver's name", m.name));
  m.description = f.string("description", false);
  m.command = f.strings("command");
  m.version_command = f.strings("version_command");
  const json& options = f.array("options");
  for (std::size_t i = 0; i < options.size(); ++i) {
    m.options.push_back(parse_option(options[i], i, source));
    for (std::size_t k = 0; k + 1 < m.options.size(); ++k)
      if (m.options[k].label == m.options.back().label)
        f.fail("options", fmt::format("label '{}' is given twice", m.options.back().label));
  }
  m.supports = f.supports();
  for (std::size_t i = 0; i < m.options.size(); ++i)
    for (const Support s : m.options[i].supports)
      if (!m.supports_all({s}))
        f.fail(fmt::format("options[{}].supports", i),
               fmt::format("'{}' is not among the code's supports", to_string(s)));
  if (const auto limit = f.number("time_limit_seconds")) {
    if (*limit > platform::kMaxTimeLimitSeconds)
      throw ManifestError(fmt::format("{}: time_limit_seconds {} is above the limit of {} s",
                                      source.string(), *limit, platform::kMaxTimeLimitSeconds));
    m.time_limit_seconds = *limit;
  }
  return m;
}

SolverManifest read_manifest(const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / "manifest.json";
  std::ifstream in(file);
  if (!in)
    throw ManifestError(fmt::format("{}: cannot be read", file.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_manifest(text.str(), file);
}

std::vector<std::string> expand_command(const std::vector<std::string>& argv,
                                        const std::filesystem::path& adapter_dir,
                                        const std::filesystem::path& case_dir,
                                        std::string_view option) {
  const std::array<std::pair<std::string_view, std::string>, 3> vars{
      {{"{adapter_dir}", adapter_dir.string()},
       {"{case_dir}", case_dir.string()},
       {"{option}", std::string(option)}}};
  std::vector<std::string> out;
  for (std::string arg : argv) {
    for (const auto& [key, value] : vars) {
      for (auto at = arg.find(key); at != std::string::npos; at = arg.find(key, at + value.size()))
        arg.replace(at, key.size(), value);
    }
    out.push_back(std::move(arg));
  }
  return out;
}

}  // namespace cs::adapters::protocol
