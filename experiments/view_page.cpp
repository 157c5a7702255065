#include "view_page.hpp"

#include <viewer_assets.hpp>

#include <stdexcept>
#include <string_view>
#include <utility>

namespace ccdlab {

std::string json_for_script(const nlohmann::json& data) {
  // In JSON these characters occur only inside strings, where \uXXXX means the same: the
  // HTML parser then never sees "</script", "<!--" (its script-data escape states) or a
  // character reference, and JavaScript never sees a line terminator inside a string.
  const std::string text = data.dump();
  std::string out;
  out.reserve(text.size() + 16);
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '>') {
      out += "\\u003e";
    } else if (c == '&') {
      out += "\\u0026";
    } else if (c == '\xE2' && i + 2 < text.size() && text[i + 1] == '\x80' &&
               (text[i + 2] == '\xA8' || text[i + 2] == '\xA9')) {  // U+2028, U+2029 in UTF-8
      out += text[i + 2] == '\xA8' ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

std::string view_page(const nlohmann::json& data) {
  namespace a = viewer_assets;
  const std::string examples = std::string(a::orbit_controls_js) + "\n" + std::string(a::convex_hull_js) + "\n" +
                               std::string(a::convex_geometry_js);
  const std::string json = json_for_script(data);
  // The template's markers, each filled once; only the template is searched, never the
  // text put in (a file name in the data may hold anything).
  const std::pair<std::string_view, std::string_view> parts[] = {{"@CCDLAB_VIEW_CSS@", a::page_css},
                                                                 {"@CCDLAB_THREE@", a::three_js},
                                                                 {"@CCDLAB_THREE_EXAMPLES@", examples},
                                                                 {"@CCDLAB_VIEW_DATA@", json},
                                                                 {"@CCDLAB_VIEW_JS@", a::page_js}};
  const std::string_view tmpl = a::page_html;
  std::string page;
  page.reserve(tmpl.size() + a::three_js.size() + examples.size() + json.size() + a::page_js.size() + a::page_css.size());
  std::size_t from = 0;
  for (const auto& [marker, text] : parts) {
    const std::size_t at = tmpl.find(marker, from);
    if (at == std::string_view::npos || tmpl.find(marker, at + marker.size()) != std::string_view::npos)
      throw std::logic_error("viewer/view.html: the marker " + std::string(marker) + " must appear once, in order");
    page.append(tmpl.substr(from, at - from));
    page.append(text);
    from = at + marker.size();
  }
  page.append(tmpl.substr(from));
  return page;
}

}  // namespace ccdlab
