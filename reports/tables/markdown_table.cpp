#include "reports/tables/markdown_table.hpp"

#include <cmath>

#include <fmt/format.h>

namespace cs::reports {
namespace {

/// A signed percentage: "+0.07 %", "−12.3 %" (2 significant decimals below 10 %, 1 above).
std::string format_percent(double percent) {
  const double magnitude = std::abs(percent);
  return fmt::format("{}{:.{}f} %", percent < 0 ? "−" : "+", magnitude, magnitude >= 10 ? 1 : 2);
}

std::string render_row(const std::vector<std::string>& cells, std::size_t width) {
  std::string line = "|";
  for (std::size_t i = 0; i < width; ++i) {
    line += ' ';
    line += i < cells.size() ? escape_cell(cells[i]) : std::string();
    line += " |";
  }
  return line + "\n";
}

}  // namespace

std::string escape_cell(const std::string& text) {
  std::string out;
  for (char c : text)
    out += c == '|' ? "\\|" : c == '\n' || c == '\r' ? " " : std::string(1, c);
  return out;
}

std::string MarkdownTable::render() const {
  std::size_t width = header_.size();
  std::string out = render_row(header_, width);
  out += "|";
  for (std::size_t i = 0; i < width; ++i) {
    const Align a = i < align_.size() ? align_[i] : i == 0 ? Align::left : Align::center;
    out += a == Align::left ? " :-- |" : a == Align::center ? " :-: |" : " --: |";
  }
  out += "\n";
  for (const auto& row : rows_)
    out += render_row(row, width);
  return out;
}

std::optional<std::string> MarkdownTable::cell(const std::string& row_label,
                                               const std::string& column) const {
  for (const auto& r : rows_) {
    if (r.empty() || r[0] != row_label)
      continue;
    for (std::size_t j = 0; j < header_.size() && j < r.size(); ++j) {
      if (header_[j] == column)
        return r[j];
    }
  }
  return std::nullopt;
}

std::string tidy_markdown(const std::string& markdown) {
  std::string out;
  int newlines = 0;
  for (char c : markdown) {
    newlines = c == '\n' ? newlines + 1 : 0;
    if (newlines <= 2)
      out += c;
  }
  return out;
}

std::string join_words(const std::vector<std::string>& items, const char* last) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? last : ", ") + items[i];
  return out;
}

std::string format_value(double v) {
  return fmt::format("{:.4f}", v);
}

std::string format_milliseconds(double ms) {
  return fmt::format("{:.{}f}", ms, ms >= 100 ? 0 : ms >= 10 ? 1 : ms >= 1 ? 2 : 3);
}

std::string format_value(const std::optional<double>& v) {
  return v ? format_value(*v) : std::string(kMissing);
}

std::string format_error_resolved(const std::optional<double>& percent) {
  return percent ? format_error_resolved(*percent) : std::string(kMissing);
}

std::string format_value_and_error(const std::optional<double>& value,
                                   const std::optional<double>& error_percent) {
  if (!value)
    return kMissing;
  const std::string text = format_value(*value);
  return error_percent ? fmt::format("{} ({})", text, format_error_resolved(*error_percent)) : text;
}

std::string join_meshes(const std::array<std::string, 3>& cells) {
  return fmt::format("{} / {} / {}", cells[0], cells[1], cells[2]);
}

std::string format_error_resolved(double percent) {
  if (percent == 0.0 || std::abs(percent) >= 0.01)
    return format_percent(percent);
  return with_minus_sign(fmt::format("{:+.1e} %", percent));
}

std::string with_minus_sign(std::string text) {
  return text.starts_with('-') ? "−" + text.substr(1) : text;
}

}  // namespace cs::reports
