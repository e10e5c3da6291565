#include "corpus/suite_reader.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

namespace exactccd::families {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// A double from a sidecar field; false for anything but one whole finite number.
bool parse_double(const std::string& text, double* value) {
  if (text.empty()) return false;
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(*value);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

// A family name of a manifest is a folder of the suite: one plain path component (no '/', not
// '.' or '..', no NUL), so that it cannot name a place outside the suite.
bool is_plain_component(const std::string& name) {
  return !name.empty() && name != "." && name != ".." &&
         name.find_first_of(std::string("/\0", 2)) == std::string::npos;
}

// The manifest's text: a regular file, read through LineReader (its limits and messages).
std::string read_manifest_text(const std::string& path) {
  LineReader in(path, "a manifest");
  std::string text, line;
  while (in.next(line)) text += line + '\n';
  return text;
}

// A non-negative integer field of a family entry; nullopt when absent.
std::optional<std::size_t> count_field(const Json& family, const char* key,
                                       const std::string& manifest_path, const std::string& name) {
  if (!family.contains(key)) return std::nullopt;
  const Json& value = family[key];
  if (!value.is_number_unsigned())
    throw InputError(manifest_path, 0,
                     "family '" + name + "': \"" + key + "\" must be a non-negative integer");
  return value.get<std::size_t>();
}

}  // namespace

std::string sidecar_path_of(const std::string& data_file) {
  const fs::path path(data_file);
  const std::string name = path.filename().string();
  if (name.rfind("data_", 0) != 0) return {};
  return (path.parent_path() / ("toi_" + name.substr(5))).string();
}

std::vector<SidecarLine> read_sidecar(const std::string& path, const QueryFile& input) {
  LineReader in(path, "a TOI sidecar");
  std::vector<SidecarLine> lines;
  std::string line;
  while (in.next(line)) {
    const std::size_t line_no = in.line_number();
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const std::vector<std::string> f = split_fields(line);
    if (f.size() != 4) throw InputError(path, line_no, "expected index,collides,toi_lo,toi_hi");
    if (f[0] != std::to_string(lines.size()))
      throw InputError(path, line_no, "expected index " + std::to_string(lines.size()));
    if (f[1] != "0" && f[1] != "1") throw InputError(path, line_no, "collides must be 0 or 1");
    SidecarLine s;
    s.collides = f[1] == "1";
    if (s.collides) {
      if (!parse_double(f[2], &s.toi_lo) || !parse_double(f[3], &s.toi_hi) ||
          !(s.toi_lo <= s.toi_hi))
        throw InputError(path, line_no, "toi_lo,toi_hi must be numbers, lo <= hi");
      s.has_toi = true;
    } else if (!f[2].empty() || !f[3].empty()) {
      throw InputError(path, line_no, "a TOI without contact");
    }
    if (lines.size() < input.queries.size() && s.collides != input.queries[lines.size()].truth)
      throw InputError(path, line_no, "collides differs from the truth column of " + input.path);
    lines.push_back(s);
  }
  if (lines.size() != input.queries.size())
    throw InputError(path, 0,
                     std::to_string(lines.size()) + " lines for " +
                         std::to_string(input.queries.size()) + " queries in " + input.path);
  return lines;
}

SuiteManifest read_suite_manifest(const std::string& suite_path) {
  SuiteManifest m;
  m.path = (fs::path(suite_path) / "manifest.json").string();
  const std::string& where = m.path;
  Json manifest;
  try {
    manifest = Json::parse(read_manifest_text(where));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where, 0, std::string("not valid JSON: ") + e.what());
  }
  if (!manifest.is_object() || !manifest.contains("families") || !manifest["families"].is_array())
    throw InputError(where, 0, "no \"families\" array");
  if (manifest["families"].empty()) throw InputError(where, 0, "the \"families\" array is empty");
  if (manifest.contains("generator") && !manifest["generator"].is_string())
    throw InputError(where, 0, "\"generator\" must be a string");
  m.generator = manifest.value("generator", "");
  m.seed = manifest.value("seed", Json());

  std::map<std::string, int> seen;
  for (const Json& family : manifest["families"]) {
    ManifestFamily f;
    try {
      f.name = family.at("name").get<std::string>();
      f.base = family.value("base", f.name);
      f.type_name = family.value("type", "");
      f.description = family.value("description", "");
      f.scale = family.value("scale", 1.0);
      f.offset = family.value("offset", 0.0);
      f.parameters = family.value("parameters", Json::object());
    } catch (const nlohmann::json::exception& e) {
      throw InputError(where, 0, std::string("bad family entry: ") + e.what());
    }
    if (!is_plain_component(f.name))
      throw InputError(where, 0,
                       "family name " + quote_for_message(f.name) +
                           " is not a plain folder name (no '/', not '.' or '..')");
    if (seen[f.name]++ > 0) throw InputError(where, 0, "family '" + f.name + "' is listed twice");
    const std::optional<std::size_t> queries = count_field(family, "queries", where, f.name);
    if (!queries) throw InputError(where, 0, "family '" + f.name + "': no \"queries\" count");
    f.queries = *queries;
    f.collisions = count_field(family, "collisions", where, f.name);
    m.families.push_back(std::move(f));
  }
  return m;
}

void check_family_counts(const SuiteManifest& manifest, const ManifestFamily& family,
                         std::size_t queries, std::size_t collisions) {
  if (queries != family.queries)
    throw InputError(manifest.path, 0,
                     "family '" + family.name + "': the manifest says " +
                         std::to_string(family.queries) + " queries, its files hold " +
                         std::to_string(queries));
  if (family.collisions && collisions != *family.collisions)
    throw InputError(manifest.path, 0,
                     "family '" + family.name + "': the manifest says " +
                         std::to_string(*family.collisions) +
                         " collisions, its truth column has " + std::to_string(collisions));
}

}  // namespace exactccd::families
