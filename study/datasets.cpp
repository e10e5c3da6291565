#include "study/datasets.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstdio>
#include <filesystem>
#include <system_error>
#include <utility>

#include "corpus/suite_reader.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "oracle/common.hpp"
#include "oracle/exact_doubles.hpp"
#include "oracle/names.hpp"

namespace exactccd::study {

using namespace exactccd::oracle;

std::size_t Group::contacts() const {
  std::size_t n = 0;
  for (const Reference& r : vertex_face_ref) n += r.collides;
  for (const Reference& r : edge_edge_ref) n += r.collides;
  return n;
}

std::size_t Dataset::size() const {
  std::size_t n = 0;
  for (const Group& g : groups) n += g.size();
  return n;
}

std::size_t Dataset::contacts() const {
  std::size_t n = 0;
  for (const Group& g : groups) n += g.contacts();
  return n;
}

namespace {

namespace fs = std::filesystem;

// The exact path's result with the tightest TOI pair, for each query, in parallel; with
// min_separation D > 0, the first time within distance D (D converted to a rational exactly).
std::vector<CcdResult> exact_results(const std::vector<const RationalQuery*>& queries,
                                     double min_separation) {
  std::vector<CcdResult> results(queries.size());
  const mpq_class delta(min_separation);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, queries.size(), 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i)
                        results[i] = min_separation > 0.0 ? exact_ccd(*queries[i], delta)
                                                          : exact_ccd(*queries[i]);
                    });
  return results;
}

std::string at_min_separation(double min_separation) {
  return "exact path at minimum separation " + format_double(min_separation);
}

// Adds every query of `file` to `group`. Verdicts: the file's truth column. Exact TOIs: the
// file's sidecar when there is one, else the exact path. With min_separation D > 0, verdicts
// and TOIs both from the exact path at D.
void add_file(Dataset& d, Group& group, const std::string& file, QueryType type,
              double min_separation) {
  const QueryFile input = read_query_file(file, type);
  const auto file_id = static_cast<std::uint32_t>(d.files.size());
  d.files.push_back(file);

  std::vector<const RationalQuery*> rational;
  for (const QueryRecord& record : input.queries) rational.push_back(&record.query);
  std::vector<Reference> refs;
  const std::string sidecar = families::sidecar_path_of(file);
  std::error_code error;
  const bool has_sidecar =
      min_separation == 0.0 && !sidecar.empty() && fs::exists(sidecar, error);
  if (error) throw InputError(sidecar, 0, error.message());  // a link loop, ...
  if (min_separation > 0.0) {
    for (const CcdResult& r : exact_results(rational, min_separation))
      refs.push_back({r.collides, r.collides, r.toi_lo, r.toi_hi});
    ++d.computed_files;
  } else if (has_sidecar) {
    for (const families::SidecarLine& s : families::read_sidecar(sidecar, input))
      refs.push_back({s.collides, s.has_toi, s.toi_lo, s.toi_hi});
    ++d.sidecar_files;
  } else {
    const std::vector<CcdResult> exact = exact_results(rational, 0.0);
    for (std::size_t i = 0; i < exact.size(); ++i) {
      Reference r;
      r.collides = input.queries[i].truth;
      // A truth column that the exact path contradicts leaves the query without exact TOI; the
      // exact method's row then shows the disagreement.
      if (r.collides && exact[i].collides) {
        r.has_toi = true;
        r.lo = exact[i].toi_lo;
        r.hi = exact[i].toi_hi;
      }
      refs.push_back(r);
    }
    ++d.computed_files;
  }

  for (std::size_t i = 0; i < input.queries.size(); ++i) {
    const QueryRecord& record = input.queries[i];
    std::size_t bad_row = 0;
    const std::optional<QueryPoints> points = exact_doubles(record.query, &bad_row);
    if (!points)
      throw InputError(file, record.line_of_row(bad_row),
                       "a coordinate is not exactly a double: the study runs the double API");
    const Origin origin{file_id, static_cast<std::uint32_t>(i)};
    if (input.type == QueryType::vertex_face) {
      group.vertex_face.push_back(vertex_face_query(*points));
      group.vertex_face_ref.push_back(refs[i]);
      group.vertex_face_origin.push_back(origin);
    } else {
      group.edge_edge.push_back(edge_edge_query(*points));
      group.edge_edge_ref.push_back(refs[i]);
      group.edge_edge_origin.push_back(origin);
    }
  }
}

// The query files of a folder or file, without the generator's toi_*.csv sidecars.
std::vector<std::string> data_files(const std::string& path) {
  std::vector<std::string> files;
  for (const std::string& file : find_query_files(path))
    if (fs::path(file).filename().string().rfind("toi_", 0) != 0) files.push_back(file);
  return files;
}

std::string name_of(const std::string& path) {
  fs::path p(path);
  while (!p.empty() && p.filename().empty()) p = p.parent_path();  // a trailing '/'
  const std::string name = p.filename().string();
  return name.empty() ? path : name;
}

std::string toi_source_of(const Dataset& d, double min_separation) {
  if (min_separation > 0.0) return at_min_separation(min_separation);
  if (d.computed_files == 0) return "sidecar (exact path, at generation)";
  if (d.sidecar_files == 0) return "exact path";
  return "sidecar where present, else exact path";
}

}  // namespace

Dataset load_plain(const std::string& path, const std::optional<QueryType>& type,
                   double min_separation) {
  Dataset d;
  d.name = name_of(path);
  d.path = path;
  d.truth_source = min_separation > 0.0 ? at_min_separation(min_separation) : "truth column";
  Group group;
  group.name = d.name;
  const std::vector<std::string> files = data_files(path);
  std::vector<std::string> empty_files;
  for (const std::string& file : files) {
    const std::size_t before = group.size();
    add_file(d, group, file, resolve_query_type(file, type), min_separation);
    if (group.size() == before) empty_files.push_back(file);
  }
  require_some_queries(empty_files, files.size(), group.size());
  d.groups.push_back(std::move(group));
  d.toi_source = toi_source_of(d, min_separation);
  return d;
}

namespace {

// Adds the files of a suite's family to its group (none when the manifest counts no query and
// the folder is absent).
void add_family_files(Dataset& d, Group& g, const std::string& suite_path,
                      const std::optional<QueryType>& type, std::size_t expected,
                      double min_separation) {
  const fs::path folder = fs::path(suite_path) / g.name;
  std::error_code error;
  if (expected == 0 && !fs::exists(folder, error)) return;
  for (const std::string& file : data_files(folder.string()))
    add_file(d, g, file, resolve_query_type(file, type), min_separation);
}

}  // namespace

Dataset load_suite(const std::string& path, const std::optional<QueryType>& type,
                   double min_separation) {
  const families::SuiteManifest manifest = families::read_suite_manifest(path);
  Dataset d;
  d.name = name_of(path);
  d.path = path;
  d.suite = true;
  d.truth_source = min_separation > 0.0 ? at_min_separation(min_separation)
                                        : "truth column (exact path, at generation)";
  d.suite_info["generator"] = manifest.generator;
  d.suite_info["seed"] = manifest.seed;
  for (const families::ManifestFamily& family : manifest.families) {
    Group g;
    g.name = family.name;
    g.is_family = true;
    g.base = family.base;
    g.type_name = family.type_name;
    g.description = family.description;
    g.scale = family.scale;
    g.offset = family.offset;
    g.parameters = family.parameters;
    add_family_files(d, g, path, type, family.queries, min_separation);
    // With D > 0 the contacts are the exact path's at D, not the truth column's the manifest
    // counts: only the query count is checked.
    families::ManifestFamily counted = family;
    if (min_separation > 0.0) counted.collisions.reset();
    families::check_family_counts(manifest, counted, g.size(), g.contacts());
    d.groups.push_back(std::move(g));
  }
  d.toi_source = toi_source_of(d, min_separation);
  return d;
}

bool is_suite(const std::string& path) {
  std::error_code error;
  return fs::is_directory(path, error) && fs::exists(fs::path(path) / "manifest.json", error);
}

// The simulation-like set; verdicts and exact TOIs from the exact path (at D when D > 0).
Dataset load_simulation(const sim::SimulationConfig& config, double min_separation) {
  std::vector<sim::SimulationQuery> queries;
  try {
    queries = sim::generate_simulation_queries(config);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  std::vector<RationalQuery> rational(queries.size());
  std::vector<const RationalQuery*> pointers(queries.size());
  tbb::parallel_for(std::size_t{0}, queries.size(), [&](std::size_t i) {
    rational[i] = queries[i].type == QueryType::vertex_face
                      ? to_rational(vertex_face_query(queries[i].points))
                      : to_rational(edge_edge_query(queries[i].points));
    pointers[i] = &rational[i];
  });
  const std::vector<CcdResult> exact = exact_results(pointers, min_separation);

  Dataset d;
  d.name = "simulation";
  char path[128];
  std::snprintf(path, sizeof path, "simulation (sheet %dx%d, %d steps, seed %llu)",
                config.sheet_resolution, config.sheet_resolution, config.steps,
                static_cast<unsigned long long>(config.seed));
  d.path = path;
  d.truth_source = min_separation > 0.0 ? at_min_separation(min_separation) : "exact path";
  d.toi_source = d.truth_source;
  d.files.push_back("simulation");
  Group g;
  g.name = d.name;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Reference r{exact[i].collides, exact[i].collides, exact[i].toi_lo, exact[i].toi_hi};
    const Origin origin{0, static_cast<std::uint32_t>(i)};
    if (queries[i].type == QueryType::vertex_face) {
      g.vertex_face.push_back(vertex_face_query(queries[i].points));
      g.vertex_face_ref.push_back(r);
      g.vertex_face_origin.push_back(origin);
    } else {
      g.edge_edge.push_back(edge_edge_query(queries[i].points));
      g.edge_edge_ref.push_back(r);
      g.edge_edge_origin.push_back(origin);
    }
  }
  d.groups.push_back(std::move(g));
  return d;
}

}  // namespace exactccd::study
