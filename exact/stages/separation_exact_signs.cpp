// PROOF: proofs/min_separation.md#interval-search
// PROOF: proofs/min_separation.md#fixed-width-signs
#include "exact/stages/separation_exact_signs.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/separation.hpp"

namespace exactccd::exact::separation {

namespace {

using predicates::FixedPoly;
using predicates::Vec3;
using Point = Vec3<FixedPoly<mpz_class, 0>>;

/// d = mantissa 2^exponent with an integer mantissa (|mantissa| < 2^53); 0 for d = 0.
void split(double d, std::int64_t* mantissa, int* exponent) {
  int e = 0;
  const double f = std::frexp(d, &e);  // d = f 2^e, 0.5 <= |f| < 1
  *mantissa = static_cast<std::int64_t>(std::ldexp(f, 53));
  *exponent = e - 53;
}

Point point(const std::array<mpz_class, 3>& x) {
  return {FixedPoly<mpz_class, 0>{{x[0]}}, FixedPoly<mpz_class, 0>{{x[1]}},
          FixedPoly<mpz_class, 0>{{x[2]}}};
}

/// The exponent of t's last bit: t = m 2^e with an integer m (0 for t = 0).
long ulp_exponent(double t) {
  if (t == 0) return 0;
  std::int64_t m = 0;
  int e = 0;
  split(t, &m, &e);
  return e;
}

thread_local std::uint64_t g_gmp_evaluations = 0;

}  // namespace

std::uint64_t gmp_evaluations_in_this_thread() noexcept { return g_gmp_evaluations; }

namespace {
thread_local std::uint64_t g_bounded_decisions = 0;
}  // namespace

std::uint64_t bounded_decisions_in_this_thread() noexcept { return g_bounded_decisions; }

ExactSignsAtDoubles::ExactSignsAtDoubles(const std::array<const Eigen::Vector3d*, 4>& t0,
                                         const std::array<const Eigen::Vector3d*, 4>& t1,
                                         double delta, predicates::SeparationPair pair)
    : t0_(t0), t1_(t1), delta_(delta), pair_(pair) {}

const exact::SeparationIntegers& ExactSignsAtDoubles::q() const {
  if (!q_) q_.emplace(exact::separation_integers(t0_, t1_, delta_));
  return *q_;
}

int ExactSignsAtDoubles::sign_at(int k, double t) const {
  return pair_ == predicates::SeparationPair::vertex_face ? vertex_face_sign(k, t)
                                                          : edge_edge_sign(k, t);
}

auto ExactSignsAtDoubles::probe_at(int k, double t) const -> Probe {
  return pair_ == predicates::SeparationPair::vertex_face ? vertex_face_probe(k, t)
                                                          : edge_edge_probe(k, t);
}

double ExactSignsAtDoubles::secant_guess(int k, double lo, double hi) const {
  return pair_ == predicates::SeparationPair::vertex_face ? vertex_face_secant(k, lo, hi)
                                                          : edge_edge_secant(k, lo, hi);
}

double ExactSignsAtDoubles::newton_guess(int k, double lo, double hi) const {
  return pair_ == predicates::SeparationPair::vertex_face ? vertex_face_guess(k, lo, hi)
                                                          : edge_edge_guess(k, lo, hi);
}

void ExactSignsAtDoubles::exact_coefficients(CoefficientTable* out) const {
  if (pair_ == predicates::SeparationPair::vertex_face) {
    vertex_face_coefficients(out);
  } else {
    edge_edge_coefficients(out);
  }
}

auto ExactSignsAtDoubles::scaled_inputs() const -> const ScaledInputs& {
  if (!scaled_) {
    ScaledInputs s{};
    s.exact = true;
    const int shift = q().common_exponent + q().bits;
    auto scaled = [&](const exact::Dyadic& x) {
      // m 2^p, exact when its magnitude is at least 2^-1022 (normal; |m| < 2^53), which is
      // decided from m and p: the rounded result can equal 2^-1022 when the exact one is
      // below it. A product by the double 2^p where that is normal, else ldexp (ldexp always
      // costs more than the rest of a contact's set-up).
      if (x.mantissa == 0) return 0.0;
      const int p = x.exponent - shift;
      s.exact &= p + exact::mantissa_bits(x.mantissa) - 1 >= -1022;
      const double m = static_cast<double>(x.mantissa);
      return p >= -1022 && p <= 1023
                 ? m * predicates::double_of(static_cast<std::uint64_t>(p + 1023) << 52)
                 : std::ldexp(m, p);
    };
    for (int end = 0; end < 2; ++end)
      for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) s.x[end][i][c] = scaled(q().coords[end][i][c]);
    s.delta = scaled(q().delta);
    scaled_ = s;
  }
  return *scaled_;
}

auto ExactSignsAtDoubles::gmp() const -> const Gmp& {
  if (!gmp_) {
    Gmp g;
    const int e = q().common_exponent;
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c) {
        g.x0[i][c] = exact::separation_integer<mpz_class>(q().coords[0][i][c], e, 0);
        g.dx[i][c] = exact::separation_integer<mpz_class>(q().coords[1][i][c], e, 0) - g.x0[i][c];
      }
    g.delta = exact::separation_integer<mpz_class>(q().delta, e, 0);
    gmp_.emplace(std::move(g));
  }
  return *gmp_;
}

void ExactSignsAtDoubles::at(double t, long shift, std::array<Position, 4>* positions,
                             mpz_class* delta) const {
  // t = m 2^e: positions (x0 + t dx) 2^shift = x0 2^shift + m dx 2^(shift + e), exactly.
  std::int64_t m = 0;
  int e = 0;
  if (t != 0) split(t, &m, &e);
  const mpz_class mz(static_cast<long>(m));
  const mp_bitcnt_t up = static_cast<mp_bitcnt_t>(shift);
  const mp_bitcnt_t up_m = t == 0 ? 0 : static_cast<mp_bitcnt_t>(shift + e);
  const Gmp& g = gmp();
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c)
      (*positions)[i][c] = (g.x0[i][c] << up) + ((mz * g.dx[i][c]) << up_m);
  *delta = g.delta << up;
}

template <class Make>
mpz_class ExactSignsAtDoubles::value(const Make& make, int k, double t, long shift) const {
  ++g_gmp_evaluations;
  exact_arithmetic_ = true;
  std::array<Position, 4> x;
  mpz_class d;
  at(t, shift, &x, &d);
  const mpz_class d2 = d * d;
  mpz_class v;
  make(point(x[0]), point(x[1]), point(x[2]), point(x[3]), d2)
      .for_each_polynomial([&v](const auto& g) { v = g.c[0]; }, k);
  return v;
}

template <class Make>
double ExactSignsAtDoubles::secant(const Make& make, int k, double lo, double hi) const {
  // One scale for both ends (the finer ulp's), so that the values are comparable.
  const long shift = std::max(-ulp_exponent(lo), -ulp_exponent(hi));
  const mpz_class v_lo = value(make, k, lo, shift), v_hi = value(make, k, hi, shift);
  const mpz_class diff = v_lo - v_hi;
  if (sgn(diff) == 0) return std::numeric_limits<double>::quiet_NaN();
  long e_num = 0, e_den = 0;
  const double num = mpz_get_d_2exp(&e_num, v_lo.get_mpz_t());
  const double den = mpz_get_d_2exp(&e_den, diff.get_mpz_t());
  return lo + (hi - lo) * std::ldexp(num / den, static_cast<int>(e_num - e_den));
}

namespace {

struct MakeVertexFace {
  template <class Point, class NT>
  auto operator()(const Point& p, const Point& a, const Point& b, const Point& c,
                  const NT& d2) const {
    return predicates::vertex_face_separation(p, a, b, c, d2);
  }
};

struct MakeEdgeEdge {
  template <class Point, class NT>
  auto operator()(const Point& a0, const Point& a1, const Point& b0, const Point& b1,
                  const NT& d2) const {
    return predicates::edge_edge_separation(a0, a1, b0, b1, d2);
  }
};

}  // namespace

namespace {

/// An interval enclosing z 2^-shift, z an integer whose bit length is at most shift (the
/// enclosure lies in [-1, 1]); below 2^-1000 in magnitude, [0, 2^-1000] on z's side of 0.
Interval enclosure(const mpz_class& z, long shift) {
  if (sgn(z) == 0) return Interval(0);
  long e = 0;
  const double d = mpz_get_d_2exp(&e, z.get_mpz_t());  // z = (d + r) 2^e, 0.5 <= |d| < 1,
                                                        // d truncated: r on d's side, |r| < ulp
  const bool exact = mpz_sizeinbase(z.get_mpz_t(), 2) - mpz_scan1(z.get_mpz_t(), 0) <= 53;
  double lo = d, hi = d;
  if (!exact) (d > 0 ? hi : lo) = std::nextafter(d, d > 0 ? 1.0 : -1.0);
  const long x = e - shift;  // <= 0
  if (x < -1000) return d > 0 ? Interval(0, 0x1p-1000) : Interval(-0x1p-1000, 0);
  return Interval(std::ldexp(lo, static_cast<int>(x)), std::ldexp(hi, static_cast<int>(x)));
}

}  // namespace

template <class Make>
void ExactSignsAtDoubles::coefficients(const Make& make, CoefficientTable* out) const {
  ++g_gmp_evaluations;
  exact_arithmetic_ = true;
  // The moving vertices x0 + t dx as integer polynomials (times 2^-E, as delta): every region
  // polynomial is homogeneous in them and delta, so this scale changes no sign either.
  using Moving = Vec3<FixedPoly<mpz_class, 1>>;
  const Gmp& g = gmp();
  auto moving = [&g](int i) {
    auto axis = [&](int c) { return FixedPoly<mpz_class, 1>{{g.x0[i][c], g.dx[i][c]}}; };
    return Moving{axis(0), axis(1), axis(2)};
  };
  const std::array<Moving, 4> x{moving(0), moving(1), moving(2), moving(3)};
  const mpz_class d2 = g.delta * g.delta;
  int k = 0;
  make(x[0], x[1], x[2], x[3], d2).for_each_polynomial([&](const auto& p) {
    constexpr int D = std::decay_t<decltype(p)>::degree;
    long bits = 0;  // the polynomial's largest coefficient bit length: its scale 2^-bits
    for (int i = 0; i <= D; ++i)
      bits = std::max(bits, static_cast<long>(mpz_sizeinbase(p.c[i].get_mpz_t(), 2)));
    for (int i = 0; i <= 6; ++i) (*out)[k].c[i] = i <= D ? enclosure(p.c[i], bits) : Interval(0);
    ++k;
  });
}

namespace {

/// f(Ints) for the staged integer types that the differences' bit bound selects:
/// FixedInt widths up to kMaxDifferenceLimbs, GMP beyond (counted).
template <class F>
auto with_stage_integers(long difference_bits, F&& f) {
  switch (exact::fixed_limbs_for(difference_bits)) {
    case 1: return f(exact::FixedStageIntegers<1>{});
    case 2: return f(exact::FixedStageIntegers<2>{});
    case 3: return f(exact::FixedStageIntegers<3>{});
    default: ++g_gmp_evaluations; return f(exact::GmpStageIntegers{});
  }
  static_assert(exact::kMaxDifferenceLimbs == 3, "extend the cases above");
}

}  // namespace

auto ExactSignsAtDoubles::vertex_face_kernel(int k) -> IntegerKernel {
  if (k == 0) return {&exact::kVertexFaceRegion, KernelKind::face_like};
  if (k < 4 || k >= 16) return {};
  const int edge = (k - 4) / 4;  // 4 + 4i the sphere, 5 + 4i and 6 + 4i the projections
  switch ((k - 4) % 4) {
    case 0: return {&exact::kVertexFaceSpheres[edge], KernelKind::sphere};
    case 1: return {&exact::kVertexFaceCapsules[edge], KernelKind::projection};
    case 2: return {&exact::kVertexFaceProjectionsFromY[edge], KernelKind::projection};
    default: return {&exact::kVertexFaceCapsules[edge], KernelKind::capsule};
  }
}

auto ExactSignsAtDoubles::edge_edge_kernel(int k) -> IntegerKernel {
  if (k == 0) return {&exact::kEdgeEdgeRegion, KernelKind::face_like};
  if (k >= 5 && k <= 8) return {&exact::kEdgeEdgeSpheres[k - 5], KernelKind::sphere};
  if (k < 9 || k >= 21) return {};
  const int endpoint = (k - 9) / 3;  // 9 + 3i and 10 + 3i the projections, 11 + 3i the capsule
  switch ((k - 9) % 3) {
    case 0: return {&exact::kEdgeEdgeCapsules[endpoint], KernelKind::projection};
    case 1: return {&exact::kEdgeEdgeProjectionsFromY[endpoint], KernelKind::projection};
    default: return {&exact::kEdgeEdgeCapsules[endpoint], KernelKind::capsule};
  }
}

const exact::StoredStepDifferences* ExactSignsAtDoubles::fixed_differences(
    const exact::DifferenceVertices& v) const {
  if (q().bits + 2 > 64 * exact::kMaxDifferenceLimbs - 1) return nullptr;
  if (fixed_differences_of_ != &v) {
    fixed_differences_.emplace(
        exact::step_differences<exact::FixedInt<exact::kMaxDifferenceLimbs>>(q(), v));
    fixed_differences_of_ = &v;
  }
  return &*fixed_differences_;
}

template <class Ints, class F, std::size_t N>
auto ExactSignsAtDoubles::kernel_values(const IntegerKernel& kernel,
                                        const std::uint64_t (&ts)[N], unsigned k,
                                        F&& f) const {
  auto each = [&](const auto& differences) {
    std::array<exact::Approximation, N> out{};
    int sign = 0;
    for (std::size_t i = 0; i < N; ++i) {
      auto take = [&](const auto& v) {
        sign = exact::sign_of(v);
        out[i] = exact::approximate(v);
      };
      switch (kernel.kind) {
        case KernelKind::face_like:
          take(exact::face_like_value<Ints>(differences, ts[i], k));
          break;
        case KernelKind::capsule: take(exact::capsule_value<Ints>(differences, ts[i], k)); break;
        case KernelKind::sphere: take(exact::sphere_value<Ints>(differences, ts[i], k)); break;
        case KernelKind::projection:
          take(exact::projection_value<Ints>(differences, ts[i], k));
          break;
      }
    }
    return f(sign, out);
  };
  if constexpr (std::is_same_v<typename Ints::Difference, mpz_class>) {
    return each(exact::step_differences<mpz_class>(q(), *kernel.vertices));
  } else {
    // A fixed width was selected: B + 2 <= 191, so the stored differences exist.
    return each(*fixed_differences(*kernel.vertices));
  }
}

auto ExactSignsAtDoubles::kernel_value_at(const IntegerKernel& kernel, double t) const
    -> KernelValue {
  exact_arithmetic_ = true;
  exact::DyadicTime d;
  exact::dyadic_time(t, &d);  // the callers pass t in [0, 1]
  const std::uint64_t ts[1] = {d.numerator};
  const KernelValue v = with_stage_integers(
      exact::separation_difference_bits(q().bits, d.exponent), [&](auto ints) {
        return kernel_values<decltype(ints)>(kernel, ts, d.exponent,
                                             [&](int sign, const auto& approx) {
                                               return KernelValue{sign, approx[0], d.exponent};
                                             });
      });
  return v;
}

std::optional<dd::Bounded> ExactSignsAtDoubles::bounded_value(const IntegerKernel& kernel,
                                                              double t) const {
  // Rounding to nearest: the coordinates and delta scaled by 2^-(E + L) (magnitudes below 1;
  // exact where the result is a normal double or 0), the kernel's differences at t from their
  // exact values at t = 0 and t = 1, and the kernel's expression, each operation's error
  // bounded. PROOF: proofs/min_separation.md#double-double-signs
  const ScaledInputs& in = scaled_inputs();
  if (!in.exact) return std::nullopt;
  const predicates::RoundToNearestGuard nearest;
  // The differences at t = 0 (exact) and their changes over the step, kept for the kernel's
  // vertices: a search asks the same kernel at several times.
  if (!bounded_steps_) bounded_steps_.emplace();
  BoundedSteps& steps = *bounded_steps_;
  if (steps.of != kernel.vertices) {
    for (int j = 0; j < 3; ++j)
      for (int c = 0; c < 3; ++c) {
        const int o = kernel.vertices->origin[j], e = kernel.vertices->end[j];
        steps.d0[j][c] = dd::exact_sum(in.x[0][e][c], -in.x[0][o][c]);
        steps.change[j][c] = dd::exact_sum(in.x[1][e][c], -in.x[1][o][c]) - steps.d0[j][c];
      }
    steps.of = kernel.vertices;
  }
  const dd::Bounded time = dd::exactly(t);
  dd::Bounded d[3][3];
  for (int j = 0; j < 3; ++j)
    for (int c = 0; c < 3; ++c) d[j][c] = steps.d0[j][c] + time * steps.change[j][c];
  const dd::Bounded delta = dd::exactly(in.delta);
  return kernel_expression(kernel.kind, d, delta * delta);
}

auto ExactSignsAtDoubles::kernel_signed_value(const IntegerKernel& kernel, double t) const
    -> SignedValue {
  const std::optional<dd::Bounded> v = bounded_value(kernel, t);
  if (v) {
    const int s = dd::certified_sign(*v);
    if (s != dd::kUncertain) {
      ++g_bounded_decisions;
      return {s, v->hi};
    }
  }
  const KernelValue exact = kernel_value_at(kernel, t);
  return {exact.sign, scaled_value(kernel.kind, exact)};
}

int ExactSignsAtDoubles::kernel_sign(const IntegerKernel& kernel, double t) const {
  return kernel_signed_value(kernel, t).sign;
}

namespace {

using Vec = std::array<double, 3>;
// Over double[3] and Vec alike.
template <class A, class B>
double dot3(const A& a, const B& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class A, class B>
Vec cross3(const A& a, const B& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec plus3(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

}  // namespace

double ExactSignsAtDoubles::scaled_value(KernelKind kind, const KernelValue& v) const {
  // The integer value is 2^(d(k - E)) g(t) for g of degree d, the unit 2^(E + L).
  const int degree = kind == KernelKind::face_like ? 6 : kind == KernelKind::capsule ? 4 : 2;
  const long exponent = v.value.exponent - degree * (static_cast<long>(v.k) + q().bits);
  return std::ldexp(v.value.mantissa, static_cast<int>(std::clamp(exponent, -4000L, 4000L)));
}

double ExactSignsAtDoubles::kernel_slope(KernelKind kind, const double (&d)[3][3],
                                         const double (&step)[3][3], double delta2) {
  const auto &w = d[0], &e = d[1], &w1 = step[0], &e1 = step[1];
  switch (kind) {
    case KernelKind::capsule: {  // c = (w.w)(e.e) - (w.e)^2 - delta^2 (e.e)
      const double ee = dot3(e, e), we = dot3(w, e);
      return 2 * dot3(w, w1) * ee + 2 * dot3(w, w) * dot3(e, e1) -
             2 * we * (dot3(w1, e) + dot3(w, e1)) - 2 * delta2 * dot3(e, e1);
    }
    case KernelKind::face_like: {  // g = (W.m)^2 - delta^2 (m.m), m = U x V
      const Vec m = cross3(d[0], d[1]);
      const Vec m1 = plus3(cross3(step[0], d[1]), cross3(d[0], step[1]));
      const double wm = dot3(m, d[2]);
      return 2 * wm * (dot3(m, step[2]) + dot3(m1, d[2])) - 2 * delta2 * dot3(m, m1);
    }
    case KernelKind::sphere: return 2 * dot3(w, w1);  // s = w.w - delta^2
    case KernelKind::projection: return dot3(w1, e) + dot3(w, e1);  // w.e
  }
  return 0;
}

auto ExactSignsAtDoubles::plain_value_slope(const IntegerKernel& kernel, double t) const
    -> ValueSlope {
  const ScaledInputs& in = scaled_inputs();
  double d[3][3], step[3][3];
  for (int j = 0; j < 3; ++j)
    for (int c = 0; c < 3; ++c) {
      const int o = kernel.vertices->origin[j], e = kernel.vertices->end[j];
      const double d0 = in.x[0][e][c] - in.x[0][o][c];
      step[j][c] = (in.x[1][e][c] - in.x[1][o][c]) - d0;
      d[j][c] = d0 + t * step[j][c];
    }
  const double delta2 = in.delta * in.delta;
  return {kernel_expression(kernel.kind, d, delta2), kernel_slope(kernel.kind, d, step, delta2)};
}

auto ExactSignsAtDoubles::kernel_probe(const IntegerKernel& kernel, double t) const -> Probe {
  const SignedValue v = kernel_signed_value(kernel, t);
  // The Newton step from the same value (its leading part), g'(t) in plain arithmetic.
  const double guess = t - v.value / plain_value_slope(kernel, t).slope;
  return {true, v.sign, std::isfinite(guess) ? guess : std::numeric_limits<double>::quiet_NaN()};
}

double ExactSignsAtDoubles::kernel_guess(const IntegerKernel& kernel, double lo,
                                         double hi) const {
  // Safeguarded Newton: [a, b] keeps a sign change of the plain values (a guess's bracket, not
  // a certified one); a step that leaves it is a bisection. Done when a step is within a few
  // ulps: closer, the plain values are rounding noise.
  constexpr int kSteps = 12;
  double a = lo, b = hi;
  const double value_a = plain_value_slope(kernel, a).value;
  double t = a + 0.5 * (b - a);
  for (int i = 0; i < kSteps; ++i) {
    const ValueSlope g = plain_value_slope(kernel, t);
    if (g.value == 0) return t;
    double next = t - g.value / g.slope;
    if (std::fabs(next - t) <= 0x1p-50 * std::fabs(t)) return next;
    ((g.value > 0) == (value_a > 0) ? a : b) = t;
    if (!(next > a && next < b)) next = a + 0.5 * (b - a);
    t = next;
  }
  return t;
}

auto ExactSignsAtDoubles::vertex_face_probe(int k, double t) const -> Probe {
  const IntegerKernel kernel = vertex_face_kernel(k);
  if (kernel.vertices && t >= 0 && t <= 1) return kernel_probe(kernel, t);
  return {false, vertex_face_sign(k, t), std::numeric_limits<double>::quiet_NaN()};
}

auto ExactSignsAtDoubles::edge_edge_probe(int k, double t) const -> Probe {
  const IntegerKernel kernel = edge_edge_kernel(k);
  if (kernel.vertices && t >= 0 && t <= 1) return kernel_probe(kernel, t);
  return {false, edge_edge_sign(k, t), std::numeric_limits<double>::quiet_NaN()};
}

double ExactSignsAtDoubles::vertex_face_guess(int k, double lo, double hi) const {
  const IntegerKernel kernel = vertex_face_kernel(k);
  return kernel.vertices ? kernel_guess(kernel, lo, hi) : std::numeric_limits<double>::quiet_NaN();
}

double ExactSignsAtDoubles::edge_edge_guess(int k, double lo, double hi) const {
  const IntegerKernel kernel = edge_edge_kernel(k);
  return kernel.vertices ? kernel_guess(kernel, lo, hi) : std::numeric_limits<double>::quiet_NaN();
}

int ExactSignsAtDoubles::vertex_face_sign(int k, double t) const {
  const IntegerKernel kernel = vertex_face_kernel(k);
  if (kernel.vertices && t >= 0 && t <= 1) return kernel_sign(kernel, t);
  return sgn(value(MakeVertexFace{}, k, t, -ulp_exponent(t)));
}

int ExactSignsAtDoubles::edge_edge_sign(int k, double t) const {
  const IntegerKernel kernel = edge_edge_kernel(k);
  if (kernel.vertices && t >= 0 && t <= 1) return kernel_sign(kernel, t);
  return sgn(value(MakeEdgeEdge{}, k, t, -ulp_exponent(t)));
}

double ExactSignsAtDoubles::vertex_face_secant(int k, double lo, double hi) const {
  return secant(MakeVertexFace{}, k, lo, hi);
}

void ExactSignsAtDoubles::vertex_face_coefficients(CoefficientTable* out) const {
  coefficients(MakeVertexFace{}, out);
}

void ExactSignsAtDoubles::edge_edge_coefficients(CoefficientTable* out) const {
  coefficients(MakeEdgeEdge{}, out);
}

double ExactSignsAtDoubles::edge_edge_secant(int k, double lo, double hi) const {
  return secant(MakeEdgeEdge{}, k, lo, hi);
}

}  // namespace exactccd::exact::separation
