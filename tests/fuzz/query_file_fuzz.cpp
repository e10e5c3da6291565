// libFuzzer harness: the benchmark CSV reader (read_query_file) on arbitrary bytes, then the
// public double API on every query it decodes.
//
// Properties: the reader (and that of the point kinds, read_primitive_query_file) returns or
// throws exactccd::InputError, nothing else (any other
// exception escapes and aborts); every decoded query has its 8 points and its first line; and
// each query, read as vertex-face and as edge-edge with its coordinates rounded to doubles
// (toward zero; the exact ones stay exact), satisfies the API's contract: non-finite ones are
// rejected with std::invalid_argument, and for the others the default path equals the exact
// path (fuzz_support.hpp, check_default_equals_exact). The corpus files are plain benchmark CSV
// files, so `exactccd check --type vf FILE` reads them too.
#include <cstddef>
#include <cstdint>

#include "exactccd/query_file.hpp"
#include "fuzz_support.hpp"

using namespace exactccd;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = (fuzz::scratch_folder() / "queries.csv").string();
  fuzz::write_file(path, data, size);
  // The readers of the point kinds and the plane (their rows and columns): they too return or
  // throw InputError, and each query has its rows.
  for (const PrimitiveKind kind : {PrimitiveKind::point_edge, PrimitiveKind::point_edge_2d,
                                   PrimitiveKind::point_point, PrimitiveKind::point_point_2d,
                                   PrimitiveKind::point_plane}) {
    try {
      for (const PrimitiveQueryRecord& record : read_primitive_query_file(path, kind).queries)
        fuzz::require(record.points.size() == rows_per_query(kind),
                      "a point query without its rows");
    } catch (const InputError&) {
    }
  }
  QueryFile file;
  try {
    file = read_query_file(path, QueryType::vertex_face);
  } catch (const InputError&) {
    return 0;  // a clear error is the right answer to malformed input
  }
  std::size_t previous_line = 0;
  for (const QueryRecord& record : file.queries) {
    fuzz::require(record.first_line > previous_line, "queries out of line order");
    previous_line = record.first_line;
    fuzz::Points v;
    for (int i = 0; i < 8; ++i) {
      const RationalPoint& p = record.query.points[i];
      fuzz::require(p.x.get_den() > 0 && p.y.get_den() > 0 && p.z.get_den() > 0,
                    "a denominator that is not positive after canonicalization");
      v[i] = Eigen::Vector3d(p.x.get_d(), p.y.get_d(), p.z.get_d());
    }
    for (QueryType type : {QueryType::vertex_face, QueryType::edge_edge}) {
      const CcdOptions options;
      if (fuzz::invalid_input(v, options))
        fuzz::check_rejected(type, v, options);
      else
        fuzz::check_default_equals_exact(type, v, options);
    }
  }
  return 0;
}
