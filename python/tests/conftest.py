"""Where the CLI and the sources are: MULTICPG_EXE / MULTICPG_SOURCE_DIR (set by ctest), else
build/multicpg and the repository this file is in."""

import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("MULTICPG_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
EXE = pathlib.Path(os.environ.get("MULTICPG_EXE", SOURCE_DIR / "build" / "multicpg"))


# A run that went to its end but whose learning did not converge exits 3 with every output
# written (docs/cli.md "Exit codes and signals"): a result these tests compare, not a failure.
NOT_CONVERGED = 3


def run_cli(*args, check=True):
    """Runs the CLI; returns the CompletedProcess (text)."""
    done = subprocess.run([str(EXE), *args], capture_output=True, text=True, check=False)
    finished = done.returncode == 0 or (done.returncode == NOT_CONVERGED and not done.stderr)
    if check and not finished:
        raise AssertionError(f"multicpg {' '.join(args)} exited {done.returncode}: {done.stderr}")
    return done


def cli_json(*args):
    return json.loads(run_cli(*args, "--json").stdout)


@pytest.fixture(scope="session")
def hexapod():
    import multicpg
    return multicpg.Robot("hexapod")
