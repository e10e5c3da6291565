// Reading and writing the CCD benchmark's CSV files (Wang et al. 2021): 8 rows per query, 7
// integer columns x_num,x_den,y_num,y_den,z_num,z_den,truth. Coordinates are read as exact
// rationals; doubles are written as their exact fractions, so a file written here reads back
// as exactly the doubles written.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "exactccd/rational_query.hpp"

namespace exactccd {

/// Malformed input: the message names the file and, where there is one, the line.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, std::size_t line, const std::string& what);
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }  ///< 1-based; 0 when the whole file is at fault

 private:
  std::string file_;
  std::size_t line_;
};

struct QueryRecord {
  RationalQuery query;
  bool truth = false;         ///< the file's truth column
  std::size_t first_line = 0; ///< 1-based line of the query's first row
};

struct QueryFile {
  std::string path;
  QueryType type = QueryType::vertex_face;
  std::vector<QueryRecord> queries;
};

/// The query type from a path component named "vertex-face" or "edge-edge" (the nearest one),
/// or nullopt.
std::optional<QueryType> query_type_from_path(const std::string& path);

/// Reads and validates a whole file. Throws InputError for: a missing or unreadable file, a
/// row without exactly 7 columns, a field that is not an integer (NaN and Inf included), a
/// zero denominator, a truth value other than 0 or 1, truth differing within a query, a query
/// cut short (row count not a multiple of 8).
QueryFile read_query_file(const std::string& path, QueryType type);

/// `path` itself when it is a file; for a directory, every `vertex-face/*.csv` and
/// `edge-edge/*.csv` below it, sorted, except files whose name starts with `toi_` (the TOI
/// sidecars `toi_K.csv` that `exactccd generate` writes next to its `data_K.csv`). Throws
/// InputError when the path does not exist or a directory holds no such file.
std::vector<std::string> find_query_files(const std::string& path);

// ---- Writing ----------------------------------------------------------------------------------

/// Appends `value` as the exact fraction "num,den": den a power of two, in lowest terms (the
/// numerator odd unless den == 1); zero (either sign) as "0,1". Throws std::invalid_argument
/// for NaN or an infinity.
void append_exact_fraction(std::string& out, double value);

/// Appends one query as its 8 CSV rows "x_num,x_den,y_num,y_den,z_num,z_den,truth\n", `rows` in
/// the benchmark's row order (as RationalQuery::points). Throws std::invalid_argument for a
/// non-finite coordinate, and then appends nothing.
void append_query_rows(std::string& out, const std::array<Eigen::Vector3d, 8>& rows, bool truth);

/// One query's rows in the benchmark's order (p_t0, a_t0, b_t0, c_t0, p_t1, ...; ea0_t0, ...);
/// throws as append_query_rows.
void append_query(std::string& out, const VertexFaceQuery& query, bool truth);
void append_query(std::string& out, const EdgeEdgeQuery& query, bool truth);

/// The same, written to a stream (the stream's error state is left to the caller to check).
void write_query_rows(std::ostream& out, const std::array<Eigen::Vector3d, 8>& rows, bool truth);
void write_query(std::ostream& out, const VertexFaceQuery& query, bool truth);
void write_query(std::ostream& out, const EdgeEdgeQuery& query, bool truth);

}  // namespace exactccd
