// Mean time per query of the exact path on the shipped sample queries, by query type; and the
// time per call of exact::IntegerQuery::bisect_root against the plain bit-order bisection it
// replaced (kept below as `plain_bisection`), on the same brackets in the same run.
//   ./build/bench/exact_path_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
// The "per_query" and "per_bracket" counters are seconds per query / per bracket (shown in
// the time unit of the table).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "exact/integer_query.hpp"
#include "exact/rational.hpp"
#include "exactccd/query_file.hpp"
#include "filters/ccd_filters.hpp"
#include "tests/random_queries.hpp"

namespace {

std::vector<exactccd::RationalQuery> sample_queries(exactccd::QueryType type) {
  std::vector<exactccd::RationalQuery> out;
  for (const auto& path : exactccd::find_query_files(EXACTCCD_SAMPLE_QUERIES)) {
    if (exactccd::query_type_from_path(path) != type) continue;
    for (auto& record : exactccd::read_query_file(path, type).queries)
      out.push_back(std::move(record.query));
  }
  return out;
}

void decide_all(benchmark::State& state, exactccd::QueryType type) {
  const auto queries = sample_queries(type);
  std::size_t collisions = 0;
  for (auto _ : state) {
    collisions = 0;
    for (const auto& q : queries) collisions += exactccd::exact_ccd(q).collides;
    benchmark::DoNotOptimize(collisions);
  }
  state.counters["queries"] = static_cast<double>(queries.size());
  state.counters["collisions"] = static_cast<double>(collisions);
  state.counters["per_query"] = benchmark::Counter(
      static_cast<double>(queries.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(decide_all, vertex_face, exactccd::QueryType::vertex_face)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(decide_all, edge_edge, exactccd::QueryType::edge_edge)
    ->Unit(benchmark::kMillisecond);

// ---- bisect_root ---------------------------------------------------------------------------

using exactccd::exact::IntegerQuery;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The bisection bisect_root used before guided probes: one exact sign at the middle double
/// (bit order) of what is left, every step.
std::pair<double, double> plain_bisection(const IntegerQuery& q, double lo, double hi,
                                          double width) {
  const int sign_lo = q.cubic_sign_at(lo);
  for (;;) {
    const double first = std::nextafter(lo, kInf), last = std::nextafter(hi, -kInf);
    if (first > last || (width > 0 && exactccd::exact::difference_at_most(hi, lo, width)))
      return {lo, hi};
    std::uint64_t a, b;
    std::memcpy(&a, &first, sizeof a);
    std::memcpy(&b, &last, sizeof b);
    const std::uint64_t mid_bits = a + (b - a) / 2;
    double mid;
    std::memcpy(&mid, &mid_bits, sizeof mid);
    const int s = q.cubic_sign_at(mid);
    if (s == 0) return {mid, mid};
    (s == sign_lo ? lo : hi) = mid;
  }
}

struct Bracket {
  std::size_t query;  // index into BracketSet::queries
  double lo, hi;
};

struct BracketSet {
  std::vector<IntegerQuery> queries;
  std::vector<Bracket> brackets;
};

/// Brackets of width about 1e-6 around the first sign change in [0, 1] of the cubics of
/// seeded random queries (short motions, and uniform in the box), for both query types.
const BracketSet& random_cubic_brackets() {
  static const BracketSet set = [] {
    using namespace exactccd::test;
    BracketSet out;
    std::mt19937_64 rng(20240617);
    std::uniform_real_distribution<double> offset(0.1e-6, 1e-6);
    for (const Family family : {Family::short_motion, Family::uniform_box}) {
      for (const exactccd::QueryType type :
           {exactccd::QueryType::vertex_face, exactccd::QueryType::edge_edge}) {
        const std::size_t wanted = out.brackets.size() + 1000;
        for (std::uint64_t i = 0; out.brackets.size() < wanted && i < 200000; ++i) {
          const DoubleQuery dq = generate({family, type}, 7, i);
          IntegerQuery q = type == exactccd::QueryType::vertex_face ? IntegerQuery(dq.vertex_face())
                                                                    : IntegerQuery(dq.edge_edge());
          // The first grid cell of [0, 1] with a sign change, then the tight pair in it.
          constexpr int kCells = 256;
          int previous = q.cubic_sign_at(0.0);
          for (int k = 1; k <= kCells && previous != 0; ++k) {
            const double t0 = std::ldexp(k - 1, -8), t1 = std::ldexp(k, -8);
            const int s = q.cubic_sign_at(t1);
            if (s == 0) break;
            if (s == previous) continue;
            const auto tight = plain_bisection(q, t0, t1, 0.0);
            const double lo = std::max(t0, tight.first - offset(rng));
            const double hi = std::min(t1, tight.second + offset(rng));
            const int s_lo = q.cubic_sign_at(lo), s_hi = q.cubic_sign_at(hi);
            if (s_lo != 0 && s_hi == -s_lo) {
              out.brackets.push_back({out.queries.size(), lo, hi});
              out.queries.push_back(std::move(q));
            }
            break;
          }
        }
      }
    }
    return out;
  }();
  return set;
}

/// Records the brackets the default pipeline hands to bisect_root on the sample queries:
/// inside the cubic filter (an undecided root) and after it (toi_final false).
class RecordingExact final : public exactccd::filters::ExactAtDoubles {
 public:
  RecordingExact(const IntegerQuery& q, std::vector<std::pair<double, double>>& calls)
      : q_(q), calls_(calls) {}
  int cubic_sign_at(double t) override { return q_.cubic_sign_at(t); }
  bool contact_at(double t) override { return q_.contact_at(t); }
  std::pair<double, double> bisect_root(double lo, double hi) override {
    calls_.emplace_back(lo, hi);
    return q_.bisect_root(lo, hi, 0.0);
  }

 private:
  const IntegerQuery& q_;
  std::vector<std::pair<double, double>>& calls_;
};

const BracketSet& sample_filter_brackets() {
  static const BracketSet set = [] {
    BracketSet out;
    const exactccd::CcdOptions options;
    for (const auto& path : exactccd::find_query_files(EXACTCCD_SAMPLE_QUERIES)) {
      const auto type = exactccd::query_type_from_path(path);
      if (!type) continue;
      for (auto& record : exactccd::read_query_file(path, *type).queries) {
        const auto& v = record.query.points;
        std::array<Eigen::Vector3d, 8> x;
        for (int i = 0; i < 8; ++i) x[i] = {v[i].x.get_d(), v[i].y.get_d(), v[i].z.get_d()};
        // Exact only when every coordinate is a double; the sample's are.
        const exactccd::VertexFaceQuery vf{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]};
        const exactccd::EdgeEdgeQuery ee{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]};
        const bool is_vf = *type == exactccd::QueryType::vertex_face;
        if (is_vf ? exactccd::filters::vertex_face_culled(vf)
                  : exactccd::filters::edge_edge_culled(ee))
          continue;
        IntegerQuery q = is_vf ? IntegerQuery(vf) : IntegerQuery(ee);
        std::vector<std::pair<double, double>> calls;
        RecordingExact exact(q, calls);
        const auto f = is_vf ? exactccd::filters::vertex_face_filter(vf, options, exact)
                             : exactccd::filters::edge_edge_filter(ee, options, exact);
        if (f.verdict == exactccd::filters::FilterOutcome::Verdict::contact && !f.toi_final &&
            f.toi_lo != f.toi_hi)
          calls.emplace_back(f.toi_lo, f.toi_hi);
        if (calls.empty()) continue;
        for (const auto& c : calls) out.brackets.push_back({out.queries.size(), c.first, c.second});
        out.queries.push_back(std::move(q));
      }
    }
    return out;
  }();
  return set;
}

enum class Method { plain, guided };

void bisect_all(benchmark::State& state, const BracketSet& (*brackets)(), Method method) {
  const BracketSet& set = brackets();
  // The two methods must agree exactly (the contract determines the tightest pair).
  for (const Bracket& b : set.brackets) {
    const IntegerQuery& q = set.queries[b.query];
    if (plain_bisection(q, b.lo, b.hi, 0.0) != q.bisect_root(b.lo, b.hi, 0.0)) {
      std::fprintf(stderr, "bisect_root differs from plain bisection on [%a, %a]\n", b.lo, b.hi);
      std::abort();
    }
  }
  double checksum = 0;
  for (auto _ : state) {
    for (const Bracket& b : set.brackets) {
      const IntegerQuery& q = set.queries[b.query];
      const auto r = method == Method::plain ? plain_bisection(q, b.lo, b.hi, 0.0)
                                             : q.bisect_root(b.lo, b.hi, 0.0);
      checksum += r.first;
    }
    benchmark::DoNotOptimize(checksum);
  }
  state.counters["brackets"] = static_cast<double>(set.brackets.size());
  state.counters["per_bracket"] = benchmark::Counter(
      static_cast<double>(set.brackets.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(bisect_all, random_1e-6_plain, random_cubic_brackets, Method::plain)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bisect_all, random_1e-6_guided, random_cubic_brackets, Method::guided)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bisect_all, sample_filter_plain, sample_filter_brackets, Method::plain)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bisect_all, sample_filter_guided, sample_filter_brackets, Method::guided)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
