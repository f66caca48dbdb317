#!/usr/bin/env bash
# README "Python", installing: `pip install .` into a fresh virtual environment, then multicpg
# imports from any directory with the project's version; `pip wheel .` makes a wheel.
# MULTICPG_BUILD_DIR lets the install build _multicpg in the test's build directory (setup.py),
# so it reuses the objects already compiled there instead of configuring and compiling anew.
# Usage: tests/python_install_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src="$1"
export MULTICPG_BUILD_DIR="$2"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
venv="$scratch/venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
"$venv/bin/pip" install --no-build-isolation --no-index --quiet "$src"

expected="$(sed -n 's/^project(multicpg VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")"
version="$(cd "$(mktemp -d -p "$scratch")" && "$venv/bin/python" -c "import multicpg; print(multicpg.__version__)")"
if [ "$version" != "$expected" ]; then
  echo "multicpg.__version__ is '$version', CMakeLists.txt says '$expected'" >&2
  exit 1
fi
(cd "$(mktemp -d -p "$scratch")" && "$venv/bin/python" - "$venv" <<'PY'
import pathlib, re, sys
import multicpg
venv = pathlib.Path(sys.argv[1]).resolve()
assert pathlib.Path(multicpg.__file__).resolve().is_relative_to(venv), multicpg.__file__
info = multicpg.build_info()
assert re.fullmatch(r"[0-9a-f]{40}(\+dirty)?", info["git_commit"]), info
sim = multicpg.Simulation(periods={"R1": 5}, warmup=0)
sim.step(10)
assert sim.step_count == 10
assert (pathlib.Path(multicpg.__file__).parent / "py.typed").exists()
PY
)
"$venv/bin/pip" wheel --no-build-isolation --no-deps --no-index --quiet -w "$scratch/wheels" "$src"
ls "$scratch/wheels/multicpg-$expected-"*.whl >/dev/null
echo "installed multicpg $version into a fresh venv and built its wheel"
