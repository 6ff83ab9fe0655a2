#include "adapters/calculix/frd_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "adapters/calculix/calculix_error.hpp"

namespace cs::adapters::calculix {
namespace {

constexpr long long kMaxCount = 1'000'000'000;  // nodes per block: far above any real model
constexpr int kMaxComponents = 64;              // components per block

/// The text as numbered lines; every failure names the source and the current line.
class Lines {
 public:
  Lines(std::string_view text, std::string_view source) : text_(text), source_(source) {}

  /// The next line without its end-of-line characters; false at the end of the text.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size())
      return false;
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r')
      line.remove_suffix(1);
    pos_ = end + 1;
    ++line_no_;
    return true;
  }
  /// The next line, or a "truncated" failure naming what was being read.
  std::string_view require(std::string_view reading) {
    std::string_view line;
    if (!next(line))
      fail(fmt::format("truncated file (end of file while reading {})", reading));
    return line;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw CalculixOutputError(fmt::format("{}: line {}: {}", source_, line_no_, what));
  }
  std::size_t size() const { return text_.size(); }

 private:
  std::string_view text_;
  std::string_view source_;
  std::size_t pos_ = 0;
  int line_no_ = 0;
};

/// line[pos, pos + len) clipped to the line (empty beyond its end).
std::string_view field(std::string_view line, std::size_t pos, std::size_t len) {
  return pos >= line.size() ? std::string_view{} : line.substr(pos, len);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
    s.remove_suffix(1);
  return s;
}

bool starts_with(std::string_view line, std::string_view prefix) {
  return line.substr(0, prefix.size()) == prefix;
}

bool parse_int(std::string_view s, long long& out) {
  s = trim(s);
  if (s.empty())
    return false;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size();
}

long long require_int(Lines& lines, std::string_view s, std::string_view what, long long lo,
                      long long hi) {
  long long v = 0;
  if (!parse_int(s, v) || v < lo || v > hi)
    lines.fail(fmt::format("bad {} '{}'", what, trim(s)));
  return v;
}

/// The whitespace-separated words of s.
std::vector<std::string_view> words(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && s[i] == ' ')
      ++i;
    const std::size_t start = i;
    while (i < s.size() && s[i] != ' ')
      ++i;
    if (i > start)
      out.push_back(s.substr(start, i - start));
  }
  return out;
}

/// The end of the number token starting at i (sign, mantissa, exponent, or a NaN/Inf word).
std::size_t number_end(std::string_view s, std::size_t i) {
  if (i < s.size() && (s[i] == '-' || s[i] == '+'))
    ++i;
  if (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) {
    while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i])))
      ++i;
    return i;
  }
  while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.'))
    ++i;
  if (i < s.size() && (s[i] == 'E' || s[i] == 'e')) {
    ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+'))
      ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])))
      ++i;
  }
  return i;
}

/// Appends the consecutive numbers of s to out; false on anything that is not a number.
bool scan_numbers(std::string_view s, std::vector<double>& out) {
  std::size_t i = 0;
  while (true) {
    while (i < s.size() && s[i] == ' ')
      ++i;
    if (i >= s.size())
      return true;
    const std::size_t end = number_end(s, i);
    std::string_view token = s.substr(i, end - i);
    if (!token.empty() && token.front() == '+')
      token.remove_prefix(1);
    double v = 0.0;
    const auto [stop, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (token.empty() || ec != std::errc() || stop != token.data() + token.size())
      return false;
    out.push_back(v);
    i = end;
  }
}

/// The node-id width of a block's format flag: 5 (short) or 10 (long); binary is refused.
std::size_t id_width(Lines& lines, std::string_view header) {
  const auto w = words(header.substr(std::min<std::size_t>(6, header.size())));
  const long long format = w.size() >= 2 ? require_int(lines, w.back(), "format flag", 0, 9) : 0;
  if (format == 2)
    lines.fail("binary results are not supported (request *NODE FILE / *EL FILE output)");
  if (format > 2)
    lines.fail(fmt::format("unknown format flag {}", format));
  return format == 0 ? 5 : 10;
}

/// One " -1<id><values>" record followed by " -2" continuations up to `count` values.
int read_record(Lines& lines, std::string_view line, std::size_t width, std::size_t count,
                std::vector<double>& values) {
  const int id = static_cast<int>(
      require_int(lines, field(line, 3, width), "node id", 1, std::numeric_limits<int>::max()));
  const std::size_t first = values.size();
  if (!scan_numbers(field(line, 3 + width, std::string_view::npos), values))
    lines.fail(fmt::format("bad number in the record of node {}", id));
  while (values.size() - first < count) {
    const std::string_view more = lines.require("a continuation record");
    if (!starts_with(more, " -2"))
      lines.fail(
          fmt::format("node {}: {} values expected, {} found", id, count, values.size() - first));
    if (!scan_numbers(field(more, 3 + width, std::string_view::npos), values))
      lines.fail(fmt::format("bad number in a continuation record of node {}", id));
  }
  if (values.size() - first != count)
    lines.fail(
        fmt::format("node {}: {} values expected, {} found", id, count, values.size() - first));
  return id;
}

void check_count(Lines& lines, std::string_view block, long long declared, std::size_t found) {
  if (static_cast<std::size_t>(declared) != found)
    lines.fail(fmt::format("block '{}' declares {} nodes but holds {} (truncated file?)", block,
                           declared, found));
}

FrdNodes read_nodes(Lines& lines, std::string_view header) {
  const auto w = words(field(header, 6, std::string_view::npos));
  if (w.empty())
    lines.fail("node block without a node count");
  const long long declared = require_int(lines, w.front(), "node count", 0, kMaxCount);
  const std::size_t width = id_width(lines, header);
  FrdNodes nodes;
  nodes.ids.reserve(std::min<std::size_t>(declared, lines.size() / 16));
  while (true) {
    const std::string_view line = lines.require("the node block");
    if (starts_with(line, " -3"))
      break;
    if (!starts_with(line, " -1"))
      lines.fail("node record expected (' -1')");
    nodes.ids.push_back(read_record(lines, line, width, 3, nodes.coordinates));
  }
  check_count(lines, "nodes", declared, nodes.ids.size());
  return nodes;
}

void skip_block(Lines& lines) {
  while (!starts_with(lines.require("the element block"), " -3")) {
  }
}

/// The " -4" name record and the " -5" component records of a result block.
void read_result_header(Lines& lines, FrdResultBlock& block) {
  const std::string_view named = lines.require("a result block header");
  if (!starts_with(named, " -4"))
    lines.fail("result block without its ' -4' name record");
  block.name = std::string(trim(field(named, 5, 8)));
  if (block.name.empty())
    lines.fail("result block without a name");
  const long long n = require_int(lines, field(named, 13, 5), "component count", 1, kMaxComponents);
  for (long long k = 0; k < n; ++k) {
    const std::string_view comp = lines.require("the component records");
    if (!starts_with(comp, " -5"))
      lines.fail(fmt::format("block '{}': component record (' -5') expected", block.name));
    const std::string_view exist = field(comp, 33, 5);
    const long long iexist = trim(exist).empty() ? 0 : require_int(lines, exist, "iexist", 0, 9);
    if (iexist == 0)
      block.components.emplace_back(trim(field(comp, 5, 8)));
  }
  if (block.components.empty())
    lines.fail(fmt::format("block '{}' stores no component", block.name));
}

FrdResultBlock read_result_block(Lines& lines, std::string_view header) {
  FrdResultBlock block;
  std::vector<double> time;
  if (!scan_numbers(field(header, 12, 12), time) || time.size() != 1)
    lines.fail("bad time in a result block header");
  block.time = time.front();
  const long long declared = require_int(lines, field(header, 24, 12), "node count", 0, kMaxCount);
  const std::size_t width = id_width(lines, header);
  read_result_header(lines, block);
  block.node_ids.reserve(std::min<std::size_t>(declared, lines.size() / 16));
  while (true) {
    const std::string_view line = lines.require(fmt::format("block '{}'", block.name));
    if (starts_with(line, " -3"))
      break;
    if (!starts_with(line, " -1"))
      lines.fail(fmt::format("block '{}': node record (' -1') expected", block.name));
    block.node_ids.push_back(
        read_record(lines, line, width, block.components.size(), block.values));
  }
  check_count(lines, block.name, declared, block.node_ids.size());
  return block;
}

}  // namespace

int FrdResultBlock::component(std::string_view wanted) const {
  for (int c = 0; c < n_components(); ++c) {
    if (components[c] == wanted)
      return c;
  }
  return -1;
}

const FrdResultBlock* FrdFile::last_block(std::string_view name) const {
  for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) {
    if (it->name == name)
      return &*it;
  }
  return nullptr;
}

FrdFile parse_frd(std::string_view text, std::string_view source) {
  Lines lines(text, source);
  FrdFile file;
  bool have_nodes = false;
  std::string_view line;
  while (lines.next(line)) {
    const std::string_view key = trim(field(line, 0, 6));
    if (key == "9999") {
      if (!have_nodes)
        lines.fail("no node block before the end record");
      return file;
    }
    if (key.empty() || key == "1C" || starts_with(key, "1U") || starts_with(key, "1P"))
      continue;
    if (key == "2C") {
      if (have_nodes)
        lines.fail("a second node block");
      file.nodes = read_nodes(lines, line);
      have_nodes = true;
    } else if (key == "3C") {
      skip_block(lines);
    } else if (key == "100C") {
      file.blocks.push_back(read_result_block(lines, line));
    } else {
      lines.fail(fmt::format("unexpected record '{}'", trim(field(line, 0, 12))));
    }
  }
  lines.fail("truncated file (no end record 9999)");
}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw CalculixOutputError(fmt::format("cannot read '{}'", path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw CalculixOutputError(fmt::format("cannot read '{}'", path.string()));
  return text.str();
}

FrdFile read_frd(const std::filesystem::path& path) {
  const std::string text = read_text_file(path);
  return parse_frd(text, path.filename().string());
}

}  // namespace cs::adapters::calculix
