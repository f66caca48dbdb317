// Checking an experiment document (sweep.h) against the defaults it is merged onto: every key
// known, every value of its default's type, lists where one value belongs taken as grid axes,
// and each section read back through its type's from_json to prove it means what it says. Nothing
// here knows which sections a document has; resolve_sweep (sweep.cpp) says that.
#pragma once

#include <cstdint>
#include <exception>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "common/errors.h"
#include "common/json_diff.h"
#include "common/limits.h"

namespace multicpg::experiments {

// One swept option: its dotted key ("learning.annealing.beta") and its values.
struct GridAxis {
  std::string key;
  nlohmann::json values;  // a JSON array
};

namespace document {

std::string join(const std::vector<std::string>& parts, const std::string& sep);
// "learning" + "seed" -> "learning.seed"; "" + "runs" -> "runs".
std::string child(const std::string& path, const std::string& key);
// "scenarios" + 2 -> "scenarios[2]".
std::string indexed(const std::string& path, std::size_t i);

// Checks a single value against its default's type (no grid); throws OptionError at `path`.
void check_type(const nlohmann::json& value, const nlohmann::json& def, const std::string& path);

// `out` = the defaults `def` with the document's `value` put in, every key and type checked;
// grid lists go to `grid` (and stay lists in `out`). A key of `forbidden` is refused as one each
// run sets.
void merge_checked(const nlohmann::json& value, const nlohmann::json& def, const std::string& path,
                   nlohmann::json& out, std::vector<GridAxis>& grid,
                   const std::set<std::string>& forbidden = {});

// "learning.annealing.beta" -> "/annealing/beta" within its section.
nlohmann::json::json_pointer pointer_in_section(const std::string& key);

// Refuses a document nested deeper than kMaxExperimentDepth or with a list longer than
// kMaxListValues, naming the key, before anything else looks at it (a document from Python is
// not bounded by a file's size). Iterative: the depth is what is being checked.
void check_bounds(const nlohmann::json& doc);

// The simulation options of a point with its terrain written as robot::terrain_text writes it
// ("slope:5" -> "slope:5:0"), so that options_from's read-back compares like with like.
nlohmann::json canonical_sim(nlohmann::json point);

// A grid point's value of one axis as a short text ("0.1", "paper", "4-5-6"); ':' (a terrain's
// "slope:5") as '_', so the value can name a run file.
std::string value_text(const nlohmann::json& v);

// A whole number at `key` of `doc` in [lo, hi], or `fallback` when absent.
template <class T>
T whole(const nlohmann::json& doc, const std::string& key, T fallback, const Limits<T>& limits,
        const std::string& path) {
  if (!doc.contains(key)) return fallback;
  const nlohmann::json& v = doc.at(key);
  if (!v.is_number_integer()) {
    throw OptionError(path, "must be a whole number, got " + v.dump());
  }
  const std::int64_t n = v.get<std::int64_t>();
  if (n < static_cast<std::int64_t>(limits.lo) || n > static_cast<std::int64_t>(limits.hi)) {
    throw OptionError(path, "must be in " + limits.text() + ", got " + std::to_string(n));
  }
  return static_cast<T>(n);
}

// `j` read into a T by its from_json (found by argument-dependent lookup).
template <typename T>
T decode(const nlohmann::json& j) {
  T t;
  from_json(j, t);
  return t;
}

// Which top-level key of `point` its from_json refuses (an unknown enum name throws without
// naming its key): each tried alone on the defaults; `section` when none alone fails.
template <typename T>
std::string failing_key(const nlohmann::json& point, const std::string& section) {
  for (const auto& item : point.items()) {
    nlohmann::json alone = T{};
    alone[item.key()] = item.value();
    try {
      decode<T>(alone);
    } catch (const std::exception&) {
      return child(section, item.key());
    }
  }
  return section;
}

// The options of one grid point, checked to read back as given (an unknown enum name, a
// whole number given for a fractional one, ...).
template <typename T>
T options_from(const nlohmann::json& point, const std::string& section) {
  T options;
  try {
    options = decode<T>(point);
  } catch (const OptionError& e) {
    throw OptionError(child(section, e.key()), e.what());
  } catch (const std::exception& e) {
    throw OptionError(failing_key<T>(point, section), e.what());
  }
  const nlohmann::json full = options;
  nlohmann::json readback = full;
  for (const auto& item : full.items()) {
    if (!point.contains(item.key())) readback.erase(item.key());  // set by each run
  }
  if (const std::vector<std::string> at = json_differences(point, readback, section); !at.empty()) {
    const nlohmann::json::json_pointer ptr = pointer_in_section(at.front());
    throw OptionError(at.front(),
                      "is not a valid value" +
                          (point.contains(ptr) ? ": " + point.at(ptr).dump() : std::string()));
  }
  return options;
}

}  // namespace document
}  // namespace multicpg::experiments
