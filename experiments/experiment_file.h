// Experiment files: TOML (toml++) read into the documents of experiments/sweep.h,
// every error one line naming the file, the line and the key. The file is bounded before it is
// parsed (experiments/experiment_limits.h): a regular file, at most kMaxExperimentFileBytes, at
// most kMaxExperimentDepth levels deep.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "experiments/sweep.h"

namespace multicpg::experiments {

// Reads and resolves FILE; `runs` (if given) replaces the file's runs; `robot = "R.toml"` is a
// robot file relative to FILE's folder. Throws BadInput as
// "FILE:LINE: key message" for a bad value, type, key or leg (the line of the key, or of its
// table when the key is not in the file), "FILE:LINE: message" for TOML syntax (a repeated key
// among them) or nesting deeper than kMaxExperimentDepth, and "FILE: message" for a file that
// is missing, cannot be read, is no regular file (a directory, FIFO, device, symlink loop), is
// larger than kMaxExperimentFileBytes, or describes more runs than `limits` allow.
Sweep load_experiment_file(const std::filesystem::path& file, std::optional<int> runs = {},
                           const SweepLimits& limits = {});

// The same for the text of a file named `name` (in messages): parse_experiment_text is what
// load_experiment_file does after reading (the fuzz target's entry, fuzz/).
Sweep parse_experiment_text(std::string_view text, const std::string& name,
                            std::optional<int> runs = {}, const SweepLimits& limits = {});

// The text of FILE, checked to be a regular file of at most kMaxExperimentFileBytes without
// reading more than that (a FIFO or /dev/zero is refused, never waited on or read to the end).
// Throws BadInput "FILE: message".
std::string read_experiment_file(const std::filesystem::path& file);

// Where `text`, read as TOML, first nests deeper than `limit` levels (each table, dotted-key part,
// list and inline table a level; the root table is level 0): its line, or nothing. Looks only at
// the structure (strings, comments, keys, brackets), so it is cheap and never recurses deeper
// than `limit`; the TOML parser runs only on text it has passed.
std::optional<long> line_nested_deeper(std::string_view text, int limit);

}  // namespace multicpg::experiments
