"""multicpg: multiple chaotic CPGs with learning for legged locomotion (Ren et al. 2015).

Robots walk in MuJoCo under one chaotic CPG per leg; when legs fail, simulated annealing finds
leg periods that walk straight again. The classes and functions mirror the `multicpg` CLI:

- Robot("hexapod" | "quadruped" | "octopod"): leg and joint names, mjcf().
- Simulation(robot, periods=..., disable=..., faults=[...], ...): step(n), set_periods,
  fail/recover, synchronise, state()/restore(), record() (NumPy arrays), measure().
- learn(...), tunnel(...): the CLI's JSON results as dicts, plus the trace as arrays.
- render(sim, width, height) -> H x W x 3 uint8 array; film(sim, "out.mp4", steps).
- experiment(file_or_dict, jobs=...): a sweep as `multicpg run` runs it; its tidy table.
- Annealer: the annealing search one step at a time; env.CompensationEnv: a Gymnasium-shaped
  environment of the learning task (one step = one trial).

Bad arguments raise ValueError with the CLI's message; a failed run raises RuntimeError.
"""

import csv
import json
import os
import tempfile

from ._multicpg import (
    _run_experiment,
    Annealer,
    Robot,
    Simulation,
    State,
    film,
    learn,
    measure_window,
    render,
    tunnel,
)
from . import env

__all__ = [
    "Annealer",
    "Robot",
    "Simulation",
    "State",
    "env",
    "experiment",
    "film",
    "learn",
    "measure_window",
    "render",
    "tunnel",
]


def _cell(text):
    """A runs.csv cell as the number it holds, or the text."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def experiment(file_or_dict, jobs=None, out=None):
    """Runs an experiment the way `multicpg run FILE.toml` does and returns its tidy table.

    file_or_dict: the path of an experiment file (README "Experiment files"), or its document as
    a dict with the file's keys ({"robot": "hexapod", "scenarios": ["R1"], "learning":
    {"annealing": {"beta": [0.5, 10]}}, ...}); lists form a grid. jobs: threads (default: every
    core). out: a directory that keeps the run files, tables and CSVs (resumable, as with the
    CLI); without it they go to a temporary directory that is removed.

    Returns runs.csv, one row per run (scenario, run, seed, each swept option, converged,
    status, trials, deviations, final periods, ...): a pandas DataFrame when pandas is
    installed, else a list of dicts with numbers as int or float. A bad document or value raises
    ValueError with the CLI's message (naming the key); a failed run raises RuntimeError.
    """
    is_document = isinstance(file_or_dict, dict)
    source = json.dumps(file_or_dict) if is_document else os.fspath(file_or_dict)
    with tempfile.TemporaryDirectory(prefix="multicpg-experiment-") as scratch:
        directory = os.fspath(out) if out is not None else os.path.join(scratch, "out")
        _run_experiment(source, is_document, 0 if jobs is None else int(jobs), directory)
        table = os.path.join(directory, "runs.csv")
        try:
            import pandas
        except ImportError:
            with open(table, newline="") as f:
                return [{k: _cell(v) for k, v in row.items()} for row in csv.DictReader(f)]
        return pandas.read_csv(table)
