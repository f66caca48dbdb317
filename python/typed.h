// What help() shows for a parameter the API reads with its own checks (python/args.h): pybind11
// names a py::object parameter "object", so each kind of argument is a py::object under a name
// of its own whose help() type is the API's (the types of multicpg/_multicpg.pyi). Loading one
// accepts any object: the checks, and their TypeError naming the parameter, stay the API's.
#pragma once

#include <pybind11/pybind11.h>

namespace multicpg::python {

namespace py = pybind11;

inline int any_object(PyObject* /*object*/) {
  return 1;
}

#define MULTICPG_TYPED_ARG(Name)                      \
  class Name : public py::object {                    \
   public:                                            \
    PYBIND11_OBJECT_DEFAULT(Name, object, any_object) \
  };

MULTICPG_TYPED_ARG(IntArg)
MULTICPG_TYPED_ARG(OptionalIntArg)
MULTICPG_TYPED_ARG(FloatArg)
MULTICPG_TYPED_ARG(OptionalFloatArg)
MULTICPG_TYPED_ARG(BoolArg)
MULTICPG_TYPED_ARG(StrArg)
MULTICPG_TYPED_ARG(OptionalStrArg)
MULTICPG_TYPED_ARG(PathArg)
MULTICPG_TYPED_ARG(LegsArg)
MULTICPG_TYPED_ARG(PeriodsArg)
MULTICPG_TYPED_ARG(PoseArg)
MULTICPG_TYPED_ARG(ProgressArg)
MULTICPG_TYPED_ARG(RobotArg)
MULTICPG_TYPED_ARG(SimulationArg)
MULTICPG_TYPED_ARG(StateArg)
MULTICPG_TYPED_ARG(BytesArg)
MULTICPG_TYPED_ARG(AnyArg)

#undef MULTICPG_TYPED_ARG

// The help() text of each, as the stub writes it (Periods, Legs, Progress as its aliases).
inline constexpr const char* kPeriodsType = "int | dict[str, int] | Sequence[int] | str";
inline constexpr const char* kLegsType = "str | Sequence[str] | None";
inline constexpr const char* kFaultsType = "Fault | str | Sequence[Fault | str] | None";
inline constexpr const char* kProgressType = "bool | Callable[[dict], Any]";
inline constexpr const char* kPathType = "str | os.PathLike[str]";

}  // namespace multicpg::python

namespace pybind11::detail {

#define MULTICPG_TYPED_NAME(Name, text)             \
  template <>                                       \
  struct handle_type_name<multicpg::python::Name> { \
    static constexpr auto name = const_name(text);  \
  };

MULTICPG_TYPED_NAME(IntArg, "int")
MULTICPG_TYPED_NAME(OptionalIntArg, "int | None")
MULTICPG_TYPED_NAME(FloatArg, "float")
MULTICPG_TYPED_NAME(OptionalFloatArg, "float | None")
MULTICPG_TYPED_NAME(BoolArg, "bool")
MULTICPG_TYPED_NAME(StrArg, "str")
MULTICPG_TYPED_NAME(OptionalStrArg, "str | None")
MULTICPG_TYPED_NAME(PathArg, "str | os.PathLike[str]")
MULTICPG_TYPED_NAME(LegsArg, "str | Sequence[str] | None")
MULTICPG_TYPED_NAME(PeriodsArg, "int | dict[str, int] | Sequence[int] | str")
MULTICPG_TYPED_NAME(PoseArg, "tuple[float, float, float]")
MULTICPG_TYPED_NAME(ProgressArg, "bool | Callable[[dict], Any]")
MULTICPG_TYPED_NAME(RobotArg, "Robot | str")
MULTICPG_TYPED_NAME(SimulationArg, "Simulation")
MULTICPG_TYPED_NAME(StateArg, "State")
MULTICPG_TYPED_NAME(BytesArg, "bytes")
MULTICPG_TYPED_NAME(AnyArg, "Any")

#undef MULTICPG_TYPED_NAME

}  // namespace pybind11::detail
