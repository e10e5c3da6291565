#include "oracle/answers_file.hpp"

#include "pipeline/trim.hpp"
#include "exactccd/query_file.hpp"
#include "oracle/common.hpp"

namespace exactccd::oracle {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The digits at the front of `text`, removed from it.
std::string_view take_digits(std::string_view& text) {
  std::size_t n = 0;
  while (n < text.size() && is_digit(text[n])) ++n;
  const std::string_view digits = text.substr(0, n);
  text.remove_prefix(n);
  return digits;
}

// The toi of a `1,toi` line: a decimal number in [0, t_max], exactly.
mpq_class parse_toi(std::string_view text, double t_max, const std::string& path,
                    std::size_t line) {
  bool exponent_too_large = false;
  const std::optional<mpq_class> value = parse_decimal(text, &exponent_too_large);
  if (exponent_too_large)
    throw InputError(path, line,
                     "toi exponent beyond +-" + std::to_string(kMaxDecimalExponent) + ": " +
                         quote_for_message(text));
  if (!value)
    throw InputError(path, line, "toi is not a decimal number: " + quote_for_message(text));
  if (sgn(*value) < 0 || *value > mpq_class(t_max))
    throw InputError(path, line,
                     "toi " + quote_for_message(text) + " lies outside [0, t_max] = [0, " +
                         format_double(t_max) + "]");
  return *value;
}

// The no-contact TOI of the +infinity convention (Tight Inclusion, ipc-toolkit, exactccd):
// inf, +inf, infinity or +infinity, in any case.
bool is_positive_infinity(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return lower == "inf" || lower == "infinity";
}

Answer parse_answer(std::string_view text, double t_max, const std::string& path,
                    std::size_t line) {
  const std::size_t comma = text.find(',');
  const std::string_view verdict = trim(text.substr(0, comma));
  Answer answer;
  answer.line = line;
  if (verdict != "0" && verdict != "1")
    throw InputError(path, line, "expected '0', '1' or '1,toi', found " + quote_for_message(text));
  answer.collides = verdict == "1";
  if (comma == std::string_view::npos) return answer;
  if (!answer.collides) {
    if (is_positive_infinity(trim(text.substr(comma + 1)))) return answer;  // `0,inf`
    throw InputError(path, line,
                     "a '0' (no collision) line takes no toi, or 'inf', found " +
                         quote_for_message(text));
  }
  answer.toi = parse_toi(trim(text.substr(comma + 1)), t_max, path, line);
  return answer;
}

}  // namespace

std::optional<mpq_class> parse_decimal(std::string_view text, bool* exponent_too_large) {
  *exponent_too_large = false;
  bool negative = false;
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) {
    negative = text.front() == '-';
    text.remove_prefix(1);
  }
  const std::string_view whole = take_digits(text);
  std::string_view fraction;
  if (!text.empty() && text.front() == '.') {
    text.remove_prefix(1);
    fraction = take_digits(text);
  }
  if (whole.empty() && fraction.empty()) return std::nullopt;
  long exponent = 0;
  if (!text.empty() && (text.front() == 'e' || text.front() == 'E')) {
    text.remove_prefix(1);
    bool negative_exponent = false;
    if (!text.empty() && (text.front() == '+' || text.front() == '-')) {
      negative_exponent = text.front() == '-';
      text.remove_prefix(1);
    }
    const std::string_view digits = take_digits(text);
    if (digits.empty()) return std::nullopt;
    for (const char c : digits) {
      exponent = 10 * exponent + (c - '0');
      if (exponent > kMaxDecimalExponent) {
        *exponent_too_large = text.empty();  // only when the rest is well-formed
        return std::nullopt;
      }
    }
    if (negative_exponent) exponent = -exponent;
  }
  if (!text.empty()) return std::nullopt;

  // value = digits * 10^(exponent - fraction digits), exactly.
  const mpz_class digits(std::string(whole) + std::string(fraction), 10);
  const long scale = exponent - static_cast<long>(fraction.size());
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
  mpq_class value = scale < 0 ? mpq_class(digits, power) : mpq_class(digits * power);
  value.canonicalize();
  return negative ? mpq_class(-value) : value;
}

std::vector<Answer> read_answers_file(const std::string& path, std::size_t query_count,
                                      const std::string& queries_path, double t_max) {
  LineReader in(path, "an answers file");
  std::vector<Answer> answers;
  std::string line;
  std::size_t blank = 0;  // the first of the blank lines just read (0: none)
  while (in.next(line)) {
    // Blank lines at the end of the file are no answers; one before an answer is an error.
    if (trim(line).empty()) {
      if (blank == 0) blank = in.line_number();
      continue;
    }
    if (blank != 0)
      throw InputError(path, blank, "a blank line among the answers (one answer per line)");
    if (answers.size() == query_count)
      throw InputError(path, in.line_number(),
                       "more answer lines than the " + std::to_string(query_count) +
                           " queries in " + queries_path);
    answers.push_back(parse_answer(trim(line), t_max, path, in.line_number()));
  }
  if (answers.size() < query_count)
    throw InputError(path, 0,
                     std::to_string(answers.size()) + " answer line(s) for the " +
                         std::to_string(query_count) + " queries in " + queries_path);
  return answers;
}

}  // namespace exactccd::oracle
