#include "apps/json_file.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "apps/usage_error.hpp"

namespace cs::apps {

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  if (!std::filesystem::exists(path)) {
    throw UsageError(fmt::format("{} file '{}' does not exist", what, path));
  }
  std::ifstream in(path);
  if (!in)
    throw UsageError(fmt::format("{} file '{}' cannot be read", what, path));
  std::stringstream text;
  text << in.rdbuf();
  try {
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw UsageError(
        fmt::format("{} file '{}' is not valid JSON (truncated?): {}", what, path, e.what()));
  }
}

void write_json_file_atomically(const std::string& path, const nlohmann::json& doc) {
  const std::filesystem::path target(path);
  const auto tmp = target.parent_path() / fmt::format(".{}.tmp-{}", target.filename().string(),
                                                      static_cast<long>(getpid()));
  {
    std::ofstream out(tmp);
    out << doc.dump(1) << "\n";
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw UsageError(fmt::format("cannot write '{}'", path));
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, target, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw UsageError(fmt::format("cannot write '{}'", path));
  }
}

}  // namespace cs::apps
