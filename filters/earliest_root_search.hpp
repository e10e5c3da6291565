// The one earliest-root search of the certified filters: the roots in [0, t_max] of a
// polynomial with interval coefficients (the coplanarity cubic of linear motion, the reduced
// coplanarity polynomial of rigid motion) isolated earliest first by Bernstein subdivision,
// each isolated root decided by the problem's inclusion policy. Anything the policy cannot
// decide ends the search as uncertain, never as a guess.
// PROOF: proofs/filters.md#cubic-filter
// PROOF: proofs/rigid_ccd.md#root-isolation
#pragma once

#include <cstdint>

#include "core/predicates/motion.hpp"
#include "filters/certified_numbers.hpp"
#include "filters/filter_outcome.hpp"
#include "filters/polynomial_bernstein.hpp"

namespace exactccd::filters {

/// Where a double lies relative to the only root of a bracket, by a certified sign there.
enum class Side : std::uint8_t { below, at, above, unknown };

/// hi - lo <= width, with the difference rounded up (through the interval type, whose
/// operations the compiler cannot move across the rounding-mode switch).
EXACTCCD_CERTIFIED bool certainly_within_width(double lo, double hi, double width) {
  return (Interval(hi) - Interval(lo)).sup() <= width;
}

/// What a policy made of a root at a double (an end of [0, t_max]) or of an isolated root.
enum class RootDecision : std::uint8_t { contact, no_contact, undecided };

/// The search over [0, t_max] of p, depth-first and left child first, so nodes leave the stack
/// in increasing time and the first confirmed contact is the earliest. `Policy` provides
/// (every call may record in `out`, which the search returns on contact or uncertain):
///   bool excluded_first(const Interval& T, bool single_root)
///       no contact at any t in T: tried before the node's end signs;
///   bool hopeless(const Bernstein<Interval, N>& b, int depth, int sign_start, int sign_end)
///       give up now (uncertain, roots_unresolved): a tighter polynomial may decide;
///   int end_sign(const Interval& enclosure, double t, FilterOutcome& out)
///       the exact sign of p at t = 0 or t_max (enclosure: the node's end coefficient);
///   RootDecision at_double(double t, FilterOutcome& out)
///       contact at a double t where p is exactly zero (then out is the contact);
///   RootDecision single_root(double lo, double hi, int sign_hi, const Interval& T,
///                            FilterOutcome& out)
///       contact at the only, simple root of p in (lo, hi), of certain signs -sign_hi, sign_hi
///       at the ends (all earlier roots were no contact): out is the contact, or uncertain;
///   bool excluded_last(const Interval& T, bool single_root)
///       no contact at any t in T: tried before subdividing.
/// Called with a RoundingGuard held. Past depth MaxDepth: uncertain with roots_unresolved.
template <int N, int MaxDepth, class Policy>
EXACTCCD_CERTIFIED FilterOutcome earliest_root_search(const predicates::FixedPoly<Interval, N>& p,
                                                      double t_max, Policy& policy) {
  FilterOutcome out;  // uncertain until decided
  struct EndSign {
    bool known = false;
    int sign = 0;
  } start, end;
  struct Node {
    Bernstein<Interval, N> b;
    double s0, s1;
    int depth;
  };
  Node stack[MaxDepth + 2];  // at most one pending right child per level
  int top = 0;
  stack[top++] = Node{bernstein_of(p, Interval(t_max)), 0.0, 1.0, 0};
  while (top > 0) {
    const Node node = stack[--top];
    if (strict_sign_of_all(node.b) != 0) continue;  // no root in the node
    // t_max [s0, s1], through the interval type (a raw product could move across the guard).
    const Interval T = Interval(t_max) * Interval(node.s0, node.s1);
    int sign_start = certain_strict_sign(node.b[0]), sign_end = certain_strict_sign(node.b[N]);
    const bool single_root =
        sign_start != 0 && sign_end == -sign_start && certainly_monotone(node.b);
    if (policy.excluded_first(T, single_root)) continue;
    if (policy.hopeless(node.b, node.depth, sign_start, sign_end)) {
      out.roots_unresolved = true;
      return out;
    }
    // The signs at 0 and t_max, resolved exactly when a node touching that end first needs
    // them; a root at 0 is decided there (the earliest possible contact).
    if (node.s0 == 0.0) {
      if (!start.known) {
        start = {true, policy.end_sign(node.b[0], 0.0, out)};
        if (start.sign == 0) {
          const RootDecision d = policy.at_double(0.0, out);
          if (d != RootDecision::no_contact) return out;
        }
      }
      sign_start = start.sign;
    }
    if (node.s1 == 1.0) {
      if (!end.known) end = {true, policy.end_sign(node.b[N], t_max, out)};
      sign_end = end.sign;
    }
    const bool root_at_start = node.s0 == 0.0 && start.sign == 0;
    const bool root_at_end = node.s1 == 1.0 && end.sign == 0;
    if (root_at_start || root_at_end) {
      if (certainly_monotone(node.b)) {
        // The node's only root is its end point, decided there (t = 0 above).
        if (root_at_start) continue;
        const RootDecision d = policy.at_double(t_max, out);
        if (d != RootDecision::no_contact) return out;
        continue;
      }
    } else if (sign_start != 0 && sign_end == -sign_start && certainly_monotone(node.b)) {
      // The node's only root r: re-certified on the rounded-out T in the power basis (T's
      // ends are exactly 0 and t_max at the ends of [0, t_max], whose signs are known).
      const double lo = T.inf(), hi = T.sup();
      const int s_lo = node.s0 == 0.0 ? start.sign
                                      : certain_strict_sign(predicates::evaluate(p, Interval(lo)));
      const int s_hi = node.s1 == 1.0 ? end.sign
                                      : certain_strict_sign(predicates::evaluate(p, Interval(hi)));
      const int d = certain_strict_sign(predicates::evaluate(predicates::derivative(p), T));
      if (s_lo != 0 && s_hi == -s_lo && d != 0) {
        const RootDecision decision = policy.single_root(lo, hi, s_hi, T, out);
        if (decision != RootDecision::no_contact) return out;
        continue;
      }
    }
    if (policy.excluded_last(T, single_root)) continue;
    if (node.depth == MaxDepth) {
      out.roots_unresolved = true;
      return out;
    }
    Node left, right;
    de_casteljau_halves(node.b, left.b, right.b);
    const double mid = (node.s0 + node.s1) / 2;  // dyadic: exact
    left.s0 = node.s0, left.s1 = mid, left.depth = node.depth + 1;
    right.s0 = mid, right.s1 = node.s1, right.depth = node.depth + 1;
    stack[top++] = right;
    stack[top++] = left;
  }
  out.verdict = FilterOutcome::Verdict::no_contact;
  return out;
}

}  // namespace exactccd::filters
