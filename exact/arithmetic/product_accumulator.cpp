// PROOF: proofs/exact_ccd.md#product-accumulator
#include "exact/arithmetic/product_accumulator.hpp"

#include <gmp.h>

#include <stdexcept>

namespace exactccd::exact {

namespace {

using u128 = unsigned __int128;

}  // namespace

ProductAccumulator::ProductAccumulator(int limbs) : limbs_(limbs) {
  if (limbs < 1 || limbs > kMaxLimbs)
    throw std::length_error("exactccd: product accumulator beyond its width");
  for (int i = 0; i < limbs; ++i) positive_[i] = negative_[i] = 0;
}

void ProductAccumulator::add_at(std::uint64_t (&sum)[kMaxLimbs], const std::uint64_t (&v)[3],
                                unsigned long s) {
  const unsigned long w = s / 64;
  const unsigned b = static_cast<unsigned>(s % 64);
  // v 2^b in four limbs.
  std::uint64_t shifted[4];
  if (b == 0) {
    shifted[0] = v[0], shifted[1] = v[1], shifted[2] = v[2], shifted[3] = 0;
  } else {
    shifted[0] = v[0] << b;
    shifted[1] = (v[1] << b) | (v[0] >> (64 - b));
    shifted[2] = (v[2] << b) | (v[1] >> (64 - b));
    shifted[3] = v[2] >> (64 - b);
  }
  // Add at limb w, carrying upward; the caller's bound keeps the sum within limbs_.
  unsigned long i = w;
  std::uint64_t carry = 0;
  for (int j = 0; j < 4; ++j, ++i) {
    if (shifted[j] == 0 && carry == 0) continue;
    if (i >= static_cast<unsigned long>(limbs_))
      throw std::length_error("exactccd: product accumulator overflow");
    const u128 t = static_cast<u128>(sum[i]) + shifted[j] + carry;
    sum[i] = static_cast<std::uint64_t>(t);
    carry = static_cast<std::uint64_t>(t >> 64);
  }
  for (; carry != 0; ++i) {
    if (i >= static_cast<unsigned long>(limbs_))
      throw std::length_error("exactccd: product accumulator overflow");
    sum[i] += 1;
    carry = sum[i] == 0 ? 1 : 0;
  }
}

void ProductAccumulator::add_product(std::int64_t m1, std::int64_t m2, unsigned long s,
                                     bool negative) {
  if (m1 == 0 || m2 == 0) return;
  const u128 p = static_cast<u128>(magnitude_of(m1)) * magnitude_of(m2);
  const std::uint64_t v[3] = {static_cast<std::uint64_t>(p), static_cast<std::uint64_t>(p >> 64),
                              0};
  const bool minus = negative != ((m1 < 0) != (m2 < 0));
  add_at(minus ? negative_ : positive_, v, s);
}

void ProductAccumulator::add_product(std::int64_t m1, std::int64_t m2, std::int64_t m3,
                                     unsigned long s, bool negative) {
  if (m1 == 0 || m2 == 0 || m3 == 0) return;
  const u128 p = static_cast<u128>(magnitude_of(m1)) * magnitude_of(m2);
  const std::uint64_t c = magnitude_of(m3);
  const u128 low = static_cast<u128>(static_cast<std::uint64_t>(p)) * c;
  const u128 high = static_cast<u128>(static_cast<std::uint64_t>(p >> 64)) * c + (low >> 64);
  const std::uint64_t v[3] = {static_cast<std::uint64_t>(low), static_cast<std::uint64_t>(high),
                              static_cast<std::uint64_t>(high >> 64)};
  const bool minus = negative != (((m1 < 0) != (m2 < 0)) != (m3 < 0));
  add_at(minus ? negative_ : positive_, v, s);
}

mpz_class ProductAccumulator::to_mpz() const {
  const int c = mpn_cmp(positive_, negative_, limbs_);
  mpz_class r;
  if (c == 0) return r;
  const std::uint64_t* big = c > 0 ? positive_ : negative_;
  const std::uint64_t* small = c > 0 ? negative_ : positive_;
  mp_limb_t* out = mpz_limbs_write(r.get_mpz_t(), limbs_);
  mpn_sub_n(out, big, small, limbs_);  // no borrow out: big >= small
  int size = limbs_;
  while (size > 0 && out[size - 1] == 0) --size;
  mpz_limbs_finish(r.get_mpz_t(), c > 0 ? size : -size);
  return r;
}

namespace {

/// Limbs for sums below 2^(terms_bits + degree L): products of `degree` coordinates, each below
/// 2^L, at most 2^terms_bits of them in a partial sum.
int limbs_for(const IntegerCoordinates& q, int degree, int terms_bits) {
  return (degree * q.bits + terms_bits) / 64 + 1;
}

unsigned long shift_of(const IntegerCoordinates& q, const Dyadic& d) {
  return static_cast<unsigned long>(d.exponent - q.common_exponent);
}

/// det[x, y, z] = (x cross y) . z of three fixed points (rows), with a sign, into acc.
void add_det(ProductAccumulator& acc, const IntegerCoordinates& q, int x, int y, int z,
             bool negative) {
  const Dyadic(&X)[3] = q.coords[x];
  const Dyadic(&Y)[3] = q.coords[y];
  const Dyadic(&Z)[3] = q.coords[z];
  // (x1 y2 - x2 y1) z0 + (x2 y0 - x0 y2) z1 + (x0 y1 - x1 y0) z2
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const Dyadic &a = X[i], &b = Y[j], &c = Z[k], &a2 = X[j], &b2 = Y[i];
    if (c.mantissa == 0) continue;
    if (a.mantissa != 0 && b.mantissa != 0)
      acc.add_product(a.mantissa, b.mantissa, c.mantissa,
                      shift_of(q, a) + shift_of(q, b) + shift_of(q, c), negative);
    if (a2.mantissa != 0 && b2.mantissa != 0)
      acc.add_product(a2.mantissa, b2.mantissa, c.mantissa,
                      shift_of(q, a2) + shift_of(q, b2) + shift_of(q, c), !negative);
  }
}

/// x_u y_v - x_v y_u of two fixed points (rows), with a sign, into acc.
void add_cross2(ProductAccumulator& acc, const IntegerCoordinates& q, int u, int v, int x, int y,
                bool negative) {
  const Dyadic &xu = q.coords[x][u], &yv = q.coords[y][v], &xv = q.coords[x][v],
               &yu = q.coords[y][u];
  acc.add_product(xu.mantissa, yv.mantissa, shift_of(q, xu) + shift_of(q, yv), negative);
  acc.add_product(xv.mantissa, yu.mantissa, shift_of(q, xv) + shift_of(q, yu), !negative);
}

}  // namespace

void accumulated_coplanarity_coefficients(const IntegerCoordinates& q, mpz_class (&c)[4]) {
  // f = det[x - o, y - o, z - o] = det[x, y, z] - det[o, y, z] + det[o, x, z] - det[o, x, y]
  // (vertex-face: o, x, y, z = a, b, c, p; edge-edge: a0, a1, b0, b1), each point moving as
  // (1 - t) P0 + t P1: det is trilinear, so f = sum_m B_m t^m (1 - t)^(3 - m) with B_m the sum
  // of the determinants whose m points are taken at t = 1.
  const bool vf = q.type == QueryType::vertex_face;
  const int o = vf ? 1 : 0, x = vf ? 2 : 1, y = vf ? 3 : 2, z = vf ? 0 : 3;
  struct Det {
    int p[3];
    bool negative;
  };
  const Det dets[4] = {{{x, y, z}, false}, {{o, y, z}, true}, {{o, x, z}, false},
                       {{o, x, y}, true}};
  // Each B_m: at most 4 determinants x 3 end-point choices x 6 products below 2^(3L).
  const int limbs = limbs_for(q, 3, 7);
  ProductAccumulator B[4] = {ProductAccumulator(limbs), ProductAccumulator(limbs),
                             ProductAccumulator(limbs), ProductAccumulator(limbs)};
  for (const Det& d : dets)
    for (int ends = 0; ends < 8; ++ends) {
      const int r0 = d.p[0] + (ends & 1 ? 4 : 0), r1 = d.p[1] + (ends & 2 ? 4 : 0),
                r2 = d.p[2] + (ends & 4 ? 4 : 0);
      add_det(B[__builtin_popcount(static_cast<unsigned>(ends))], q, r0, r1, r2, d.negative);
    }
  const mpz_class b0 = B[0].to_mpz(), b1 = B[1].to_mpz(), b2 = B[2].to_mpz(),
                  b3 = B[3].to_mpz();
  // (1-t)^3 = 1 - 3t + 3t^2 - t^3, t(1-t)^2 = t - 2t^2 + t^3, t^2(1-t) = t^2 - t^3.
  c[0] = b0;
  c[1] = b1 - 3 * b0;
  c[2] = 3 * b0 - 2 * b1 + b2;
  c[3] = b1 - b0 - b2 + b3;
}

void accumulated_cross2_coefficients(const IntegerCoordinates& q, int k, const Cross2Term* terms,
                                     int count, mpz_class (&c)[3]) {
  const int u = (k + 1) % 3, v = (k + 2) % 3;
  // cross2 is bilinear: cross2(x(t), y(t)) = (1-t)^2 cross2(x0, y0) + t(1-t) (cross2(x0, y1) +
  // cross2(x1, y0)) + t^2 cross2(x1, y1). Each B_m: at most 2 count terms of 2 products,
  // count <= 64 (the orientations here have 3 or 4 terms).
  if (count < 0 || count > 64) throw std::length_error("exactccd: too many cross terms");
  const int limbs = limbs_for(q, 2, 8);
  ProductAccumulator B[3] = {ProductAccumulator(limbs), ProductAccumulator(limbs),
                             ProductAccumulator(limbs)};
  for (int i = 0; i < count; ++i) {
    const Cross2Term& t = terms[i];
    add_cross2(B[0], q, u, v, t.x, t.y, t.negative);
    add_cross2(B[1], q, u, v, t.x, t.y + 4, t.negative);
    add_cross2(B[1], q, u, v, t.x + 4, t.y, t.negative);
    add_cross2(B[2], q, u, v, t.x + 4, t.y + 4, t.negative);
  }
  const mpz_class b0 = B[0].to_mpz(), b1 = B[1].to_mpz(), b2 = B[2].to_mpz();
  // (1-t)^2 = 1 - 2t + t^2, t(1-t) = t - t^2.
  c[0] = b0;
  c[1] = b1 - 2 * b0;
  c[2] = b0 - b1 + b2;
}

}  // namespace exactccd::exact
