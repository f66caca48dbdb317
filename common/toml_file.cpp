#include "common/toml_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/errors.h"
#include "common/input_file.h"
#include "common/user_text.h"

namespace multicpg {
namespace {

// `text` on one line.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  text.erase(text.find_last_not_of(' ') + 1);
  return text;
}

}  // namespace

toml::table parse_toml(std::string_view text, const std::string& name) {
  try {
    return toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    const toml::source_position& at = e.source().begin;
    throw BadInput(one_line(name + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                            ": " + std::string(e.description())));
  }
}

std::string TomlReader::read(std::size_t max_bytes, std::string_view max_text,
                             std::string_view what) const {
  return read_input_file(path_, max_bytes, max_text, what);
}

void TomlReader::fail(const std::string& key, const std::string& what) const {
  throw BadInput(one_line(path_.string() + ": " + (key.empty() ? "" : key + ": ") + what));
}

void TomlReader::only(const toml::table& table, const std::string& prefix,
                      std::initializer_list<std::string_view> known) const {
  for (const auto& [key, value] : table) {
    if (std::find(known.begin(), known.end(), key.str()) != known.end()) continue;
    const std::optional<std::string> meant =
        closest_name(key.str(), std::vector<std::string>(known.begin(), known.end()));
    const toml::source_region& where = key.source();
    fail(prefix + printable(key.str()),
         "unknown key" +
             (where.begin.line > 0 ? " on line " + std::to_string(where.begin.line)
                                   : std::string()) +
             (meant ? " (did you mean " + *meant + "?)" : std::string()));
  }
}

const toml::node& TomlReader::node(const toml::table& t, const std::string& prefix,
                                   std::string_view key) const {
  const toml::node* n = t.get(key);
  if (n == nullptr) fail(prefix + std::string(key), "missing");
  return *n;
}

const toml::table& TomlReader::table(const toml::table& t, const std::string& prefix,
                                     std::string_view key) const {
  const toml::table* sub = node(t, prefix, key).as_table();
  if (sub == nullptr) fail(prefix + std::string(key), "must be a table");
  return *sub;
}

std::string TomlReader::text(const toml::table& t, const std::string& prefix,
                             std::string_view key) const {
  const std::optional<std::string> v = node(t, prefix, key).value_exact<std::string>();
  if (!v || v->empty()) fail(prefix + std::string(key), "must be a non-empty string");
  return *v;
}

long TomlReader::integer(const toml::table& t, const std::string& prefix, std::string_view key,
                         long lo, long hi) const {
  const std::optional<std::int64_t> v = node(t, prefix, key).value_exact<std::int64_t>();
  if (!v) fail(prefix + std::string(key), "must be an integer");
  if (*v < lo || *v > hi) {
    fail(prefix + std::string(key), "must be in " + std::to_string(lo) + ".." + std::to_string(hi) +
                                        ", got " + std::to_string(*v));
  }
  return static_cast<long>(*v);
}

long TomlReader::integer_or(const toml::table& t, const std::string& prefix, std::string_view key,
                            long lo, long hi, long fallback) const {
  return t.contains(key) ? integer(t, prefix, key, lo, hi) : fallback;
}

double TomlReader::number(const toml::node& n, const std::string& key) const {
  if (!n.is_number()) fail(key, "must be a number");
  const double v = *n.value<double>();
  if (!std::isfinite(v)) fail(key, "must be finite");
  return v;
}

double TomlReader::number(const toml::table& t, const std::string& prefix,
                          std::string_view key) const {
  return number(node(t, prefix, key), prefix + std::string(key));
}

double TomlReader::positive(const toml::table& t, const std::string& prefix,
                            std::string_view key) const {
  const double v = number(t, prefix, key);
  if (!(v > 0.0)) fail(prefix + std::string(key), "must be above 0");
  return v;
}

bool TomlReader::boolean(const toml::table& t, const std::string& prefix, std::string_view key,
                         bool fallback) const {
  if (!t.contains(key)) return fallback;
  const std::optional<bool> v = node(t, prefix, key).value_exact<bool>();
  if (!v) fail(prefix + std::string(key), "must be true or false");
  return *v;
}

}  // namespace multicpg
