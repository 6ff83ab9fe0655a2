#include "schema/json_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "schema/schema_error.hpp"

namespace cs::schema {

nlohmann::json parse_json_text(std::string_view text, const std::string& what,
                               const std::string& source) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw SchemaError(
        fmt::format("{} file '{}' is not valid JSON (truncated?): {}", what, source, e.what()));
  }
}

nlohmann::json read_json_file(const std::filesystem::path& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw SchemaError(fmt::format("{} file '{}' does not exist", what, path.string()));
  if (std::filesystem::is_directory(path, ec))
    throw SchemaError(fmt::format("{} file '{}' is a directory", what, path.string()));
  std::ifstream in(path);
  if (!in)
    throw SchemaError(fmt::format("{} file '{}' cannot be read", what, path.string()));
  std::stringstream text;
  text << in.rdbuf();
  return parse_json_text(text.str(), what, path.string());
}

void write_json_file_atomically(const std::filesystem::path& path, const nlohmann::json& doc) {
  const auto dir = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  const auto tmp =
      dir / fmt::format(".{}.tmp-{}", path.filename().string(), static_cast<long>(getpid()));
  {
    std::ofstream out(tmp);
    // A byte that is not UTF-8 (a path in another encoding, in a case's reason) reads U+FFFD.
    out << doc.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    out.flush();
    if (!out) {
      const std::string why = std::strerror(errno);  // e.g. "No space left on device"
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw SchemaError(fmt::format("cannot write '{}': {}", path.string(), why));
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw SchemaError(fmt::format("cannot write '{}': {}", path.string(), ec.message()));
  }
}

}  // namespace cs::schema
