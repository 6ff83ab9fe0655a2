#pragma once
// The report's prose lives in Mustache templates (reports/templates/*.mustache, checked and
// embedded at build time: reports/embedded_templates.hpp names each one). A page's C++ computes
// the numbers and flags that fill a template; every sentence a reader sees is in a template.
//
//   TemplateData d;
//   d.set("n_rows", "12");
//   std::string md = render_template(templates::verdict_page, d);
//
// Values are inserted verbatim (no HTML escaping: the output is Markdown).

#include <string>
#include <string_view>

#include <kainjow/mustache.hpp>

#include "reports/embedded_templates.hpp"
#include "reports/figures/plot_model.hpp"

namespace cs::reports {

using TemplateData = kainjow::mustache::data;

/// A Mustache list of `items`.
template <typename Range, typename ToData>
TemplateData template_list(const Range& items, ToData&& to_data) {
  TemplateData list{TemplateData::type::list};
  for (const auto& item : items)
    list.push_back(to_data(item));
  return list;
}

/// `text`, or false when it is empty, so that "{{#key}}…{{/key}}" shows only a non-empty text.
inline TemplateData text_or_false(const std::string& text) {
  return text.empty() ? TemplateData(false) : TemplateData(text);
}

/// A figure's fields for a template: produced, file, error ("nothing to plot" when a figure was
/// not drawn for no stated reason), caption (Markdown) and notes (a list of texts).
TemplateData figure_data(const Figure& figure);

/// One caption or note of a figure: templates/figure_text.mustache's section `key`, rendered with
/// `data`, e.g. figure_text("sweep", TemplateData("key", "fkn")).
std::string figure_text(const std::string& key, const TemplateData& data = TemplateData(true));

/// `text` (an embedded template) rendered with `data`; throws ReportError if rendering fails.
std::string render_template(std::string_view text, const TemplateData& data);

}  // namespace cs::reports
