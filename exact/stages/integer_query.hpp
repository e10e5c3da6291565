// A double-precision query in exact integer arithmetic, for fast exact decisions at double
// times (exact/stages/integer_cubic.hpp): the cubic's exact signs, the guided bisection of its root,
// the contact test. Each computation runs in the smallest fixed-size stack integer that its
// proven bit-length bound admits (exact/arithmetic/integer_bounds.hpp), chosen before computing, so a
// query whose bounds fit allocates nothing; GMP is used only beyond the largest fixed width,
// or throughout on request (the reference the tests compare against).
// PROOF: proofs/filters.md#exact-at-double-times
// PROOF: proofs/filters.md#fixed-size-exact-at-doubles
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <optional>
#include <utility>

#include "core/predicates/fp_environment.hpp"  // refuses fast-math builds
#include "exact/arithmetic/fixed_int.hpp"
#include "exact/polynomials/guided_bisection.hpp"
#include "exact/arithmetic/integer_bounds.hpp"
#include "exact/stages/integer_cubic.hpp"
#include "exactccd/types.hpp"

namespace exactccd::exact {

/// How many computations of the calling thread's IntegerQuery objects ran in GMP (beyond the
/// fixed widths, or requested): tells tests which queries stayed within the fixed widths.
std::uint64_t gmp_computations_in_this_thread() noexcept;

class IntegerQuery final : public CubicAtDoubles {
 public:
  enum class Arithmetic {
    fixed_first,  ///< fixed-size integers within the proven bounds, GMP beyond
    gmp,          ///< GMP throughout (the same templates instantiated with mpz_class)
  };

  explicit IntegerQuery(const VertexFaceQuery& q, Arithmetic a = Arithmetic::fixed_first);
  explicit IntegerQuery(const EdgeEdgeQuery& q, Arithmetic a = Arithmetic::fixed_first);

  /// The exact sign of the coplanarity cubic at the finite double t >= 0 (GMP for t > 1).
  int cubic_sign_at(double t) const { return sign_at(t, nullptr); }

  /// Doubles around the only root of the cubic in [lo, hi]: guided_bisection
  /// (exact/polynomials/guided_bisection.hpp), whose contract applies.
  std::pair<double, double> bisect_root(double lo, double hi, double width) const {
    return guided_bisection(*this, lo, hi, width);
  }

  /// Exact contact test at the double t in [0, 1], where the cubic vanishes (coplanar).
  /// Throws std::domain_error for t outside [0, 1].
  bool contact_at(double t) const;

  // CubicAtDoubles
  int sign_at(double t, Approximation* value) const override;
  void approximate_coefficients(Approximation (&c)[4]) const override;

  /// Enclosures in doubles of the coefficients of coefficients() divided by 2^s, s the largest
  /// of their bit lengths (so the largest magnitude lies in [1/2, 1)): lo[i] <= c_i 2^-s <=
  /// hi[i], equal when exact (zeros included), else one unit of the 53rd bit apart. A positive
  /// multiple of the cubic: the same roots and signs. PROOF: proofs/filters.md#exact-cubic-retry
  void scaled_coefficient_bounds(double (&lo)[4], double (&hi)[4]) const;

  // For tests and benchmarks.
  const IntegerCoordinates& coordinates() const { return coords_; }
  /// Limbs of the FixedInt holding the coefficients; 0 when they are in GMP.
  int coefficient_limbs() const { return coefficient_limbs_; }
  /// Limbs of the FixedInt an evaluation at t (in [0, 1]) runs in; 0: GMP.
  int value_limbs(double t) const;
  /// Limbs of the FixedInt the contact test at t (in [0, 1]) runs in; 0: GMP.
  int contact_limbs(double t) const;
  /// The exact coefficients (scaled by 2^(-3E)) and the exact 2^(3k) f(t), t in [0, 1].
  std::array<mpz_class, 4> coefficients() const;
  mpz_class scaled_value_at(double t) const;

 private:
  void compute_coefficients();
  /// The coefficients in GMP (converted when they are held in a FixedInt).
  void gmp_coefficients(mpz_class (&c)[4]) const;
  /// 2^(3k) f(t) in GMP, for any finite t >= 0.
  mpz_class gmp_scaled_value_at(double t) const;
  int value_limbs(DyadicTime d) const;

  struct GmpCoefficients {
    mpz_class c[4];
  };

  IntegerCoordinates coords_;
  Arithmetic arithmetic_;
  int coefficient_limbs_ = 0;
  // When coefficient_limbs_ > 0 (widened from that width; written before any read).
  using Stored = FixedInt<kMaxFixedLimbs>;
  Stored fixed_[4] = {Stored(Stored::Uninitialized{}), Stored(Stored::Uninitialized{}),
                      Stored(Stored::Uninitialized{}), Stored(Stored::Uninitialized{})};
  std::optional<GmpCoefficients> gmp_;  // when coefficient_limbs_ == 0
};

}  // namespace exactccd::exact
