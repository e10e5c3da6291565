// Exact signs of the minimum-separation region polynomials at double times. Polynomial 0 (the
// face or interior region), the capsules' sides, the end spheres and the sides' projections,
// the ones the search tightens, are first evaluated in double-double with a proven error bound
// (core/predicates/double_double_bounds.hpp); where that bound does not exclude 0, and for the
// other polynomials, in integer arithmetic: the query and delta scaled by one power of two to
// integers, the positions at t = m 2^e computed exactly as integers (scaled by 2^-e), and the
// one polynomial asked for evaluated on them. Every region polynomial is homogeneous in the
// coordinates and delta, so the common positive scale changes no sign. The kernels run in
// fixed-width integers chosen from proven bounds (exact/stages/separation_integers.hpp: no
// allocation); the others, and the kernels beyond the widest fixed width, in GMP (allocates).
// PROOF: proofs/min_separation.md#interval-search
// PROOF: proofs/min_separation.md#fixed-width-signs
// PROOF: proofs/min_separation.md#double-double-signs
#pragma once

#include <gmpxx.h>

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>

#include "core/predicates/double_double.hpp"
#include "core/predicates/double_double_bounds.hpp"
#include "core/predicates/interval.hpp"
#include "core/predicates/motion.hpp"
#include "core/predicates/separation_exact_stage.hpp"
#include "exact/stages/separation_integers.hpp"

namespace exactccd::exact::separation {

using predicates::Interval;
namespace dd = predicates::dd;

/// How many evaluations of the calling thread's ExactSignsAtDoubles ran in GMP: tells tests
/// which queries stayed within the fixed widths.
std::uint64_t gmp_evaluations_in_this_thread() noexcept;
/// How many signs the calling thread's ExactSignsAtDoubles took from double-double with an
/// error bound, before any exact integer: tells tests which path decided.
std::uint64_t bounded_decisions_in_this_thread() noexcept;

using CoefficientTable = predicates::SeparationCoefficientTable;

/// a.b in plain arithmetic (the kernels' expressions in double: guesses only).
inline double dot(const double (&a)[3], const double (&b)[3]) {
  return (a[0] * b[0] + a[1] * b[1]) + a[2] * b[2];
}

/// A kernel's differences at t = 0 and their changes over the step in double-double with error
/// bounds (ExactSignsAtDoubles::bounded_value), for the kernel vertices `of`. Complete before the
/// class holds an optional of it (clang checks it is constructible there).
struct BoundedSteps {
  const exact::DifferenceVertices* of = nullptr;
  dd::Bounded d0[3][3], change[3][3];
};

class ExactSignsAtDoubles final : public predicates::SeparationExactStage {
 public:
  /// The four moving vertices (x_t0, x_t1 each, kept by address: they must outlive this) and
  /// delta, all finite doubles, of a query of the given pair. No allocation; the integer query
  /// is formed when first needed (most queries are decided without it).
  ExactSignsAtDoubles(const std::array<const Eigen::Vector3d*, 4>& t0,
                      const std::array<const Eigen::Vector3d*, 4>& t1, double delta,
                      predicates::SeparationPair pair = predicates::SeparationPair::vertex_face);

  // The stage's interface, for the pair given at construction.
  int sign_at(int k, double t) const override;
  Probe probe_at(int k, double t) const override;
  double secant_guess(int k, double lo, double hi) const override;
  double newton_guess(int k, double lo, double hi) const override;
  void exact_coefficients(CoefficientTable* out) const override;
  bool used_exact_arithmetic() const override { return exact_arithmetic_; }

  /// The exact sign of region polynomial k of the vertex-face separation (vertices p, a, b,
  /// c) or of the edge-edge one (a0, a1, b0, b1) at the double t in [0, 1].
  int vertex_face_sign(int k, double t) const;
  int edge_edge_sign(int k, double t) const;

  /// A guess, in plain arithmetic and never a decision, of the root of polynomial k in
  /// (lo, hi), 0 < lo < hi: the secant through its exact values at lo and hi (GMP); NaN when
  /// there is none in (lo, hi). The search asks it only for the polynomials without a kernel
  /// (the others are tightened by *_probe).
  double vertex_face_secant(int k, double lo, double hi) const;
  double edge_edge_secant(int k, double lo, double hi) const;

  /// One probe of the tightening at the double t: the exact sign of polynomial k there and,
  /// for a polynomial with a kernel (polynomial 0, the capsules' sides, the end spheres, the
  /// sides' projections) at t in [0, 1], a Newton guess of its root from the same value (never
  /// a decision; NaN when there is none, and for the others, whose sign is *_sign's and
  /// `kernel` false). The sign is always exact: never a default 0 that would read as a root.
  Probe vertex_face_probe(int k, double t) const;
  Probe edge_edge_probe(int k, double t) const;

  /// A guess, never a decision, of the root of polynomial k in (lo, hi) (0 <= lo < hi <= 1),
  /// where it changes sign and is monotone: Newton's method on its kernel in plain double
  /// arithmetic, kept inside a bracket by bisection; NaN when k has no kernel.
  double vertex_face_guess(int k, double lo, double hi) const;
  double edge_edge_guess(int k, double lo, double hi) const;

  /// Every region polynomial from its exact integer coefficients, each polynomial times its
  /// own positive power of two (no sign changes) and each coefficient rounded outwards once.
  /// Where a polynomial is tiny against the products of the coordinates (nearly parallel
  /// edges, a vertex sliding on a face), its enclosure computed in intervals from the
  /// coordinates is as wide as those products, and this one is not. GMP (allocates).
  /// PROOF: proofs/min_separation.md#exact-coefficients
  void vertex_face_coefficients(CoefficientTable* out) const;
  void edge_edge_coefficients(CoefficientTable* out) const;

 private:
  using Position = std::array<mpz_class, 3>;
  /// The query in GMP integers, for the polynomials other than 0 (formed when first needed).
  struct Gmp {
    std::array<Position, 4> x0, dx;  // integers: coordinates times 2^-E
    mpz_class delta;
  };
  const Gmp& gmp() const;
  /// The positions at t and delta, all times 2^shift, exactly; shift >= -(t's ulp exponent).
  void at(double t, long shift, std::array<Position, 4>* positions, mpz_class* delta) const;
  template <class Make>
  mpz_class value(const Make& make, int k, double t, long shift) const;
  template <class Make>
  double secant(const Make& make, int k, double lo, double hi) const;
  template <class Make>
  void coefficients(const Make& make, CoefficientTable* out) const;
  /// A polynomial computed from differences in fixed-width integers (proofs/min_separation.md
  /// #fixed-width-signs): the face-like polynomial 0, a capsule's side, an end sphere or a
  /// side's projection; none for the others (edge-edge 1-4, vertex-face 1-3 and the strict).
  enum class KernelKind : std::uint8_t { face_like, capsule, sphere, projection };
  struct IntegerKernel {
    const exact::DifferenceVertices* vertices = nullptr;
    KernelKind kind = KernelKind::face_like;
  };
  static IntegerKernel vertex_face_kernel(int k);
  static IntegerKernel edge_edge_kernel(int k);
  /// A kernel's exact sign at t and its value's leading bits (the integer value, 2^(d(k - E))
  /// times the polynomial of degree d at t = T 2^-k).
  struct KernelValue {
    int sign = 0;
    exact::Approximation value;
    unsigned k = 0;
  };
  KernelValue kernel_value_at(const IntegerKernel& kernel, double t) const;
  /// The kernel's value at t in double-double with a running error bound
  /// (core/predicates/double_double_bounds.hpp); none where the scaled inputs are not exact
  /// doubles.
  std::optional<dd::Bounded> bounded_value(const IntegerKernel& kernel, double t) const;
  /// A kernel's exact sign at t and its value's leading part in the scaled inputs' units: from
  /// bounded_value when its bound excludes 0 (counted), else from exact integers.
  struct SignedValue {
    int sign;
    double value;
  };
  SignedValue kernel_signed_value(const IntegerKernel& kernel, double t) const;
  Probe kernel_probe(const IntegerKernel& kernel, double t) const;
  double kernel_guess(const IntegerKernel& kernel, double lo, double hi) const;
  /// A kernel's value and derivative at t in plain double arithmetic from the scaled inputs,
  /// in the caller's rounding mode (guesses only).
  struct ValueSlope {
    double value, slope;
  };
  ValueSlope plain_value_slope(const IntegerKernel& kernel, double t) const;
  /// An exact kernel value's leading bits in the scaled inputs' units (plain_value_slope's).
  double scaled_value(KernelKind kind, const KernelValue& v) const;
  /// A kernel's derivative in t from its differences d at t and their changes over the step.
  static double kernel_slope(KernelKind kind, const double (&d)[3][3],
                             const double (&step)[3][3], double delta2);
  int kernel_sign(const IntegerKernel& kernel, double t) const;
  /// A kernel's polynomial from its differences at a time, in the number type T: double (a
  /// guess's value) or double-double with an error bound (dd::Bounded, a certified sign). The
  /// same expressions as exact/stages/separation_integers.hpp's kernels.
  template <class T>
  static T kernel_expression(KernelKind kind, const T (&d)[3][3], const T& delta2) {
    switch (kind) {
      case KernelKind::capsule: {  // (w.w)(e.e) - (w.e)^2 - delta^2 (e.e)
        const T ee = dot(d[1], d[1]), we = dot(d[0], d[1]);
        return (dot(d[0], d[0]) * ee - we * we) - delta2 * ee;
      }
      case KernelKind::face_like: {  // (W.m)^2 - delta^2 (m.m), m = U x V
        const T m[3] = {d[0][1] * d[1][2] - d[0][2] * d[1][1],
                        d[0][2] * d[1][0] - d[0][0] * d[1][2],
                        d[0][0] * d[1][1] - d[0][1] * d[1][0]};
        const T wm = dot(d[2], m);
        return wm * wm - delta2 * dot(m, m);
      }
      case KernelKind::sphere: return dot(d[0], d[0]) - delta2;
      case KernelKind::projection: return dot(d[0], d[1]);
    }
    return {};
  }
  /// The differences of a kernel in FixedInt (formed when first needed, the last kernel's
  /// kept; none when the coordinates need more than the widest fixed width).
  const exact::StoredStepDifferences* fixed_differences(const exact::DifferenceVertices& v) const;
  /// f(the kernel's value at T 2^-k, at each T of ts) in the integer types Ints.
  template <class Ints, class F, std::size_t N>
  auto kernel_values(const IntegerKernel& kernel, const std::uint64_t (&ts)[N], unsigned k,
                     F&& f) const;

  /// The coordinates and delta times 2^-(E + L) as doubles (magnitudes below 1), formed when
  /// first needed; `exact` when every one is (a normal double or 0: no rounding).
  struct ScaledInputs {
    double x[2][4][3];  // [end][vertex][axis]
    double delta;
    bool exact;
  };
  const ScaledInputs& scaled_inputs() const;

  /// The query in integers (formed when first asked for).
  const exact::SeparationIntegers& q() const;

  std::array<const Eigen::Vector3d*, 4> t0_, t1_;
  double delta_;
  predicates::SeparationPair pair_;
  mutable std::optional<exact::SeparationIntegers> q_;
  mutable std::optional<ScaledInputs> scaled_;
  mutable std::optional<BoundedSteps> bounded_steps_;  // formed when first needed
  mutable std::optional<Gmp> gmp_;
  mutable std::optional<exact::StoredStepDifferences> fixed_differences_;
  mutable const exact::DifferenceVertices* fixed_differences_of_ = nullptr;
  mutable bool exact_arithmetic_ = false;
};

}  // namespace exactccd::exact::separation
