// Folders of inspector pages: `exactccd grade --html` (the grading tables and one page per
// wrong verdict or late TOI) and `exactccd generate --html` (an index of the generated suite,
// one page per family). The pages of a folder share one copy of three.js (DIR/scripts/), so a
// folder of a hundred pages stays small; each page needs nothing outside its folder.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "oracle/output_file.hpp"

namespace exactccd::oracle {

/// A folder of inspector pages. Refuses a folder that exists (or a file in its place) unless
/// `overwrite` is replace; then pages and scripts of the same names are replaced and nothing
/// else is touched.
class InspectionFolder {
 public:
  /// `option` names the command's option in messages (e.g. "--html").
  InspectionFolder(std::string folder, Overwrite overwrite, std::string option);

  /// Writes FOLDER/`name`.html for the inspection JSON `json`; returns its file name.
  std::string add_page(const std::string& name, const std::string& json);
  const std::string& folder() const { return folder_; }
  std::size_t pages() const { return pages_; }

 private:
  std::string folder_;
  Overwrite overwrite_;
  std::string option_;
  std::size_t pages_ = 0;
};

/// One row of an index page's table: cells (HTML-escaped here) and an optional link per cell
/// (empty: none).
struct IndexRow {
  std::vector<std::string> cells;
  std::vector<std::string> links;
};

/// A section of an index page: a heading, a paragraph, a table.
struct IndexSection {
  std::string heading;
  std::string text;
  std::vector<std::string> columns;
  std::vector<IndexRow> rows;
};

/// A plain, self-contained HTML page of sections (no script).
std::string index_page(const std::string& title, const std::string& intro,
                       const std::vector<IndexSection>& sections);

}  // namespace exactccd::oracle
