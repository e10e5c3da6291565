// exactccd.dask's C++ side: `exactccd check` and `exactccd grade` on one shard (a file, a range
// of a file's queries, or an array of queries) as a task, and the command's tables printed from
// the merged tallies, all through the oracle layer (oracle/) the command itself uses.
#include <pybind11/stl.h>

#include <chrono>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/query_file.hpp"
#include "oracle/answers_file.hpp"
#include "oracle/check.hpp"
#include "oracle/common.hpp"
#include "oracle/exact_doubles.hpp"
#include "oracle/grade.hpp"
#include "oracle/inspection.hpp"
#include "oracle/inspector_page.hpp"
#include "oracle/output_file.hpp"
#include "oracle/names.hpp"

namespace exactccd::python {

namespace {

using oracle::CheckTally;
using oracle::GradeFindings;

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
    oracle::validate_t_max(t_max);
  } catch (const oracle::UsageError& e) {
    throw py::value_error(e.what());
  }
}

std::optional<QueryType> forced_type(const std::optional<std::string>& type) {
  if (!type) return std::nullopt;
  return parse_query_type(*type);
}

// ---- check ------------------------------------------------------------------------------------

// Queries [begin, end) of one file (end clipped to the file's count), decided as the command
// decides them (oracle::check_queries).
py::dict check_file_shard(const std::string& path, const std::optional<std::string>& type,
                          std::size_t begin, std::optional<std::size_t> end,
                          const std::string& mode, double t_max) {
  validate_t_max(t_max);
  oracle::CheckSettings settings;
  settings.t_max = t_max;
  settings.mode = parse_mode(mode);
  const QueryType query_type = oracle::resolve_query_type(path, forced_type(type));
  CheckTally tally;
  {
    py::gil_scoped_release release;
    const QueryFile input = read_query_file(path, query_type);
    tally = oracle::check_queries(input, begin, end.value_or(input.queries.size()), settings);
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
      const oracle::QueryPoints p = points_of(array.data() + 24 * i);
      const auto start = std::chrono::steady_clock::now();
      CcdResult result;
      try {
        result = query_type == QueryType::vertex_face
                     ? vertex_face_ccd(oracle::vertex_face_query(p), options)
                     : edge_edge_ccd(oracle::edge_edge_query(p), options);
      } catch (const std::invalid_argument& e) {
        throw py::value_error(name + ": query " + std::to_string(i) + ": " + e.what());
      }
      tally.seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      oracle::count_query(tally, result, flags.data()[i]);
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

// Answers [begin, end) of one (queries, answers) pair of files, graded as the command grades
// them (oracle::grade_answers); indices in the whole file.
py::dict grade_file_shard(const std::string& queries_path, const std::string& answers_path,
                          const std::optional<std::string>& type, std::size_t begin,
                          std::optional<std::size_t> end, double t_max) {
  validate_t_max(t_max);
  const QueryType query_type = oracle::resolve_query_type(queries_path, forced_type(type));
  GradeFindings findings;
  {
    py::gil_scoped_release release;
    require_regular_file(queries_path, "a CSV file (grade takes one file per answers file)");
    const QueryFile input = read_query_file(queries_path, query_type);
    if (input.queries.empty()) throw InputError(input.path, 0, "no queries in the file");
    const std::vector<oracle::Answer> answers =
        oracle::read_answers_file(answers_path, input.queries.size(), queries_path, t_max);
    findings = oracle::grade_answers(input, answers, t_max, begin,
                                     end.value_or(input.queries.size()));
  }
  return to_dict(findings);
}

}  // namespace

void bind_oracle(py::module_& m) {
  // The command's usage errors (a t_max outside (0, 1], no query at all) are bad input here.
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const oracle::UsageError& e) {
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
  // exactccd.inspect: the command's inspection and page (oracle/inspection.hpp).
  m.def(
      "_inspect",
      [](const std::string& path, std::size_t index, const std::optional<std::string>& type,
         const std::string& mode, double t_max, double min_separation) {
        oracle::validate_t_max(t_max);
        oracle::validate_min_separation(min_separation);
        oracle::InspectSettings settings;
        settings.mode = parse_mode(mode);
        settings.t_max = t_max;
        settings.min_separation = min_separation;
        py::gil_scoped_release release;
        return oracle::inspect_file_query(path, forced_type(type), index, settings);
      },
      py::arg("path"), py::arg("index"), py::arg("type"), py::arg("mode"), py::arg("t_max"),
      py::arg("min_separation"));
  m.def(
      "_write_inspector_page",
      [](const std::string& json, const std::string& path, bool force) {
        const oracle::Overwrite overwrite =
            force ? oracle::Overwrite::replace : oracle::Overwrite::refuse;
        oracle::write_file_atomically(path, oracle::inspector_page(json), overwrite, "html");
      },
      py::arg("json"), py::arg("path"), py::arg("force"));
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
        oracle::print_check_table(out, parse_mode(mode), tallies_of(files), tally_of(total));
        return out.str();
      },
      py::arg("mode"), py::arg("files"), py::arg("total"));
  m.def(
      "_check_json",
      [](const std::string& mode, const py::list& files, const py::dict& total, double t_max) {
        std::ostringstream out;
        oracle::print_check_json(out, parse_mode(mode), tallies_of(files), tally_of(total), t_max);
        return out.str();
      },
      py::arg("mode"), py::arg("files"), py::arg("total"), py::arg("t_max"));
  m.def(
      "_require_some_queries",
      [](const std::vector<std::string>& empty_files, std::size_t file_count,
         std::size_t queries) { oracle::require_some_queries(empty_files, file_count, queries); },
      py::arg("empty_files"), py::arg("file_count"), py::arg("queries"));
  m.def(
      "_grade_text",
      [](const py::dict& findings) {
        std::ostringstream out;
        oracle::print_grade_text(out, findings_of(findings));
        return out.str();
      },
      py::arg("findings"));
  m.def(
      "_grade_json",
      [](const py::dict& findings, double t_max) {
        std::ostringstream out;
        oracle::print_grade_json(out, findings_of(findings), t_max);
        return out.str();
      },
      py::arg("findings"), py::arg("t_max"));
}

}  // namespace exactccd::python
