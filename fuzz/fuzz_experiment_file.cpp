// libFuzzer target for experiment files (docs/experiments.md "Experiment files"): TOML text read,
// bounded and resolved as `multicpg run FILE --check` does (experiments::parse_experiment_text).
// Each input must resolve or throw BadInput; anything else (another exception, a crash, a sanitizer
// report, a stack overflow in the TOML parser) is a finding. It also checks the nesting scan
// against toml++: text the scan passes must parse to a tree no deeper than the scan's limit, else
// the scan under-counts and a deeper file could reach the parser's unbounded recursion.
#include <toml++/toml.h>

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "common/errors.h"
#include "experiments/experiment_file.h"
#include "experiments/experiment_limits.h"

namespace {

// Runs per input: enough for every example's grid, few enough that resolving stays fast.
constexpr std::int64_t kFuzzMaxRuns = 1000;

// The depth of the deepest node (the root table is level 0), without recursion.
int tree_depth(const toml::table& root) {
  int deepest = 0;
  std::vector<std::pair<const toml::node*, int>> todo{{&root, 0}};
  while (!todo.empty()) {
    const auto [node, depth] = todo.back();
    todo.pop_back();
    deepest = depth > deepest ? depth : deepest;
    if (const toml::table* t = node->as_table()) {
      for (const auto& [key, value] : *t) todo.emplace_back(&value, depth + 1);
    } else if (const toml::array* a = node->as_array()) {
      for (const toml::node& value : *a) todo.emplace_back(&value, depth + 1);
    }
  }
  return deepest;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace multicpg;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    experiments::parse_experiment_text(text, "fuzz.toml", {}, {kFuzzMaxRuns, "max_runs"});
  } catch (const BadInput&) {
  }
  if (!experiments::line_nested_deeper(text, experiments::kMaxExperimentDepth)) {
    try {
      if (tree_depth(toml::parse(text)) > experiments::kMaxExperimentDepth) __builtin_trap();
    } catch (const toml::parse_error&) {
    }
  }
  return 0;
}
