// The contact geometry (exactccd/contact.hpp) on the sample queries, the degenerate suite and
// the simulation-like set: how often each kind occurs, how wide the enclosures are (median and
// worst, in units of the double spacing at 1: 2^-52), and what it costs (every query decided
// with the geometry off and on, in one run, medians of the repetitions).
//   ./build/bench/contact_geometry_bench [--repetitions R] [--full-simulation]
//       [--min-separation D]   (every query decided within D, the closest points' geometry)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "corpus/simulation_queries.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/query_file.hpp"

namespace {

using Points = std::array<Eigen::Vector3d, 8>;

struct Query {
  exactccd::QueryType type;
  Points p;
};

/// The minimum separation of the run (0: contact).
double g_delta = 0.0;

exactccd::CcdResult decide(const Query& q) {
  const auto& p = q.p;
  exactccd::CcdOptions o;
  o.min_separation = g_delta;
  if (q.type == exactccd::QueryType::vertex_face)
    return exactccd::vertex_face_ccd({p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]}, o);
  return exactccd::edge_edge_ccd({p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]}, o);
}

exactccd::ContactGeometry geometry(const Query& q, const exactccd::CcdResult& r) {
  const auto& p = q.p;
  if (q.type == exactccd::QueryType::vertex_face)
    return exactccd::contact_geometry(
        exactccd::VertexFaceQuery{p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]}, r, g_delta);
  return exactccd::contact_geometry(
      exactccd::EdgeEdgeQuery{p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]}, r, g_delta);
}

std::vector<Query> load(const std::string& path) {
  std::vector<Query> out;
  for (const auto& file : exactccd::find_query_files(path)) {
    const auto type = exactccd::query_type_from_path(file);
    if (!type) continue;
    for (const auto& record : exactccd::read_query_file(file, *type).queries) {
      Query q{*type, {}};
      bool doubles = true;
      for (int row = 0; row < 8; ++row) {
        const auto& r = record.query.points[row];
        double x, y, z;
        doubles = doubles && exactccd::exact::to_double_exactly(r.x, &x) &&
                  exactccd::exact::to_double_exactly(r.y, &y) &&
                  exactccd::exact::to_double_exactly(r.z, &z);
        if (doubles) q.p[row] = {x, y, z};
      }
      if (doubles) out.push_back(q);
    }
  }
  return out;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void report(const char* name, const std::vector<Query>& queries, int repetitions) {
  // Kinds and widths.
  std::size_t colliding = 0, kinds[6] = {0, 0, 0, 0, 0, 0}, oriented = 0;
  std::vector<double> parameter_widths, normal_widths;
  for (const Query& q : queries) {
    const auto r = decide(q);
    if (!r.collides) continue;
    ++colliding;
    const auto g = geometry(q, r);
    ++kinds[static_cast<int>(g.kind)];
    oriented += g.normal_oriented;
    if (g.kind != exactccd::ContactKind::point && g.kind != exactccd::ContactKind::at_start)
      continue;
    double pw = 0, nw = 0;
    for (int i = 0; i < g.parameter_count; ++i)
      pw = std::max(pw, g.parameters[i].hi - g.parameters[i].lo);
    for (const auto& e : g.normal) nw = std::max(nw, e.hi - e.lo);
    parameter_widths.push_back(pw / 0x1p-52);
    normal_widths.push_back(nw / 0x1p-52);
  }
  // Cost: all queries decided, geometry off and on (for the colliding ones), interleaved.
  std::vector<double> off, on;
  for (int rep = 0; rep < repetitions; ++rep) {
    std::size_t sink = 0;
    auto start = std::chrono::steady_clock::now();
    for (const Query& q : queries) sink += decide(q).collides;
    off.push_back(seconds_since(start));
    start = std::chrono::steady_clock::now();
    for (const Query& q : queries) {
      const auto r = decide(q);
      if (r.collides) sink += static_cast<std::size_t>(geometry(q, r).kind);
    }
    on.push_back(seconds_since(start));
    if (sink == 12345678) std::puts("");
  }
  const double t_off = median(off), t_on = median(on);
  const auto worst = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
  };
  std::printf(
      "%-18s %9zu queries %8zu colliding | point %zu, at_start %zu, unresolved %zu, "
      "degenerate triangle %zu, parallel edges %zu, coplanar %zu, normal oriented %zu | widths in 2^-52: parameters median %.3g worst %.3g, normal median %.3g "
      "worst %.3g | off %.1f ns/query, on %.1f ns/query (%.3fx), geometry %.1f ns per colliding "
      "query\n",
      name, queries.size(), colliding, kinds[0], kinds[1], kinds[2], kinds[3], kinds[4],
      kinds[5], oriented,
      median(parameter_widths), worst(parameter_widths), median(normal_widths),
      worst(normal_widths), 1e9 * t_off / queries.size(), 1e9 * t_on / queries.size(),
      t_on / t_off, colliding ? 1e9 * (t_on - t_off) / colliding : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
  int repetitions = 5;
  bool full = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--repetitions") && i + 1 < argc) {
      repetitions = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--full-simulation")) {
      full = true;
    } else if (!std::strcmp(argv[i], "--min-separation") && i + 1 < argc) {
      g_delta = std::strtod(argv[++i], nullptr);
      if (!(g_delta >= 0.0) || !std::isfinite(g_delta)) {
        std::fprintf(stderr, "--min-separation: a finite number >= 0\n");
        return 2;
      }
    } else {
      std::fprintf(stderr, "usage: contact_geometry_bench [--repetitions R] [--full-simulation] "
                           "[--min-separation D]\n");
      return 2;
    }
  }
  if (g_delta > 0) std::printf("minimum separation %g: the closest points' geometry\n", g_delta);
  const std::string sample = EXACTCCD_SAMPLE_QUERIES;
  const std::string data = sample.substr(0, sample.rfind('/') + 1);
  std::vector<Query> simulation;
  for (const auto& q : exactccd::sim::generate_simulation_queries(
           full ? exactccd::sim::SimulationConfig{} : exactccd::sim::small_simulation_config()))
    simulation.push_back({q.type, q.points});
  report("sample queries", load(sample), repetitions);
  report("degenerate suite", load(data + "degenerate-suite"), repetitions);
  report(full ? "simulation (full)" : "simulation (small)", simulation, repetitions);
  return 0;
}
