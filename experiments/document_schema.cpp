#include "experiments/document_schema.h"

#include <algorithm>

#include "experiments/experiment_limits.h"
#include "experiments/scenarios.h"
#include "robot/terrain.h"

namespace multicpg::experiments::document {
namespace {

using nlohmann::json;

std::string type_name(const json& j) {
  if (j.is_boolean()) return "true or false";
  if (j.is_number_integer()) return "a whole number";
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_array()) return "a list";
  if (j.is_object()) return "a table";
  return "a value";
}

// `value` as the default's number type: a whole number given for a fractional option is
// recorded as the fraction it means (1 -> 1.0), so equal documents record equal values.
json as_default_type(const json& value, const json& def) {
  if (def.is_number_float() && value.is_number_integer()) return value.get<double>();
  if (def.is_array() && value.is_array() && !def.empty()) {
    json out = json::array();
    for (const json& v : value) out.push_back(as_default_type(v, def.front()));
    return out;
  }
  return value;
}

// A list where the default is no list, or a list of lists where it is one: a grid axis.
bool is_grid(const json& value, const json& def) {
  if (!value.is_array()) return false;
  if (!def.is_array()) return true;
  return !value.empty() &&
         std::all_of(value.begin(), value.end(), [](const json& v) { return v.is_array(); });
}

std::string known_keys(const json& def, const std::set<std::string>& except = {}) {
  std::vector<std::string> keys;
  for (const auto& item : def.items()) {
    if (!except.count(item.key())) keys.push_back(item.key());
  }
  return join(keys, ", ");
}

}  // namespace

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : sep) + p;
  return out;
}

std::string child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string indexed(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

void check_type(const json& value, const json& def, const std::string& path) {
  const auto wrong = [&] {
    return OptionError(path, "must be " + type_name(def) + ", got " + value.dump());
  };
  if (def.is_null()) return;  // an optional: its from_json decides
  if (def.is_boolean() || def.is_string()) {
    if (value.type() != def.type()) throw wrong();
  } else if (def.is_number_integer()) {
    if (!value.is_number_integer()) throw wrong();
    if (def.is_number_unsigned() && value.get<std::int64_t>() < 0) {
      throw OptionError(path, "must be at least 0, got " + value.dump());
    }
  } else if (def.is_number()) {
    if (!value.is_number()) throw wrong();
  } else if (def.is_array()) {
    if (!value.is_array()) throw wrong();
    for (std::size_t i = 0; i < value.size() && !def.empty(); ++i) {
      check_type(value[i], def.front(), indexed(path, i));
    }
  } else if (def.is_object()) {
    if (!value.is_object()) throw wrong();  // an element of a list of tables
  }
}

void merge_checked(const json& value, const json& def, const std::string& path, json& out,
                   std::vector<GridAxis>& grid, const std::set<std::string>& forbidden) {
  if (def.is_object()) {
    if (!value.is_object()) {
      throw OptionError(path, "must be a table, got " + value.dump());
    }
    for (const auto& item : value.items()) {
      const std::string key = child(path, item.key());
      if (forbidden.count(item.key())) {
        throw OptionError(key, "is set by each run (scenarios, seed), not here");
      }
      if (!def.contains(item.key())) {
        throw OptionError(key, "is not an option here (known: " + known_keys(def, forbidden) + ")");
      }
      merge_checked(item.value(), def.at(item.key()), key, out[item.key()], grid);
    }
    return;
  }
  if (is_grid(value, def)) {
    if (value.empty()) throw OptionError(path, "is an empty list");
    json values = json::array();
    for (std::size_t i = 0; i < value.size(); ++i) {
      check_type(value[i], def, indexed(path, i));
      values.push_back(as_default_type(value[i], def));
    }
    grid.push_back({path, values});
    out = values;
  } else {
    check_type(value, def, path);
    out = as_default_type(value, def);
  }
}

json::json_pointer pointer_in_section(const std::string& key) {
  std::string p = key.substr(key.find('.'));
  std::replace(p.begin(), p.end(), '.', '/');
  return json::json_pointer(p);
}

json canonical_sim(json point) {
  const json::json_pointer at("/scene/terrain");
  if (!point.contains(at) || !point.at(at).is_string()) return point;
  try {
    point[at] = robot::terrain_text(robot::parse_terrain(point.at(at).get<std::string>()));
  } catch (const BadInput& e) {
    throw OptionError("sim.scene.terrain", e.what());
  }
  return point;
}

std::string value_text(const json& v) {
  if (v.is_number_float()) return format_number(v.get<double>());
  if (v.is_string()) {
    std::string text = v.get<std::string>();
    std::replace(text.begin(), text.end(), ':', '_');
    return text;
  }
  if (v.is_array()) {
    std::vector<std::string> parts;
    for (const json& e : v) parts.push_back(value_text(e));
    return join(parts, "-");
  }
  // A learner (experiments/learner_table.h) by its name, unique within its axis.
  if (v.is_object() && v.contains("name")) return value_text(v.at("name"));
  return v.dump();
}

void check_bounds(const json& doc) {
  struct Item {
    const json* value;
    std::string path;
    int depth;
  };
  std::vector<Item> todo{{&doc, "", 0}};
  while (!todo.empty()) {
    const Item item = std::move(todo.back());
    todo.pop_back();
    if (item.depth > kMaxExperimentDepth) {
      throw OptionError(
          item.path, "is nested more than " + std::to_string(kMaxExperimentDepth) + " levels deep");
    }
    if (item.value->is_array()) {
      if (item.value->size() > kMaxListValues) {
        throw OptionError(item.path, "has " + std::to_string(item.value->size()) +
                                         " values, more than the " +
                                         std::to_string(kMaxListValues) + " a list may have");
      }
      for (std::size_t i = 0; i < item.value->size(); ++i) {
        todo.push_back({&(*item.value)[i], indexed(item.path, i), item.depth + 1});
      }
    } else if (item.value->is_object()) {
      for (const auto& entry : item.value->items()) {
        todo.push_back({&entry.value(), child(item.path, entry.key()), item.depth + 1});
      }
    }
  }
}

}  // namespace multicpg::experiments::document
