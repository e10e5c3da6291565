// Command-line pieces shared by the demonstration scene programs (CLI11).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include "exactccd/types.hpp"

namespace exactccd::scenes {

/// --threads (at most this many, 0: all) and --mode (each pair's test).
inline void add_threads_and_mode_options(CLI::App& app, int& threads, Mode& mode) {
  app.add_option("--threads", threads, "At most this many threads (0: all)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--mode", mode,
                 "Each pair's test: filtered (certified, the default), exact, or float_only "
                 "(uncertified doubles, for comparison: the self-check may fail)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, Mode>{{"filtered", Mode::filtered},
                                      {"default", Mode::filtered},  // its old name
                                      {"exact", Mode::exact},
                                      {"float_only", Mode::float_only}},
          CLI::ignore_case))
      ->capture_default_str();
}

/// Parses the arguments and runs the scene; exit status 3 (with the message) on an exception.
template <class Run>
int parse_and_run(CLI::App& app, int argc, char** argv, const char* program, Run&& run) {
  CLI11_PARSE(app, argc, argv);
  try {
    return run();
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program, e.what());
    return 3;
  }
}

}  // namespace exactccd::scenes
