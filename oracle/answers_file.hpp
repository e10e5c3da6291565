// The answers file that `exactccd grade` judges: one line per query, in order, `0`, `1` or
// `1,toi` (toi a decimal number, the graded code's reported time of impact, read exactly); a
// no-collision line may carry the +infinity TOI of the no-contact convention, `0,inf`.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace exactccd::oracle {

struct Answer {
  bool collides = false;
  std::optional<mpq_class> toi;  ///< only on a `1` line, when given: exactly the decimal written
  std::size_t line = 0;          ///< 1-based
};

/// Reads `path`, expecting exactly `query_count` answers (the number of queries in
/// `queries_path`, named in the message when the counts differ). Throws InputError
/// ("path:line: what") for a file that cannot be read (see LineReader), a malformed line, a
/// toi that is not a decimal number, a toi outside [0, t_max], a toi other than inf on a `0`
/// line, or too few
/// / too many lines.
std::vector<Answer> read_answers_file(const std::string& path, std::size_t query_count,
                                      const std::string& queries_path, double t_max);

/// The exact value of a decimal number `[+-]digits[.digits][(e|E)[+-]digits]` (at least one
/// digit before the exponent; no spaces), computed from its digits and exponent without
/// rounding; nullopt for anything else (nan, inf, hexadecimal). An exponent beyond
/// +-kMaxDecimalExponent is refused too (nullopt, *exponent_too_large set), so that the value
/// stays cheap to compute.
inline constexpr long kMaxDecimalExponent = 100000;
std::optional<mpq_class> parse_decimal(std::string_view text, bool* exponent_too_large);

}  // namespace exactccd::oracle
