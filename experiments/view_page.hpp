#pragma once
// The viewer page (`ccdlab view`): one self-contained HTML file, viewer/view.html with its
// style (viewer/view.css), its script (viewer/view.js), Debian's three.js and the page's
// data (experiments/view_data.hpp) put in place. The files are embedded in the program at
// build time (cmake/embed_files.cmake), so the page works from the build tree, from an
// install and offline from a file:// URL.
#include <nlohmann/json.hpp>
#include <string>

namespace ccdlab {

/// The whole page for `data` (body_view_data or cloth_view_data).
std::string view_page(const nlohmann::json& data);

/// `data` as JSON text safe inside an HTML <script> element: every `<`, `>` and `&` and the
/// line terminators U+2028 and U+2029 written as \uXXXX escapes (the same JSON value).
std::string json_for_script(const nlohmann::json& data);

}  // namespace ccdlab
