#include "bench/study/study.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "corpus/tolerance_ccd.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "oracle/common.hpp"
#include "oracle/exact_doubles.hpp"
#include "oracle/names.hpp"
#include "oracle/output_file.hpp"
#include "oracle/progress.hpp"

namespace exactccd::study {

using namespace exactccd::oracle;

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using Json = nlohmann::ordered_json;

// ---- Data sets ----------------------------------------------------------------------------------

// The exact answer a query is judged against: the verdict, and when it collides the exact
// path's tightest pair of doubles [lo, hi] around the first contact time t* (lo == hi == t*
// when t* is a double).
struct Reference {
  bool collides = false;
  bool has_toi = false;
  double lo = 0.0, hi = 0.0;
};

// Where a query comes from, for the examples listed in the JSON output.
struct Origin {
  std::uint32_t file = 0;   // index into Dataset::files
  std::uint32_t index = 0;  // 0-based query index in its file
};

// A set of queries reported together: a whole data set, or one family of a generated suite.
struct Group {
  std::string name;
  bool is_family = false;  // from a suite manifest: the fields below are set
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
  std::size_t contacts() const {
    std::size_t n = 0;
    for (const Reference& r : vertex_face_ref) n += r.collides;
    for (const Reference& r : edge_edge_ref) n += r.collides;
    return n;
  }
};

struct Dataset {
  std::string name, path;
  std::string truth_source;  // where the verdicts come from
  std::string toi_source;    // where the exact TOIs come from
  bool suite = false;
  Json suite_info;           // generator and seed of a suite's manifest
  std::vector<std::string> files;
  std::vector<Group> groups;
  std::size_t sidecar_files = 0, computed_files = 0;

  std::size_t size() const {
    std::size_t n = 0;
    for (const Group& g : groups) n += g.size();
    return n;
  }
};

// x for labels: a power of ten as 1eN (1e-6, 1e8), anything else as %g (0, 1, 0.5, 2.5e-07).
std::string short_number(double x) {
  char buffer[32];
  for (int n = -30; n <= 30; ++n) {
    if (n == 0) continue;
    std::snprintf(buffer, sizeof buffer, "1e%d", n);
    if (std::strtod(buffer, nullptr) == x) return buffer;
  }
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

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

// The generator's sidecar of data_K.csv: toi_K.csv in the same folder (empty path when the name
// does not follow that pattern).
fs::path sidecar_of(const std::string& data_file) {
  const fs::path path(data_file);
  const std::string name = path.filename().string();
  if (name.rfind("data_", 0) != 0) return {};
  return path.parent_path() / ("toi_" + name.substr(5));
}

// Reads a sidecar: one line per query, `index,collides,toi_lo,toi_hi`, TOI fields empty without
// contact. Its verdicts must equal the file's truth column.
std::vector<Reference> read_sidecar(const fs::path& path, const QueryFile& input) {
  LineReader in(path.string(), "a TOI sidecar");
  std::vector<Reference> refs;
  std::string line;
  while (in.next(line)) {
    const std::size_t line_no = in.line_number();
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    const std::vector<std::string> f = split_fields(line);
    if (f.size() != 4)
      throw InputError(path.string(), line_no, "expected index,collides,toi_lo,toi_hi");
    if (f[0] != std::to_string(refs.size()))
      throw InputError(path.string(), line_no, "expected index " + std::to_string(refs.size()));
    if (f[1] != "0" && f[1] != "1")
      throw InputError(path.string(), line_no, "collides must be 0 or 1");
    Reference r;
    r.collides = f[1] == "1";
    if (r.collides) {
      if (!parse_double(f[2], &r.lo) || !parse_double(f[3], &r.hi) || !(r.lo <= r.hi))
        throw InputError(path.string(), line_no, "toi_lo,toi_hi must be numbers, lo <= hi");
      r.has_toi = true;
    } else if (!f[2].empty() || !f[3].empty()) {
      throw InputError(path.string(), line_no, "a TOI without contact");
    }
    if (refs.size() < input.queries.size() && r.collides != input.queries[refs.size()].truth)
      throw InputError(path.string(), line_no,
                       "collides differs from the truth column of " + input.path);
    refs.push_back(r);
  }
  if (refs.size() != input.queries.size())
    throw InputError(path.string(), 0,
                     std::to_string(refs.size()) + " lines for " +
                         std::to_string(input.queries.size()) + " queries in " + input.path);
  return refs;
}

// The exact path's result with the tightest TOI pair, for each query, in parallel.
std::vector<CcdResult> exact_results(const std::vector<const RationalQuery*>& queries) {
  std::vector<CcdResult> results(queries.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, queries.size(), 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i)
                        results[i] = exact_ccd(*queries[i]);
                    });
  return results;
}

// Adds every query of `file` to `group`. Verdicts: the file's truth column. Exact TOIs: the
// file's sidecar when there is one, else the exact path.
void add_file(Dataset& d, Group& group, const std::string& file, QueryType type) {
  const QueryFile input = read_query_file(file, type);
  const auto file_id = static_cast<std::uint32_t>(d.files.size());
  d.files.push_back(file);

  std::vector<Reference> refs;
  const fs::path sidecar = sidecar_of(file);
  std::error_code error;
  const bool has_sidecar = !sidecar.empty() && fs::exists(sidecar, error);
  if (error) throw InputError(sidecar.string(), 0, error.message());  // a link loop, ...
  if (has_sidecar) {
    refs = read_sidecar(sidecar, input);
    ++d.sidecar_files;
  } else {
    std::vector<const RationalQuery*> rational;
    for (const QueryRecord& record : input.queries) rational.push_back(&record.query);
    const std::vector<CcdResult> exact = exact_results(rational);
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

std::string toi_source_of(const Dataset& d) {
  if (d.computed_files == 0) return "sidecar (exact path, at generation)";
  if (d.sidecar_files == 0) return "exact path";
  return "sidecar where present, else exact path";
}

Dataset load_plain(const std::string& path, const std::optional<QueryType>& type) {
  Dataset d;
  d.name = name_of(path);
  d.path = path;
  d.truth_source = "truth column";
  Group group;
  group.name = d.name;
  const std::vector<std::string> files = data_files(path);
  std::vector<std::string> empty_files;
  for (const std::string& file : files) {
    const std::size_t before = group.size();
    add_file(d, group, file, resolve_query_type(file, type));
    if (group.size() == before) empty_files.push_back(file);
  }
  require_some_queries(empty_files, files.size(), group.size());
  d.groups.push_back(std::move(group));
  d.toi_source = toi_source_of(d);
  return d;
}

// A family name of a manifest is a folder of the suite: one plain path component (no '/', not
// '.' or '..', no NUL), so that it cannot name a place outside the suite.
bool is_plain_component(const std::string& name) {
  return !name.empty() && name != "." && name != ".." &&
         name.find_first_of(std::string("/\0", 2)) == std::string::npos;
}

// The manifest's text: a regular file, read through LineReader (its limits and messages).
std::string read_manifest_text(const fs::path& path) {
  LineReader in(path.string(), "a manifest");
  std::string text, line;
  while (in.next(line)) text += line + '\n';
  return text;
}

// A non-negative integer field of a family entry; nullopt when absent.
std::optional<std::size_t> count_field(const Json& family, const char* key,
                                       const fs::path& manifest_path, const std::string& name) {
  if (!family.contains(key)) return std::nullopt;
  const Json& value = family[key];
  if (!value.is_number_unsigned())
    throw InputError(manifest_path.string(), 0,
                     "family '" + name + "': \"" + key + "\" must be a non-negative integer");
  return value.get<std::size_t>();
}

// A generated suite: one group per family of its manifest. The manifest is checked, not
// trusted: a non-empty "families" array; each name a plain folder name, listed once; each
// family's "queries" (required) and "collisions" (when given) equal to what its files hold.
Dataset load_suite(const std::string& path, const std::optional<QueryType>& type) {
  const fs::path manifest_path = fs::path(path) / "manifest.json";
  const std::string where = manifest_path.string();
  Json manifest;
  try {
    manifest = Json::parse(read_manifest_text(manifest_path));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where, 0, std::string("not valid JSON: ") + e.what());
  }
  if (!manifest.is_object() || !manifest.contains("families") || !manifest["families"].is_array())
    throw InputError(where, 0, "no \"families\" array");
  if (manifest["families"].empty()) throw InputError(where, 0, "the \"families\" array is empty");

  Dataset d;
  d.name = name_of(path);
  d.path = path;
  d.suite = true;
  d.truth_source = "truth column (exact path, at generation)";
  if (manifest.contains("generator") && !manifest["generator"].is_string())
    throw InputError(where, 0, "\"generator\" must be a string");
  d.suite_info["generator"] = manifest.value("generator", "");
  d.suite_info["seed"] = manifest.value("seed", Json());
  std::map<std::string, int> seen;
  for (const Json& family : manifest["families"]) {
    Group g;
    try {
      g.name = family.at("name").get<std::string>();
      g.is_family = true;
      g.base = family.value("base", g.name);
      g.type_name = family.value("type", "");
      g.description = family.value("description", "");
      g.scale = family.value("scale", 1.0);
      g.offset = family.value("offset", 0.0);
      g.parameters = family.value("parameters", Json::object());
    } catch (const nlohmann::json::exception& e) {
      throw InputError(where, 0, std::string("bad family entry: ") + e.what());
    }
    if (!is_plain_component(g.name))
      throw InputError(where, 0,
                       "family name " + quote_for_message(g.name) +
                           " is not a plain folder name (no '/', not '.' or '..')");
    if (seen[g.name]++ > 0)
      throw InputError(where, 0, "family '" + g.name + "' is listed twice");
    const std::optional<std::size_t> expected = count_field(family, "queries", manifest_path, g.name);
    if (!expected)
      throw InputError(where, 0, "family '" + g.name + "': no \"queries\" count");
    const std::optional<std::size_t> collisions =
        count_field(family, "collisions", manifest_path, g.name);
    const fs::path folder = fs::path(path) / g.name;
    std::error_code error;
    if (!(*expected == 0 && !fs::exists(folder, error)))
      for (const std::string& file : data_files(folder.string()))
        add_file(d, g, file, resolve_query_type(file, type));
    if (g.size() != *expected)
      throw InputError(where, 0,
                       "family '" + g.name + "': the manifest says " + std::to_string(*expected) +
                           " queries, its files hold " + std::to_string(g.size()));
    if (collisions && g.contacts() != *collisions)
      throw InputError(where, 0,
                       "family '" + g.name + "': the manifest says " +
                           std::to_string(*collisions) + " collisions, its truth column has " +
                           std::to_string(g.contacts()));
    d.groups.push_back(std::move(g));
  }
  d.toi_source = toi_source_of(d);
  return d;
}

// The simulation-like set; verdicts and exact TOIs from the exact path.
Dataset load_simulation(const sim::SimulationConfig& config) {
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
  const std::vector<CcdResult> exact = exact_results(pointers);

  Dataset d;
  d.name = "simulation";
  char path[128];
  std::snprintf(path, sizeof path, "simulation (sheet %dx%d, %d steps, seed %llu)",
                config.sheet_resolution, config.sheet_resolution, config.steps,
                static_cast<unsigned long long>(config.seed));
  d.path = path;
  d.truth_source = "exact path";
  d.toi_source = "exact path";
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

// ---- Methods ------------------------------------------------------------------------------------

enum class Kind { float_only, tolerance, filtered, exact };

struct Method {
  Kind kind = Kind::filtered;
  double parameter = 0.0;  // tolerance: eps; filtered: the TOI width
  std::string name;        // float_only, tolerance, default, exact
  std::string setting;     // eps=1e-9, width=0, or empty
  bool certified = false;

  std::string label() const { return setting.empty() ? name : name + " " + setting; }
};

std::vector<Method> methods_of(const StudyOptions& options) {
  std::vector<Method> methods;
  methods.push_back({Kind::float_only, 0.0, "float_only", "", false});
  for (const double eps : options.tolerances)
    methods.push_back({Kind::tolerance, eps, "tolerance", "eps=" + short_number(eps), false});
  for (const double width : options.widths)
    methods.push_back({Kind::filtered, width, "default", "width=" + short_number(width), true});
  methods.push_back({Kind::exact, 0.0, "exact", "", true});
  return methods;
}

// Calls f(decide_vertex_face, decide_edge_edge) with the method's two deciders, so that the
// timed loops call them directly, with no per-query dispatch on the method.
template <class F>
auto with_method(const Method& m, F&& f) {
  CcdOptions options;
  switch (m.kind) {
    case Kind::tolerance: {
      const double eps = m.parameter;
      return f(
          [eps](const VertexFaceQuery& q) { return methods::tolerance_vertex_face_ccd(q, eps); },
          [eps](const EdgeEdgeQuery& q) { return methods::tolerance_edge_edge_ccd(q, eps); });
    }
    case Kind::float_only: options.mode = Mode::float_only; break;
    case Kind::filtered:
      options.mode = Mode::filtered;
      options.toi_width = m.parameter;
      break;
    case Kind::exact: options.mode = Mode::exact; break;
  }
  return f([options](const VertexFaceQuery& q) { return vertex_face_ccd(q, options); },
           [options](const EdgeEdgeQuery& q) { return edge_edge_ccd(q, options); });
}

// ---- Measurement --------------------------------------------------------------------------------

constexpr std::size_t kMaxExamples = 5;

// One method's results on a set of queries; `add` merges sets.
struct Outcome {
  std::size_t queries = 0, collisions = 0, false_positives = 0, false_negatives = 0;
  std::size_t late = 0, true_positives = 0;
  std::vector<double> toi_errors;  // signed, over true positives with an exact TOI
  std::vector<double> late_errors;  // the toi errors of the late TOIs (>= 0)
  double total_ns = 0.0;           // mean ns per query times queries
  std::vector<std::string> fp_examples, fn_examples, late_examples;

  void add(const Outcome& o) {
    queries += o.queries;
    collisions += o.collisions;
    false_positives += o.false_positives;
    false_negatives += o.false_negatives;
    late += o.late;
    true_positives += o.true_positives;
    toi_errors.insert(toi_errors.end(), o.toi_errors.begin(), o.toi_errors.end());
    late_errors.insert(late_errors.end(), o.late_errors.begin(), o.late_errors.end());
    total_ns += o.total_ns;
    for (auto [to, from] : {std::pair{&fp_examples, &o.fp_examples},
                            std::pair{&fn_examples, &o.fn_examples},
                            std::pair{&late_examples, &o.late_examples}})
      for (const std::string& e : *from)
        if (to->size() < kMaxExamples) to->push_back(e);
  }
  double mean_ns() const { return queries == 0 ? 0.0 : total_ns / static_cast<double>(queries); }
  bool clean() const { return false_positives == 0 && false_negatives == 0 && late == 0; }
};

// The signed TOI error of a reported toi against the exact pair [lo, hi]: 0 inside it, else the
// distance to the nearer end (positive: later). Resolution one ulp: a toi equal to hi > lo is
// late (t* < hi) with error 0.
double toi_error(double toi, const Reference& ref) {
  if (toi < ref.lo) return toi - ref.lo;
  if (toi > ref.hi) return toi - ref.hi;
  return 0.0;
}

void judge(const CcdResult& r, const Reference& ref, Outcome& o, const Dataset& d,
           const Origin& origin) {
  auto where = [&] { return d.files[origin.file] + ":" + std::to_string(origin.index); };
  ++o.queries;
  o.collisions += r.collides;
  if (r.collides && !ref.collides) {
    if (o.false_positives++ < kMaxExamples) o.fp_examples.push_back(where());
  } else if (!r.collides && ref.collides) {
    if (o.false_negatives++ < kMaxExamples) o.fn_examples.push_back(where());
  } else if (r.collides) {
    ++o.true_positives;
    if (!ref.has_toi) return;
    // A conservative method reports toi_lo <= t*; for a double, toi <= t* iff toi <= lo.
    const double error = toi_error(r.toi_lo, ref);
    o.toi_errors.push_back(error);
    if (r.toi_lo > ref.lo) {
      o.late_errors.push_back(error);
      if (o.late++ < kMaxExamples) o.late_examples.push_back(where());
    }
  }
}

double median_of(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  return 0.5 * (*std::max_element(values.begin(), values.begin() + mid) + upper);
}

double nanoseconds(Clock::duration d) {
  return static_cast<double>(std::chrono::duration_cast<std::chrono::nanoseconds>(d).count());
}

volatile std::size_t g_sink;  // keeps the timed passes' results observable

// Shortest timed sample: small groups are passed over several times per clock reading pair, so
// that the clock's own cost (tens of ns) stays below about 0.1% of a sample.
constexpr double kMinSampleNs = 200e3;

// One untimed pass for the verdicts, then `repetitions` timed samples of whole passes (single
// thread, one clock reading pair per sample); mean time: the median sample / queries.
Outcome measure(const Dataset& d, const Group& g, const Method& m, int repetitions) {
  return with_method(m, [&](auto&& decide_vertex_face, auto&& decide_edge_edge) {
    Outcome o;
    const auto verdict_start = Clock::now();
    for (std::size_t i = 0; i < g.vertex_face.size(); ++i)
      judge(decide_vertex_face(g.vertex_face[i]), g.vertex_face_ref[i], o, d,
            g.vertex_face_origin[i]);
    for (std::size_t i = 0; i < g.edge_edge.size(); ++i)
      judge(decide_edge_edge(g.edge_edge[i]), g.edge_edge_ref[i], o, d, g.edge_edge_origin[i]);
    const double first_pass_ns = nanoseconds(Clock::now() - verdict_start);
    if (g.size() == 0) return o;

    const int passes =
        static_cast<int>(std::max(1.0, std::ceil(kMinSampleNs / std::max(first_pass_ns, 1.0))));
    std::vector<double> samples;
    for (int rep = 0; rep < repetitions; ++rep) {
      std::size_t collisions = 0;
      const auto start = Clock::now();
      for (int pass = 0; pass < passes; ++pass) {
        for (const VertexFaceQuery& q : g.vertex_face) collisions += decide_vertex_face(q).collides;
        for (const EdgeEdgeQuery& q : g.edge_edge) collisions += decide_edge_edge(q).collides;
      }
      const auto stop = Clock::now();
      g_sink = collisions;
      samples.push_back(nanoseconds(stop - start) / (static_cast<double>(passes) * g.size()));
    }
    o.total_ns = median_of(samples) * static_cast<double>(g.size());
    return o;
  });
}

// ---- Reports ------------------------------------------------------------------------------------

struct ErrorStats {
  double max_abs = 0.0, median_abs = 0.0, median = 0.0, max_late_by = 0.0, max_early_by = 0.0;
};

// Late TOIs by how late: the upper ends of the bins (a late toi equal to the exact pair's upper
// end has error 0: less than one ulp late).
constexpr double kLateBins[] = {1e-15, 1e-12, 1e-9, 1e-6, 1e-3};

Json late_histogram(const Outcome& o) {
  std::vector<std::size_t> counts(std::size(kLateBins) + 1, 0);
  for (const double e : o.late_errors) {
    std::size_t k = 0;
    while (k < std::size(kLateBins) && e > kLateBins[k]) ++k;
    ++counts[k];
  }
  Json j;
  for (std::size_t k = 0; k < std::size(kLateBins); ++k)
    j["<=" + short_number(kLateBins[k])] = counts[k];
  j[">" + short_number(kLateBins[std::size(kLateBins) - 1])] = counts.back();
  return j;
}

ErrorStats error_stats(const Outcome& o) {
  ErrorStats s;
  std::vector<double> abs_errors;
  for (const double e : o.toi_errors) {
    abs_errors.push_back(std::abs(e));
    s.max_abs = std::max(s.max_abs, std::abs(e));
    s.max_late_by = std::max(s.max_late_by, e);
    s.max_early_by = std::max(s.max_early_by, -e);
  }
  s.median_abs = median_of(abs_errors);
  s.median = median_of(o.toi_errors);
  return s;
}

// A breakdown key of a suite's families: coordinate scale and translation.
struct ScaleKey {
  double offset = 0.0, scale = 1.0;
  bool operator<(const ScaleKey& k) const {
    return offset != k.offset ? offset < k.offset : scale < k.scale;
  }
  std::string label() const {
    if (offset == 0.0) return "scale " + short_number(scale);
    return "offset " + short_number(offset) + (scale == 1.0 ? "" : " scale " + short_number(scale));
  }
};

// Results of one data set: per group and method, and the merged views.
struct DatasetResults {
  const Dataset* dataset = nullptr;
  std::vector<std::vector<Outcome>> by_group;  // [group][method]
  std::vector<Outcome> total;                  // [method]
  std::map<ScaleKey, std::vector<Outcome>> by_scale;
  std::map<ScaleKey, std::pair<std::size_t, std::size_t>> scale_counts;  // queries, contacts
  // Per base family (a family and its scaled / translated variants), in manifest order.
  std::vector<std::string> bases;
  std::map<std::string, std::vector<Outcome>> by_base;
  std::map<std::string, std::pair<std::size_t, std::size_t>> base_counts;
  std::map<std::string, std::string> base_type;
};

DatasetResults run_dataset(const Dataset& d, const std::vector<Method>& methods,
                           int repetitions) {
  DatasetResults r;
  r.dataset = &d;
  r.total.assign(methods.size(), Outcome{});
  Progress progress;
  for (std::size_t k = 0; k < d.groups.size(); ++k) {
    const Group& g = d.groups[k];
    std::vector<Outcome> outcomes;
    for (std::size_t m = 0; m < methods.size(); ++m) {
      progress.update(k, d.groups.size(), d.name + " " + g.name + " " + methods[m].label(), m,
                      methods.size());
      outcomes.push_back(measure(d, g, methods[m], repetitions));
      r.total[m].add(outcomes.back());
    }
    if (d.suite) {
      const ScaleKey key{g.offset, g.scale};
      auto& merged = r.by_scale[key];
      if (merged.empty()) merged.assign(methods.size(), Outcome{});
      for (std::size_t m = 0; m < methods.size(); ++m) merged[m].add(outcomes[m]);
      r.scale_counts[key].first += g.size();
      r.scale_counts[key].second += g.contacts();
      auto& base = r.by_base[g.base];
      if (base.empty()) {
        base.assign(methods.size(), Outcome{});
        r.bases.push_back(g.base);
        r.base_type[g.base] = g.type_name;
      }
      for (std::size_t m = 0; m < methods.size(); ++m) base[m].add(outcomes[m]);
      r.base_counts[g.base].first += g.size();
      r.base_counts[g.base].second += g.contacts();
    }
    r.by_group.push_back(std::move(outcomes));
  }
  return r;
}

Json outcome_json(const Outcome& o, const Method& m) {
  const ErrorStats s = error_stats(o);
  Json j;
  j["method"] = m.name;
  j["setting"] = m.setting;
  j["label"] = m.label();
  j["parameter"] = m.parameter;
  j["certified"] = m.certified;
  j["queries"] = o.queries;
  j["collisions"] = o.collisions;
  j["false_positives"] = o.false_positives;
  j["false_negatives"] = o.false_negatives;
  j["late_tois"] = o.late;
  j["true_positives"] = o.true_positives;
  j["toi_errors_measured"] = o.toi_errors.size();
  j["max_abs_toi_error"] = s.max_abs;
  j["median_abs_toi_error"] = s.median_abs;
  j["median_toi_error"] = s.median;
  j["max_late_by"] = s.max_late_by;
  j["max_early_by"] = s.max_early_by;
  j["late_by"] = late_histogram(o);
  j["mean_ns"] = o.mean_ns();
  j["examples"] = {{"false_positives", o.fp_examples},
                   {"false_negatives", o.fn_examples},
                   {"late_tois", o.late_examples}};
  return j;
}

Json methods_json(const std::vector<Outcome>& outcomes, const std::vector<Method>& methods) {
  Json a = Json::array();
  for (std::size_t m = 0; m < methods.size(); ++m)
    a.push_back(outcome_json(outcomes[m], methods[m]));
  return a;
}

std::size_t contacts_of(const Dataset& d) {
  std::size_t n = 0;
  for (const Group& g : d.groups) n += g.contacts();
  return n;
}

Json study_json(const std::vector<DatasetResults>& results, const std::vector<Method>& methods,
                const StudyOptions& options) {
  Json j;
  j["command"] = "exactccd study";
  j["timing"] = {{"threads", 1},
                 {"repetitions", options.repetitions},
                 {"min_sample_ns", kMinSampleNs},
                 {"mean_ns", "median over the repetitions of (sample time / queries decided in "
                             "it); a sample is one or more whole passes over a group"}};
  j["toi_error"] =
      "reported toi (toi_lo for an enclosure) minus the exact first contact time t*, as its "
      "signed distance to the exact path's tightest pair [lo, hi]; late: toi > lo (t* < toi)";
  Json datasets = Json::array();
  for (const DatasetResults& r : results) {
    const Dataset& d = *r.dataset;
    Json dj;
    dj["name"] = d.name;
    dj["path"] = d.path;
    dj["queries"] = d.size();
    dj["contacts"] = contacts_of(d);
    dj["truth"] = d.truth_source;
    dj["exact_toi"] = d.toi_source;
    dj["methods"] = methods_json(r.total, methods);
    if (d.suite) {
      dj["suite"] = d.suite_info;
      Json families = Json::array();
      for (std::size_t k = 0; k < d.groups.size(); ++k) {
        const Group& g = d.groups[k];
        Json fj;
        fj["name"] = g.name;
        fj["base"] = g.base;
        fj["type"] = g.type_name;
        fj["scale"] = g.scale;
        fj["offset"] = g.offset;
        fj["description"] = g.description;
        fj["parameters"] = g.parameters;
        fj["queries"] = g.size();
        fj["contacts"] = g.contacts();
        fj["methods"] = methods_json(r.by_group[k], methods);
        families.push_back(std::move(fj));
      }
      dj["families"] = std::move(families);
      Json scales = Json::array();
      for (const auto& [key, outcomes] : r.by_scale) {
        Json sj;
        sj["label"] = key.label();
        sj["scale"] = key.scale;
        sj["offset"] = key.offset;
        sj["queries"] = r.scale_counts.at(key).first;
        sj["contacts"] = r.scale_counts.at(key).second;
        sj["methods"] = methods_json(outcomes, methods);
        scales.push_back(std::move(sj));
      }
      dj["scales"] = std::move(scales);
      Json bases = Json::array();
      for (const std::string& base : r.bases) {
        Json bj;
        bj["base"] = base;
        bj["type"] = r.base_type.at(base);
        bj["queries"] = r.base_counts.at(base).first;
        bj["contacts"] = r.base_counts.at(base).second;
        bj["methods"] = methods_json(r.by_base.at(base), methods);
        bases.push_back(std::move(bj));
      }
      dj["bases"] = std::move(bases);
    }
    datasets.push_back(std::move(dj));
  }
  j["datasets"] = std::move(datasets);
  return j;
}

std::string format_error(double e) {
  if (e == 0.0) return "0";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2e", e);
  return buffer;
}

std::string markdown_escape(std::string s) {
  std::string out;
  for (const char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

// One row per method: time, errors.
void summary_markdown(std::ostream& out, const std::vector<Outcome>& outcomes,
                      const std::vector<Method>& methods) {
  out << "| method | mean ns/query | false positives | false negatives | late TOIs | "
         "max \\|TOI error\\| | median \\|TOI error\\| | max late by |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const Outcome& o = outcomes[m];
    const ErrorStats s = error_stats(o);
    char ns[32];
    std::snprintf(ns, sizeof ns, "%.1f", o.mean_ns());
    out << "| " << markdown_escape(methods[m].label())
        << (methods[m].certified ? " (certified)" : "") << " | " << ns << " | " << o.false_positives << " | " << o.false_negatives << " | "
        << o.late << " | " << format_error(s.max_abs) << " | " << format_error(s.median_abs)
        << " | " << format_error(s.max_late_by) << " |\n";
  }
}

// One row per family or scale, one `FP / FN / late` cell per method.
void breakdown_header(std::ostream& out, const std::string& first,
                      const std::vector<std::string>& extra, const std::vector<Method>& methods) {
  out << "| " << first;
  for (const std::string& e : extra) out << " | " << e;
  for (const Method& m : methods) out << " | " << markdown_escape(m.label());
  out << " |\n|---";
  for (std::size_t k = 0; k < extra.size(); ++k) out << "|---:";
  for (std::size_t k = 0; k < methods.size(); ++k) out << "|:---:";
  out << "|\n";
}

void breakdown_cells(std::ostream& out, const std::vector<Outcome>& outcomes) {
  for (const Outcome& o : outcomes)
    out << " | " << o.false_positives << " / " << o.false_negatives << " / " << o.late;
  out << " |\n";
}

void study_markdown(std::ostream& out, const std::vector<DatasetResults>& results,
                    const std::vector<Method>& methods) {
  for (const DatasetResults& r : results) {
    const Dataset& d = *r.dataset;
    out << "### " << markdown_escape(d.name) << "\n\n"
        << d.size() << " queries, " << contacts_of(d) << " with contact; `" << d.path
        << "`; verdicts: " << d.truth_source << "; exact TOIs: " << d.toi_source << ".\n\n";
    summary_markdown(out, r.total, methods);
    out << '\n';
    if (!d.suite) continue;
    out << "#### " << markdown_escape(d.name)
        << " per coordinate scale and translation (false positives / false negatives / late "
           "TOIs)\n\n";
    breakdown_header(out, "variant", {"queries", "contacts"}, methods);
    for (const auto& [key, outcomes] : r.by_scale) {
      const auto& counts = r.scale_counts.at(key);
      out << "| " << key.label() << " | " << counts.first << " | " << counts.second;
      breakdown_cells(out, outcomes);
    }
    out << "\n#### " << markdown_escape(d.name)
        << " per base family, all scales and translations together (false positives / false "
           "negatives / late TOIs)\n\n";
    breakdown_header(out, "base family", {"type", "queries", "contacts"}, methods);
    for (const std::string& base : r.bases) {
      const auto& counts = r.base_counts.at(base);
      out << "| " << markdown_escape(base) << " | " << r.base_type.at(base) << " | "
          << counts.first << " | " << counts.second;
      breakdown_cells(out, r.by_base.at(base));
    }
    out << "\n#### " << markdown_escape(d.name)
        << " per family (false positives / false negatives / late TOIs)\n\n";
    breakdown_header(out, "family", {"type", "queries", "contacts"}, methods);
    for (std::size_t k = 0; k < d.groups.size(); ++k) {
      const Group& g = d.groups[k];
      out << "| " << markdown_escape(g.name) << " | " << g.type_name << " | " << g.size() << " | "
          << g.contacts();
      breakdown_cells(out, r.by_group[k]);
    }
    out << '\n';
  }
}

}  // namespace

int run_study(const StudyOptions& options) {
  if (options.repetitions < 1) throw UsageError("--repetitions must be at least 1");
  if (options.paths.empty() && !options.simulation)
    throw UsageError("no data set: give a PATH or --simulation");
  for (const double w : options.widths)
    if (!(w >= 0.0 && std::isfinite(w)))
      throw UsageError("--widths: every width must be finite and >= 0, got " + format_double(w));
  for (const double eps : options.tolerances)
    if (!(eps >= 0.0 && std::isfinite(eps)))
      throw UsageError("--eps: every eps must be finite and >= 0, got " + format_double(eps));

  // Opened before the work, so that an unwritable --out-md fails at once.
  std::optional<OutputFile> md_file;
  if (!options.out_md.empty())
    md_file.emplace(options.out_md, options.force ? Overwrite::replace : Overwrite::refuse,
                    "--out-md");

  std::vector<Dataset> datasets;
  for (const std::string& path : options.paths) {
    std::error_code error;
    const bool suite = fs::is_directory(path, error) &&
                       fs::exists(fs::path(path) / "manifest.json", error);
    datasets.push_back(suite ? load_suite(path, options.type) : load_plain(path, options.type));
  }
  if (options.simulation) datasets.push_back(load_simulation(options.simulation_config));
  // Distinct names: the report names its plots after them.
  std::map<std::string, int> seen;
  for (Dataset& d : datasets)
    if (++seen[d.name] > 1) d.name += "-" + std::to_string(seen[d.name]);

  const std::vector<Method> methods = methods_of(options);
  std::vector<DatasetResults> results;
  for (const Dataset& d : datasets) results.push_back(run_dataset(d, methods, options.repetitions));

  if (options.json)
    std::cout << study_json(results, methods, options).dump(2) << '\n';
  else
    study_markdown(std::cout, results, methods);
  if (md_file) {
    std::ostringstream markdown;
    study_markdown(markdown, results, methods);
    md_file->write(markdown.str());
    md_file->commit();
  }

  for (const DatasetResults& r : results)
    for (std::size_t m = 0; m < methods.size(); ++m)
      if (methods[m].certified && !r.total[m].clean()) return kExitDisagree;
  return kExitAgree;
}

}  // namespace exactccd::study
