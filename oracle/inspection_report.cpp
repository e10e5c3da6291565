#include "oracle/inspection_report.hpp"

#include <filesystem>
#include <system_error>

#include "oracle/common.hpp"
#include "oracle/inspector_page.hpp"

namespace exactccd::oracle {

namespace fs = std::filesystem;

InspectionFolder::InspectionFolder(std::string folder, Overwrite overwrite, std::string option)
    : folder_(std::move(folder)), overwrite_(overwrite), option_(std::move(option)) {
  require_inspector();
  std::error_code error;
  const fs::path path(folder_);
  if (fs::exists(path, error)) {
    if (!fs::is_directory(path, error))
      throw OutputError(folder_, "exists and is not a folder (" + option_ + " writes a folder of pages here)");
    if (overwrite_ == Overwrite::refuse)
      throw OutputError(folder_, "the folder exists; " + option_ +
                                     " replaces the pages in it only with --force");
  } else if (!fs::create_directories(path, error) || error) {
    throw OutputError(folder_, "cannot create the folder: " + error.message());
  }
  fs::create_directories(path / "scripts", error);
  if (error) throw OutputError((path / "scripts").string(), "cannot create: " + error.message());
  for (const auto& [name, text] : inspector_scripts())
    write_file_atomically((path / "scripts" / name).string(), text, Overwrite::replace, option_);
}

std::string InspectionFolder::add_page(const std::string& name, const std::string& json) {
  const std::string file = name + ".html";
  write_file_atomically((fs::path(folder_) / file).string(), inspector_page(json, "scripts"),
                        Overwrite::replace, option_);
  ++pages_;
  return file;
}

std::string index_page(const std::string& title, const std::string& intro,
                       const std::vector<IndexSection>& sections) {
  std::string page =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
      html_escape(title) +
      "</title>\n<style>body{font:15px/1.45 system-ui,sans-serif;margin:2em auto;max-width:70em;"
      "color:#222;padding:0 1em}h1{font-size:1.5em}h2{font-size:1.15em;margin-top:1.6em}"
      "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:.25em "
      ".6em;text-align:left;vertical-align:top}th{background:#f2f2f2}td.num{text-align:right}"
      "a{color:#0645ad}</style></head>\n<body>\n<h1>" +
      html_escape(title) + "</h1>\n<p>" + html_escape(intro) + "</p>\n";
  for (const IndexSection& s : sections) {
    page += "<h2>" + html_escape(s.heading) + "</h2>\n";
    if (!s.text.empty()) page += "<p>" + html_escape(s.text) + "</p>\n";
    if (s.columns.empty()) continue;
    page += "<table><tr>";
    for (const std::string& c : s.columns) page += "<th>" + html_escape(c) + "</th>";
    page += "</tr>\n";
    for (const IndexRow& row : s.rows) {
      page += "<tr>";
      for (std::size_t k = 0; k < row.cells.size(); ++k) {
        const std::string cell = html_escape(row.cells[k]);
        const bool link = k < row.links.size() && !row.links[k].empty();
        page += "<td>" + (link ? "<a href=\"" + html_escape(row.links[k]) + "\">" + cell + "</a>"
                               : cell) +
                "</td>";
      }
      page += "</tr>\n";
    }
    page += "</table>\n";
  }
  page += "<p>Written by exactccd. Each linked page is an inspector: open it in a browser "
          "(nothing is fetched; its scripts are in the folder).</p>\n</body></html>\n";
  return page;
}

}  // namespace exactccd::oracle
