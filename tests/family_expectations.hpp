// Expectations shared by the generated families' tests (families_test,
// min_separation_families_test): a result against a member's constructed truth.
#pragma once

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "corpus/families.hpp"
#include "exactccd/types.hpp"

namespace exactccd::test {

/// lo <= t <= hi, and the pair is the tightest: lo == hi == t when t is a double, else two
/// consecutive doubles around t.
inline void expect_tightest_enclosure(const mpq_class& t, double lo, double hi) {
  EXPECT_TRUE(mpq_class(lo) <= t && t <= mpq_class(hi))
      << "t* = " << t << " not in [" << lo << ", " << hi << "]";
  if (mpq_class(t.get_d()) == t) {
    EXPECT_EQ(mpq_class(lo), t);
    EXPECT_EQ(mpq_class(hi), t);
  } else {
    EXPECT_EQ(hi, std::nextafter(lo, std::numeric_limits<double>::infinity()))
        << "not consecutive doubles around t* = " << t;
  }
}

/// The verdict is the member's, and so is the TOI (tightest enclosure) of a contact.
inline void expect_answer(const families::Member& m, const CcdResult& r,
                          const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(r.collides, m.collides);
  if (m.collides) expect_tightest_enclosure(m.toi, r.toi_lo, r.toi_hi);
}

}  // namespace exactccd::test
