// `exactccd check --type pe|pe2d|pp|pp2d|pl`: the point kinds and the plane (query_file.hpp,
// PrimitiveKind), each query decided by its own function and compared with the truth column.
#include <chrono>

#include "exact/arithmetic/rational.hpp"
#include "exactccd/ccd.hpp"
#include "corpus/point_families.hpp"
#include "oracle/check.hpp"

namespace exactccd::oracle {

namespace {

/// The edge-edge query that a point-edge or point-point query is (proofs/api_reductions.md,
/// point-primitives): each point the zero-length segment [p, p], rows copied.
RationalQuery as_edge_edge(const PrimitiveQueryRecord& r, PrimitiveKind kind) {
  static constexpr int kPointEdge[8] = {0, 0, 1, 2, 3, 3, 4, 5};
  static constexpr int kPointPoint[8] = {0, 0, 1, 1, 2, 2, 3, 3};
  const bool pe = kind == PrimitiveKind::point_edge || kind == PrimitiveKind::point_edge_2d;
  RationalQuery q{QueryType::edge_edge, {}};
  for (int i = 0; i < 8; ++i) q.points[i] = r.points[(pe ? kPointEdge : kPointPoint)[i]];
  return q;
}

CcdResult decide(const PrimitiveQueryFile& file, const PrimitiveQueryRecord& r,
                 const CcdOptions& options, double* seconds) {
  std::vector<Eigen::Vector3d> x(r.points.size());
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const RationalPoint& p = r.points[i];
    if (!exact::to_double_exactly(p.x, &x[i].x()) || !exact::to_double_exactly(p.y, &x[i].y()) ||
        !exact::to_double_exactly(p.z, &x[i].z())) {
      if (file.kind == PrimitiveKind::point_plane)
        throw InputError(file.path, r.first_line + i,
                         "a coordinate is not exactly a double: point-plane queries are "
                         "decided on doubles only");
      if (options.mode != Mode::exact)
        throw InputError(file.path, r.first_line + i,
                         std::string("a coordinate is not exactly a double: only --mode exact "
                                     "decides such queries (--mode ") +
                             to_string(options.mode) + ")");
      const auto start = std::chrono::steady_clock::now();
      const CcdResult result = exact_ccd(as_edge_edge(r, file.kind), options);
      *seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return result;
    }
  }
  const auto start = std::chrono::steady_clock::now();
  CcdResult result;
  try {
    result = families::decide_point_query(file.kind, x, options);
  } catch (const std::invalid_argument& e) {  // a zero normal: the file's fault, at its line
    if (file.kind != PrimitiveKind::point_plane) throw;
    throw InputError(file.path, r.first_line, e.what());
  }
  *seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

QueryFile as_edge_edge_file(const PrimitiveQueryFile& file) {
  if (file.kind == PrimitiveKind::point_plane)
    throw InputError(file.path, 0,
                     "point-plane queries (--type pl) are not edge-edge queries");
  QueryFile out{file.path, QueryType::edge_edge, {}};
  out.queries.reserve(file.queries.size());
  for (const PrimitiveQueryRecord& r : file.queries) {
    QueryRecord record;
    record.query = as_edge_edge(r, file.kind);
    record.truth = r.truth;
    record.first_line = r.first_line;
    out.queries.push_back(std::move(record));
  }
  return out;
}

CheckTally check_primitive_file(const std::string& path, PrimitiveKind kind,
                                const CheckSettings& settings, const CheckVisitor& on_query) {
  const PrimitiveQueryFile input = read_primitive_query_file(path, kind);
  CcdOptions options;
  options.t_max = settings.t_max;
  options.mode = settings.mode;
  options.min_separation = settings.min_separation;
  CheckTally tally;
  tally.file = input.path;
  for (std::size_t i = 0; i < input.queries.size(); ++i) {
    const PrimitiveQueryRecord& record = input.queries[i];
    const CcdResult result = decide(input, record, options, &tally.seconds);
    count_query(tally, result, record.truth);
    if (on_query) on_query(i, input.queries.size(), result);
  }
  return tally;
}

}  // namespace exactccd::oracle
