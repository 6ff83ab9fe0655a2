#include "reports/render/template_text.hpp"

#include "reports/report_error.hpp"

namespace cs::reports {

std::string render_template(std::string_view text, const TemplateData& data) {
  kainjow::mustache::mustache tmpl{std::string(text)};
  tmpl.set_custom_escape([](const std::string& s) { return s; });
  std::string out = tmpl.render(data);
  if (!tmpl.is_valid())
    throw ReportError("report template: " + tmpl.error_message());
  return out;
}

}  // namespace cs::reports
