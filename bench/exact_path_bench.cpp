// Mean time per query of the exact path on the shipped sample queries, by query type; and the
// time per call of exact::IntegerQuery::bisect_root against the plain bit-order bisection it
// replaced (kept below as `plain_bisection`), on the same brackets in the same run.
//   ./build/bench/exact_path_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
// The "per_query" and "per_bracket" counters are seconds per query / per bracket (shown in
// the time unit of the table).
//
// kernels/...: the integer kernels of the exact stage at double times
// (exact/stages/integer_cubic.hpp) on the sample and scene queries that reach that stage, per
// query: the cubic's coefficients, one exact value at a double time, one contact test; in the stack
// integers the library uses (FixedInt, width chosen from the proven bounds), in GMP (the same
// templates with mpz_class) and in Boost.Multiprecision's fixed-precision cpp_int (unchecked,
// expression templates off; 256, 512 or 1024 bits chosen from the same bounds), the candidate the
// library measured.
//   ./build/bench/exact_path_bench --benchmark_filter=kernels --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <boost/multiprecision/cpp_int.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "corpus/random_queries.hpp"
#include "exact/arithmetic/integer_bounds.hpp"
#include "exact/stages/integer_cubic.hpp"
#include "exact/stages/integer_query.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exactccd/query_file.hpp"
#include "filters/ccd_filters.hpp"

// The operations the integer kernels call, for Boost's fixed-precision integers (found by
// argument-dependent lookup).
namespace boost::multiprecision {
template <unsigned Bits>
using BoostFixed =
    number<cpp_int_backend<Bits, Bits, signed_magnitude, unchecked, void>, et_off>;

template <unsigned Bits>
int sign_of(const BoostFixed<Bits>& x) {
  return x.sign();
}
template <unsigned Bits>
void multiply_by(BoostFixed<Bits>& r, std::uint64_t m) {
  r *= m;
}
template <unsigned Bits>
void add_shifted(BoostFixed<Bits>& r, const BoostFixed<Bits>& c, unsigned s) {
  r += c << s;
}
template <unsigned Bits>
void add_product(BoostFixed<Bits>& out, const BoostFixed<Bits>& a, const BoostFixed<Bits>& b) {
  out += a * b;
}
template <unsigned Bits>
void sub_product(BoostFixed<Bits>& out, const BoostFixed<Bits>& a, const BoostFixed<Bits>& b) {
  out -= a * b;
}
}  // namespace boost::multiprecision

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
    using namespace exactccd::random_queries;
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
class RecordingExact final : public exactccd::filters::ContactExactStage {
 public:
  RecordingExact(const IntegerQuery& q, std::vector<std::pair<double, double>>& calls)
      : q_(q), calls_(calls) {}
  int cubic_sign_at(double t) override { return q_.cubic_sign_at(t); }
  bool contact_at(double t) override { return q_.contact_at(t); }
  std::pair<double, double> bisect_root(double lo, double hi) override {
    calls_.emplace_back(lo, hi);
    return q_.bisect_root(lo, hi, 0.0);
  }
  void cubic_coefficient_bounds(double (&lo)[4], double (&hi)[4]) override {
    q_.scaled_coefficient_bounds(lo, hi);
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
        if (is_vf ? exactccd::filters::vertex_face_ccd_culling(vf)
                  : exactccd::filters::edge_edge_ccd_culling(ee))
          continue;
        IntegerQuery q = is_vf ? IntegerQuery(vf) : IntegerQuery(ee);
        std::vector<std::pair<double, double>> calls;
        RecordingExact exact(q, calls);
        const auto f = is_vf ? exactccd::filters::vertex_face_ccd_filter(vf, options, exact)
                             : exactccd::filters::edge_edge_ccd_filter(ee, options, exact);
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

// ---- the integer kernels: FixedInt, GMP, Boost -------------------------------------------------

using boost::multiprecision::BoostFixed;
using exactccd::exact::IntegerCoordinates;

/// The sample and scene queries the default path decides at double times (exact_at_double,
/// filter_exact_toi), each with a time: its TOI when it collides, else a random one in [0, 1].
struct KernelSet {
  std::vector<exactccd::VertexFaceQuery> vertex_face;
  std::vector<exactccd::EdgeEdgeQuery> edge_edge;
  std::vector<IntegerCoordinates> coordinates;  // vertex-face first, then edge-edge
  std::vector<double> times;
};

const KernelSet& kernel_set() {
  static const KernelSet set = [] {
    KernelSet out;
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::string sample = EXACTCCD_SAMPLE_QUERIES;
    const std::string scene = sample.substr(0, sample.rfind('/') + 1) + "scene-queries";
    std::vector<double> vf_times, ee_times;
    for (const std::string& root : {sample, scene}) {
      for (const auto& path : exactccd::find_query_files(root)) {
        const auto type = exactccd::query_type_from_path(path);
        if (!type) continue;
        for (auto& record : exactccd::read_query_file(path, *type).queries) {
          const auto& v = record.query.points;
          std::array<Eigen::Vector3d, 8> x;
          for (int i = 0; i < 8; ++i) x[i] = {v[i].x.get_d(), v[i].y.get_d(), v[i].z.get_d()};
          const exactccd::VertexFaceQuery vf{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]};
          const exactccd::EdgeEdgeQuery ee{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]};
          const bool is_vf = *type == exactccd::QueryType::vertex_face;
          const exactccd::CcdResult r =
              is_vf ? exactccd::vertex_face_ccd(vf) : exactccd::edge_edge_ccd(ee);
          if (r.decided_by != exactccd::Stage::exact_at_double &&
              r.decided_by != exactccd::Stage::filter_exact_toi)
            continue;
          const double t = r.collides ? r.toi_lo : unit(rng);
          if (is_vf) {
            out.vertex_face.push_back(vf);
            vf_times.push_back(t);
          } else {
            out.edge_edge.push_back(ee);
            ee_times.push_back(t);
          }
        }
      }
    }
    for (const auto& q : out.vertex_face)
      out.coordinates.push_back(exactccd::exact::integer_coordinates(q));
    for (const auto& q : out.edge_edge)
      out.coordinates.push_back(exactccd::exact::integer_coordinates(q));
    out.times = vf_times;
    out.times.insert(out.times.end(), ee_times.begin(), ee_times.end());
    return out;
  }();
  return set;
}

enum class Arithmetic { fixed, gmp, boost };

IntegerQuery::Arithmetic library_arithmetic(Arithmetic a) {
  return a == Arithmetic::gmp ? IntegerQuery::Arithmetic::gmp
                              : IntegerQuery::Arithmetic::fixed_first;
}

/// Calls f(BoostFixed<Bits>{}) for the narrowest of 256, 512, 1024 bits holding magnitudes
/// below 2^bits; false beyond (not run).
template <class F>
bool with_boost_width(long bits, F&& f) {
  if (bits <= 256) return f(BoostFixed<256>{}), true;
  if (bits <= 512) return f(BoostFixed<512>{}), true;
  if (bits <= 1024) return f(BoostFixed<1024>{}), true;
  return false;
}

/// The time t in [0, 1] as T 2^-k.
exactccd::exact::DyadicTime split(double t) {
  exactccd::exact::DyadicTime d;
  exactccd::exact::dyadic_time(t, &d);
  return d;
}

void kernels_cubic(benchmark::State& state, Arithmetic a) {
  const KernelSet& set = kernel_set();
  std::size_t sink = 0;
  for (auto _ : state) {
    if (a == Arithmetic::boost) {
      for (const auto& q : set.vertex_face) {
        const IntegerCoordinates c = exactccd::exact::integer_coordinates(q);
        with_boost_width(exactccd::exact::cubic_coefficient_bits(c.bits), [&](auto zero) {
          decltype(zero) coefficients[4];
          exactccd::exact::coplanarity_coefficients(c, coefficients);
          sink += coefficients[0].sign() > 0;
        });
      }
      for (const auto& q : set.edge_edge) {
        const IntegerCoordinates c = exactccd::exact::integer_coordinates(q);
        with_boost_width(exactccd::exact::cubic_coefficient_bits(c.bits), [&](auto zero) {
          decltype(zero) coefficients[4];
          exactccd::exact::coplanarity_coefficients(c, coefficients);
          sink += coefficients[0].sign() > 0;
        });
      }
    } else {
      for (const auto& q : set.vertex_face)
        sink += IntegerQuery(q, library_arithmetic(a)).coefficient_limbs();
      for (const auto& q : set.edge_edge)
        sink += IntegerQuery(q, library_arithmetic(a)).coefficient_limbs();
    }
    benchmark::DoNotOptimize(sink);
  }
  state.counters["queries"] = static_cast<double>(set.coordinates.size());
  state.counters["per_query"] = benchmark::Counter(
      static_cast<double>(set.coordinates.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// The library's queries for the value and contact kernels (built outside the timed loop).
std::vector<IntegerQuery> library_queries(Arithmetic a) {
  const KernelSet& set = kernel_set();
  std::vector<IntegerQuery> out;
  for (const auto& q : set.vertex_face) out.emplace_back(q, library_arithmetic(a));
  for (const auto& q : set.edge_edge) out.emplace_back(q, library_arithmetic(a));
  return out;
}

/// Boost coefficients in the width of each query's value bound.
struct BoostCoefficients {
  std::vector<std::pair<std::size_t, std::array<BoostFixed<256>, 4>>> w256;
  std::vector<std::pair<std::size_t, std::array<BoostFixed<512>, 4>>> w512;
  std::vector<std::pair<std::size_t, std::array<BoostFixed<1024>, 4>>> w1024;
};

BoostCoefficients boost_coefficients() {
  const KernelSet& set = kernel_set();
  BoostCoefficients out;
  for (std::size_t i = 0; i < set.coordinates.size(); ++i) {
    const IntegerCoordinates& c = set.coordinates[i];
    const long bits = exactccd::exact::cubic_value_bits(c.bits, split(set.times[i]).exponent);
    with_boost_width(bits, [&](auto zero) {
      using Int = decltype(zero);
      Int k[4];
      exactccd::exact::coplanarity_coefficients(c, k);
      const std::array<Int, 4> a = {k[0], k[1], k[2], k[3]};
      if constexpr (std::is_same_v<Int, BoostFixed<256>>) out.w256.emplace_back(i, a);
      else if constexpr (std::is_same_v<Int, BoostFixed<512>>) out.w512.emplace_back(i, a);
      else out.w1024.emplace_back(i, a);
    });
  }
  return out;
}

template <class Groups>
std::size_t boost_values(const Groups& groups, const KernelSet& set) {
  std::size_t sink = 0;
  for (const auto& [i, a] : groups) {
    using Int = typename std::decay_t<decltype(a)>::value_type;
    const Int k[4] = {a[0], a[1], a[2], a[3]};
    const auto d = split(set.times[i]);
    sink += exactccd::exact::scaled_cubic_value(k, d.numerator, d.exponent).sign() > 0;
  }
  return sink;
}

void kernels_value(benchmark::State& state, Arithmetic a) {
  const KernelSet& set = kernel_set();
  const std::vector<IntegerQuery> queries =
      a == Arithmetic::boost ? std::vector<IntegerQuery>{} : library_queries(a);
  const BoostCoefficients boost = a == Arithmetic::boost ? boost_coefficients()
                                                         : BoostCoefficients{};
  std::size_t sink = 0;
  for (auto _ : state) {
    if (a == Arithmetic::boost) {
      sink += boost_values(boost.w256, set) + boost_values(boost.w512, set) +
              boost_values(boost.w1024, set);
    } else {
      for (std::size_t i = 0; i < queries.size(); ++i)
        sink += queries[i].cubic_sign_at(set.times[i]) > 0;
    }
    benchmark::DoNotOptimize(sink);
  }
  state.counters["queries"] = static_cast<double>(set.coordinates.size());
  state.counters["per_query"] = benchmark::Counter(
      static_cast<double>(set.coordinates.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void kernels_contact(benchmark::State& state, Arithmetic a) {
  const KernelSet& set = kernel_set();
  const std::vector<IntegerQuery> queries =
      a == Arithmetic::boost ? std::vector<IntegerQuery>{} : library_queries(a);
  std::size_t sink = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < set.coordinates.size(); ++i) {
      if (a != Arithmetic::boost) {
        sink += queries[i].contact_at(set.times[i]);
        continue;
      }
      const IntegerCoordinates& c = set.coordinates[i];
      const auto d = split(set.times[i]);
      with_boost_width(exactccd::exact::contact_bits(c.bits, d.exponent), [&](auto zero) {
        sink += exactccd::exact::contact_at_time<decltype(zero)>(c, d.numerator, d.exponent);
      });
    }
    benchmark::DoNotOptimize(sink);
  }
  state.counters["queries"] = static_cast<double>(set.coordinates.size());
  state.counters["per_query"] = benchmark::Counter(
      static_cast<double>(set.coordinates.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(kernels_cubic, kernels/cubic/fixed, Arithmetic::fixed)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(kernels_cubic, kernels/cubic/gmp, Arithmetic::gmp)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(kernels_cubic, kernels/cubic/boost, Arithmetic::boost)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(kernels_value, kernels/value/fixed, Arithmetic::fixed)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(kernels_value, kernels/value/gmp, Arithmetic::gmp)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(kernels_value, kernels/value/boost, Arithmetic::boost)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(kernels_contact, kernels/contact/fixed, Arithmetic::fixed)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(kernels_contact, kernels/contact/gmp, Arithmetic::gmp)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(kernels_contact, kernels/contact/boost, Arithmetic::boost)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
