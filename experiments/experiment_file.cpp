#include "experiments/experiment_file.h"

#include <cmath>
#include <cstring>
#include <map>

#include "common/errors.h"
#include "common/input_file.h"
#include "common/toml_file.h"
#include "experiments/experiment_limits.h"
#include "sim/robot_file.h"

namespace multicpg::experiments {
namespace {

using nlohmann::json;

// Where each key of the file is: dotted path ("learning.annealing.beta", "scenarios[1]") ->
// line.
using Lines = std::map<std::string, long>;

std::string child(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

// The document of a parsed file; `depth` counts levels as line_nested_deeper does, a second
// guard of the bound the text was scanned for.
json to_json(const toml::node& node, const std::string& path, int depth, Lines& lines,
             const std::string& file) {
  lines.emplace(path, static_cast<long>(node.source().begin.line));
  const auto bad = [&](const std::string& what) {
    return BadInput(file + ":" + std::to_string(node.source().begin.line) + ": " + path + " " +
                    what);
  };
  if (depth > kMaxExperimentDepth) {
    throw bad("is nested more than " + std::to_string(kMaxExperimentDepth) + " levels deep");
  }
  if (const toml::table* t = node.as_table()) {
    json out = json::object();
    for (const auto& [key, value] : *t) {
      const std::string p = child(path, key.str());
      lines.emplace(p, static_cast<long>(key.source().begin.line));
      out[std::string(key.str())] = to_json(value, p, depth + 1, lines, file);
    }
    return out;
  }
  if (const toml::array* a = node.as_array()) {
    if (a->size() > kMaxListValues) {
      throw bad("has " + std::to_string(a->size()) + " values, more than the " +
                std::to_string(kMaxListValues) + " a list may have");
    }
    json out = json::array();
    for (std::size_t i = 0; i < a->size(); ++i) {
      out.push_back(to_json((*a)[i], path + "[" + std::to_string(i) + "]", depth + 1, lines, file));
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

// The nesting of TOML text, from its structure alone (line_nested_deeper). Written by hand
// because toml++ has no bound on tables and dotted keys and builds the whole tree before it
// could be measured (experiment_limits.h). It follows TOML 1.0: statements line by line (a table
// header or key = value), keys of bare or quoted parts joined by dots, values that are strings,
// lists, inline tables or anything else up to the next delimiter. What it cannot follow (a
// syntax error, which toml++ then reports) it skips to the next line, so it never stops early.
class NestingScan {
 public:
  NestingScan(std::string_view text, int limit) : t_(text), limit_(limit) {}

  std::optional<long> run() {
    int table = 0;  // the level of the current [table] or [[array of tables]]
    for (;;) {
      skip_blank_lines();
      if (at_end()) return std::nullopt;
      if (peek() == '[') {
        i_ += peek(1) == '[' ? 2 : 1;  // [table] or [[array of tables]]
        const int parts = key();
        if (parts < 0) {
          next_line();
          continue;
        }
        // Any part may name an array of tables, whose last element is one level more.
        table = 2 * parts;
        if (too_deep(table)) return line_;
        next_line();
        continue;
      }
      const int parts = key();
      skip_blank();
      if (parts < 0 || peek() != '=') {
        next_line();
        continue;
      }
      ++i_;
      const Result r = value(table + parts);
      if (r == Result::deep) return line_;
      if (r == Result::bad) next_line();
    }
  }

 private:
  enum class Result { ok, bad, deep };

  bool at_end() const { return i_ >= t_.size(); }
  char peek(std::size_t ahead = 0) const { return i_ + ahead < t_.size() ? t_[i_ + ahead] : '\0'; }
  bool too_deep(int depth) const { return depth > limit_; }

  void skip_blank() {
    while (peek() == ' ' || peek() == '\t' || peek() == '\r') ++i_;
  }
  // Blanks, comments and newlines: what may separate values in a list.
  void skip_blank_lines() {
    for (;;) {
      skip_blank();
      if (peek() == '#') {
        while (!at_end() && peek() != '\n') ++i_;
      }
      if (at_end() || peek() != '\n') return;
      ++i_;
      ++line_;
    }
  }
  // To the end of the line (its newline is left for skip_blank_lines to count).
  void next_line() {
    while (!at_end() && peek() != '\n') ++i_;
  }

  // At a quote: skips a basic or literal string, one line or multi-line; false when it does not
  // end (an end of line in a one-line string, the end of the text).
  bool string() {
    const char quote = peek();
    const bool escapes = quote == '"';
    if (peek(1) == quote && peek(2) == quote) {
      i_ += 3;
      while (!at_end()) {
        const char c = peek();
        if (c == '\n') ++line_;
        if (escapes && c == '\\') {
          ++i_;
          if (peek() == '\n') ++line_;
          if (!at_end()) ++i_;
          continue;
        }
        if (c == quote && peek(1) == quote && peek(2) == quote) {
          i_ += 3;
          // Up to two more quotes belong to the string ("""a""""" is a"").
          for (int extra = 0; extra < 2 && peek() == quote; ++extra) ++i_;
          return true;
        }
        ++i_;
      }
      return false;
    }
    ++i_;
    while (!at_end() && peek() != '\n') {
      const char c = peek();
      ++i_;
      if (c == quote) return true;
      if (escapes && c == '\\' && !at_end() && peek() != '\n') ++i_;
    }
    return false;
  }

  static bool bare(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  }

  // A key: how many dot-separated parts it has, or -1 when none starts here.
  int key() {
    int parts = 0;
    for (;;) {
      skip_blank();
      const char c = peek();
      if (c == '"' || c == '\'') {
        if (peek(1) == c && peek(2) == c) return -1;  // multi-line strings are no keys
        if (!string()) return -1;
      } else if (bare(c)) {
        while (bare(peek())) ++i_;
      } else {
        return -1;
      }
      ++parts;
      skip_blank();
      if (peek() != '.') return parts;
      ++i_;
    }
  }

  // A value whose node is at level `depth`.
  Result value(int depth) {
    if (too_deep(depth)) return Result::deep;
    skip_blank();
    const char c = peek();
    if (c == '"' || c == '\'') return string() ? Result::ok : Result::bad;
    if (c == '[') return list(depth);
    if (c == '{') return inline_table(depth);
    // A number, true/false, date or time: up to the next delimiter.
    const std::size_t start = i_;
    while (!at_end() && std::strchr(",]}\n#", peek()) == nullptr) ++i_;
    return i_ > start ? Result::ok : Result::bad;
  }

  Result list(int depth) {
    ++i_;
    for (;;) {
      skip_blank_lines();
      if (peek() == ']') {
        ++i_;
        return Result::ok;
      }
      if (at_end()) return Result::bad;
      if (const Result r = value(depth + 1); r != Result::ok) return r;
      skip_blank_lines();
      if (peek() == ',') {
        ++i_;
        continue;
      }
      if (peek() != ']') return Result::bad;
    }
  }

  Result inline_table(int depth) {
    ++i_;
    skip_blank();
    if (peek() == '}') {
      ++i_;
      return Result::ok;
    }
    for (;;) {
      const int parts = key();
      skip_blank();
      if (parts < 0 || peek() != '=') return Result::bad;
      ++i_;
      if (const Result r = value(depth + parts); r != Result::ok) return r;
      skip_blank();
      if (peek() == ',') {
        ++i_;
        continue;
      }
      if (peek() != '}') return Result::bad;
      ++i_;
      return Result::ok;
    }
  }

  std::string_view t_;
  int limit_;
  std::size_t i_ = 0;
  long line_ = 1;
};

std::string too_large(const std::string& name, const std::string& size) {
  return name + ": is " + size + ", more than the " + std::string(kMaxExperimentFileText) +
         " an experiment file may have";
}

}  // namespace

std::optional<long> line_nested_deeper(std::string_view text, int limit) {
  return NestingScan(text, limit).run();
}

std::string read_experiment_file(const std::filesystem::path& file) {
  return read_input_file(file, kMaxExperimentFileBytes, kMaxExperimentFileText,
                         "an experiment file");
}

Sweep parse_experiment_text(std::string_view text, const std::string& name, std::optional<int> runs,
                            const SweepLimits& limits) {
  if (text.size() > kMaxExperimentFileBytes) {
    throw BadInput(too_large(name, std::to_string(text.size()) + " bytes"));
  }
  if (const std::optional<long> line = line_nested_deeper(text, kMaxExperimentDepth)) {
    throw BadInput(name + ":" + std::to_string(*line) + ": nested more than " +
                   std::to_string(kMaxExperimentDepth) +
                   " levels deep (each table, dotted-key part, list and inline table is a level)");
  }
  const toml::table table = parse_toml(text, name);
  Lines lines;
  json document = to_json(table, "", 0, lines, name);
  if (runs) document["runs"] = *runs;
  // A robot file is named relative to the experiment file, as a robot file names its model.
  if (const auto robot = document.find("robot");
      robot != document.end() && robot->is_string() && sim::is_robot_file(*robot)) {
    *robot = (std::filesystem::path(name).parent_path() / robot->get<std::string>()).string();
  }
  try {
    return resolve_sweep(document, limits);
  } catch (const OptionError& e) {
    const std::optional<long> line = line_of(lines, e.key());
    throw BadInput(name + (line ? ":" + std::to_string(*line) : std::string()) + ": " + e.key() +
                   " " + e.what());
  } catch (const BadInput& e) {
    throw BadInput(name + ": " + e.what());
  }
}

Sweep load_experiment_file(const std::filesystem::path& file, std::optional<int> runs,
                           const SweepLimits& limits) {
  return parse_experiment_text(read_experiment_file(file), file.string(), runs, limits);
}

}  // namespace multicpg::experiments
