// Many queries at once: an (N, 8, 3) array decided in parallel (TBB) without the GIL.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/scene.hpp"

namespace exactccd::python {

namespace {

// The first failing query (lowest index, whatever the order the threads reach them in).
class FirstFailure {
 public:
  void record(std::size_t index, std::exception_ptr error) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!error_ || index < index_) {
      index_ = index;
      error_ = std::move(error);
    }
  }
  // Raises the failure, naming the query: a ValueError for bad input, else as it was thrown.
  void raise_if_any() const {
    if (!error_) return;
    try {
      std::rethrow_exception(error_);
    } catch (const std::invalid_argument& e) {
      throw py::value_error("query " + std::to_string(index_) + ": " + e.what());
    }
  }

 private:
  std::mutex mutex_;
  std::size_t index_ = 0;
  std::exception_ptr error_;
};

// Built in place from the rows (a list of points first would cost a copy per query).
template <class Query>
Query query_of(const double* d) {
  return {row_of(d, 0), row_of(d, 1), row_of(d, 2), row_of(d, 3),
          row_of(d, 4), row_of(d, 5), row_of(d, 6), row_of(d, 7)};
}

CcdResult decide(QueryType type, const double* data, const CcdOptions& options) {
  return type == QueryType::vertex_face
             ? vertex_face_ccd(query_of<VertexFaceQuery>(data), options)
             : edge_edge_ccd(query_of<EdgeEdgeQuery>(data), options);
}

ContactGeometry geometry(QueryType type, const double* data, const CcdResult& r,
                         double min_separation) {
  return type == QueryType::vertex_face
             ? contact_geometry(query_of<VertexFaceQuery>(data), r, min_separation)
             : contact_geometry(query_of<EdgeEdgeQuery>(data), r, min_separation);
}

/// Writes k enclosures as k rows of [lo, hi].
void write_enclosures(double* out, const Enclosure* e, int k) {
  for (int i = 0; i < k; ++i) {
    out[2 * i] = e[i].lo;
    out[2 * i + 1] = e[i].hi;
  }
}

/// Calls body(i) for i in [0, n) without the GIL, serially on the calling thread (threads 1)
/// or in parallel; the first query that throws (lowest index) is raised afterwards.
template <class Body>
void for_each_query(std::size_t n, const std::optional<int>& threads, Body&& body) {
  FirstFailure failure;
  {
    py::gil_scoped_release release;
    const auto run = [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        try {
          body(i);
        } catch (...) {
          failure.record(i, std::current_exception());
          return;  // later queries of this range cannot lower the index
        }
      }
    };
    if (threads && *threads == 1) {
      run(0, n);
    } else {
      tbb::task_arena arena(threads ? *threads : tbb::task_arena::automatic);
      arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 64),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                            run(r.begin(), r.end());
                          });
      });
    }
  }
  failure.raise_if_any();
}

void check_threads(const std::optional<int>& threads) {
  if (threads && (*threads < 1 || *threads > kMaxThreads))
    throw py::value_error("threads must be in [1, " + std::to_string(kMaxThreads) +
                          "] (or None for every core), not " + std::to_string(*threads));
}

/// The batch of one kind: `rows` points per query (the queries' (N, rows, 3) array), `k`
/// contact parameters, decide(data, options) and geometry(data, result, delta) on a query's
/// first double.
template <class Decide, class Geometry>
py::tuple decide_batch(const py::handle& queries, int rows_per_query, int k, double t_max,
                       double toi_width, const std::string& mode,
                       const std::optional<int>& threads, double min_separation, bool contact,
                       Decide&& decide, Geometry&& geometry) {
  const CcdOptions options = make_options(t_max, toi_width, mode, min_separation);
  if (contact && options.mode == Mode::float_only)
    throw py::value_error("contact=True needs a certified mode (\"filtered\" or \"exact\")");
  check_threads(threads);
  const DoubleArray array = as_double_array(queries, {-1, rows_per_query, 3}, "queries");
  const auto n = static_cast<std::size_t>(array.shape(0));
  const std::size_t stride = 3 * static_cast<std::size_t>(rows_per_query);
  py::array_t<bool> collides(static_cast<py::ssize_t>(n));
  py::array_t<double> toi_lo(static_cast<py::ssize_t>(n));
  py::array_t<double> toi_hi(static_cast<py::ssize_t>(n));
  py::array_t<std::uint8_t> stage(static_cast<py::ssize_t>(n));
  const double* data = array.data();
  bool* out_collides = collides.mutable_data();
  double* out_lo = toi_lo.mutable_data();
  double* out_hi = toi_hi.mutable_data();
  std::uint8_t* out_stage = stage.mutable_data();
  // The contact geometry (contact=True): NaN and kind -1 for the queries without contact.
  const auto rows = static_cast<py::ssize_t>(contact ? n : 0);
  py::array_t<double> parameters({rows, static_cast<py::ssize_t>(k), py::ssize_t{2}});
  py::array_t<double> normal({rows, py::ssize_t{3}, py::ssize_t{2}});
  py::array_t<double> point({rows, py::ssize_t{3}, py::ssize_t{2}});
  py::array_t<std::int8_t> kind(rows);
  py::array_t<bool> oriented(rows);
  double* out_parameters = parameters.mutable_data();
  double* out_normal = normal.mutable_data();
  double* out_point = point.mutable_data();
  std::int8_t* out_kind = kind.mutable_data();
  bool* out_oriented = oriented.mutable_data();

  for_each_query(n, threads, [&](std::size_t i) {
    const CcdResult r = decide(data + stride * i, options);
    out_collides[i] = r.collides;
    out_lo[i] = r.toi_lo;
    out_hi[i] = r.toi_hi;
    out_stage[i] = static_cast<std::uint8_t>(r.decided_by);
    if (!contact) return;
    if (!r.collides) {
      constexpr double nan = std::numeric_limits<double>::quiet_NaN();
      std::fill(out_parameters + 2 * k * i, out_parameters + 2 * k * (i + 1), nan);
      std::fill(out_normal + 6 * i, out_normal + 6 * (i + 1), nan);
      std::fill(out_point + 6 * i, out_point + 6 * (i + 1), nan);
      out_kind[i] = -1;
      out_oriented[i] = false;
      return;
    }
    const ContactGeometry g = geometry(data + stride * i, r, options.min_separation);
    write_enclosures(out_parameters + 2 * k * i, g.parameters.data(), k);
    write_enclosures(out_normal + 6 * i, g.normal.data(), 3);
    write_enclosures(out_point + 6 * i, g.point.data(), 3);
    out_kind[i] = static_cast<std::int8_t>(g.kind);
    out_oriented[i] = g.normal_oriented;
  });
  if (!contact) return py::make_tuple(collides, toi_lo, toi_hi, stage);
  return py::make_tuple(collides, toi_lo, toi_hi, stage,
                        py::make_tuple(parameters, normal, point, kind, oriented));
}

/// A point-plane query from its 6 rows: p, origin, normal at t0 then at t1.
PointPlaneQuery point_plane_of(const double* d) {
  return {row_of(d, 0), row_of(d, 1), row_of(d, 2), row_of(d, 3), row_of(d, 4), row_of(d, 5)};
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def(
      "_point_plane_batch",
      [](const py::handle& queries, double t_max, double toi_width, const std::string& mode,
         const std::optional<int>& threads, double min_separation, bool contact) {
        return decide_batch(
            queries, 6, 0, t_max, toi_width, mode, threads, min_separation, contact,
            [](const double* d, const CcdOptions& o) { return point_plane_ccd(point_plane_of(d), o); },
            [](const double* d, const CcdResult& r, double delta) {
              return contact_geometry(point_plane_of(d), r, delta);
            });
      },
      py::arg("queries"), py::arg("t_max"), py::arg("toi_width"), py::arg("mode"),
      py::arg("threads"), py::arg("min_separation"), py::arg("contact") = false);
  m.def(
      "_ccd_batch",
      [](const std::string& type_name, const py::handle& queries, double t_max, double toi_width,
         const std::string& mode, const std::optional<int>& threads, double min_separation,
         bool contact) {
        const QueryType type = parse_query_type(type_name);
        return decide_batch(
            queries, 8, type == QueryType::vertex_face ? 3 : 2, t_max, toi_width, mode, threads,
            min_separation, contact,
            [type](const double* d, const CcdOptions& o) { return decide(type, d, o); },
            [type](const double* d, const CcdResult& r, double delta) {
              return geometry(type, d, r, delta);
            });
      },
      py::arg("type"), py::arg("queries"), py::arg("t_max"), py::arg("toi_width"),
      py::arg("mode"), py::arg("threads"), py::arg("min_separation"), py::arg("contact") = false);
}

}  // namespace exactccd::python
