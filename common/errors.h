// Error kinds the CLI maps to exit codes: BadInput -> 2, RuntimeFailure -> 1.
#pragma once

#include <stdexcept>
#include <string>

namespace multicpg {

// The user gave something the program cannot accept (flag, file, leg name, period, path).
class BadInput : public std::runtime_error {
 public:
  explicit BadInput(const std::string& what) : std::runtime_error(what) {}
};

// Valid input, but the run itself failed (physics blow-up, I/O failure mid-run, ...).
class RuntimeFailure : public std::runtime_error {
 public:
  explicit RuntimeFailure(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace multicpg
