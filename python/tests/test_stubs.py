"""The type stubs (multicpg/_multicpg.pyi) name what the compiled module has, with the same
parameters, so editors complete and check the calls that run."""

import ast
import inspect
import pathlib
import re

import multicpg
from multicpg import _multicpg

STUB = pathlib.Path(multicpg.__file__).with_name("_multicpg.pyi")


def stub_tree():
    return ast.parse(STUB.read_text())


def runtime_parameters(function):
    """Parameter names from the signature line ("name(a: int, *, b: str | None = None)")."""
    first = function.__doc__.splitlines()[0]
    inside = first[first.index("(") + 1:first.rindex(")")]
    names = []
    for part in re.split(r",\s*(?![^\[]*\])", inside):
        part = part.strip()
        if not part or part == "*":
            continue
        names.append(part.split(":")[0].split("=")[0].strip())
    return [n for n in names if n != "self"]


def stub_parameters(node):
    args = node.args
    names = [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs]
    return [n for n in names if n != "self"]


def test_the_package_is_marked_typed_and_the_stub_parses():
    assert STUB.with_name("py.typed").exists()
    stub_tree()


def test_every_public_name_of_the_module_is_in_the_stub():
    stubbed = {n.name if hasattr(n, "name") else n.target.id for n in stub_tree().body
               if isinstance(n, (ast.FunctionDef, ast.ClassDef))
               or isinstance(n, ast.AnnAssign) and isinstance(n.target, ast.Name)}
    public = {n for n in dir(_multicpg) if not n.startswith("__") or n == "__version__"}
    assert public <= stubbed, public - stubbed


def test_functions_and_methods_have_the_stubs_parameters():
    checked = 0
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef):
            assert runtime_parameters(getattr(_multicpg, node.name)) == stub_parameters(node), \
                node.name
            checked += 1
        if isinstance(node, ast.ClassDef):
            cls = getattr(_multicpg, node.name)
            for member in node.body:
                if not isinstance(member, ast.FunctionDef):
                    continue
                if any(isinstance(d, ast.Name) and d.id == "property"
                       for d in member.decorator_list):
                    assert isinstance(inspect.getattr_static(cls, member.name), property), \
                        f"{node.name}.{member.name}"
                    continue
                if member.name in ("__eq__", "__hash__", "__copy__", "__deepcopy__"):
                    continue
                runtime = getattr(cls, member.name)
                assert runtime_parameters(runtime) == stub_parameters(member), \
                    f"{node.name}.{member.name}"
                checked += 1
    assert checked > 30
