// The keyword arguments of the API's long calls (Robot, Simulation, learn, tunnel and the env's
// learning options), described once as data: each parameter's name and default. A call is read
// against its description, so a mistyped keyword is named with the nearest known one ("learn():
// no keyword 'mdoe' (did you mean 'mode'?)") instead of pybind11's dump of every overload, and a
// call knows which keywords were given (robust-only learning options are refused in paper mode
// when given, whatever their value). The description also writes the signature line that
// help() shows and the stubs test reads.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <string_view>
#include <vector>

namespace multicpg::python {

namespace py = pybind11;

// One parameter: its name and default (None where it has none of its own).
struct Param {
  std::string name;
  py::object fallback;
};
using Params = std::vector<Param>;

// The arguments of one call: what was given, else the default.
class Keywords {
 public:
  py::object operator[](std::string_view name) const;
  bool given(std::string_view name) const;
  // The given ones among `names`.
  std::vector<std::string> given_of(const Params& params) const;

 private:
  friend class Signature;
  std::vector<std::string> names_;
  std::vector<py::object> values_;
  std::vector<bool> given_;
};

// A function's parameters: the positional-or-keyword ones, then the keyword-only ones.
class Signature {
 public:
  Signature(std::string function, Params positional, Params keyword_only);
  // Reads a call. TypeError for too many positional arguments, a keyword given twice or an
  // unknown keyword (naming it, with the nearest known one when one is near).
  Keywords read(const py::args& args, const py::kwargs& kwargs) const;
  // "learn(robot: Robot | str = 'hexapod', *, disable: str | Sequence[str] | None = None, ...)
  // -> dict", as pybind11 writes one, each keyword typed as the stub types it; `name` is the
  // function's (__init__ for a class, with self first).
  std::string text(std::string_view name, std::string_view returns) const;
  const std::string& function() const { return function_; }

 private:
  std::string function_;
  Params params_;
  std::size_t positional_;
};

// While one lives, pybind11 writes no signature line of its own (for a function read by a
// Signature it would say (*args, **kwargs)): the docstring starts with Signature::text.
class OwnSignatures {
 public:
  OwnSignatures() { options_.disable_function_signatures(); }

 private:
  py::options options_;
};

// Params joined in order.
Params join(std::initializer_list<Params> parts);

// "did you mean 'mode'?" for the known name nearest `name`, or "" when none is near.
std::string suggestion(std::string_view name, const std::vector<std::string>& known);

}  // namespace multicpg::python
