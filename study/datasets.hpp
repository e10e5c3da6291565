// The study's data sets: the queries of benchmark CSV files, generated suites (per family) or
// the simulation-like set, each with the exact answer it is judged against.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "corpus/simulation_queries.hpp"
#include "exactccd/types.hpp"

namespace exactccd::study {

using Json = nlohmann::ordered_json;

/// The exact answer a query is judged against: the verdict, and when it collides the exact
/// path's tightest pair of doubles [lo, hi] around the first contact time t* (lo == hi == t*
/// when t* is a double).
struct Reference {
  bool collides = false;
  bool has_toi = false;
  double lo = 0.0, hi = 0.0;
};

/// Where a query comes from, for the examples listed in the JSON output.
struct Origin {
  std::uint32_t file = 0;   ///< index into Dataset::files
  std::uint32_t index = 0;  ///< 0-based query index in its file
};

/// A set of queries reported together: a whole data set, or one family of a generated suite.
struct Group {
  std::string name;
  bool is_family = false;  ///< from a suite manifest: the fields below are set
  std::string base, type_name, description;
  double scale = 1.0, offset = 0.0;
  Json parameters;

  std::vector<VertexFaceQuery> vertex_face;
  std::vector<Reference> vertex_face_ref;
  std::vector<Origin> vertex_face_origin;
  std::vector<EdgeEdgeQuery> edge_edge;
  std::vector<Reference> edge_edge_ref;
  std::vector<Origin> edge_edge_origin;

  std::size_t size() const { return vertex_face.size() + edge_edge.size(); }
  std::size_t contacts() const;
};

struct Dataset {
  std::string name, path;
  std::string truth_source;  ///< where the verdicts come from
  std::string toi_source;    ///< where the exact TOIs come from
  bool suite = false;
  Json suite_info;           ///< generator and seed of a suite's manifest
  std::vector<std::string> files;
  std::vector<Group> groups;
  std::size_t sidecar_files = 0, computed_files = 0;

  std::size_t size() const;
  std::size_t contacts() const;
};

/// A CSV file or a folder of them, one group. Verdicts: the truth column; exact TOIs: each
/// data_K.csv file's toi_K.csv sidecar when present, else the exact path. With a minimum
/// separation D > 0 both come from the exact path at D (truth columns and sidecars are for the
/// contact, or for the delta of their generation, so they are not read). Throws InputError (a
/// bad file, a coordinate that is not a double, no query at all) or UsageError.
Dataset load_plain(const std::string& path, const std::optional<QueryType>& type,
                   double min_separation = 0.0);

/// A generated suite (a folder with a manifest.json, corpus/suite_reader.hpp): one group per
/// family, the manifest's counts checked against the files (with D > 0 only the query counts:
/// the verdicts are the exact path's at D, as in load_plain). Throws InputError.
Dataset load_suite(const std::string& path, const std::optional<QueryType>& type,
                   double min_separation = 0.0);

/// True when `path` is a folder holding a manifest.json (a generated suite).
bool is_suite(const std::string& path);

/// The simulation-like set; verdicts and exact TOIs from the exact path (at minimum separation
/// D when D > 0). Throws UsageError for a bad configuration.
Dataset load_simulation(const sim::SimulationConfig& config, double min_separation = 0.0);

}  // namespace exactccd::study
