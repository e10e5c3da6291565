#include "exact/integer_query.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "core/predicates/double_bits.hpp"
#include "core/predicates/fp_environment.hpp"
#include "core/predicates/inclusion.hpp"
#include "exact/rational.hpp"

namespace exactccd::exact {

namespace {

using predicates::FixedPoly;
using predicates::Vec3;
using Dyadic = IntegerQuery::Dyadic;

Dyadic dyadic(double x) {
  if (x == 0) return {};
  int e;
  const double m = std::frexp(x, &e);  // x = m 2^e, 0.5 <= |m| < 1: exact
  return {static_cast<std::int64_t>(std::ldexp(m, 53)), e - 53};
}

/// z = d * 2^(d.exponent - common): the coordinate scaled to an integer.
void set_scaled(mpz_class& z, const Dyadic& d, int common) {
  z = static_cast<long>(d.mantissa);
  if (d.mantissa != 0) mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), d.exponent - common);
}

/// Per-thread temporaries: their limbs are reused from query to query.
struct Workspace {
  mpz_class a, b;                        // scratch
  mpz_class v0[3], dv[3], w0[3], dw[3], u0[3], du[3];
  mpz_class x0[3], x1[3], x2[3];         // cross(v, w) = x0 + t x1 + t^2 x2
  mpz_class r, term;                     // Horner
};
thread_local Workspace workspace;

/// out = first - second for the scaled coordinate k of two points, at t = 0 and t = 1.
void difference(const Dyadic (&c)[8][3], int common, int first, int second, mpz_class out0[3],
                mpz_class out1[3]) {
  Workspace& w = workspace;
  for (int k = 0; k < 3; ++k) {
    set_scaled(w.a, c[first][k], common);
    set_scaled(w.b, c[second][k], common);
    out0[k] = w.a - w.b;
    set_scaled(w.a, c[first + 4][k], common);
    set_scaled(w.b, c[second + 4][k], common);
    out1[k] = w.a - w.b;
    out1[k] -= out0[k];  // the change over the step
  }
}

/// out += p x q, componentwise, with add-multiply (no temporaries).
void add_cross(mpz_class out[3], const mpz_class p[3], const mpz_class q[3]) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    mpz_addmul(out[k].get_mpz_t(), p[i].get_mpz_t(), q[j].get_mpz_t());
    mpz_submul(out[k].get_mpz_t(), p[j].get_mpz_t(), q[i].get_mpz_t());
  }
}

void add_dot(mpz_class& out, const mpz_class p[3], const mpz_class q[3]) {
  for (int k = 0; k < 3; ++k) mpz_addmul(out.get_mpz_t(), p[k].get_mpz_t(), q[k].get_mpz_t());
}

/// Positions at t = tau 2^-k, scaled by 2^k: 2^k x0 + tau (x1 - x0), exact integers.
using Position = Vec3<FixedPoly<mpz_class, 0>>;
Position position_at(const Dyadic (&c)[8][3], int common, int point, long tau, long k) {
  Position p;
  mpz_class* out[3] = {&p.x.c[0], &p.y.c[0], &p.z.c[0]};
  for (int axis = 0; axis < 3; ++axis) {
    mpz_class x0, x1;
    set_scaled(x0, c[point][axis], common);
    set_scaled(x1, c[point + 4][axis], common);
    mpz_class& r = *out[axis];
    r = x1 - x0;
    r *= tau;
    mpz_mul_2exp(x0.get_mpz_t(), x0.get_mpz_t(), static_cast<mp_bitcnt_t>(k));
    r += x0;
  }
  return p;
}

}  // namespace

// The same cubics as core/predicates/coplanarity_cubic.hpp, expanded for in-place integer
// arithmetic (tests/filters_test.cpp checks the two agree): with v, w, u the difference
// vectors (vertex-face b-a, c-a, p-a; edge-edge a1-a0, b0-a0, b1-a0), each v0 + t dv,
// f(t) = (v x w) . u.
void IntegerQuery::compute_cubic() {
  int common = INT_MAX;
  for (const auto& point : coords_)
    for (const Dyadic& d : point)
      if (d.mantissa != 0) common = std::min(common, d.exponent);
  common_exponent_ = common == INT_MAX ? 0 : common;
  const bool vf = type_ == QueryType::vertex_face;
  // Row indices at t = 0 (the t = 1 row is index + 4).
  // vertex-face rows p, a, b, c: v = b - a, w = c - a, u = p - a;
  // edge-edge rows a0, a1, b0, b1: v = a1 - a0, w = b0 - a0, u = b1 - a0.
  const int origin = vf ? 1 : 0, v_end = vf ? 2 : 1, w_end = vf ? 3 : 2, u_end = vf ? 0 : 3;
  Workspace& ws = workspace;
  difference(coords_, common_exponent_, v_end, origin, ws.v0, ws.dv);
  difference(coords_, common_exponent_, w_end, origin, ws.w0, ws.dw);
  difference(coords_, common_exponent_, u_end, origin, ws.u0, ws.du);
  for (int k = 0; k < 3; ++k) ws.x0[k] = 0, ws.x1[k] = 0, ws.x2[k] = 0;
  add_cross(ws.x0, ws.v0, ws.w0);
  add_cross(ws.x1, ws.v0, ws.dw);
  add_cross(ws.x1, ws.dv, ws.w0);
  add_cross(ws.x2, ws.dv, ws.dw);
  for (auto& c : cubic_) c = 0;
  add_dot(cubic_[0], ws.x0, ws.u0);
  add_dot(cubic_[1], ws.x0, ws.du);
  add_dot(cubic_[1], ws.x1, ws.u0);
  add_dot(cubic_[2], ws.x1, ws.du);
  add_dot(cubic_[2], ws.x2, ws.u0);
  add_dot(cubic_[3], ws.x2, ws.du);
}

IntegerQuery::IntegerQuery(const VertexFaceQuery& q) : type_(QueryType::vertex_face) {
  const Eigen::Vector3d* p[8] = {&q.p_t0, &q.a_t0, &q.b_t0, &q.c_t0,
                                 &q.p_t1, &q.a_t1, &q.b_t1, &q.c_t1};
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) coords_[i][k] = dyadic(p[i]->coeff(k));
  compute_cubic();
}

IntegerQuery::IntegerQuery(const EdgeEdgeQuery& q) : type_(QueryType::edge_edge) {
  const Eigen::Vector3d* p[8] = {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0,
                                 &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1};
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) coords_[i][k] = dyadic(p[i]->coeff(k));
  compute_cubic();
}

namespace {

/// Sets workspace.r = 2^shift f(t), an exact integer with the sign of f(t), for the finite
/// double t >= 0, and returns shift (t = T 2^-k: shift = 3k; t = 0 or an integer t: 0).
long evaluate_scaled(const mpz_class (&cubic)[4], double t) {
  Workspace& ws = workspace;
  if (t == 0) {
    ws.r = cubic[0];
    return 0;
  }
  // t = T 2^-k: 2^(3k) f(t) = ((c3 T + c2 2^k) T + c1 2^(2k)) T + c0 2^(3k), all integers.
  const Dyadic d = dyadic(t);
  if (d.exponent >= 0) {  // an integer t (t >= 2^52)
    mpz_class tz = static_cast<long>(d.mantissa);
    mpz_mul_2exp(tz.get_mpz_t(), tz.get_mpz_t(), static_cast<mp_bitcnt_t>(d.exponent));
    ws.r = cubic[3];
    for (int i = 2; i >= 0; --i) {
      ws.r *= tz;
      ws.r += cubic[i];
    }
    return 0;
  }
  const long T = static_cast<long>(d.mantissa);
  const auto k = static_cast<mp_bitcnt_t>(-d.exponent);
  ws.r = cubic[3];
  for (int i = 2; i >= 0; --i) {
    ws.r *= T;
    mpz_mul_2exp(ws.term.get_mpz_t(), cubic[i].get_mpz_t(), k * static_cast<mp_bitcnt_t>(3 - i));
    ws.r += ws.term;
  }
  return 3 * static_cast<long>(k);
}

}  // namespace

int IntegerQuery::cubic_sign_at(double t) const {
  evaluate_scaled(cubic_, t);
  return sgn(workspace.r);
}

// ---------------------------------------------------------------------------------------------
// Root bracketing with guided probes. PROOF: proofs/filters.md#guided-bisection
//
// The result is defined by the reference loop (bit-order bisection of [lo, hi] with the exact
// sign at every middle double; see reference_bisection below). Under the contract (f(lo) and
// f(hi) non-zero of opposite signs, exactly one root r in [lo, hi]) the sign of f at any
// t in [lo, hi] is sign_lo for t < r, 0 at r and -sign_lo for t > r, so the loop's path is a
// function of where r lies. bisect_root replays that path (for width 0 it returns the unique
// tightest pair as soon as the signs pin it) and asks for a sign only where the exact signs
// gathered so far do not already tell on which side of r the middle double lies; it gathers
// them first at points chosen by Newton's method (on exact values of f), which usually pin r
// between two consecutive doubles in two exact evaluations instead of the loop's 30 to 60.

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double next_up(double x) { return std::nextafter(x, kInf); }
double next_down(double x) { return std::nextafter(x, -kInf); }

/// hi - lo <= width exactly (0 <= lo <= hi finite, width > 0 finite): difference_at_most
/// without its rationals unless the rounded difference equals width. Rounding, in any IEEE
/// mode, is monotone and leaves a double unchanged, so hi - lo <= width gives
/// fl(hi - lo) <= width and hi - lo >= width gives fl(hi - lo) >= width; the difference
/// cannot overflow (0 <= hi - lo <= hi).
bool width_at_most(double hi, double lo, double width) {
  const double rounded = hi - lo;
  if (rounded != width) return rounded < width;
  return difference_at_most(hi, lo, width);
}

/// The bit pattern of the double x >= 0, with -0 read as +0: for non-negative doubles the
/// patterns are ordered as the values and consecutive doubles have consecutive patterns, so
/// next_up(x) has pattern order_bits(x) + 1 and, for x > 0, next_down(x) order_bits(x) - 1.
std::uint64_t order_bits(double x) { return x == 0 ? 0 : predicates::bits_of(x); }

double from_order_bits(std::uint64_t bits) { return predicates::double_of(bits); }

/// One step of the reference loop on [lo, hi] (lo, hi >= 0 finite): false when it stops
/// there (no double strictly inside, or width > 0 met), else true with *mid the middle
/// double of those strictly inside, in bit order (the loop's probe). The doubles strictly
/// inside have the patterns order_bits(lo) + 1 ... order_bits(hi) - 1.
bool middle_double(double lo, double hi, double width, double* mid) {
  const std::uint64_t l = order_bits(lo), h = order_bits(hi);
  if (h < l + 2 || (width > 0 && width_at_most(hi, lo, width))) return false;
  *mid = from_order_bits(l + 1 + (h - l - 2) / 2);
  return true;
}

/// The floating point of the guidance: x87 extended precision where long double is that
/// (64-bit significands: a first estimate within an ulp of the root more often, so one exact
/// evaluation fewer), else double (a long double emulated in software would cost more than
/// the evaluation it saves).
using Real = std::conditional_t<std::numeric_limits<long double>::digits == 64, long double,
                                double>;

/// z ~ m 2^e with 1/2 <= |m| <= 1 (m = 0 for z = 0), rounded from the two leading limbs:
/// a cheaper mpz_get_d_2exp, for guidance only.
Real approximate(const mpz_class& z, long* e) {
#if GMP_NUMB_BITS == 64 && defined(__GNUC__)
  const std::size_t n = mpz_size(z.get_mpz_t());
  if (n == 0) {
    *e = 0;
    return 0.0;
  }
  const mp_limb_t top = mpz_getlimbn(z.get_mpz_t(), n - 1);
  const mp_limb_t below = n >= 2 ? mpz_getlimbn(z.get_mpz_t(), n - 2) : 0;
  const int lz = __builtin_clzll(top);
  const std::uint64_t leading = lz == 0 ? top : (top << lz) | (below >> (64 - lz));
  *e = 64 * static_cast<long>(n) - lz;
  const Real m = static_cast<Real>(leading) * static_cast<Real>(0x1p-64);
  return mpz_sgn(z.get_mpz_t()) < 0 ? -m : m;
#else
  return mpz_get_d_2exp(e, z.get_mpz_t());
#endif
}

/// The reference loop: bit-order bisection with an exact sign at every middle double.
std::pair<double, double> reference_bisection(const IntegerQuery& q, double lo, double hi,
                                              double width, int sign_lo) {
  double mid;
  while (middle_double(lo, hi, width, &mid)) {
    const int s = q.cubic_sign_at(mid);
    if (s == 0) return {mid, mid};
    (s == sign_lo ? lo : hi) = mid;
  }
  return {lo, hi};
}

enum class Side { below, at, above, unknown };

/// What the exact signs gathered so far prove about the root r of the bracket [lo0, hi0],
/// under the contract. Once sign_lo (the sign of f on [lo0, r)) is known, a probe t with
/// f(t) != 0 is below r when its sign is sign_lo and above r otherwise. Before that, probes
/// that all have one sign are "pending": they are on one side of r, which one is unknown, and
/// a probe of the other sign settles it (r lies between the two kinds).
class RootKnowledge {
 public:
  RootKnowledge(double lo, double hi) : below_(lo), above_(hi) {}

  Side side_of(double t) const {
    if (root_known_) return t < root_ ? Side::below : t > root_ ? Side::above : Side::at;
    if (t <= below_) return Side::below;
    if (t >= above_) return Side::above;
    return Side::unknown;
  }
  bool sign_lo_known() const { return sign_lo_ != 0; }
  bool root_known() const { return root_known_; }
  double root() const { return root_; }
  double below() const { return below_; }
  double above() const { return above_; }

  /// Whether a probe at t can add anything: inside (below, above), and outside the pending
  /// range (a probe there would have the pending sign, or break the contract).
  bool informative(double t) const {
    if (!(t > below_ && t < above_)) return false;
    return sign_lo_ != 0 || !pending_ || t < pending_min_ || t > pending_max_;
  }

  /// Records sign(f(t)) = s for t in (below, above). False when the signs seen contradict
  /// the contract (two sign changes).
  bool learn(double t, int s) {
    if (s == 0) {  // the only root of [lo0, hi0]
      root_known_ = true;
      root_ = t;
      return true;
    }
    if (sign_lo_ != 0) {
      (s == sign_lo_ ? below_ : above_) = t;
      return true;
    }
    if (!pending_) {
      pending_ = true;
      pending_min_ = pending_max_ = t;
      pending_sign_ = s;
      return true;
    }
    if (s == pending_sign_) {
      pending_min_ = std::min(pending_min_, t);
      pending_max_ = std::max(pending_max_, t);
      return true;
    }
    if (t > pending_max_) {  // pending probes below r, t above it
      sign_lo_ = pending_sign_;
      below_ = pending_max_;
      above_ = t;
    } else if (t < pending_min_) {  // t below r, pending probes above it
      sign_lo_ = s;
      below_ = t;
      above_ = pending_min_;
    } else {
      return false;
    }
    pending_ = false;
    return true;
  }

  /// Records sign(f(lo0)) = s. False when s == 0 (the contract excludes it).
  bool learn_sign_lo(int s) {
    if (s == 0) return false;
    sign_lo_ = s;
    if (pending_ && pending_sign_ == s) below_ = pending_max_;
    if (pending_ && pending_sign_ != s) above_ = pending_min_;
    pending_ = false;
    return true;
  }

 private:
  double below_, above_;  // lo0 <= below < r < above <= hi0
  bool root_known_ = false;
  double root_ = 0;
  int sign_lo_ = 0;
  bool pending_ = false;
  double pending_min_ = 0, pending_max_ = 0;
  int pending_sign_ = 0;
};

/// Chooses probe points near the root: floating-point Newton on the cubic with rounded
/// coefficients for the first one, then Newton steps driven by the EXACT value of f at the
/// latest probe (rounded), aimed slightly past the predicted root so that consecutive probes
/// tend to straddle it. Nothing it computes decides anything: a poor guess only costs an
/// exact evaluation, whatever the precision of Real and the rounding mode.
class Guide {
 public:
  explicit Guide(const mpz_class (&cubic)[4]) {
    long exponent[4];
    Real mantissa[4];
    scale_ = LONG_MIN;
    for (int i = 0; i < 4; ++i) {
      mantissa[i] = approximate(cubic[i], &exponent[i]);
      if (mantissa[i] != 0) scale_ = std::max(scale_, exponent[i]);
    }
    if (scale_ == LONG_MIN) scale_ = 0;
    for (int i = 0; i < 4; ++i)  // f(t) ~ 2^scale (a0 + a1 t + a2 t^2 + a3 t^3)
      a_[i] = mantissa[i] * power_of_two(exponent[i] - scale_);
  }

  /// The next probe: a point where RootKnowledge::informative holds, or NaN when guidance
  /// has nothing useful to offer.
  double next_probe(const RootKnowledge& known, double lo, double hi) const {
    double x;
    if (!has_probe_) {
      x = initial_estimate(lo, hi);
    } else {
      x = newton_probe();
    }
    // r lies in (below, above): a target at or beyond an end means that r is next to it.
    if (x <= known.below()) x = next_up(known.below());
    if (x >= known.above()) x = next_down(known.above());
    return known.informative(x) ? x : std::numeric_limits<double>::quiet_NaN();
  }

  /// The probe t gave 2^shift f(t) = value (exact), of sign s != 0.
  void record(double t, int s, const mpz_class& value, long shift) {
    if (has_probe_ && s == sign_) ++misses_;
    else misses_ = 0;
    has_probe_ = true;
    t_ = t;
    sign_ = s;
    long e;
    m_ = approximate(value, &e);
    e_ = e - shift;  // f(t) ~ m 2^e
  }

 private:
  static int clamp(long e) { return static_cast<int>(std::min(4000L, std::max(-4000L, e))); }

  /// 2^k for -1022 <= k <= 1023, 0 below (a cheap ldexp where tiny values may be dropped).
  static double power_of_two(long k) {
    if (k < -1022) return 0.0;
    return from_order_bits(static_cast<std::uint64_t>(std::min(k, 1023L) + 1023) << 52);
  }

  Real g(Real t) const { return ((a_[3] * t + a_[2]) * t + a_[1]) * t + a_[0]; }
  Real dg(Real t) const { return (3 * a_[3] * t + 2 * a_[2]) * t + a_[1]; }

  /// Newton's method on the rounded cubic from the middle of [lo, hi], kept inside it.
  double initial_estimate(double lo, double hi) const {
    Real t = lo + (static_cast<Real>(hi) - lo) / 2;
    for (int i = 0; i < 8; ++i) {
      const Real next = t - g(t) / dg(t);
      if (!(next >= lo && next <= hi)) break;  // NaN included
      const bool converged = std::fabs(next - t) <= std::fabs(t) * static_cast<Real>(0x1p-60);
      t = next;
      if (converged) break;
    }
    return static_cast<double>(t);
  }

  /// A Newton step from the latest probe with its exact value, f' from the rounded cubic,
  /// carried past the predicted root by a margin: 2^-10 of the step (the step's relative
  /// error is far smaller near a simple root), 16 times more, plus 16^(n-1) ulps, after n
  /// probes in a row that stayed on the same side. The probe is the first double beyond
  /// the target in the step's direction, and never the latest probe itself.
  double newton_probe() const {
    const Real q = -m_ / dg(t_);  // step = q 2^(e - scale)
    if (!std::isfinite(q) || q == 0) return std::numeric_limits<double>::quiet_NaN();
    const Real step = std::ldexp(q, clamp(e_ - scale_));
    if (!std::isfinite(step)) return std::numeric_limits<double>::quiet_NaN();
    const bool up = q > 0;
    const int growth = 4 * std::min(misses_, 12);
    Real margin = std::fabs(step) * power_of_two(-10 + growth);
    if (misses_ > 0) margin += static_cast<Real>(next_up(t_) - t_) * power_of_two(growth - 4);
    const Real target_step = up ? step + margin : step - margin;
    const double c = static_cast<double>(t_ + target_step);
    if (!std::isfinite(c)) return std::numeric_limits<double>::quiet_NaN();
    const Real residual = target_step - (static_cast<Real>(c) - t_);  // which side of c
    double x = c;
    if (up && residual > 0) x = next_up(c);
    if (!up && residual < 0) x = next_down(c);
    if (x == t_) x = up ? next_up(t_) : next_down(t_);
    return x;
  }

  Real a_[4];
  long scale_;
  bool has_probe_ = false;
  double t_ = 0;
  Real m_ = 0;
  long e_ = 0;
  int sign_ = 0, misses_ = 0;
};

/// Exact evaluations spent on guided probes at most (then plain bisection of what is left).
constexpr int kMaxGuidedProbes = 8;

}  // namespace

// Each pass of the loop makes exactly one exact evaluation (PROOF:
// proofs/filters.md#guided-bisection, with the proof that the result is the reference loop's):
//  (a) a guided probe: at most kMaxGuidedProbes = 8 in all;
//  (b) the sign at lo0: at most once (sign_lo is then known);
//  (c) with sign_lo known, the sign at `mid`. For width 0, mid is the middle double (bit
//      order) strictly inside (below, above): the count of doubles there, at most 2^63, at
//      least halves, so (c) happens at most 64 times before no double is left (tight). For
//      width > 0, mid is the reference loop's next middle, whose side is then known: the
//      replay takes at least one step of that loop, which stops within 64 steps.
// So at most 8 + 1 + 64 = 73 evaluations (the reference loop: at most 65), and, where the
// signs seen contradict the contract, at most 65 more in the reference loop.
std::pair<double, double> IntegerQuery::bisect_root(double lo, double hi, double width) const {
  double mid;
  if (!middle_double(lo, hi, width, &mid)) return {lo, hi};  // the reference loop's first stop
  // The guide computes in long double (x87): no caller's x87 trap or precision applies there.
  const predicates::X87EnvironmentGuard x87;
  const double lo0 = lo, hi0 = hi;
  RootKnowledge known(lo0, hi0);
  std::optional<Guide> guide;
  int guided_left = kMaxGuidedProbes;
  for (;;) {
    if (width == 0) {
      // The answer is the tightest pair around r: unique, so whatever pins r gives the
      // reference loop's answer.
      if (known.root_known()) return {known.root(), known.root()};
      if (!middle_double(known.below(), known.above(), 0.0, &mid))  // consecutive doubles
        return {known.below(), known.above()};
    } else {
      // Replay the reference loop as far as the signs gathered so far determine it.
      for (Side side; (side = known.side_of(mid)) != Side::unknown;) {
        if (side == Side::at) return {mid, mid};
        (side == Side::below ? lo : hi) = mid;
        if (!middle_double(lo, hi, width, &mid)) return {lo, hi};
      }
    }
    // One exact evaluation. A guided probe, unless guidance is spent (or, with a coarse
    // width, the replay ends within two or three middles anyway); else the middle, once the
    // sign at lo0 is known.
    double probe = std::numeric_limits<double>::quiet_NaN();
    if (guided_left > 0 && !(width > 0 && hi - lo <= 4 * width)) {
      if (!guide) guide.emplace(cubic_);
      probe = guide->next_probe(known, lo0, hi0);
      guided_left = std::isnan(probe) ? 0 : guided_left - 1;
    }
    if (std::isnan(probe)) {
      if (!known.sign_lo_known()) {
        const int s = cubic_sign_at(lo0);
        if (!known.learn_sign_lo(s)) return reference_bisection(*this, lo0, hi0, width, s);
        continue;
      }
      probe = mid;
    }
    const long shift = evaluate_scaled(cubic_, probe);
    const int s = sgn(workspace.r);
    if (!known.learn(probe, s))
      return reference_bisection(*this, lo0, hi0, width, cubic_sign_at(lo0));
    if (guide && s != 0) guide->record(probe, s, workspace.r, shift);
  }
}

bool IntegerQuery::contact_at(double t) const {
  long tau = 0, k = 0;
  if (t != 0) {
    const Dyadic d = dyadic(t);
    if (d.exponent >= 0) {  // t == 1 (t <= 1 always): positions at t = 1
      tau = 1;
    } else {
      tau = static_cast<long>(d.mantissa);
      k = -d.exponent;
    }
  }
  Position x[4];
  for (int i = 0; i < 4; ++i) x[i] = position_at(coords_, common_exponent_, i, tau, k);
  auto sign_at = [](const auto& q) { return sgn(q.c[0]); };
  return type_ == QueryType::vertex_face
             ? predicates::point_in_triangle_at(x[0], x[1], x[2], x[3], sign_at)
             : predicates::segments_intersect_at(x[0], x[1], x[2], x[3], sign_at);
}

}  // namespace exactccd::exact
