// The sample queries (tests/data/sample-queries) as the double API takes them: every coordinate
// of the shipped files is exactly a double.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "corpus/random_queries.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exactccd/query_file.hpp"

namespace exactccd::test {

using namespace exactccd::random_queries;  // corpus/random_queries.hpp

/// Every sample query, read once per program; throws if a coordinate is not exactly a double.
inline const std::vector<DoubleQuery>& sample_double_queries() {
  static const std::vector<DoubleQuery> all = [] {
    std::vector<DoubleQuery> out;
    for (const std::string& path : find_query_files(EXACTCCD_SAMPLE_QUERIES)) {
      const auto type = query_type_from_path(path);
      if (!type) throw std::runtime_error(path + ": neither vertex-face nor edge-edge");
      for (const QueryRecord& r : read_query_file(path, *type).queries) {
        DoubleQuery q;
        q.type = *type;
        for (int i = 0; i < 8; ++i)
          if (!exact::to_double_exactly(r.query.points[i].x, &q.v[i].x()) ||
              !exact::to_double_exactly(r.query.points[i].y, &q.v[i].y()) ||
              !exact::to_double_exactly(r.query.points[i].z, &q.v[i].z()))
            throw std::runtime_error(path + ": a coordinate is not exactly a double");
        out.push_back(q);
      }
    }
    return out;
  }();
  return all;
}

}  // namespace exactccd::test
