// The command-line conventions of the oracle's programs (`exactccd`, `exactccd_study`): option
// validators and shared options (CLI11), and one line on stderr with the exit status for every
// failure.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <tuple>

#include "corpus/simulation_queries.hpp"

namespace exactccd::oracle {

/// Reports an error on one line of stderr, "exactccd: <message>" (control characters escaped,
/// '\n' among them).
void report_error(const std::string& message);

/// The exit status once stdout is flushed: output lost to a full disk or a closed descriptor is
/// an error (kExitBadInput), not a success.
int finish(int status);

/// Runs `command` and returns finish(its status); every exception ends as one line on stderr
/// (report_error) with its exit status: kExitBadInput for bad input (InputError, UsageError,
/// OutputError, a filesystem error), kExitInternal for anything else.
int run_reporting_errors(const std::function<int()>& command);

/// Checks that an option's argument is a whole number before CLI11 converts it (CLI11 reads an
/// empty argument as 0): [+-]digits for an integer; for a number, what strtod reads entirely.
CLI::Validator numeric_text(bool integer);

/// Digits only, below 2^64: CLI11 would wrap a negative number around and saturate a large one.
CLI::Validator seed_text();

void add_force_flag(CLI::App* command, bool& force);
/// --type vf|ee|vertex-face|edge-edge (parse_type_name).
void add_type_option(CLI::App* command, std::string& type_name);
/// `exactccd check`'s --type: the benchmark's kinds, and the point kinds and the plane
/// (pe|pe2d|pp|pp2d|pl: primitive_kind_from_name).
void add_check_type_option(CLI::App* command, std::string& type_name);
void add_t_max_option(CLI::App* command, double& t_max);
/// --min-separation D: the run decides minimum-separation CCD with delta = D (0: contact).
void add_min_separation_option(CLI::App* command, double& delta);

/// --resolution, --steps, --seed of the simulation-like set.
std::tuple<CLI::Option*, CLI::Option*, CLI::Option*> add_simulation_options(
    CLI::App* command, sim::SimulationConfig& config);

}  // namespace exactccd::oracle
