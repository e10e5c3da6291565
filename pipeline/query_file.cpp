#include "exactccd/query_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <string_view>
#include <system_error>

#include "pipeline/trim.hpp"

namespace exactccd {

namespace fs = std::filesystem;

InputError::InputError(const std::string& file, std::size_t line, const std::string& what)
    : std::runtime_error(file + (line ? ":" + std::to_string(line) : std::string()) + ": " +
                         what),
      file_(file),
      line_(line) {}

std::optional<QueryType> query_type_from_path(const std::string& path) {
  const fs::path p(path);
  std::optional<QueryType> type;
  for (const auto& part : p) {  // the last matching component wins: the nearest folder
    if (part == "vertex-face") type = QueryType::vertex_face;
    if (part == "edge-edge") type = QueryType::edge_edge;
  }
  return type;
}

// ---- Reading ----------------------------------------------------------------------------------

namespace {

// "is a directory", "is a FIFO (named pipe)", ... for a file that is not a regular one.
std::string kind_of_non_regular(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "is a character device";
  if (S_ISBLK(mode)) return "is a block device";
  if (S_ISSOCK(mode)) return "is a socket";
  return "is not a regular file";
}

std::string system_message(int error) {
  return std::error_code(error, std::generic_category()).message();
}

}  // namespace

void require_regular_file(const std::string& path, const std::string& what) {
  // The C library would stop at the NUL and open another file (Python strings may hold one).
  if (path.find('\0') != std::string::npos)
    throw InputError(printable(path), 0, "a path must not contain a NUL byte");
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) throw InputError(path, 0, system_message(errno));
  if (!S_ISREG(status.st_mode))
    throw InputError(path, 0, kind_of_non_regular(status.st_mode) + ", not " + what);
}

LineReader::LineReader(const std::string& path, const std::string& what) : path_(path) {
  // stat() first, so that a FIFO or a device is never opened; O_NONBLOCK and fstat() close the
  // window in which the path could be replaced by one.
  require_regular_file(path, what);
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) throw InputError(path, 0, system_message(errno));
  struct stat status {};
  const bool examined = ::fstat(fd_, &status) == 0;
  const int error = errno;
  if (examined && S_ISREG(status.st_mode)) {
    buffer_.resize(4 * kMaxLineBytes);  // larger than a line: next() stops a line at the cap
    return;
  }
  ::close(fd_);
  fd_ = -1;
  throw InputError(path, 0,
                   examined ? kind_of_non_regular(status.st_mode) + ", not " + what
                            : system_message(error));
}

LineReader::~LineReader() {
  if (fd_ >= 0) ::close(fd_);
}

bool LineReader::fill() {
  if (at_end_) return false;
  if (begin_ > 0) {  // keep the unread part at the front
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  for (;;) {
    const ssize_t n = ::read(fd_, buffer_.data() + end_, buffer_.size() - end_);
    if (n > 0) {
      end_ += static_cast<std::size_t>(n);
      return true;
    }
    if (n == 0) {
      at_end_ = true;
      return false;
    }
    if (errno != EINTR)
      throw InputError(path_, line_number_ + 1, "read error: " + system_message(errno));
  }
}

bool LineReader::next(std::string& line) {
  const auto too_long = [&] {
    return InputError(path_, line_number_ + 1,
                      "line longer than " + std::to_string(kMaxLineBytes) +
                          " bytes, the limit (a file without line ends?)");
  };
  std::size_t scanned = 0;  // bytes after begin_ known to hold no '\n'
  for (;;) {
    // The line end, looked for among at most kMaxLineBytes + 1 bytes.
    const std::size_t window = std::min(end_ - begin_, kMaxLineBytes + 1);
    const char* from = buffer_.data() + begin_ + scanned;
    if (const void* found = std::memchr(from, '\n', window - scanned)) {
      const auto stop = static_cast<std::size_t>(static_cast<const char*>(found) - buffer_.data());
      if (stop - begin_ > kMaxLineBytes) throw too_long();
      line.assign(buffer_.data() + begin_, stop - begin_);
      begin_ = stop + 1;
      ++line_number_;
      return true;
    }
    scanned = window;
    if (scanned > kMaxLineBytes) throw too_long();
    if (!fill()) break;
  }
  if (begin_ == end_) return false;
  line.assign(buffer_.data() + begin_, end_ - begin_);  // the last line, without '\n'
  begin_ = end_;
  ++line_number_;
  return true;
}

// ---- Text for messages ------------------------------------------------------------------------

namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

void append_hex_bytes(std::string& out, std::string_view bytes) {
  static const char* const kDigits = "0123456789ABCDEF";
  for (const char c : bytes) {
    const auto b = static_cast<unsigned char>(c);
    out += "\\x";
    out += kDigits[b >> 4];
    out += kDigits[b & 15];
  }
}

// The length (2-4) of the well-formed UTF-8 sequence at the start of `s` and its code point, or
// 0 when it is not one (overlong forms and surrogates included).
std::size_t utf8_sequence(std::string_view s, char32_t* code_point) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
  const unsigned char lead = byte(0);
  std::size_t length = 0;
  char32_t cp = 0, minimum = 0;
  if (lead >= 0xC2 && lead <= 0xDF) length = 2, cp = lead & 0x1F, minimum = 0x80;
  else if (lead >= 0xE0 && lead <= 0xEF) length = 3, cp = lead & 0x0F, minimum = 0x800;
  else if (lead >= 0xF0 && lead <= 0xF4) length = 4, cp = lead & 0x07, minimum = 0x10000;
  else return 0;
  if (s.size() < length) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(i) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i) & 0x3F);
  }
  if (cp < minimum || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  *code_point = cp;
  return length;
}

// Code points shown escaped although valid: C1 controls, the byte-order mark, and the
// bidirectional overrides and isolates that reorder the text around them on a terminal.
bool invisible(char32_t cp) {
  return (cp >= 0x80 && cp <= 0x9F) || cp == 0xFEFF || (cp >= 0x202A && cp <= 0x202E) ||
         (cp >= 0x2066 && cp <= 0x2069);
}

// Appends the escaped form of `text` to `out`, at most `limit` input bytes (whole characters);
// returns the number of input bytes consumed.
std::size_t append_printable(std::string& out, std::string_view text, std::size_t limit) {
  std::size_t i = 0;
  while (i < text.size() && i < limit) {
    const char c = text[i];
    const auto b = static_cast<unsigned char>(c);
    if (c == '\t') out += "\\t";
    else if (c == '\r') out += "\\r";
    else if (c == '\n') out += "\\n";
    if (c == '\t' || c == '\r' || c == '\n') {
      ++i;
      continue;
    }
    if (b < 0x20 || b == 0x7F) {
      append_hex_bytes(out, text.substr(i, 1));
      ++i;
      continue;
    }
    if (b < 0x80) {
      out += c;
      ++i;
      continue;
    }
    char32_t cp = 0;
    const std::size_t length = utf8_sequence(text.substr(i), &cp);
    if (length == 0) {
      append_hex_bytes(out, text.substr(i, 1));
      ++i;
    } else {
      if (invisible(cp))
        append_hex_bytes(out, text.substr(i, length));
      else
        out.append(text.substr(i, length));
      i += length;
    }
  }
  return i;
}

}  // namespace

std::string printable(std::string_view text) {
  std::string out;
  append_printable(out, text, text.size());
  return out;
}

std::string quote_for_message(std::string_view text) {
  constexpr std::size_t kShown = 60;
  std::string out = "'";
  const std::size_t shown = append_printable(out, text, kShown);
  out += shown < text.size() ? "...'" : "'";
  if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark)
    out += " (starts with a UTF-8 byte-order mark)";
  else if (text.find(kByteOrderMark) != std::string_view::npos)
    out += " (holds a UTF-8 byte-order mark)";
  return out;
}

// ---- Query files ------------------------------------------------------------------------------

namespace {

bool is_integer(std::string_view s) {
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) s.remove_prefix(1);
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

mpz_class parse_integer(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  return mpz_class(std::string(s), 10);
}

}  // namespace

namespace {

/// The rows of a query file: `rows` rows per query, each with the coordinate columns of
/// `dimension` (2 or 3) coordinates and a truth column; emit(points, truth, first_line) per
/// query (it may move the points out). Every error names the file and line.
template <class Emit>
void read_query_rows(const std::string& path, std::size_t rows, int dimension, Emit&& emit) {
  LineReader in(path, "a CSV file");
  static const char* const kColumns3[7] = {"x_num", "x_den", "y_num", "y_den",
                                           "z_num", "z_den", "truth"};
  static const char* const kColumns2[5] = {"x_num", "x_den", "y_num", "y_den", "truth"};
  const char* const* columns = dimension == 3 ? kColumns3 : kColumns2;
  const std::size_t count = dimension == 3 ? 7 : 5;
  const std::string header = dimension == 3 ? "(x_num,x_den,y_num,y_den,z_num,z_den,truth)"
                                            : "(x_num,x_den,y_num,y_den,truth)";
  std::string line;
  std::size_t row = 0;
  std::size_t blank_in_query = 0;  // line of a blank line after a partial query, 0 for none
  std::size_t first_line = 0;
  bool truth = false;
  std::vector<RationalPoint> points(rows);
  while (in.next(line)) {
    const std::size_t line_no = in.line_number();
    const std::string_view text = trim(line);
    if (text.empty()) {  // a blank line: allowed between queries only
      if (row % rows != 0 && blank_in_query == 0) blank_in_query = line_no;
      continue;
    }
    if (blank_in_query != 0)
      throw InputError(path, blank_in_query,
                       "blank line inside a query (the query starting at line " +
                           std::to_string(first_line) + " has " + std::to_string(row % rows) +
                           " of its " + std::to_string(rows) +
                           " rows; blank lines may only stand between queries)");
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = text.find(',', start);
      fields.push_back(trim(text.substr(start, comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    if (fields.size() != count)
      throw InputError(path, line_no,
                       "expected " + std::to_string(count) + " comma-separated columns " +
                           header + ", found " + std::to_string(fields.size()));
    mpz_class v[7];
    for (std::size_t i = 0; i < count; ++i) {
      if (!is_integer(fields[i]))
        throw InputError(path, line_no,
                         std::string("column ") + columns[i] +
                             " is not an integer: " + quote_for_message(fields[i]));
      v[i] = parse_integer(fields[i]);
    }
    for (std::size_t i = 1; i + 1 < count; i += 2)
      if (sgn(v[i]) == 0)
        throw InputError(path, line_no, std::string("zero denominator in column ") + columns[i]);
    const mpz_class& t = v[count - 1];
    if (t != 0 && t != 1)
      throw InputError(path, line_no, "truth must be 0 or 1, found " + t.get_str());
    const std::size_t k = row % rows;
    if (k == 0) {
      truth = t == 1;
      first_line = line_no;
    } else if ((t == 1) != truth) {
      throw InputError(path, line_no,
                       "truth differs within a query (the query starting at line " +
                           std::to_string(first_line) + ")");
    }
    RationalPoint& pt = points[k];
    pt.x = mpq_class(v[0], v[1]);
    pt.y = mpq_class(v[2], v[3]);
    pt.z = dimension == 3 ? mpq_class(v[4], v[5]) : mpq_class(0);
    pt.x.canonicalize();
    pt.y.canonicalize();
    pt.z.canonicalize();
    if (k + 1 == rows) emit(points, truth, first_line);
    ++row;
  }
  if (row % rows != 0)
    throw InputError(path, in.line_number(),
                     "query cut short: " + std::to_string(row % rows) + " rows in the last query (" +
                         std::to_string(rows) + " per query), starting at line " +
                         std::to_string(first_line));
}

}  // namespace

QueryFile read_query_file(const std::string& path, QueryType type) {
  QueryFile file{path, type, {}};
  read_query_rows(path, 8, 3,
                  [&](std::vector<RationalPoint>& points, bool truth, std::size_t line) {
                    QueryRecord record;
                    record.query.type = type;
                    // Moved: the reader assigns every point again before the next query.
                    std::move(points.begin(), points.end(), record.query.points.begin());
                    record.truth = truth;
                    record.first_line = line;
                    file.queries.push_back(std::move(record));
                  });
  return file;
}

const char* to_string(PrimitiveKind kind) noexcept {
  switch (kind) {
    case PrimitiveKind::point_edge: return "pe";
    case PrimitiveKind::point_edge_2d: return "pe2d";
    case PrimitiveKind::point_point: return "pp";
    case PrimitiveKind::point_point_2d: return "pp2d";
    case PrimitiveKind::point_plane: return "pl";
  }
  return "unknown";
}

std::optional<PrimitiveKind> primitive_kind_from_name(std::string_view name) {
  for (const PrimitiveKind k : {PrimitiveKind::point_edge, PrimitiveKind::point_edge_2d,
                                PrimitiveKind::point_point, PrimitiveKind::point_point_2d,
                                PrimitiveKind::point_plane})
    if (name == to_string(k)) return k;
  return std::nullopt;
}

std::size_t rows_per_query(PrimitiveKind kind) noexcept {
  return kind == PrimitiveKind::point_point || kind == PrimitiveKind::point_point_2d ? 4 : 6;
}

int dimension_of(PrimitiveKind kind) noexcept {
  return kind == PrimitiveKind::point_edge_2d || kind == PrimitiveKind::point_point_2d ? 2 : 3;
}

PrimitiveQueryFile read_primitive_query_file(const std::string& path, PrimitiveKind kind) {
  PrimitiveQueryFile file{path, kind, {}};
  read_query_rows(path, rows_per_query(kind), dimension_of(kind),
                  [&](const std::vector<RationalPoint>& points, bool truth, std::size_t line) {
                    file.queries.push_back({points, truth, line});
                  });
  return file;
}

std::vector<std::string> find_query_files(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec) throw InputError(path, 0, ec.message());  // the real reason: missing, a link loop, ...
  if (!fs::is_directory(status)) return {path};      // read_query_file rejects non-regular files
  std::vector<std::string> files;
  for (auto it = fs::recursive_directory_iterator(path, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    const fs::path& p = it->path();
    std::error_code entry_error;  // an entry that cannot be examined (a link loop) is no query file
    if (p.extension() != ".csv" || !it->is_regular_file(entry_error)) continue;
    // toi_K.csv: the TOI sidecars of `exactccd generate`, not queries.
    if (p.filename().string().rfind("toi_", 0) == 0) continue;
    const auto parent = p.parent_path().filename();
    if (parent == "vertex-face" || parent == "edge-edge") files.push_back(p.string());
  }
  if (ec) throw InputError(path, 0, "cannot list directory: " + ec.message());
  if (files.empty())
    throw InputError(path, 0, "no vertex-face/*.csv or edge-edge/*.csv files below this directory");
  std::sort(files.begin(), files.end());
  return files;
}

// ---- Writing ----------------------------------------------------------------------------------

void append_exact_fraction(std::string& out, double value) {
  if (!std::isfinite(value)) throw std::invalid_argument("exactccd: non-finite coordinate");
  if (value == 0.0) {
    out += "0,1";
    return;
  }
  // value = fraction * 2^exponent with 1/2 <= |fraction| < 1, so fraction * 2^53 is an
  // integer of at most 53 bits (subnormals included): value = mantissa * 2^(exponent - 53).
  int exponent = 0;
  const double fraction = std::frexp(value, &exponent);
  const auto mantissa = static_cast<std::int64_t>(std::ldexp(fraction, 53));
  std::uint64_t m = mantissa < 0 ? static_cast<std::uint64_t>(-mantissa)
                                 : static_cast<std::uint64_t>(mantissa);
  exponent -= 53;
  while ((m & 1u) == 0) {  // lowest terms: the denominator is a power of two
    m >>= 1;
    ++exponent;
  }
  if (mantissa < 0) out += '-';
  if (exponent >= 0) {
    if (exponent <= 10) {  // m < 2^53, so m * 2^10 < 2^63
      out += std::to_string(m << exponent);
    } else {
      mpz_class numerator(static_cast<unsigned long>(m));
      mpz_mul_2exp(numerator.get_mpz_t(), numerator.get_mpz_t(), exponent);
      out += numerator.get_str();
    }
    out += ",1";
    return;
  }
  out += std::to_string(m);
  out += ',';
  if (-exponent <= 63) {
    out += std::to_string(std::uint64_t{1} << -exponent);
  } else {
    mpz_class denominator;
    mpz_setbit(denominator.get_mpz_t(), -exponent);
    out += denominator.get_str();
  }
}

void append_query_rows(std::string& out, const std::array<Eigen::Vector3d, 8>& rows, bool truth) {
  for (const Eigen::Vector3d& p : rows)
    if (!p.allFinite()) throw std::invalid_argument("exactccd: non-finite coordinate");
  const char* truth_field = truth ? ",1\n" : ",0\n";
  for (const Eigen::Vector3d& p : rows) {
    append_exact_fraction(out, p.x());
    out += ',';
    append_exact_fraction(out, p.y());
    out += ',';
    append_exact_fraction(out, p.z());
    out += truth_field;
  }
}

void write_query_rows(std::ostream& out, const std::array<Eigen::Vector3d, 8>& rows, bool truth) {
  std::string text;
  append_query_rows(text, rows, truth);
  out << text;
}

void append_query(std::string& out, const VertexFaceQuery& q, bool truth) {
  append_query_rows(out, {q.p_t0, q.a_t0, q.b_t0, q.c_t0, q.p_t1, q.a_t1, q.b_t1, q.c_t1}, truth);
}

void append_query(std::string& out, const EdgeEdgeQuery& q, bool truth) {
  append_query_rows(
      out, {q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1},
      truth);
}

void write_query(std::ostream& out, const VertexFaceQuery& q, bool truth) {
  std::string text;
  append_query(text, q, truth);
  out << text;
}

void write_query(std::ostream& out, const EdgeEdgeQuery& q, bool truth) {
  std::string text;
  append_query(text, q, truth);
  out << text;
}

}  // namespace exactccd
