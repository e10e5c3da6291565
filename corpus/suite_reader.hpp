// Reading a generated suite (corpus_writer.hpp, `exactccd generate`, tests/data/degenerate-suite)
// back: its manifest.json and the TOI sidecars toi_K.csv next to its data_K.csv files. Both are
// checked, not trusted: every failure is an InputError naming the file (and line).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "exactccd/query_file.hpp"

namespace exactccd::families {

/// One line of a sidecar, `index,collides,toi_lo,toi_hi`: the exact path's tightest pair of
/// doubles around the first contact time when the query collides.
struct SidecarLine {
  bool collides = false;
  bool has_toi = false;  ///< collides: toi_lo <= toi_hi given
  double toi_lo = 0.0, toi_hi = 0.0;
};

/// The sidecar of `data_file` (data_K.csv): toi_K.csv in the same folder; empty when the name
/// does not follow that pattern.
std::string sidecar_path_of(const std::string& data_file);

/// Reads the sidecar `path` of `input`: one line per query, in order, `index,collides,toi_lo,
/// toi_hi` (TOI fields empty without contact; blank lines skipped), its verdicts equal to the
/// file's truth column. Throws InputError for a file that cannot be read (LineReader), a
/// malformed line, or a line count other than the query count.
std::vector<SidecarLine> read_sidecar(const std::string& path, const QueryFile& input);

/// One family entry of a manifest.
struct ManifestFamily {
  std::string name;  ///< a plain folder name of the suite
  std::string base, type_name, description;
  double scale = 1.0, offset = 0.0;
  nlohmann::ordered_json parameters;
  std::size_t queries = 0;                ///< what its files must hold
  std::optional<std::size_t> collisions;  ///< when given: the truth column's count of 1
};

struct SuiteManifest {
  std::string path;  ///< SUITE/manifest.json
  std::string generator;
  nlohmann::ordered_json seed;  ///< null when absent
  std::vector<ManifestFamily> families;
};

/// Reads SUITE/manifest.json (a regular file, through LineReader) and checks it: valid JSON, a
/// non-empty "families" array, "generator" a string when given; each family an object with a
/// "name" that is a plain folder name (no '/', not '.' or '..', no NUL) listed once, a
/// non-negative integer "queries" and, when given, "collisions". Throws InputError naming the
/// manifest.
SuiteManifest read_suite_manifest(const std::string& suite_path);

/// Throws InputError naming the manifest unless the family's files hold the manifest's query
/// count and, when it gives one, its collision count.
void check_family_counts(const SuiteManifest& manifest, const ManifestFamily& family,
                         std::size_t queries, std::size_t collisions);

}  // namespace exactccd::families
