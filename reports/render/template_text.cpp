#include "reports/render/template_text.hpp"

#include "reports/report_error.hpp"

namespace cs::reports {

TemplateData figure_data(const Figure& f) {
  TemplateData d;
  d.set("produced", f.produced);
  d.set("file", f.file);
  d.set("error", f.error.empty() ? "nothing to plot" : f.error);
  d.set("caption", f.caption_md);
  d.set("notes", template_list(f.notes, [](const std::string& n) { return TemplateData(n); }));
  return d;
}

std::string figure_text(const std::string& key, const TemplateData& data) {
  std::string out = render_template(templates::figure_text, TemplateData(key, data));
  std::erase(out, '\n');
  return out;
}

std::string render_template(std::string_view text, const TemplateData& data) {
  kainjow::mustache::mustache tmpl{std::string(text)};
  tmpl.set_custom_escape([](const std::string& s) { return s; });
  std::string out = tmpl.render(data);
  if (!tmpl.is_valid())
    throw ReportError("report template: " + tmpl.error_message());
  return out;
}

}  // namespace cs::reports
