#include "schema/json_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "schema/schema_error.hpp"

namespace cs::schema {

namespace {

/// How deep a file may nest. Ours nest 6 levels; a document far deeper (a hand-made file)
/// would exhaust the stack when it is copied or written, since both recurse.
constexpr int kMaxJsonDepth = 64;

/// Why a well-formed text is still refused: too deep, or a key given twice in one object (the
/// parser would keep the last, so a merge-conflict leftover would pass unnoticed).
struct Refused {
  std::string why;
};

}  // namespace

nlohmann::json parse_json_text(std::string_view text, const std::string& what,
                               const std::string& source) {
  using nlohmann::json;
  std::vector<std::set<std::string>> keys;  // of each object being read
  const json::parser_callback_t check = [&](int depth, json::parse_event_t event, json& parsed) {
    if (depth >= kMaxJsonDepth)  // the root is at depth 0
      throw Refused{fmt::format("it nests deeper than {} levels", kMaxJsonDepth)};
    if (event == json::parse_event_t::object_start)
      keys.emplace_back();
    else if (event == json::parse_event_t::object_end)
      keys.pop_back();
    else if (event == json::parse_event_t::key &&
             !keys.back().insert(parsed.get<std::string>()).second)
      throw Refused{
          fmt::format("the key '{}' is given twice in one object", parsed.get<std::string>())};
    return true;
  };
  try {
    return json::parse(text, check);
  } catch (const json::exception& e) {
    throw SchemaError(
        fmt::format("{} file '{}' is not valid JSON (truncated?): {}", what, source, e.what()));
  } catch (const Refused& r) {
    throw SchemaError(fmt::format("{} file '{}' is refused: {}", what, source, r.why));
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
