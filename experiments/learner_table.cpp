#include "experiments/learner_table.h"

#include <set>
#include <string>

#include "common/errors.h"
#include "learning/learners.h"

namespace multicpg::experiments {
namespace {

constexpr const char* kLearnerKey = "learning.learner";

nlohmann::json resolved(const nlohmann::json& table, const std::string& path) {
  if (!table.is_object()) {
    throw OptionError(path, "must be a table such as { name = \"bayes\" }, got " + table.dump());
  }
  for (const auto& [key, value] : table.items()) {
    if (key != "name" && key != "options") {
      throw OptionError(path + "." + key, "is not a learner key (known: name, options)");
    }
  }
  if (!table.contains("name") || !table.at("name").is_string()) {
    throw OptionError(path + ".name", "must name a learner (" + learning::learner_names() + ")");
  }
  learning::LearnerChoice asked;
  asked.name = table.at("name").get<std::string>();
  asked.options = table.value("options", nlohmann::json::object());
  try {
    return learning::resolve_learner(asked);
  } catch (const OptionError& e) {
    throw OptionError(path + "." + e.key(), e.what());
  }
}

}  // namespace

std::optional<nlohmann::json> take_learner(nlohmann::json& learning) {
  if (!learning.is_object() || !learning.contains("learner")) return std::nullopt;
  nlohmann::json given = learning.at("learner");
  learning.erase("learner");
  return given;
}

void add_learner(const nlohmann::json& given, nlohmann::json& learning,
                 std::vector<GridAxis>& grid) {
  if (!given.is_array()) {
    learning["learner"] = resolved(given, kLearnerKey);
    return;
  }
  if (given.empty()) throw OptionError(kLearnerKey, "is an empty list");
  nlohmann::json values = nlohmann::json::array();
  std::set<std::string> names;
  for (std::size_t i = 0; i < given.size(); ++i) {
    const std::string path = std::string(kLearnerKey) + "[" + std::to_string(i) + "]";
    nlohmann::json r = resolved(given[i], path);
    // A run's key and group name its learner by name alone, so each name appears once.
    if (!names.insert(r.at("name").get<std::string>()).second) {
      throw OptionError(path, "names learner '" + r.at("name").get<std::string>() +
                                  "' again; one entry per learner (an option study is its own "
                                  "experiment)");
    }
    values.push_back(std::move(r));
  }
  grid.push_back({kLearnerKey, values});
  learning["learner"] = values;
}

}  // namespace multicpg::experiments
