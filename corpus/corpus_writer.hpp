// The degenerate-query corpus that `exactccd generate` writes (and tests/data/degenerate-suite
// ships): the families of families.hpp (or, with --min-separation, those of
// min_separation_families.hpp for one delta, recorded in the manifest) with the exact path's
// verdict and tightest TOI for every member, serialised as
//   DIR/manifest.json
//   DIR/<family>/<vertex-face|edge-edge>/data_0.csv  benchmark CSV, 8 rows per query,
//       x_num,x_den,y_num,y_den,z_num,z_den,truth; every coordinate its exact lowest-terms
//       fraction; truth from the exact path
//   DIR/<family>/<vertex-face|edge-edge>/toi_0.csv   one line per query,
//       index,collides,toi_lo,toi_hi (%.17g, the exact path's tightest pair; toi fields empty
//       without contact), no header
// The texts depend only on the seed, per_family and the family list (not on threads).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "corpus/families.hpp"
#include "corpus/min_separation_families.hpp"
#include "exactccd/types.hpp"

namespace exactccd::families {

struct GeneratedFamily {
  Family family;
  std::vector<CcdResult> exact;  ///< the exact path (exact_ccd, toi_width 0), per member
  /// Variants: members whose exact verdict equals that of the base member they round.
  std::size_t kept_verdict = 0;
  std::size_t collisions() const;
};

struct Corpus {
  std::uint64_t seed = 1;
  int per_family = kDefaultPerFamily;
  /// The minimum-separation families' delta (min_separation_families.hpp); none for the
  /// degenerate families.
  std::optional<double> min_separation;
  std::vector<GeneratedFamily> families;
};

/// Generates the named families (all when empty) and decides every member with the exact
/// path, in parallel (TBB). Throws std::invalid_argument for an unknown family or a bad
/// per_family.
Corpus generate_corpus(std::uint64_t seed, int per_family,
                       const std::vector<std::string>& names = {});

/// The minimum-separation families (all when `names` is empty) for `delta`, every member
/// decided by the exact path with that delta (exact_ccd with the rational delta), in parallel.
/// Throws std::invalid_argument as generate_min_separation_families.
Corpus generate_min_separation_corpus(double delta, std::uint64_t seed, int per_family,
                                      const std::vector<std::string>& names = {});

/// One line per member with a claim (base families; power-of-two variants where the scaling is
/// exact) whose exact verdict or TOI contradicts it (collides; toi_lo <= t* <= toi_hi with the
/// tightest pair: lo == hi == t* when t* is a double, else consecutive doubles around it).
/// Empty when all agree; random families and rounded variants carry no claim: empty.
std::vector<std::string> claim_mismatches(const GeneratedFamily& family);

/// "<family>/<vertex-face|edge-edge>"
std::string family_folder(const Family& family);
std::string data_csv_text(const GeneratedFamily& family);
std::string toi_csv_text(const GeneratedFamily& family);
std::string manifest_text(const Corpus& corpus);

/// `value` as its exact lowest-terms fraction "num,den" (0 as "0,1").
std::string exact_fraction(double value);

}  // namespace exactccd::families
