// The fast exact stage: CCD of a double query decided exactly in integer arithmetic, with every
// root of the coplanarity cubic (or, coplanar throughout, of the vertex-edge candidates)
// bracketed between doubles (exact/polynomials/bracketed_root.hpp). Roots are isolated by Descartes' rule
// on Bernstein coefficients; the sign of an inclusion polynomial g at a root r of f is read from
// g's Bernstein coefficients on r's bracket, narrowed as needed, and g(r) = 0 is recognised
// exactly by a common factor of f and g that changes sign on the bracket. Fixed-size integers
// within the proven bounds; GMP for common factors, square-free parts, brackets finer than the
// doubles and coordinates beyond the widest fixed width.
//
// nullopt only past a step cap (a pathological input; never seen on any test or benchmark set):
// the caller then decides with the rational path (exact/reference/exact_ccd.hpp), kept as the reference.
// PROOF: proofs/exact_ccd.md#exact-at-double-brackets
#pragma once

#include <cstdint>
#include <optional>

#include "exactccd/types.hpp"

namespace exactccd::exact {

class IntegerQuery;

/// `known`: the same query's IntegerQuery when an earlier stage built it (its cubic, when held
/// in GMP, is then taken from it instead of computed again), else nullptr.
std::optional<CcdResult> vertex_face_ccd_at_doubles(const VertexFaceQuery& q,
                                                    const CcdOptions& options,
                                                    const IntegerQuery* known = nullptr);
std::optional<CcdResult> edge_edge_ccd_at_doubles(const EdgeEdgeQuery& q,
                                                  const CcdOptions& options,
                                                  const IntegerQuery* known = nullptr);

/// How many queries of the calling thread this stage left to the rational path (tests).
std::uint64_t unresolved_at_doubles_in_this_thread() noexcept;

/// For differential tests: whether the calling thread's stage takes the contact test at roots
/// for coordinates in GMP from exact/stages/wide_inclusion.hpp (true, the default) or from the general
/// predicates with exact signs only (false: the route before it, kept as its reference).
void use_wide_contact_test_in_this_thread(bool on) noexcept;

}  // namespace exactccd::exact
