#include "exact/root_isolation.hpp"

#include <stdexcept>

namespace exactccd::exact {

SturmSequence::SturmSequence(const Polynomial& p) {
  if (p.is_zero()) throw std::domain_error("exactccd: Sturm sequence of the zero polynomial");
  seq_.push_back(p);
  if (p.degree() == 0) return;
  seq_.push_back(p.derivative());
  for (;;) {
    Polynomial r;
    divide(seq_[seq_.size() - 2], seq_.back(), nullptr, &r);
    if (r.is_zero()) break;  // p square-free: the last element is a non-zero constant
    seq_.push_back(-r);
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

std::vector<AlgebraicTime> real_roots_in(const Polynomial& p, const Rational& a,
                                         const Rational& b) {
  std::vector<AlgebraicTime> out;
  if (p.is_zero()) throw std::domain_error("exactccd: roots of the zero polynomial");
  if (p.degree() == 0) return out;
  const Polynomial f = square_free_part(p);
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
