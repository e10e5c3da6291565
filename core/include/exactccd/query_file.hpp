/// \file
/// Reading and writing the CCD benchmark's CSV files (Wang et al. 2021): 8 rows per query, 7
/// integer columns x_num,x_den,y_num,y_den,z_num,z_den,truth. Coordinates are read as exact
/// rationals; doubles are written as their exact fractions, so a file written here reads back
/// as exactly the doubles written.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "exactccd/export.hpp"
#include "exactccd/rational_query.hpp"

namespace exactccd {

/// Malformed input: the message names the file and, where there is one, the line.
class EXACTCCD_API InputError : public std::runtime_error {
 public:
  /// \param file the file at fault, as the user named it.
  /// \param line 1-based line number, or 0 when the whole file is at fault.
  /// \param what the reason; what() returns "file:line: what" (or "file: what" for line 0).
  InputError(const std::string& file, std::size_t line, const std::string& what);
  /// \return the file at fault.
  const std::string& file() const { return file_; }
  /// \return the 1-based line at fault; 0 when the whole file is at fault.
  std::size_t line() const { return line_; }

 private:
  std::string file_;
  std::size_t line_;
};

/// One query of a benchmark file, read exactly.
struct QueryRecord {
  RationalQuery query;        ///< the coordinates, exact rationals
  bool truth = false;         ///< the file's truth column
  std::size_t first_line = 0; ///< 1-based line of the query's first row

  /// The 1-based line of row `row` (0-7): a query's rows are consecutive lines, since the
  /// reader rejects a blank line inside a query.
  /// \param row 0-7.
  /// \return first_line + row.
  std::size_t line_of_row(std::size_t row) const { return first_line + row; }
};

/// A whole benchmark file.
struct QueryFile {
  std::string path;                         ///< as given to read_query_file
  QueryType type = QueryType::vertex_face;  ///< the type every query of the file has
  std::vector<QueryRecord> queries;         ///< in file order
};

/// The query type from a path component named "vertex-face" or "edge-edge" (the nearest one),
/// or nullopt.
/// \param path any path (only its text is examined; nothing is opened).
/// \return the type, or nullopt when no component names one. Throws only std::bad_alloc.
EXACTCCD_API std::optional<QueryType> query_type_from_path(const std::string& path);

// ---- Reading ----------------------------------------------------------------------------------

/// The longest line the readers accept, in bytes: a row of exact doubles takes at most about
/// 1,030 (three fractions like -9007199254740991,2^1074). The cap keeps a file without line ends (or a device streaming bytes) from
/// growing memory without bound.
inline constexpr std::size_t kMaxLineBytes = 64 * 1024;

/// Reads the lines of a regular file, one at a time. Only regular files are opened for reading
/// (a FIFO would block, a device may never end). Throws InputError naming the file: the
/// system's reason when it cannot be opened ("No such file or directory", "Permission denied",
/// "Too many levels of symbolic links"), what it is when it is not a regular file ("is a
/// directory, not <what>", "is a FIFO (named pipe), not <what>", ...), a line longer than
/// kMaxLineBytes (with its number), a read error.
class EXACTCCD_API LineReader {
 public:
  /// Opens the file.
  /// \param path the file to read.
  /// \param what names the expected content in messages, e.g. "a CSV file".
  /// \throws InputError when `path` cannot be opened or is not a regular file.
  LineReader(const std::string& path, const std::string& what);
  /// Closes the file.
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  /// The next line, without its '\n' (a last line without one counts).
  /// \param line receives the line.
  /// \return false at the end of the file (`line` is then unspecified).
  /// \throws InputError for a line longer than kMaxLineBytes or a read error.
  bool next(std::string& line);
  /// \return the 1-based number of the line last returned (0 before the first).
  std::size_t line_number() const { return line_number_; }
  /// \return the path as given.
  const std::string& path() const { return path_; }

 private:
  bool fill();  // reads more bytes; false at the end of the file

  std::string path_;
  int fd_ = -1;
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0;
  std::size_t line_number_ = 0;
  bool at_end_ = false;
};

/// Throws InputError unless `path` names a regular file (following symbolic links); the message
/// as LineReader's. Opens nothing.
/// \param path the path to examine.
/// \param what names the expected content in messages, e.g. "a CSV file".
/// \throws InputError when `path` is missing, unreadable or not a regular file.
EXACTCCD_API void require_regular_file(const std::string& path, const std::string& what);

/// `text` for an error message, in single quotes: tab, carriage return and line feed as `\t`,
/// `\r`, `\n`; other control characters (NUL included), bytes that are not UTF-8, C1 controls
/// and bidirectional overrides as `\xNN` per byte; cut after about 60 bytes ("..."). A UTF-8
/// byte-order mark (EF BB BF) is escaped and named: "(starts with a UTF-8 byte-order mark)".
/// \param text any bytes.
/// \return the quoted text. Throws only std::bad_alloc.
EXACTCCD_API std::string quote_for_message(std::string_view text);

/// `text` with the escapes of quote_for_message, unquoted and uncut (for whole messages).
/// \param text any bytes.
/// \return the escaped text. Throws only std::bad_alloc.
EXACTCCD_API std::string printable(std::string_view text);

/// Reads and validates a whole file (through LineReader). Lines holding only spaces, tabs or a
/// carriage return are blank: allowed between queries, rejected inside one. Throws InputError
/// for: a file that cannot be read (see LineReader), a row without exactly 7 columns, a field
/// that is not an integer (NaN and Inf included), a zero denominator, a truth value other than
/// 0 or 1, truth differing within a query, a blank line inside a query, a query cut short (row
/// count not a multiple of 8). An empty file gives no queries (callers decide whether that is
/// an error).
/// \param path the file.
/// \param type the type of its queries (see query_type_from_path).
/// \return every query, exactly, with its truth and line.
/// \throws InputError as listed above, naming the file and line.
EXACTCCD_API QueryFile read_query_file(const std::string& path, QueryType type);

/// The kinds of query files beyond the benchmark's vertex-face and edge-edge: the same CSV
/// form, with these rows per query (the points at t0, then the same points at t1):
/// point-edge `pe` 6 (p, e0, e1), point-point `pp` 4 (p, q), point-plane `pl` 6 (p, origin,
/// normal); the 2D kinds `pe2d` (6 rows) and `pp2d` (4 rows) have 5 columns,
/// x_num,x_den,y_num,y_den,truth.
enum class PrimitiveKind : std::uint8_t {
  point_edge,      ///< `pe`: point_edge_ccd
  point_edge_2d,   ///< `pe2d`: point_edge_ccd_2d
  point_point,     ///< `pp`: point_point_ccd
  point_point_2d,  ///< `pp2d`: point_point_ccd_2d
  point_plane,     ///< `pl`: point_plane_ccd
};

/// The kind's short name, as `exactccd check --type` takes it. Never throws.
/// \param kind a kind.
/// \return "pe", "pe2d", "pp", "pp2d" or "pl".
EXACTCCD_API const char* to_string(PrimitiveKind kind) noexcept;
/// The kind named `name` (its short name), or nullopt.
/// \param name a short name.
/// \return the kind, or nullopt.
EXACTCCD_API std::optional<PrimitiveKind> primitive_kind_from_name(std::string_view name);
/// Rows per query of the kind's files. Never throws.
/// \param kind a kind.
/// \return 6 or 4.
EXACTCCD_API std::size_t rows_per_query(PrimitiveKind kind) noexcept;
/// Coordinates per row of the kind's files. Never throws.
/// \param kind a kind.
/// \return 3, or 2 for the 2D kinds.
EXACTCCD_API int dimension_of(PrimitiveKind kind) noexcept;

/// One query of a file of one of these kinds, read exactly (2D points with z = 0).
struct PrimitiveQueryRecord {
  std::vector<RationalPoint> points;  ///< rows_per_query points: those at t0, then at t1
  bool truth = false;                 ///< the file's truth column
  std::size_t first_line = 0;         ///< 1-based line of the query's first row
};

/// A whole file of one of these kinds.
struct PrimitiveQueryFile {
  std::string path;                           ///< as given
  PrimitiveKind kind = PrimitiveKind::point_edge;  ///< the kind of every query
  std::vector<PrimitiveQueryRecord> queries;  ///< in file order
};

/// Reads and validates a file of `kind`, with the rules of read_query_file (columns, integers,
/// zero denominators, truth, blank lines, a query cut short), for its rows per query and
/// columns.
/// \param path the file.
/// \param kind the kind of its queries.
/// \return every query, exactly.
/// \throws InputError naming the file and line.
EXACTCCD_API PrimitiveQueryFile read_primitive_query_file(const std::string& path,
                                                          PrimitiveKind kind);

/// `path` itself when it is a file; for a directory, every `vertex-face/*.csv` and
/// `edge-edge/*.csv` below it, sorted, except files whose name starts with `toi_` (the TOI
/// sidecars `toi_K.csv` that `exactccd generate` writes next to its `data_K.csv`). Throws
/// InputError when the path cannot be examined (the system's reason: missing, a link loop, ...)
/// or a directory holds no such file.
/// \param path a file or a directory.
/// \return the files, sorted (just `path` for a file).
/// \throws InputError as listed above.
EXACTCCD_API std::vector<std::string> find_query_files(const std::string& path);

// ---- Writing ----------------------------------------------------------------------------------

/// Appends `value` as the exact fraction "num,den": den a power of two, in lowest terms (the
/// numerator odd unless den == 1); zero (either sign) as "0,1". Throws std::invalid_argument
/// for NaN or an infinity.
/// \param out the text appended to.
/// \param value a finite double.
/// \throws std::invalid_argument for NaN or an infinity (nothing is appended).
EXACTCCD_API void append_exact_fraction(std::string& out, double value);

/// Appends one query as its 8 CSV rows "x_num,x_den,y_num,y_den,z_num,z_den,truth\n", `rows` in
/// the benchmark's row order (as RationalQuery::points). Throws std::invalid_argument for a
/// non-finite coordinate, and then appends nothing.
/// \param out the text appended to.
/// \param rows the 8 points, finite.
/// \param truth the truth column of every row.
/// \throws std::invalid_argument for a non-finite coordinate.
EXACTCCD_API void append_query_rows(std::string& out, const std::array<Eigen::Vector3d, 8>& rows,
                                    bool truth);

/// One vertex-face query's rows in the benchmark's order (p_t0, a_t0, b_t0, c_t0, p_t1, ...).
/// \param out the text appended to.
/// \param query finite coordinates.
/// \param truth the truth column.
/// \throws std::invalid_argument for a non-finite coordinate (nothing is appended).
EXACTCCD_API void append_query(std::string& out, const VertexFaceQuery& query, bool truth);
/// One edge-edge query's rows in the benchmark's order (ea0_t0, ea1_t0, eb0_t0, eb1_t0, ...).
/// \param out the text appended to.
/// \param query finite coordinates.
/// \param truth the truth column.
/// \throws std::invalid_argument for a non-finite coordinate (nothing is appended).
EXACTCCD_API void append_query(std::string& out, const EdgeEdgeQuery& query, bool truth);

/// As append_query_rows, written to a stream (the stream's error state is left to the caller
/// to check).
/// \param out the stream.
/// \param rows the 8 points, finite.
/// \param truth the truth column of every row.
/// \throws std::invalid_argument for a non-finite coordinate (nothing is written).
EXACTCCD_API void write_query_rows(std::ostream& out, const std::array<Eigen::Vector3d, 8>& rows,
                                   bool truth);
/// As append_query, written to a stream (the stream's error state is left to the caller).
/// \param out the stream.
/// \param query finite coordinates.
/// \param truth the truth column.
/// \throws std::invalid_argument for a non-finite coordinate (nothing is written).
EXACTCCD_API void write_query(std::ostream& out, const VertexFaceQuery& query, bool truth);
/// As append_query, written to a stream (the stream's error state is left to the caller).
/// \param out the stream.
/// \param query finite coordinates.
/// \param truth the truth column.
/// \throws std::invalid_argument for a non-finite coordinate (nothing is written).
EXACTCCD_API void write_query(std::ostream& out, const EdgeEdgeQuery& query, bool truth);

}  // namespace exactccd
