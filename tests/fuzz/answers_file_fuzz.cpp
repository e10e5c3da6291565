// libFuzzer harness: the answers-file reader of `exactccd grade` (read_answers_file) on
// arbitrary bytes, with the expected answer count one below, equal to and one above the
// number of lines, and t_max 1 and 1/2.
//
// Properties: the reader returns or throws exactccd::InputError, nothing else; what it returns
// has exactly the expected number of answers, one per line in order, a toi only on a '1'
// line, and every toi inside [0, t_max] (answers_file.hpp).
#include <cstddef>
#include <cstdint>
#include <string>

#include "exactccd/query_file.hpp"
#include "fuzz_support.hpp"
#include "oracle/answers_file.hpp"

using namespace exactccd;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = (fuzz::scratch_folder() / "answers.txt").string();
  fuzz::write_file(path, data, size);
  std::size_t lines = 0;  // '\n'-terminated lines, plus a last one without '\n'
  for (std::size_t i = 0; i < size; ++i) lines += data[i] == '\n';
  if (size > 0 && data[size - 1] != '\n') ++lines;

  for (const std::size_t count : {lines > 0 ? lines - 1 : 0, lines, lines + 1})
    for (const double t_max : {1.0, 0.5}) {
      if (count != lines && t_max != 1.0) continue;
      std::vector<oracle::Answer> answers;
      try {
        answers = oracle::read_answers_file(path, count, "queries.csv", t_max);
      } catch (const InputError&) {
        continue;
      }
      fuzz::require(answers.size() == count, "answer count " + std::to_string(answers.size()) +
                                                 " for an expected " + std::to_string(count));
      for (std::size_t i = 0; i < answers.size(); ++i) {
        const oracle::Answer& a = answers[i];
        fuzz::require(a.line == i + 1, "answer " + std::to_string(i) + " on line " +
                                           std::to_string(a.line));
        if (!a.toi) continue;
        fuzz::require(a.collides, "a toi on a '0' answer, line " + std::to_string(a.line));
        fuzz::require(sgn(*a.toi) >= 0 && *a.toi <= mpq_class(t_max),
                      "toi " + a.toi->get_str() + " outside [0, t_max], line " +
                          std::to_string(a.line));
      }
    }
  return 0;
}
