#include "answers_file.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "exactccd/query_file.hpp"

namespace exactccd::cli {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

// `text` quoted for a message, cut short so that a huge line still gives a one-line message.
std::string quoted(std::string_view text) {
  constexpr std::size_t kMax = 60;
  if (text.size() <= kMax) return "'" + std::string(text) + "'";
  return "'" + std::string(text.substr(0, kMax)) + "...'";
}

// A finite decimal double, the whole field (std::from_chars: locale-free, correctly rounded).
double parse_toi(std::string_view text, const std::string& path, std::size_t line) {
  double value = 0.0;
  const auto [end, error] =
      std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::general);
  if (text.empty() || error == std::errc::invalid_argument || end != text.data() + text.size())
    throw InputError(path, line, "toi is not a decimal number: " + quoted(text));
  if (error == std::errc::result_out_of_range)
    throw InputError(path, line, "toi is out of the range of doubles: " + quoted(text));
  if (!std::isfinite(value))
    throw InputError(path, line, "toi must be finite, found " + quoted(text));
  return value;
}

Answer parse_answer(std::string_view text, const std::string& path, std::size_t line) {
  const std::size_t comma = text.find(',');
  const std::string_view verdict = trim(text.substr(0, comma));
  Answer answer;
  answer.line = line;
  if (verdict != "0" && verdict != "1")
    throw InputError(path, line, "expected '0', '1' or '1,toi', found " + quoted(text));
  answer.collides = verdict == "1";
  if (comma == std::string_view::npos) return answer;
  if (!answer.collides)
    throw InputError(path, line, "a toi on a '0' (no collision) line: " + quoted(text));
  answer.toi = parse_toi(trim(text.substr(comma + 1)), path, line);
  return answer;
}

}  // namespace

std::vector<Answer> read_answers_file(const std::string& path, std::size_t query_count,
                                      const std::string& queries_path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path, 0, "no such file");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, "is a directory, not an answers file");
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open for reading");

  std::vector<Answer> answers;
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (answers.size() == query_count)
      throw InputError(path, line_no,
                       "more answer lines than the " + std::to_string(query_count) +
                           " queries in " + queries_path);
    answers.push_back(parse_answer(trim(line), path, line_no));
  }
  if (in.bad()) throw InputError(path, line_no, "read error");
  if (answers.size() < query_count)
    throw InputError(path, 0,
                     std::to_string(answers.size()) + " answer line(s) for the " +
                         std::to_string(query_count) + " queries in " + queries_path);
  return answers;
}

}  // namespace exactccd::cli
