#!/usr/bin/env bash
# README "Python" and docs/python.md: `pip wheel .` makes a wheel; installed into a fresh venv in
# another folder, multicpg imports from any directory with the project's version, the prior-based
# learner learns from the landscape datasets the wheel carries (not the source tree's), and the
# notebook runs on the venv's own kernel, importing multicpg from the venv.
# MULTICPG_BUILD_DIR lets the wheel build _multicpg in the test's build directory (setup.py), so
# it reuses the objects already compiled there instead of configuring and compiling anew.
# Usage: tests/python_install_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src="$1"
export MULTICPG_BUILD_DIR="$2"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
# Nothing may point the installed module at the source tree or at other data.
unset PYTHONPATH MULTICPG_DATA
export PYDEVD_DISABLE_FILE_VALIDATION=1  # ipykernel's debugger notice
venv="$scratch/venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
expected="$(sed -n 's/^project(multicpg VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")"
"$venv/bin/pip" wheel --no-build-isolation --no-deps --no-index --quiet -w "$scratch/wheels" "$src"
wheels=("$scratch/wheels/multicpg-$expected-"*.whl)
"$venv/bin/pip" install --no-index --quiet "${wheels[0]}"

elsewhere="$(mktemp -d -p "$scratch")"
(cd "$elsewhere" && "$venv/bin/python" - "$venv" "$expected" <<'PY'
import pathlib, re, sys
import multicpg
venv = pathlib.Path(sys.argv[1]).resolve()
assert pathlib.Path(multicpg.__file__).resolve().is_relative_to(venv), multicpg.__file__
assert multicpg.__version__ == sys.argv[2], (multicpg.__version__, sys.argv[2])
info = multicpg.build_info()
assert re.fullmatch(r"[0-9a-f]{40}(\+dirty)?", info["git_commit"]), info
sim = multicpg.Simulation(periods={"R1": 5}, warmup=0)
sim.step(10)
assert sim.step_count == 10
assert (pathlib.Path(multicpg.__file__).parent / "py.typed").exists()
# The prior's dataset is the wheel's copy, found before the source tree's.
dataset = pathlib.Path(multicpg.landscape_dataset("hexapod"))
assert dataset.resolve().is_relative_to(venv), dataset
result = multicpg.learn("hexapod", disable="R1", steering="off", learner="prior", seed=1,
                        progress=False)
assert result["converged"], result["status"]
print(f"the prior learned from {dataset} and converged in {result['trials']} trials")
PY
)
# The run above read that copy: damaged, a fresh run is refused naming it.
manifest="$(cd "$elsewhere" && "$venv/bin/python" -c \
  'import multicpg; print(multicpg.landscape_dataset("hexapod"))').json"
cp "$manifest" "$scratch/hexapod.json"
echo '{}' > "$manifest"
(cd "$elsewhere" && "$venv/bin/python" - "$manifest" <<'PY'
import sys
import multicpg
try:
    multicpg.learn("hexapod", disable="R1", steering="off", learner="prior", progress=False)
except ValueError as e:
    assert sys.argv[1] in str(e), e
else:
    raise AssertionError("a damaged packaged dataset was not read")
PY
)
cp "$scratch/hexapod.json" "$manifest"

# The notebook on the venv's kernel (docs/python.md "The notebook from the venv"), registered in
# the scratch folder rather than the user's Jupyter directory (ipykernel warns that the folder is
# not on Jupyter's path: JUPYTER_PATH puts it there). TMPDIR: ipykernel leaves the empty folder
# it writes the spec in behind.
TMPDIR="$scratch" "$venv/bin/python" -m ipykernel install --prefix "$scratch/jupyter" \
  --name multicpg-venv >"$scratch/kernel.log" 2>&1 || { cat "$scratch/kernel.log" >&2; exit 1; }
(cd "$elsewhere" && JUPYTER_PATH="$scratch/jupyter/share/jupyter" \
  MULTICPG_NOTEBOOK_KERNEL=multicpg-venv MULTICPG_SOURCE_DIR="$src" \
  "$venv/bin/python" -m pytest -q -p no:cacheprovider "$src/python/tests/test_notebook.py")
echo "installed the wheel of multicpg $expected into a fresh venv: the prior used its datasets, the notebook ran on its kernel"
