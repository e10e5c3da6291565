// The inspector page: one self-contained HTML file (every script and style inline, nothing
// fetched at view time) that draws an inspection (inspection.hpp) with Debian's three.js.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace exactccd::oracle {

/// Whether this build carries three.js (Debian's libjs-three, found at configure time).
bool inspector_available();
/// Throws std::runtime_error naming the package to install unless inspector_available().
void require_inspector();

/// The page for the inspection JSON `json` (inspection_json's text), every script inline; or,
/// when `scripts` is not empty, loading three.js and its camera controls from the files
/// `scripts`/three.min.js and `scripts`/orbit_controls.js (a relative URL: the pages of one
/// output folder share them; write_inspector_scripts writes them). Throws std::runtime_error
/// naming the package to install when the build has no three.js.
std::string inspector_page(const std::string& json, const std::string& scripts = "");

/// The two script files a page made with `scripts` loads: {file name, text}.
std::vector<std::pair<std::string, std::string_view>> inspector_scripts();

/// `text` escaped for HTML element content and attribute values.
std::string html_escape(const std::string& text);

}  // namespace exactccd::oracle
