// Reading a TOML file the user names (a robot, hardware or experiment file): the one way such a
// file is read (read_input_file, common/input_file.h), parsed (toml++, a syntax error's line and
// column) and its keys and values checked, every error one line naming the file and the key.
// A library of its own (multicpg_toml) so that only the readers link toml++.
#pragma once

#include <toml++/toml.h>

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "common/enum_names.h"

namespace multicpg {

// The document of TOML `text`, read from `name`. Throws BadInput "NAME:LINE:COLUMN: what toml++
// found" for text that is no TOML.
toml::table parse_toml(std::string_view text, const std::string& name);

// The keys and values of one TOML file; every error is BadInput "FILE: KEY: what" on one line.
// `prefix` is the dotted path of the table a key is in ("stop.", "legs[2].").
class TomlReader {
 public:
  explicit TomlReader(std::filesystem::path path) : path_(std::move(path)) {}

  // The file's text, at most `max_bytes` (`max_text`, e.g. "1 MiB", names the bound; `what`, e.g.
  // "hardware file", the kind of file), and its document.
  std::string read(std::size_t max_bytes, std::string_view max_text, std::string_view what) const;
  toml::table parse(std::string_view text) const { return parse_toml(text, path_.string()); }

  // "FILE: KEY: what" (no "KEY: " for an empty key).
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

  // Only the keys `known` may appear in `table` (a misspelt key is not silently ignored): an
  // unknown key is named with its line and, as a mistyped flag is, the key meant.
  void only(const toml::table& table, const std::string& prefix,
            std::initializer_list<std::string_view> known) const;

  const toml::node& node(const toml::table& t, const std::string& prefix,
                         std::string_view key) const;
  const toml::table& table(const toml::table& t, const std::string& prefix,
                           std::string_view key) const;
  // A non-empty string.
  std::string text(const toml::table& t, const std::string& prefix, std::string_view key) const;
  long integer(const toml::table& t, const std::string& prefix, std::string_view key, long lo,
               long hi) const;
  long integer_or(const toml::table& t, const std::string& prefix, std::string_view key, long lo,
                  long hi, long fallback) const;
  // A finite number (an integer or a float); `key` is the whole dotted key.
  double number(const toml::node& n, const std::string& key) const;
  double number(const toml::table& t, const std::string& prefix, std::string_view key) const;
  double positive(const toml::table& t, const std::string& prefix, std::string_view key) const;
  bool boolean(const toml::table& t, const std::string& prefix, std::string_view key,
               bool fallback) const;

  // The value `names` names: "KEY: 'typed' (a or b)" for any other string.
  template <class Enum, std::size_t N>
  Enum choice(const toml::table& t, const std::string& prefix, std::string_view key,
              const EnumNames<Enum, N>& names) const {
    const std::string v = text(t, prefix, key);
    if (const std::optional<Enum> value = names.find(v)) return *value;
    fail(prefix + std::string(key), "'" + v + "' (" + names.list(" or ") + ")");
  }

 private:
  std::filesystem::path path_;
};

}  // namespace multicpg
