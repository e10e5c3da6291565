// What exactccd.dask needs of the oracle command: one shard of `exactccd check` or `exactccd
// grade` as a task, and the command's tables printed from the merged tallies. The only file of
// the module that uses tools/ (check, check_report, grade_report, answers_file, cli_common).
#include <pybind11/stl.h>

#include <chrono>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "answers_file.hpp"
#include "bindings.hpp"
#include "check.hpp"
#include "check_report.hpp"
#include "cli_common.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "grade_report.hpp"

namespace exactccd::python {

namespace {

using cli::CheckTally;
using cli::GradeFindings;

// ---- Tallies and findings as Python dicts (they travel between Dask workers) ----------------

py::dict to_dict(const CheckTally& t) {
  py::dict d;
  d["file"] = t.file;
  d["queries"] = t.queries;
  d["collisions"] = t.collisions;
  d["false_positives"] = t.false_positives;
  d["false_negatives"] = t.false_negatives;
  d["seconds"] = t.seconds;
  d["stage_counts"] = t.stage_counts;
  return d;
}

CheckTally tally_of(const py::handle& d) {
  CheckTally t;
  t.file = d["file"].cast<std::string>();
  t.queries = d["queries"].cast<std::size_t>();
  t.collisions = d["collisions"].cast<std::size_t>();
  t.false_positives = d["false_positives"].cast<std::size_t>();
  t.false_negatives = d["false_negatives"].cast<std::size_t>();
  t.seconds = d["seconds"].cast<double>();
  t.stage_counts = d["stage_counts"].cast<std::vector<std::size_t>>();
  return t;
}

py::dict to_dict(const GradeFindings& f) {
  py::dict d;
  d["queries"] = f.queries;
  d["tois_given"] = f.tois_given;
  d["false_positives"] = f.false_positives;
  d["false_negatives"] = f.false_negatives;
  d["non_conservative"] = f.non_conservative;
  return d;
}

GradeFindings findings_of(const py::handle& d) {
  GradeFindings f;
  f.queries = d["queries"].cast<std::size_t>();
  f.tois_given = d["tois_given"].cast<std::size_t>();
  f.false_positives = d["false_positives"].cast<std::vector<std::size_t>>();
  f.false_negatives = d["false_negatives"].cast<std::vector<std::size_t>>();
  f.non_conservative = d["non_conservative"].cast<std::vector<std::size_t>>();
  return f;
}

void validate_t_max(double t_max) {
  try {
    cli::validate_t_max(t_max);
  } catch (const cli::UsageError& e) {
    throw py::value_error(e.what());
  }
}

std::optional<QueryType> forced_type(const std::optional<std::string>& type) {
  if (!type) return std::nullopt;
  return parse_query_type(*type);
}

// ---- check ------------------------------------------------------------------------------------

// One query as `exactccd check` decides it: through the double API when every coordinate is a
// double, else (only in mode exact) on the rationals.
CcdResult decide(const std::string& path, QueryType type, const QueryRecord& record,
                 const CcdOptions& options, double* seconds) {
  std::size_t bad_row = 0;
  const std::optional<cli::QueryPoints> points = cli::exact_doubles(record.query, &bad_row);
  if (!points && options.mode != Mode::exact)
    throw InputError(path, record.line_of_row(bad_row),
                     std::string("a coordinate is not exactly a double: only --mode exact "
                                 "decides such queries (--mode ") +
                         to_string(options.mode) + ")");
  const auto start = std::chrono::steady_clock::now();
  CcdResult result;
  if (!points)
    result = exact_ccd(record.query, options);
  else if (type == QueryType::vertex_face)
    result = vertex_face_ccd(cli::vertex_face_query(*points), options);
  else
    result = edge_edge_ccd(cli::edge_edge_query(*points), options);
  *seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void count(CheckTally& tally, const CcdResult& result, bool truth) {
  ++tally.queries;
  tally.collisions += result.collides;
  tally.false_positives += result.collides && !truth;
  tally.false_negatives += !result.collides && truth;
  tally.count_stage(result.decided_by);
}

// Queries [begin, end) of one file (end clipped to the file's count).
py::dict check_file_shard(const std::string& path, const std::optional<std::string>& type,
                          std::size_t begin, std::optional<std::size_t> end,
                          const std::string& mode, double t_max) {
  validate_t_max(t_max);
  CcdOptions options;
  options.t_max = t_max;
  options.mode = parse_mode(mode);
  const QueryType query_type = cli::resolve_query_type(path, forced_type(type));
  CheckTally tally;
  {
    py::gil_scoped_release release;
    const QueryFile input = read_query_file(path, query_type);
    tally.file = input.path;
    const std::size_t stop = std::min(end.value_or(input.queries.size()), input.queries.size());
    for (std::size_t i = begin; i < stop; ++i)
      count(tally, decide(input.path, input.type, input.queries[i], options, &tally.seconds),
            input.queries[i].truth);
  }
  return to_dict(tally);
}

// An (N, 8, 3) array of queries with their truth values, as one "file" named `name`.
py::dict check_array_shard(const std::string& name, const std::string& type,
                           const py::handle& queries, const py::handle& truth,
                           const std::string& mode, double t_max) {
  validate_t_max(t_max);
  CcdOptions options;
  options.t_max = t_max;
  options.mode = parse_mode(mode);
  const QueryType query_type = parse_query_type(type);
  const DoubleArray array = as_double_array(queries, {-1, 8, 3}, "queries");
  const py::array_t<bool, py::array::c_style | py::array::forcecast> flags =
      py::module_::import("numpy").attr("ascontiguousarray")(truth, py::arg("dtype") = "bool");
  if (flags.ndim() != 1 || flags.shape(0) != array.shape(0))
    throw py::value_error("truth must hold one value per query");
  CheckTally tally;
  tally.file = name;
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < array.shape(0); ++i) {
      const cli::QueryPoints p = points_of(array.data() + 24 * i);
      const auto start = std::chrono::steady_clock::now();
      CcdResult result;
      try {
        result = query_type == QueryType::vertex_face
                     ? vertex_face_ccd(cli::vertex_face_query(p), options)
                     : edge_edge_ccd(cli::edge_edge_query(p), options);
      } catch (const std::invalid_argument& e) {
        throw py::value_error(name + ": query " + std::to_string(i) + ": " + e.what());
      }
      tally.seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      count(tally, result, flags.data()[i]);
    }
  }
  return to_dict(tally);
}

std::vector<CheckTally> tallies_of(const py::list& files) {
  std::vector<CheckTally> tallies;
  for (const py::handle& f : files) tallies.push_back(tally_of(f));
  return tallies;
}

// ---- grade ------------------------------------------------------------------------------------

// Whether a reported toi is later than the exact first contact time t* of `query`, as
// tools/grade.cpp decides it (see there for why): `exact` is exact_ccd(query) with toi_width 0
// and a contact.
bool later_than_first_contact(const mpq_class& toi, const RationalQuery& query,
                              const CcdResult& exact) {
  if (toi <= mpq_class(exact.toi_lo)) return false;
  if (exact.toi_lo == exact.toi_hi || toi >= mpq_class(exact.toi_hi)) return true;
  RationalQuery over_toi = query;
  for (int k = 0; k < 4; ++k) {
    const RationalPoint& x0 = query.points[k];
    const RationalPoint& x1 = query.points[k + 4];
    RationalPoint& end = over_toi.points[k + 4];
    end.x = x0.x + toi * (x1.x - x0.x);
    end.y = x0.y + toi * (x1.y - x0.y);
    end.z = x0.z + toi * (x1.z - x0.z);
  }
  const CcdResult restricted = exact_ccd(over_toi);
  return restricted.collides && restricted.toi_lo < 1.0;
}

// Answers [begin, end) of one (queries, answers) pair of files; indices in the whole file.
py::dict grade_file_shard(const std::string& queries_path, const std::string& answers_path,
                          const std::optional<std::string>& type, std::size_t begin,
                          std::optional<std::size_t> end, double t_max) {
  validate_t_max(t_max);
  const QueryType query_type = cli::resolve_query_type(queries_path, forced_type(type));
  GradeFindings findings;
  {
    py::gil_scoped_release release;
    require_regular_file(queries_path, "a CSV file (grade takes one file per answers file)");
    const QueryFile input = read_query_file(queries_path, query_type);
    if (input.queries.empty()) throw InputError(input.path, 0, "no queries in the file");
    const std::vector<cli::Answer> answers =
        cli::read_answers_file(answers_path, input.queries.size(), queries_path, t_max);
    CcdOptions options;
    options.t_max = t_max;
    options.toi_width = 0.0;
    const std::size_t stop = std::min(end.value_or(input.queries.size()), input.queries.size());
    for (std::size_t i = begin; i < stop; ++i) {
      const cli::Answer& answer = answers[i];
      const RationalQuery& query = input.queries[i].query;
      const CcdResult exact = exact_ccd(query, options);
      ++findings.queries;
      findings.tois_given += answer.toi.has_value();
      if (answer.collides && !exact.collides) findings.false_positives.push_back(i);
      if (!answer.collides && exact.collides) findings.false_negatives.push_back(i);
      if (answer.collides && exact.collides && answer.toi &&
          later_than_first_contact(*answer.toi, query, exact))
        findings.non_conservative.push_back(i);
    }
  }
  return to_dict(findings);
}

}  // namespace

void bind_oracle(py::module_& m) {
  // The command's usage errors (a t_max outside (0, 1], no query at all) are bad input here.
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const cli::UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  m.def("_check_file_shard", &check_file_shard, py::arg("path"), py::arg("type"),
        py::arg("begin"), py::arg("end"), py::arg("mode"), py::arg("t_max"));
  m.def("_check_array_shard", &check_array_shard, py::arg("name"), py::arg("type"),
        py::arg("queries"), py::arg("truth"), py::arg("mode"), py::arg("t_max"));
  m.def("_grade_file_shard", &grade_file_shard, py::arg("queries_path"),
        py::arg("answers_path"), py::arg("type"), py::arg("begin"), py::arg("end"),
        py::arg("t_max"));
  m.def(
      "_merge_tallies",
      [](const py::list& tallies, const std::string& file) {
        CheckTally total;
        total.file = file;
        for (const CheckTally& t : tallies_of(tallies)) total.add(t);
        return to_dict(total);
      },
      py::arg("tallies"), py::arg("file"));
  m.def(
      "_check_table",
      [](const std::string& mode, const py::list& files, const py::dict& total) {
        std::ostringstream out;
        cli::print_check_table(out, parse_mode(mode), tallies_of(files), tally_of(total));
        return out.str();
      },
      py::arg("mode"), py::arg("files"), py::arg("total"));
  m.def(
      "_check_json",
      [](const std::string& mode, const py::list& files, const py::dict& total, double t_max) {
        std::ostringstream out;
        cli::print_check_json(out, parse_mode(mode), tallies_of(files), tally_of(total), t_max);
        return out.str();
      },
      py::arg("mode"), py::arg("files"), py::arg("total"), py::arg("t_max"));
  m.def(
      "_require_some_queries",
      [](const std::vector<std::string>& empty_files, std::size_t file_count,
         std::size_t queries) { cli::require_some_queries(empty_files, file_count, queries); },
      py::arg("empty_files"), py::arg("file_count"), py::arg("queries"));
  m.def(
      "_grade_text",
      [](const py::dict& findings) {
        std::ostringstream out;
        cli::print_grade_text(out, findings_of(findings));
        return out.str();
      },
      py::arg("findings"));
  m.def(
      "_grade_json",
      [](const py::dict& findings, double t_max) {
        std::ostringstream out;
        cli::print_grade_json(out, findings_of(findings), t_max);
        return out.str();
      },
      py::arg("findings"), py::arg("t_max"));
}

}  // namespace exactccd::python
