#include "exact/polynomials/polynomial.hpp"

#include <stdexcept>
#include <utility>

namespace exactccd::exact {

Polynomial::Polynomial(std::vector<Rational> c) : c_(std::move(c)) { trim(); }

void Polynomial::trim() {
  while (!c_.empty() && sgn(c_.back()) == 0) c_.pop_back();
  integer_ = true;
  for (const Rational& x : c_) integer_ = integer_ && x.get_den() == 1;
}

// PROOF: proofs/exact_ccd.md#lemma-root-isolation (integer signs)
int Polynomial::sign_at(const Rational& t) const {
  if (!integer_ || c_.size() <= 1) return sgn(evaluate(t));
  // t = a / b, b > 0: b^d p(t) = sum_i c_i a^i b^(d - i) (Horner in a, powers of b), exact
  // integers whose sign is p(t)'s. A power-of-two b (a double t) is a shift.
  const mpz_class& a = t.get_num();
  const mpz_class& b = t.get_den();
  const long shift = dyadic_exponent(t);
  mpz_class r = c_.back().get_num(), b_power = 1, term;
  for (std::size_t i = c_.size() - 1; i-- > 0;) {
    r *= a;
    if (shift >= 0) {
      mpz_mul_2exp(term.get_mpz_t(), c_[i].get_num_mpz_t(),
                   static_cast<unsigned long>(shift) * (c_.size() - 1 - i));
    } else {
      b_power *= b;
      term = c_[i].get_num() * b_power;
    }
    r += term;
  }
  return sgn(r);
}

Rational Polynomial::evaluate(const Rational& t) const {
  Rational r = 0;
  for (auto it = c_.rbegin(); it != c_.rend(); ++it) {
    r *= t;
    r += *it;
  }
  return r;
}

Polynomial Polynomial::derivative() const {
  std::vector<Rational> d;
  for (std::size_t i = 1; i < c_.size(); ++i) d.push_back(c_[i] * static_cast<long>(i));
  return Polynomial(std::move(d));
}

Polynomial Polynomial::monic() const {
  if (is_zero()) return *this;
  std::vector<Rational> m(c_);
  const Rational lead = leading();
  for (auto& x : m) x /= lead;
  return Polynomial(std::move(m));
}

Polynomial Polynomial::taylor_shift(const Rational& t0) const {
  // Repeated synthetic division by (t - t0): O(n^2), exact.
  std::vector<Rational> a(c_);
  const std::size_t n = a.size();
  for (std::size_t k = 0; k + 1 < n; ++k)
    for (std::size_t i = n - 1; i > k; --i) a[i - 1] += t0 * a[i];
  return Polynomial(std::move(a));
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  if (a.is_zero() || b.is_zero()) return Polynomial();
  std::vector<Rational> r(a.c_.size() + b.c_.size() - 1);
  for (std::size_t i = 0; i < a.c_.size(); ++i)
    for (std::size_t j = 0; j < b.c_.size(); ++j) r[i + j] += a.c_[i] * b.c_[j];
  return Polynomial(std::move(r));
}

Polynomial operator-(const Polynomial& a) {
  std::vector<Rational> r(a.c_);
  for (auto& x : r) x = -x;
  return Polynomial(std::move(r));
}

void divide(const Polynomial& a, const Polynomial& b, Polynomial* q, Polynomial* r) {
  if (b.is_zero()) throw std::domain_error("exactccd: polynomial division by zero");
  std::vector<Rational> rem(a.c_);
  const int db = b.degree();
  std::vector<Rational> quo(a.degree() >= db ? a.degree() - db + 1 : 0);
  for (int k = a.degree() - db; k >= 0; --k) {
    const Rational f = rem[k + db] / b.leading();
    quo[k] = f;
    if (sgn(f) == 0) continue;
    for (int j = 0; j <= db; ++j) rem[k + j] -= f * b.c_[j];
  }
  rem.resize(db > 0 ? db : 0);
  if (q) *q = Polynomial(std::move(quo));
  if (r) *r = Polynomial(std::move(rem));
}

Polynomial gcd(Polynomial a, Polynomial b) {
  while (!b.is_zero()) {
    Polynomial r;
    divide(a, b, nullptr, &r);
    a = std::move(b);
    b = r.monic();  // keeps coefficient growth in check
  }
  return a.monic();
}

Polynomial primitive_part(const Polynomial& p) {
  if (p.is_zero()) return p;
  mpz_class lcm = 1, content = 0;
  for (const Rational& x : p.coefficients()) mpz_lcm(lcm.get_mpz_t(), lcm.get_mpz_t(), x.get_den_mpz_t());
  std::vector<mpz_class> n;
  n.reserve(p.coefficients().size());
  for (const Rational& x : p.coefficients()) {
    n.push_back(x.get_num() * (lcm / x.get_den()));
    mpz_gcd(content.get_mpz_t(), content.get_mpz_t(), n.back().get_mpz_t());
  }
  std::vector<Rational> c;
  c.reserve(n.size());
  for (mpz_class& x : n) {
    mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), content.get_mpz_t());
    c.emplace_back(x);
  }
  return Polynomial(std::move(c));
}

Polynomial pseudo_remainder(const Polynomial& a, const Polynomial& b, int* sign) {
  if (!a.has_integer_coefficients() || !b.has_integer_coefficients() || b.is_zero() ||
      a.degree() < b.degree())
    throw std::domain_error("exactccd: pseudo-remainder needs integer a, b, deg a >= deg b");
  std::vector<mpz_class> r;
  for (const Rational& x : a.coefficients()) r.push_back(x.get_num());
  const int db = b.degree(), e = a.degree() - db + 1;
  const mpz_class& lead = b.leading().get_num();
  for (int k = a.degree(); k >= db; --k) {  // e steps: r <- lc(b) r - r_k t^(k - db) b
    const mpz_class top = r[k];
    for (mpz_class& x : r) x *= lead;
    if (sgn(top) != 0)
      for (int j = 0; j <= db; ++j) r[k - db + j] -= top * b.coefficients()[j].get_num();
  }
  r.resize(static_cast<std::size_t>(db));
  *sign = (sgn(lead) < 0 && e % 2 == 1) ? -1 : 1;
  return Polynomial(std::vector<Rational>(r.begin(), r.end()));
}

long dyadic_exponent(const Rational& q) {
  const mpz_class& den = q.get_den();
  const auto k = static_cast<long>(mpz_scan1(den.get_mpz_t(), 0));
  return static_cast<long>(mpz_sizeinbase(den.get_mpz_t(), 2)) == k + 1 ? k : -1;
}

bool descartes_root_free_dyadic(const Polynomial& p, const mpz_class& A, const mpz_class& B,
                                unsigned long K) {
  const auto& c = p.coefficients();
  const std::size_t n = c.size();
  if (n == 0 || !p.has_integer_coefficients()) return false;
  // R(y) = 2^(K d) p((A + W y) 2^-K), W = B - A: scale, Taylor shift by A, scale by W^i.
  std::vector<mpz_class> r(n);
  for (std::size_t i = 0; i < n; ++i)
    mpz_mul_2exp(r[i].get_mpz_t(), c[i].get_num_mpz_t(), K * (n - 1 - i));
  for (std::size_t k = 0; k + 1 < n; ++k)
    for (std::size_t i = n - 1; i > k; --i) r[i - 1] += A * r[i];
  const mpz_class W = B - A;
  mpz_class w = 1;
  for (std::size_t i = 1; i < n; ++i) {
    w *= W;
    r[i] *= w;
  }
  return no_root_on_unit_interval(r);
}

Polynomial square_free_part(const Polynomial& p) {
  if (p.is_zero()) throw std::domain_error("exactccd: square-free part of the zero polynomial");
  const Polynomial g = gcd(p, p.derivative());
  Polynomial q;
  divide(p, g, &q, nullptr);
  return q.monic();
}

}  // namespace exactccd::exact
