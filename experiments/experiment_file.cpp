#include "experiments/experiment_file.h"

#include <toml++/toml.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "common/errors.h"

namespace multicpg::experiments {
namespace {

using nlohmann::json;

// Where each key of the file is: dotted path ("learning.annealing.beta", "scenarios[1]") ->
// line.
using Lines = std::map<std::string, long>;

std::string child(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

json to_json(const toml::node& node, const std::string& path, Lines& lines,
             const std::string& file) {
  lines.emplace(path, static_cast<long>(node.source().begin.line));
  const auto bad = [&](const std::string& what) {
    return BadInput(file + ":" + std::to_string(node.source().begin.line) + ": " + path + " " +
                    what);
  };
  if (const toml::table* t = node.as_table()) {
    json out = json::object();
    for (const auto& [key, value] : *t) {
      const std::string p = child(path, key.str());
      lines.emplace(p, static_cast<long>(key.source().begin.line));
      out[std::string(key.str())] = to_json(value, p, lines, file);
    }
    return out;
  }
  if (const toml::array* a = node.as_array()) {
    json out = json::array();
    for (std::size_t i = 0; i < a->size(); ++i) {
      out.push_back(to_json((*a)[i], path + "[" + std::to_string(i) + "]", lines, file));
    }
    return out;
  }
  if (const auto* s = node.as_string()) return s->get();
  if (const auto* i = node.as_integer()) return i->get();
  if (const auto* b = node.as_boolean()) return b->get();
  if (const auto* d = node.as_floating_point()) {
    if (!std::isfinite(d->get())) throw bad("must be a finite number");
    return d->get();
  }
  throw bad("must be a number, string, true/false, list or table (no dates or times)");
}

// The line of `key`, or of the nearest enclosing key the file has.
std::optional<long> line_of(const Lines& lines, std::string key) {
  while (true) {
    if (const auto it = lines.find(key); it != lines.end()) return it->second;
    const std::size_t cut = key.find_last_of(".[");
    if (cut == std::string::npos) return std::nullopt;
    key.resize(cut);
  }
}

}  // namespace

Sweep load_experiment_file(const std::filesystem::path& file, std::optional<int> runs) {
  const std::string name = file.string();
  if (std::filesystem::is_directory(file)) throw BadInput(name + ": is a directory, not a file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw BadInput(name + ": cannot read (" + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) throw BadInput(name + ": cannot read");
  toml::table table;
  try {
    table = toml::parse(text.str(), name);
  } catch (const toml::parse_error& e) {
    throw BadInput(name + ":" + std::to_string(e.source().begin.line) + ": " +
                   std::string(e.description()));
  }
  Lines lines;
  json document = to_json(table, "", lines, name);
  if (runs) document["runs"] = *runs;
  try {
    return resolve_sweep(document);
  } catch (const OptionError& e) {
    const std::optional<long> line = line_of(lines, e.key());
    throw BadInput(name + (line ? ":" + std::to_string(*line) : std::string()) + ": " + e.key() +
                   " " + e.what());
  }
}

}  // namespace multicpg::experiments
