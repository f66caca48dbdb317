// Error kinds the CLI maps to exit codes: BadInput -> 2, RuntimeFailure -> 1.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace multicpg {

// The user gave something the program cannot accept (flag, file, leg name, period, path).
class BadInput : public std::runtime_error {
 public:
  explicit BadInput(const std::string& what) : std::runtime_error(what) {}
};

// A bad value of one option, named by its key: the dotted path of the option in its JSON record
// ("annealing.beta"). The CLI names the flag bound to the key, an experiment file the file, line
// and key; what() is the message without either ("must be at least 0, got -1").
class OptionError : public BadInput {
 public:
  OptionError(std::string key, const std::string& what) : BadInput(what), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// Valid input, but the run itself failed (physics blow-up, I/O failure mid-run, ...).
class RuntimeFailure : public std::runtime_error {
 public:
  explicit RuntimeFailure(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace multicpg
