// Checks of flag values at parse time, so every bad value is one line naming its flag (CLI11
// prints "--beta: must be in 0..100, got -1") before any work starts. Ranges
// come from the option structs' Limits, the same that validate() and experiment files use.
#pragma once

#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdint>
#include <string>
#include <vector>

#include "common/limits.h"

namespace multicpg::apps {

// A number in `limits`: not empty, no trailing junk, finite. Shown in --help as "in lo..hi".
template <class T>
CLI::Validator in(const Limits<T>& limits) {
  return CLI::Validator(
      [limits](std::string& text) -> std::string {
        T value{};
        if (text.empty()) return "needs a value in " + limits.text() + ", got an empty string";
        if (!CLI::detail::lexical_cast(text, value)) {
          return "'" + text + "' is not a number in " + limits.text();
        }
        if (!limits.contains(value)) return "must be in " + limits.text() + ", got " + text;
        return {};
      },
      "in " + limits.text());
}

// A seed in kSeedLimits written in digits only (no sign, so -1 cannot wrap).
inline CLI::Validator seed_value() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (text.empty() || ptr != end ||
            (ec != std::errc() && ec != std::errc::result_out_of_range)) {
          return "'" + text + "' is not a seed (a whole number in " + kSeedLimits.text() + ")";
        }
        if (ec == std::errc::result_out_of_range || !kSeedLimits.contains(value)) {
          return "must be in " + kSeedLimits.text() + ", got " + text;
        }
        return {};
      },
      "in " + kSeedLimits.text());
}

// A name from `names` (an enum's, a registry's), checked at parse time: "--mode: unknown mode
// 'Paper' (did you mean paper?)", or the names when none is near ("(paper or robust)").
// `what` names the kind of value ("mode"). No description: the flag's help lists the names.
CLI::Validator one_of(std::vector<std::string> names, std::string what);

// --robot: a built-in robot's name (did you mean, as one_of) or a robot file (FILE.toml,
// docs/robots.md).
CLI::Validator robot_name();

// A path or name that is not the empty string. No description: it holds for every flag, so
// --help would only repeat it after each one.
inline const CLI::Validator kNotEmpty(
    [](std::string& text) -> std::string { return text.empty() ? "must not be empty" : ""; }, "");

// --max-runs: the most runs (grid points x scenarios x runs, or a landscape's combinations) an
// experiment may have (experiments/experiment_limits.h).
void add_max_runs_flag(CLI::App& cmd, std::int64_t& max_runs);

// Makes every option of `cmd` from its `first`-th (in the order they were added) need `needed`:
// flags that do nothing without it are refused ("--beta requires --learn"), never ignored.
void require_for_options_from(CLI::App& cmd, std::size_t first, CLI::Option* needed);

// Adds kNotEmpty to every option of `app` and its subcommands that takes a value: no flag of
// multicpg has a meaning for the empty string (a number, path, name or list).
void refuse_empty_values(CLI::App& app);

}  // namespace multicpg::apps
