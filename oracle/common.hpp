// Pieces shared by the oracle's commands (`exactccd`, `exactccd_study`): exit statuses, usage
// and output errors, warnings, option checks, doubles printed exactly.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace exactccd::oracle {

/// Exit statuses of the `exactccd` command (documented in its --help text).
enum ExitStatus : int {
  kExitAgree = 0,     ///< everything ran and every answer / truth value is right
  kExitDisagree = 1,  ///< some result disagrees (check: with the truth column; grade: answers)
  kExitBadInput = 2,  ///< bad command line or malformed input file: nothing judged
  kExitInternal = 3,  ///< unexpected failure (a bug or out of memory)
};

/// A bad command line (as opposed to a bad file, which is an exactccd::InputError).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An output that cannot be written: a full disk, a refused overwrite (exit status 2).
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::string& path, const std::string& what)
      : std::runtime_error(path + ": " + what) {}
};

/// Prints "exactccd: warning: <message>" on stderr, one line, control characters escaped.
void warn(const std::string& message);

/// The rule for query files without a query (empty, or only blank lines): a warning for each
/// of `empty_files` when other files hold queries; when no query was read at all (`queries`
/// 0), an InputError naming the file, or a UsageError counting the `file_count` files.
void require_some_queries(const std::vector<std::string>& empty_files, std::size_t file_count,
                          std::size_t queries);

/// Throws UsageError unless t_max lies in (0, 1] (NaN rejected).
void validate_t_max(double t_max);

/// Throws UsageError unless delta (--min-separation) is finite and >= 0.
void validate_min_separation(double delta);

/// `value` with 17 significant digits (%.17g): reading it back gives the same double.
std::string format_double(double value);

}  // namespace exactccd::oracle
