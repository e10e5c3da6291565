#include "exact/polynomials/root_isolation.hpp"

#include <stdexcept>

namespace exactccd::exact {

SturmSequence::SturmSequence(const Polynomial& p) {
  if (p.is_zero()) throw std::domain_error("exactccd: Sturm sequence of the zero polynomial");
  // Each element a positive multiple of the classical one (rem(x A, y B) = x rem(A, B) for
  // x, y > 0): the same signs everywhere, integer coefficients for cheap evaluations.
  seq_.push_back(primitive_part(p));
  if (p.degree() == 0) return;
  seq_.push_back(primitive_part(p.derivative()));
  for (;;) {
    // -rem(A, B) as a positive multiple: lc(B)^e rem(A, B) is the integer pseudo-remainder.
    int sign = 1;
    const Polynomial r = pseudo_remainder(seq_[seq_.size() - 2], seq_.back(), &sign);
    if (r.is_zero()) break;  // p square-free: the last element is a non-zero constant
    seq_.push_back(primitive_part(sign > 0 ? -r : r));
  }
}

int SturmSequence::variations(const Rational& t) const {
  int changes = 0, last = 0;
  for (const auto& q : seq_) {
    const int s = q.sign_at(t);
    if (s == 0) continue;
    if (last != 0 && s != last) ++changes;
    last = s;
  }
  return changes;
}

namespace {

struct Isolator {
  const Polynomial& f;  // square-free
  const SturmSequence& sturm;
  std::vector<AlgebraicTime>& out;

  // Appends the n roots of f in (lo, hi], ascending.
  void isolate(const Rational& lo, const Rational& hi, int n) {
    if (n == 0) return;
    if (n == 1) {
      if (f.sign_at(hi) == 0) {
        out.push_back(AlgebraicTime::rational(hi));
        return;
      }
      if (f.sign_at(lo) != 0) {
        out.emplace_back(f, lo, hi);  // simple root: f changes sign on (lo, hi)
        return;
      }
      // lo is itself a root (found earlier): move lo up until it is not.
    }
    const Rational m = split_point(lo, hi);
    const int left = sturm.count_roots(lo, m);
    isolate(lo, m, left);
    isolate(m, hi, n - left);
  }
};

}  // namespace

bool certainly_root_free(const Polynomial& p, const Rational& a, const Rational& b) {
  if (p.is_zero()) return false;
  const int d = p.degree();
  if (d == 0) return true;
  std::vector<Rational> c = p.taylor_shift(a).coefficients();  // p(a + s)
  c.resize(static_cast<std::size_t>(d) + 1);
  const Rational w = b - a;
  Rational wi = 1;
  for (int i = 1; i <= d; ++i) {  // p(a + w y)
    wi *= w;
    c[i] *= wi;
  }
  return no_root_on_unit_interval(c);
}

std::vector<AlgebraicTime> real_roots_in(const Polynomial& p, const Rational& a,
                                         const Rational& b) {
  std::vector<AlgebraicTime> out;
  if (p.is_zero()) throw std::domain_error("exactccd: roots of the zero polynomial");
  if (p.degree() == 0) return out;
  const Polynomial f = primitive_part(square_free_part(p));  // integer: cheap signs
  if (f.degree() == 1) {  // the root is rational: no isolation needed
    const Rational root = -f.coefficients()[0] / f.coefficients()[1];
    if (cmp(a, root) <= 0 && cmp(root, b) <= 0) out.push_back(AlgebraicTime::rational(root));
    return out;
  }
  if (f.sign_at(a) == 0) out.push_back(AlgebraicTime::rational(a));
  const SturmSequence sturm(f);
  Isolator{f, sturm, out}.isolate(a, b, sturm.count_roots(a, b));
  return out;
}

}  // namespace exactccd::exact
