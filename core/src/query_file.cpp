#include "exactccd/query_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string_view>

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

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

bool is_integer(std::string_view s) {
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) s.remove_prefix(1);
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

mpz_class parse_integer(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  return mpz_class(std::string(s), 10);
}

}  // namespace

QueryFile read_query_file(const std::string& path, QueryType type) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, 0, "no such file");
  if (fs::is_directory(path, ec)) throw InputError(path, 0, "is a directory, not a CSV file");
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open for reading");

  QueryFile file{path, type, {}};
  static const char* const kColumns[7] = {"x_num", "x_den", "y_num", "y_den",
                                          "z_num", "z_den", "truth"};
  std::string line;
  std::size_t line_no = 0, row = 0;
  QueryRecord current;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string_view text = trim(line);
    if (text.empty()) continue;  // blank lines carry no data
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = text.find(',', start);
      fields.push_back(trim(text.substr(start, comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    if (fields.size() != 7)
      throw InputError(path, line_no,
                       "expected 7 comma-separated columns "
                       "(x_num,x_den,y_num,y_den,z_num,z_den,truth), found " +
                           std::to_string(fields.size()));
    mpz_class v[7];
    for (int i = 0; i < 7; ++i) {
      if (!is_integer(fields[i]))
        throw InputError(path, line_no,
                         std::string("column ") + kColumns[i] + " is not an integer: '" +
                             std::string(fields[i]) + "'");
      v[i] = parse_integer(fields[i]);
    }
    for (int i = 1; i < 6; i += 2)
      if (sgn(v[i]) == 0)
        throw InputError(path, line_no, std::string("zero denominator in column ") + kColumns[i]);
    if (v[6] != 0 && v[6] != 1)
      throw InputError(path, line_no, "truth must be 0 or 1, found " + v[6].get_str());
    const bool truth = v[6] == 1;
    const std::size_t k = row % 8;
    if (k == 0) {
      current = QueryRecord{};
      current.query.type = type;
      current.truth = truth;
      current.first_line = line_no;
    } else if (truth != current.truth) {
      throw InputError(path, line_no,
                       "truth differs within a query (the query starting at line " +
                           std::to_string(current.first_line) + ")");
    }
    RationalPoint& pt = current.query.points[k];
    pt.x = mpq_class(v[0], v[1]);
    pt.y = mpq_class(v[2], v[3]);
    pt.z = mpq_class(v[4], v[5]);
    pt.x.canonicalize();
    pt.y.canonicalize();
    pt.z.canonicalize();
    if (k == 7) file.queries.push_back(std::move(current));
    ++row;
  }
  if (in.bad()) throw InputError(path, line_no, "read error");
  if (row % 8 != 0)
    throw InputError(path, line_no,
                     "query cut short: " + std::to_string(row % 8) +
                         " rows in the last query (8 per query), starting at line " +
                         std::to_string(current.first_line));
  return file;
}

std::vector<std::string> find_query_files(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, 0, "no such file or directory");
  if (!fs::is_directory(path, ec)) return {path};
  std::vector<std::string> files;
  for (auto it = fs::recursive_directory_iterator(path, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    const fs::path& p = it->path();
    if (!it->is_regular_file() || p.extension() != ".csv") continue;
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
