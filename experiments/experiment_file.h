// Experiment files (issue 10): TOML (toml++) read into the documents of experiments/sweep.h,
// every error one line naming the file, the line and the key.
#pragma once

#include <filesystem>
#include <optional>

#include "experiments/sweep.h"

namespace multicpg::experiments {

// Reads and resolves FILE; `runs` (if given) replaces the file's runs. Throws BadInput as
// "FILE:LINE: key message" for a bad value, type, key or leg (the line of the key, or of its
// table when the key is not in the file), "FILE:LINE: message" for TOML syntax (a repeated key
// among them), and "FILE: message" for a file that is missing or cannot be read.
Sweep load_experiment_file(const std::filesystem::path& file, std::optional<int> runs = {});

}  // namespace multicpg::experiments
