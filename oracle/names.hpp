// The names of modes, stages and query types, as the oracle's commands accept and print them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exactccd/types.hpp"

namespace exactccd::oracle {

/// The Mode named `name`: "float_only", "filtered" or "exact" (to_string(Mode)), or "default",
/// the old name of "filtered", still accepted as an alias (old scripts, old A/B commands);
/// nullopt otherwise. The one parser of mode names: command, scene files and Python.
std::optional<Mode> parse_mode_name(const std::string& name);
/// The canonical names, to_string(Mode): "float_only", "filtered", "exact" (the alias not listed).
const std::vector<std::string>& mode_names();
/// The accepted names for a message: "float_only", "filtered" or "exact" ("default": filtered).
const std::string& mode_names_text();

/// Every Stage in enum order. Found through to_string(Stage), which names each stage and
/// answers "unknown" past the last, so that a stage added to the library is listed too.
const std::vector<Stage>& all_stages();

/// The stages that can decide a query in `mode` (the table's share columns).
std::vector<Stage> stages_of(Mode mode);

/// "vf" / "vertex-face" or "ee" / "edge-edge", as accepted by --type; nullopt otherwise.
std::optional<QueryType> parse_type_name(const std::string& name);

/// The type of the queries in `file`: `forced` when given (--type), else from the folder name.
/// Throws InputError naming the file when neither tells.
QueryType resolve_query_type(const std::string& file, const std::optional<QueryType>& forced);

}  // namespace exactccd::oracle
