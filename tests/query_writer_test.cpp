// Writing queries in the benchmark's CSV format (query_file.hpp): every double as its exact
// fraction, so that read_query_file gives back exactly the doubles written.
//
// Expected strings are worked out by hand from the binary expansions; round trips are checked
// against GMP's own exact conversion of a double (mpq_set_d), not against the writer's frexp.
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "exactccd/query_file.hpp"
#include "test_support.hpp"

namespace exactccd {
namespace {

namespace fs = std::filesystem;

std::string fraction(double v) {
  std::string s;
  append_exact_fraction(s, v);
  return s;
}

/// Decimal of 2^e computed by repeated multiplication (independent of the writer's mpz_setbit).
std::string power_of_two(unsigned long e) {
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 2, e);
  return p.get_str();
}

TEST(ExactFraction, SmallValuesByHand) {
  EXPECT_EQ(fraction(0.0), "0,1");
  EXPECT_EQ(fraction(-0.0), "0,1");
  EXPECT_EQ(fraction(1.0), "1,1");
  EXPECT_EQ(fraction(-3.0), "-3,1");
  EXPECT_EQ(fraction(0.5), "1,2");
  EXPECT_EQ(fraction(-0.75), "-3,4");
  EXPECT_EQ(fraction(6.25), "25,4");
  // 0.1 rounds to 0x1.999999999999ap-4 = 0x1999999999999a / 2^56 = 3602879701896397 / 2^55.
  EXPECT_EQ(fraction(0.1), "3602879701896397,36028797018963968");
  EXPECT_EQ(fraction(-0.1), "-3602879701896397,36028797018963968");
}

// The writer switches from 64-bit integers to GMP at numerator 2^11 and denominator 2^64:
// values on both sides of each switch.
TEST(ExactFraction, AroundTheIntegerWidthSwitches) {
  EXPECT_EQ(fraction(1024.0), "1024,1");
  EXPECT_EQ(fraction(2048.0), "2048,1");
  EXPECT_EQ(fraction(3.0 * 1024.0), "3072,1");
  EXPECT_EQ(fraction(-(std::ldexp(1.0, 53) - 1.0)), "-9007199254740991,1");
  EXPECT_EQ(fraction(std::ldexp(3.0, 60)), "3458764513820540928,1");
  EXPECT_EQ(fraction(std::ldexp(1.0, -63)), "1,9223372036854775808");
  EXPECT_EQ(fraction(std::ldexp(1.0, -64)), "1,18446744073709551616");
  EXPECT_EQ(fraction(std::ldexp(-5.0, -70)), "-5," + power_of_two(70));
}

TEST(ExactFraction, ExtremeMagnitudes) {
  const double min_subnormal = std::numeric_limits<double>::denorm_min();  // 2^-1074
  EXPECT_EQ(fraction(min_subnormal), "1," + power_of_two(1074));
  EXPECT_EQ(fraction(-min_subnormal), "-1," + power_of_two(1074));
  // Largest subnormal: (2^52 - 1) * 2^-1074 (odd numerator, already in lowest terms).
  EXPECT_EQ(fraction(DBL_MIN - min_subnormal), "4503599627370495," + power_of_two(1074));
  EXPECT_EQ(fraction(-DBL_MIN), "-1," + power_of_two(1022));  // 2^-1022
  // DBL_MAX = (2^53 - 1) * 2^971.
  mpz_class max_value;
  mpz_ui_pow_ui(max_value.get_mpz_t(), 2, 971);
  max_value *= mpz_class("9007199254740991");
  EXPECT_EQ(fraction(DBL_MAX), max_value.get_str() + ",1");
  EXPECT_EQ(fraction(-DBL_MAX), "-" + max_value.get_str() + ",1");
}

TEST(ExactFraction, NonFiniteThrows) {
  std::string s = "kept";
  EXPECT_THROW(append_exact_fraction(s, std::numeric_limits<double>::quiet_NaN()),
               std::invalid_argument);
  EXPECT_THROW(append_exact_fraction(s, std::numeric_limits<double>::infinity()),
               std::invalid_argument);
  EXPECT_THROW(append_exact_fraction(s, -std::numeric_limits<double>::infinity()),
               std::invalid_argument);
  EXPECT_EQ(s, "kept");
}

TEST(QueryRows, NonFiniteCoordinateThrowsAndWritesNothing) {
  std::array<Eigen::Vector3d, 8> rows;
  for (int k = 0; k < 8; ++k) rows[k] = Eigen::Vector3d(k, 0.5 * k, -k);
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()}) {
    auto broken = rows;
    broken[7].z() = bad;  // the last coordinate: nothing before it may be written either
    std::string text = "kept";
    EXPECT_THROW(append_query_rows(text, broken, true), std::invalid_argument);
    EXPECT_EQ(text, "kept");
    std::ostringstream stream;
    EXPECT_THROW(write_query_rows(stream, broken, false), std::invalid_argument);
    EXPECT_EQ(stream.str(), "");
    VertexFaceQuery vf{rows[0], rows[1], rows[2], rows[3], rows[4], rows[5], rows[6], rows[7]};
    vf.a_t0.x() = bad;
    EXPECT_THROW(write_query(stream, vf, false), std::invalid_argument);
    EdgeEdgeQuery ee{rows[0], rows[1], rows[2], rows[3], rows[4], rows[5], rows[6], rows[7]};
    ee.eb1_t1.y() = bad;
    EXPECT_THROW(write_query(stream, ee, true), std::invalid_argument);
    EXPECT_EQ(stream.str(), "");
    EXPECT_THROW(append_query(text, vf, true), std::invalid_argument);
    EXPECT_THROW(append_query(text, ee, true), std::invalid_argument);
    EXPECT_EQ(text, "kept");
  }
}

TEST(QueryRows, RowLayoutByHand) {
  std::array<Eigen::Vector3d, 8> rows;
  for (int k = 0; k < 8; ++k) rows[k] = Eigen::Vector3d(0.0, 0.0, 0.0);
  rows[0] = Eigen::Vector3d(0.5, -2.0, 0.1);
  std::string text;
  append_query_rows(text, rows, true);
  std::string expected = "1,2,-2,1,3602879701896397,36028797018963968,1\n";
  for (int k = 1; k < 8; ++k) expected += "0,1,0,1,0,1,1\n";
  EXPECT_EQ(text, expected);
  std::ostringstream stream;
  write_query_rows(stream, rows, true);
  EXPECT_EQ(stream.str(), expected);
}

// ---- Round trips through read_query_file -------------------------------------------------------

/// Finite doubles of every kind: random bit patterns (all exponents, subnormals included) and a
/// fixed list of edge values.
std::vector<double> test_values(std::uint64_t seed, std::size_t random_count) {
  std::vector<double> values = {0.0,
                                -0.0,
                                1.0,
                                -1.0,
                                0.1,
                                -1e-300,
                                1e300,
                                std::numeric_limits<double>::denorm_min(),
                                -std::numeric_limits<double>::denorm_min(),
                                DBL_MIN,
                                -DBL_MIN,
                                DBL_MIN - std::numeric_limits<double>::denorm_min(),
                                DBL_MAX,
                                -DBL_MAX,
                                std::nextafter(1.0, 2.0),
                                std::nextafter(1.0, 0.0),
                                std::ldexp(1.0, -64),
                                std::ldexp(1.0, 64),
                                1024.0,
                                2048.0};
  std::mt19937_64 rng(seed);
  while (values.size() < random_count) {
    const std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) values.push_back(v);
  }
  return values;
}

class RoundTrip : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("exactccd-query-writer-test-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

/// The 8 rows of query `q` of a value list (cycled), so that every value lands in every column.
std::array<Eigen::Vector3d, 8> rows_from(const std::vector<double>& values, std::size_t q) {
  std::array<Eigen::Vector3d, 8> rows;
  for (int k = 0; k < 8; ++k) {
    const std::size_t i = (q * 24 + static_cast<std::size_t>(k) * 3) % values.size();
    rows[k] = Eigen::Vector3d(values[i], values[(i + 1) % values.size()],
                              values[(i + 2) % values.size()]);
  }
  return rows;
}

void expect_exact(const RationalPoint& read, const Eigen::Vector3d& written, const char* what) {
  // mpq_class(double) is GMP's exact conversion (mpq_set_d).
  EXPECT_EQ(read.x, mpq_class(written.x())) << what << " x = " << written.x();
  EXPECT_EQ(read.y, mpq_class(written.y())) << what << " y = " << written.y();
  EXPECT_EQ(read.z, mpq_class(written.z())) << what << " z = " << written.z();
}

TEST_F(RoundTrip, VertexFaceQueriesReadBackAsTheSameDoubles) {
  const std::vector<double> values = test_values(test::test_seed("vertex-face round trip"), 2000);
  const std::size_t count = values.size() / 8 + 3;
  const fs::path path = dir_ / "vertex-face" / "data_0.csv";
  fs::create_directories(path.parent_path());
  std::vector<VertexFaceQuery> written;
  {
    std::ofstream out(path);
    for (std::size_t q = 0; q < count; ++q) {
      const auto r = rows_from(values, q);
      written.push_back({r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]});
      write_query(out, written.back(), q % 3 == 0);
    }
    ASSERT_TRUE(out.good());
  }
  const QueryFile file = read_query_file(path.string(), QueryType::vertex_face);
  ASSERT_EQ(file.queries.size(), count);
  for (std::size_t q = 0; q < count; ++q) {
    const VertexFaceQuery& w = written[q];
    const auto& p = file.queries[q].query.points;
    EXPECT_EQ(file.queries[q].truth, q % 3 == 0);
    expect_exact(p[0], w.p_t0, "p_t0");
    expect_exact(p[1], w.a_t0, "a_t0");
    expect_exact(p[2], w.b_t0, "b_t0");
    expect_exact(p[3], w.c_t0, "c_t0");
    expect_exact(p[4], w.p_t1, "p_t1");
    expect_exact(p[5], w.a_t1, "a_t1");
    expect_exact(p[6], w.b_t1, "b_t1");
    expect_exact(p[7], w.c_t1, "c_t1");
  }
}

TEST_F(RoundTrip, EdgeEdgeQueriesReadBackAsTheSameDoubles) {
  const std::vector<double> values = test_values(test::test_seed("edge-edge round trip"), 2000);
  const std::size_t count = values.size() / 8 + 3;
  const fs::path path = dir_ / "edge-edge" / "data_0.csv";
  fs::create_directories(path.parent_path());
  std::vector<EdgeEdgeQuery> written;
  {
    std::ofstream out(path);
    for (std::size_t q = 0; q < count; ++q) {
      const auto r = rows_from(values, q + 5);
      written.push_back({r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]});
      write_query(out, written.back(), q % 2 == 1);
    }
    ASSERT_TRUE(out.good());
  }
  const QueryFile file = read_query_file(path.string(), QueryType::edge_edge);
  ASSERT_EQ(file.queries.size(), count);
  for (std::size_t q = 0; q < count; ++q) {
    const EdgeEdgeQuery& w = written[q];
    const auto& p = file.queries[q].query.points;
    EXPECT_EQ(file.queries[q].truth, q % 2 == 1);
    expect_exact(p[0], w.ea0_t0, "ea0_t0");
    expect_exact(p[1], w.ea1_t0, "ea1_t0");
    expect_exact(p[2], w.eb0_t0, "eb0_t0");
    expect_exact(p[3], w.eb1_t0, "eb1_t0");
    expect_exact(p[4], w.ea0_t1, "ea0_t1");
    expect_exact(p[5], w.ea1_t1, "ea1_t1");
    expect_exact(p[6], w.eb0_t1, "eb0_t1");
    expect_exact(p[7], w.eb1_t1, "eb1_t1");
  }
}

// Every field is in lowest terms with a power-of-two denominator (the reader canonicalizes, so
// this is checked on the text itself).
TEST(ExactFraction, LowestTermsWithPowerOfTwoDenominator) {
  for (const double v : test_values(test::test_seed("lowest terms"), 5000)) {
    const std::string s = fraction(v);
    const std::size_t comma = s.find(',');
    ASSERT_NE(comma, std::string::npos) << s;
    const mpz_class num(s.substr(0, comma), 10), den(s.substr(comma + 1), 10);
    ASSERT_GT(den, 0) << s;
    EXPECT_EQ(mpz_popcount(den.get_mpz_t()), 1u) << s;  // a power of two
    mpz_class g;
    mpz_gcd(g.get_mpz_t(), num.get_mpz_t(), den.get_mpz_t());
    if (num == 0)
      EXPECT_EQ(den, 1) << s;
    else
      EXPECT_EQ(g, 1) << s;
    EXPECT_EQ(mpq_class(num, den), mpq_class(v)) << s;
  }
}

}  // namespace
}  // namespace exactccd
