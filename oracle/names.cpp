#include "oracle/names.hpp"

#include <cstring>

#include "exactccd/query_file.hpp"

namespace exactccd::oracle {

std::optional<Mode> parse_mode_name(const std::string& name) {
  for (const Mode m : {Mode::float_only, Mode::filtered, Mode::exact})
    if (name == to_string(m)) return m;
  if (name == "default") return Mode::filtered;  // the name of Mode::filtered before
  return std::nullopt;
}

const std::vector<std::string>& mode_names() {
  static const std::vector<std::string> names = {
      to_string(Mode::float_only), to_string(Mode::filtered), to_string(Mode::exact)};
  return names;
}

const std::string& mode_names_text() {
  static const std::string text = std::string("\"") + to_string(Mode::float_only) + "\", \"" +
                                  to_string(Mode::filtered) + "\" or \"" +
                                  to_string(Mode::exact) + "\" (\"default\": " +
                                  to_string(Mode::filtered) + ")";
  return text;
}

const std::vector<Stage>& all_stages() {
  static const std::vector<Stage> stages = [] {
    std::vector<Stage> found;
    for (int k = 0; k < 256; ++k) {
      const Stage s = static_cast<Stage>(k);
      if (std::strcmp(to_string(s), "unknown") == 0) break;
      found.push_back(s);
    }
    return found;
  }();
  return stages;
}

std::vector<Stage> stages_of(Mode mode) {
  switch (mode) {
    case Mode::float_only: return {Stage::float_only};
    case Mode::exact: return {Stage::exact};
    case Mode::filtered: break;
  }
  std::vector<Stage> stages;
  for (const Stage s : all_stages())
    if (s != Stage::float_only) stages.push_back(s);
  return stages;
}

std::optional<QueryType> parse_type_name(const std::string& name) {
  if (name == "vf" || name == "vertex-face") return QueryType::vertex_face;
  if (name == "ee" || name == "edge-edge") return QueryType::edge_edge;
  return std::nullopt;
}

QueryType resolve_query_type(const std::string& file, const std::optional<QueryType>& forced) {
  if (forced) return *forced;
  if (const auto type = query_type_from_path(file)) return *type;
  throw InputError(file, 0,
                   "unknown query type: no 'vertex-face' or 'edge-edge' folder in the path "
                   "(pass --type vf or --type ee)");
}

}  // namespace exactccd::oracle
