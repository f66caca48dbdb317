"""multicpg: multiple chaotic CPGs with learning for legged locomotion (Ren et al. 2015).

Robots walk in MuJoCo under one chaotic CPG per leg; when legs fail, simulated annealing finds
leg periods that walk straight again. The classes and functions mirror the ``multicpg`` CLI:

- ``Robot("hexapod" | "quadruped" | "octopod" | "R.toml", terrain=..., model="paper-sim" |
  "real", body={...})``: legs, joints, ``mjcf()``; equal robots are interchangeable (``==``,
  ``hash``, pickle). A robot file (docs/robots.md) is named by its path, as the CLI's --robot.
- ``Terrain.flat()``, ``.slope(deg)``, ``.rough(height_m, seed)``, ``.steps(height_m, depth_m)``:
  the ground (the CLI's ``"slope:5"`` text is accepted too).
- ``Simulation(robot, periods=..., terrain=..., disable=..., faults=[...], ...)``: ``step(n)``,
  ``set_periods``, ``fail``/``recover``, ``synchronise``, ``steer`` (the reflex),
  ``walk_window``, ``state()``/``restore()``, ``record()`` (NumPy arrays), ``measure()``.
- ``Fault(legs, step, kind=..., joint=..., value=...)``, ``Recovery(...)``: a run's fault
  timeline as objects: whole legs (the paper's), locked, passive and weak joints, a short tibia,
  a slippery foot, a drifting or noisy yaw sensor (the CLI's ``"R2.CTr:locked@600"`` text is
  accepted too).
- ``State``: a complete, immutable, picklable copy of a simulation; restores bit for bit.
- ``learn(...)``, ``tunnel(...)``: the CLI's JSON results as dicts, plus the trace as arrays
  (from trial 0, as the CLI's trace); ``learner="bayes", learner_options={...}`` chooses the
  learner as ``--learner`` and ``--learner-option`` do.
- ``render(sim, width, height)`` -> H x W x 3 uint8 array; ``film(sim, "out.mp4", steps)``.
- ``replay(sim, "run.html", steps=400)`` or ``replay(learn(...), "learn.html")``: a 3D replay,
  one HTML page that opens offline in any browser and shows itself inline in Jupyter.
- ``experiment(file_or_dict, jobs=...)``: a sweep as ``multicpg run`` runs it; its tidy table.
- ``landscape_dataset("hexapod")``: the landscape dataset the prior learns from by default, found
  in $MULTICPG_DATA, else in the data installed with this package, else in the source tree.
- ``Learner(name, failed=..., windows=...)``: any learner driven from your own loop, ``ask()``
  the next periods, ``tell(windows=...)`` what they measured (ask/tell; docs/python.md);
  ``window_error(window, mode=..., steering=...)``: a window's E as such a run judges it.
- ``Annealer``: the annealing search one step at a time; ``env.CompensationEnv``: the learning
  task as a Gymnasium environment (one step = one trial) with its action and observation spaces.

Arguments are Python values: periods as an int, a dict ``{"R1": 5}`` or one per leg in leg
order; legs as a list of names. A wrong type raises TypeError and a wrong value ValueError, each
naming the parameter (``periods: period 7 gives no gait ...``; a mistyped keyword with the
nearest known one); a failed run raises RuntimeError.

Long calls (learn, tunnel, Simulation.step, replay, experiment) stop on Ctrl-C or a Jupyter interrupt
within half a second with KeyboardInterrupt, leaving their objects usable; learn, tunnel and
step show a tqdm bar once they have run half a second (``progress=False``: none; a callable:
your own, given a dict per report). ``__version__`` is the project's version, ``build_info()`` says what was built.
"""

# Underscored: the module's namespace holds its API alone (dir(multicpg), help, completion).
import csv as _csv
import json as _json
import os as _os
import tempfile as _tempfile
from typing import Any as _Any, Dict as _Dict, List as _List
from typing import Optional as _Optional, Union as _Union

from ._multicpg import (
    __version__,
    LEARNERS,
    _run_experiment,
    Annealer,
    Fault,
    Learner,
    Recovery,
    Robot,
    Simulation,
    State,
    Terrain,
    build_info,
    film,
    landscape_dataset,
    learn,
    measure_window,
    render,
    tunnel,
    window_error,
)
from . import env, spaces
from .replay import Replay, replay

__all__ = [
    "Annealer",
    "LEARNERS",
    "Fault",
    "Learner",
    "Recovery",
    "Replay",
    "Robot",
    "Simulation",
    "State",
    "Terrain",
    "__version__",
    "build_info",
    "env",
    "experiment",
    "film",
    "landscape_dataset",
    "learn",
    "measure_window",
    "render",
    "replay",
    "spaces",
    "tunnel",
    "window_error",
]


def _cell(text: str) -> _Union[int, float, str]:
    """A runs.csv cell as the number it holds, or the text."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def experiment(file_or_dict: _Union[str, _os.PathLike[str], _Dict[str, _Any]],
               jobs: _Optional[int] = None,
               out: _Union[None, str, _os.PathLike[str]] = None) -> _Any:
    """Runs an experiment the way ``multicpg run FILE.toml`` does and returns its tidy table.

    file_or_dict: the path of an experiment file (README "Experiment files"), or its document as
    a dict with the file's keys ({"robot": "hexapod", "scenarios": ["R1"], "learning":
    {"annealing": {"beta": [0.5, 10]}}, ...}); lists form a grid. jobs: threads, 1..4096
    (default: every core). out: a directory that keeps the run files, tables and CSVs
    (resumable, as with the CLI); without it they go to a temporary directory that is removed.

    Returns runs.csv, one row per run (scenario, run, seed, each swept option, converged,
    status, trials, deviations, final periods, ...): a pandas DataFrame when pandas is
    installed, else a list of dicts with numbers as int or float. A bad document or value raises
    ValueError with the CLI's message (naming the key); a failed run raises RuntimeError.
    Ctrl-C stops the runs and raises KeyboardInterrupt; with `out`, the same call resumes from
    the runs that finished.
    """
    is_document = isinstance(file_or_dict, dict)
    if is_document:
        try:
            source = _json.dumps(file_or_dict, allow_nan=False)
        except (TypeError, ValueError) as e:
            raise TypeError(f"file_or_dict: the document is not plain data: {e}") from None
    else:
        source = file_or_dict
    with _tempfile.TemporaryDirectory(prefix="multicpg-experiment-") as scratch:
        directory = _os.path.join(scratch, "out") if out is None else out
        _run_experiment(source, is_document, jobs, directory)
        table = _os.path.join(_os.fspath(directory), "runs.csv")
        try:
            import pandas
        except ImportError:
            with open(table, newline="") as f:
                rows: _List[_Dict[str, _Any]] = [{k: _cell(v) for k, v in row.items()}
                                              for row in _csv.DictReader(f)]
            return rows
        return pandas.read_csv(table)
