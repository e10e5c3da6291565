#include "oracle/command_line.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <new>
#include <system_error>

#include "exactccd/query_file.hpp"
#include "oracle/common.hpp"

namespace exactccd::oracle {

namespace {

constexpr const char* kTypeHelp =
    "Query type: vf (vertex-face) or ee (edge-edge); default: from the nearest folder named "
    "vertex-face or edge-edge in each file's path";

}  // namespace

void report_error(const std::string& message) {
  std::cerr << "exactccd: " << exactccd::printable(message) << '\n';
}

int finish(int status) {
  // std::cout writes through stdout's buffer (synchronised with stdio): one fflush covers both,
  // and keeps the reason in errno (std::cout.flush() would flush first and lose it).
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  std::cout.flush();
  if (flushed && std::cout.good() && !std::ferror(stdout)) return status;
  report_error("stdout: write failed" +
               (!flushed && error != 0
                    ? ": " + std::error_code(error, std::generic_category()).message()
                    : std::string()));
  return kExitBadInput;
}

int run_reporting_errors(const std::function<int()>& command) {
  int status = kExitInternal;
  try {
    status = command();
  } catch (const exactccd::InputError& e) {
    report_error(e.what());
    return kExitBadInput;
  } catch (const UsageError& e) {
    report_error(e.what());
    return kExitBadInput;
  } catch (const OutputError& e) {
    report_error(e.what());
    return kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    // "<path>: <reason>", not the library's "filesystem error: cannot ...: <reason> [<path>]".
    std::string where = e.path1().string();
    if (!e.path2().empty()) where += (where.empty() ? "" : ", ") + e.path2().string();
    report_error((where.empty() ? std::string() : where + ": ") + e.code().message());
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    report_error("internal error: out of memory");
    return kExitInternal;
  } catch (const std::exception& e) {
    report_error(std::string("internal error: ") + e.what());
    return kExitInternal;
  } catch (...) {
    report_error("internal error: an unknown exception");
    return kExitInternal;
  }
  return finish(status);
}

CLI::Validator numeric_text(bool integer) {
  return CLI::Validator(
      [integer](std::string& text) {
        bool ok = !text.empty();
        if (ok && integer) {
          const std::size_t digits = text[0] == '+' || text[0] == '-' ? 1 : 0;
          ok = text.size() > digits &&
               text.find_first_not_of("0123456789", digits) == std::string::npos;
        } else if (ok) {
          char* end = nullptr;
          errno = 0;
          const double value = std::strtod(text.c_str(), &end);
          ok = !std::isspace(static_cast<unsigned char>(text[0])) &&
               end == text.c_str() + text.size();
          // Out of the doubles' range: strtod would give 0 or infinity without a word.
          if (ok && errno == ERANGE && value == 0)
            return exactccd::quote_for_message(text) +
                   " is too small for a double: it would round to 0 (the least positive double "
                   "is about 4.9e-324)";
          if (ok && errno == ERANGE && std::isinf(value))
            return exactccd::quote_for_message(text) +
                   " is beyond the largest double (about 1.8e308)";
        }
        return ok ? std::string()
                  : exactccd::quote_for_message(text) + " is not " +
                        (integer ? "an integer" : "a number");
      },
      integer ? "INTEGER" : "NUMBER");
}

CLI::Validator seed_text() {
  return CLI::Validator(
      [](std::string& text) {
        const bool digits =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        const bool fits =
            text.size() < 20 || (text.size() == 20 && text <= "18446744073709551615");
        return digits && fits ? std::string()
                              : exactccd::quote_for_message(text) +
                                    " is not an integer in [0, 2^64 - 1]";
      },
      "SEED");
}

void add_force_flag(CLI::App* command, bool& force) {
  command->add_flag("--force", force,
                    "Replace output files that already exist (never deletes other files)");
}

void add_type_option(CLI::App* command, std::string& type_name) {
  command->add_option("--type", type_name, kTypeHelp)
      ->check(CLI::IsMember({"vf", "ee", "vertex-face", "edge-edge"}));
}

void add_check_type_option(CLI::App* command, std::string& type_name) {
  command
      ->add_option("--type", type_name,
                   std::string(kTypeHelp) +
                       "; or a point kind, whose files are given one by one: pe (point-edge, 6 "
                       "rows per query: p, e0, e1 at t0 then t1), pe2d (the same in the plane, "
                       "5 columns x_num,x_den,y_num,y_den,truth), pp (point-point, 4 rows: p, q), "
                       "pp2d, pl (point-plane, 6 rows: p, origin, normal)")
      ->check(CLI::IsMember(
          {"vf", "ee", "vertex-face", "edge-edge", "pe", "pe2d", "pp", "pp2d", "pl"}));
}

void add_t_max_option(CLI::App* command, double& t_max) {
  command->add_option("--t-max", t_max, "End of the time interval [0, T]; T in (0, 1]")
      ->check(numeric_text(false))
      ->capture_default_str();
}

void add_min_separation_option(CLI::App* command, double& delta) {
  command
      ->add_option("--min-separation", delta,
                   "Minimum separation delta >= 0: a query collides when its primitives come "
                   "within Euclidean distance delta, its TOI is the earliest such time (0: "
                   "contact). The files' truth column is read as the truth for this delta "
                   "(generate --min-separation writes such files)")
      ->check(numeric_text(false))
      ->capture_default_str();
}

std::tuple<CLI::Option*, CLI::Option*, CLI::Option*> add_simulation_options(
    CLI::App* command, sim::SimulationConfig& config) {
  CLI::Option* resolution =
      command->add_option("--resolution", config.sheet_resolution, "Sheet vertices per side")
          ->check(numeric_text(true))
          ->check(CLI::Range(2, 1024))
          ->capture_default_str();
  CLI::Option* steps = command->add_option("--steps", config.steps, "Time steps")
                           ->check(numeric_text(true))
                           ->check(CLI::Range(1, 100000))
                           ->capture_default_str();
  CLI::Option* seed =
      command->add_option("--seed", config.seed, "Seed of the placement and initial wrinkles")
          ->check(seed_text())
          ->capture_default_str();
  return {resolution, steps, seed};
}

}  // namespace exactccd::oracle
