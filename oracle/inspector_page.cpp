#include "oracle/inspector_page.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>
#include <string_view>

namespace exactccd::oracle {

// Generated at build time by cmake/embed_text_assets.cmake from oracle/inspector/inspector.html
// and Debian's libjs-three (empty when the package was missing).
namespace assets {
extern const std::string_view inspector_html;
extern const std::string_view three_js;
extern const std::string_view orbit_controls_js;
}  // namespace assets

namespace {

// Where `marker` appears in the template: exactly once.
std::size_t marker_at(std::string_view page, std::string_view marker) {
  const std::size_t at = page.find(marker);
  if (at == std::string_view::npos || page.find(marker, at + 1) != std::string_view::npos)
    throw std::logic_error("inspector template: marker " + std::string(marker) +
                           " must appear exactly once");
  return at;
}

// JSON inside <script>: "</script" would end the element early and "<!--" would change how
// the HTML parser reads it; '<' occurs in JSON only inside strings, where \u003c means the same.
std::string script_safe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (char c : json) {
    if (c == '<')
      out += "\\u003c";
    else
      out += c;
  }
  return out;
}

}  // namespace

bool inspector_available() {
  return !assets::three_js.empty() && !assets::orbit_controls_js.empty();
}

void require_inspector() {
  if (!inspector_available())
    throw std::runtime_error(
        "this build has no three.js for the inspector page: install Debian's libjs-three "
        "(bash .ci/install-deps.sh), then configure (cmake -S . -B build) and build again");
}

std::vector<std::pair<std::string, std::string_view>> inspector_scripts() {
  return {{"three.min.js", assets::three_js}, {"orbit_controls.js", assets::orbit_controls_js}};
}

std::string inspector_page(const std::string& json, const std::string& scripts) {
  require_inspector();
  // The template holds each script as <script>/*@NAME@*/</script>: inline, the marker becomes
  // the script's text; linked, the whole element becomes <script src="...">.
  auto script = [&](std::string_view text, const std::string& file) {
    return scripts.empty() ? "<script>" + std::string(text) + "</script>"
                           : "<script src=\"" + html_escape(scripts + "/" + file) + "\"></script>";
  };
  // Markers are found in the template and filled from the last to the first, so that the
  // text filled in (a file name in the data, say) is never searched for markers.
  struct Fill {
    std::string_view marker;
    std::string text;
    std::size_t at;
  };
  const std::string_view page_template = assets::inspector_html;
  std::vector<Fill> fills;
  for (auto [marker, text] :
       {std::pair<std::string_view, std::string>{"@DATA_JSON@", script_safe(json)},
        {"<script>/*@ORBIT_CONTROLS_JS@*/</script>",
         script(assets::orbit_controls_js, "orbit_controls.js")},
        {"<script>/*@THREE_JS@*/</script>", script(assets::three_js, "three.min.js")}})
    fills.push_back({marker, std::move(text), marker_at(page_template, marker)});
  std::sort(fills.begin(), fills.end(), [](const Fill& a, const Fill& b) { return a.at > b.at; });
  std::string page(page_template);
  for (const Fill& f : fills) page.replace(f.at, f.marker.size(), f.text);
  return page;
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace exactccd::oracle
