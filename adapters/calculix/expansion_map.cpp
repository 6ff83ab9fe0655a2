#include "adapters/calculix/expansion_map.hpp"

#include <charconv>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "adapters/calculix/calculix_error.hpp"
#include "adapters/calculix/frd_reader.hpp"

namespace cs::adapters::calculix {
namespace {

/// The words of the text with their line numbers.
struct Word {
  std::string_view text;
  int line = 0;
};

std::vector<Word> split_words(std::string_view text) {
  std::vector<Word> out;
  int line = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '\n')
      ++line;
    if (text[i] == ' ' || text[i] == '\n' || text[i] == '\r' || text[i] == '\t') {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\n' && text[i] != '\r' &&
           text[i] != '\t')
      ++i;
    out.push_back({text.substr(start, i - start), line});
  }
  return out;
}

bool to_id(std::string_view s, int& id) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), id);
  return ec == std::errc() && end == s.data() + s.size() && id > 0;
}

/// Reads consecutive positive integers from words[k...]; stops at the first other word.
std::vector<int> read_ids(const std::vector<Word>& words, std::size_t& k) {
  std::vector<int> ids;
  int id = 0;
  while (k < words.size() && to_id(words[k].text, id)) {
    ids.push_back(id);
    ++k;
  }
  return ids;
}

/// Records the expanded copies of each 2D node (see the header for the layout).
bool map_element(const std::vector<int>& nodes, const std::vector<int>& expanded,
                 ExpansionMap& map) {
  if (nodes.size() == 4 && expanded.size() == 8) {
    for (int j = 0; j < 4; ++j)
      map[expanded[j]] = map[expanded[j + 4]] = nodes[j];
    return true;
  }
  if (nodes.size() == 8 && expanded.size() == 20) {
    for (int j = 0; j < 4; ++j) {
      map[expanded[j]] = map[expanded[j + 4]] = map[expanded[16 + j]] = nodes[j];
      map[expanded[8 + j]] = map[expanded[12 + j]] = nodes[4 + j];
    }
    return true;
  }
  return false;
}

/// Skips words up to and including the one ending with `marker` (e.g. "nodes:").
bool skip_past(const std::vector<Word>& words, std::size_t& k, std::string_view marker) {
  while (k < words.size()) {
    const std::string_view w = words[k++].text;
    if (w.size() >= marker.size() && w.substr(w.size() - marker.size()) == marker)
      return true;
  }
  return false;
}

}  // namespace

ExpansionMap parse_expansion(std::string_view text, std::string_view source) {
  const std::vector<Word> words = split_words(text);
  ExpansionMap map;
  std::size_t k = 0;
  auto fail = [&](const std::string& what) {
    const int line = k < words.size() ? words[k].line : (words.empty() ? 1 : words.back().line);
    throw CalculixOutputError(fmt::format("{}: line {}: {}", source, line, what));
  };
  while (k < words.size()) {
    if (words[k].text != "ELEMENT")
      fail(fmt::format("'ELEMENT' expected, found '{}'", words[k].text.substr(0, 20)));
    ++k;
    if (!skip_past(words, k, "nodes:"))
      fail("truncated element record (no node list)");
    const std::vector<int> nodes = read_ids(words, k);
    if (!skip_past(words, k, "topology:"))
      fail("truncated element record (no expanded topology)");
    const std::vector<int> expanded = read_ids(words, k);
    if (!map_element(nodes, expanded, map))
      fail(
          fmt::format("element with {} nodes expanded into {}: not a 4 -> 8 or 8 -> 20 "
                      "expansion",
                      nodes.size(), expanded.size()));
  }
  return map;
}

ExpansionMap read_expansion(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path))
    return {};
  const std::string text = read_text_file(path);
  return parse_expansion(text, path.filename().string());
}

}  // namespace cs::adapters::calculix
