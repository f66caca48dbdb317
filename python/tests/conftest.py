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


def run_cli(*args, check=True):
    """Runs the CLI; returns the CompletedProcess (text)."""
    done = subprocess.run([str(EXE), *args], capture_output=True, text=True, check=False)
    if check and done.returncode != 0:
        raise AssertionError(f"multicpg {' '.join(args)} exited {done.returncode}: {done.stderr}")
    return done


def cli_json(*args):
    return json.loads(run_cli(*args, "--json").stdout)


@pytest.fixture(scope="session")
def hexapod():
    import multicpg
    return multicpg.Robot("hexapod")
