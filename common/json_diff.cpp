#include "common/json_diff.h"

#include <set>

namespace multicpg {
namespace {

void collect(const nlohmann::json& a, const nlohmann::json& b, const std::string& path,
             std::vector<std::string>& out) {
  if (!a.is_object() || !b.is_object()) {
    if (a != b) out.push_back(path);
    return;
  }
  std::set<std::string> keys;
  for (const nlohmann::json* side : {&a, &b}) {
    for (const auto& item : side->items()) keys.insert(item.key());
  }
  for (const std::string& key : keys) {
    const std::string child = path.empty() ? key : path + "." + key;
    if (!a.contains(key) || !b.contains(key)) {
      out.push_back(child);
    } else {
      collect(a.at(key), b.at(key), child, out);
    }
  }
}

}  // namespace

std::vector<std::string> json_differences(const nlohmann::json& a, const nlohmann::json& b,
                                          const std::string& path) {
  std::vector<std::string> out;
  collect(a, b, path, out);
  return out;
}

}  // namespace multicpg
