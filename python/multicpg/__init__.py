"""multicpg: multiple chaotic CPGs with learning for legged locomotion (Ren et al. 2015).

Robots walk in MuJoCo under one chaotic CPG per leg; when legs fail, simulated annealing finds
leg periods that walk straight again. The classes and functions mirror the `multicpg` CLI:

- Robot("hexapod" | "quadruped" | "octopod"): leg and joint names, mjcf().
- Simulation(robot, periods=..., disable=..., faults=[...], ...): step(n), set_periods,
  fail/recover, synchronise, state()/restore(), record() (NumPy arrays), measure().
- learn(...), tunnel(...): the CLI's JSON results as dicts, plus the trace as arrays.
- render(sim, width, height) -> H x W x 3 uint8 array; film(sim, "out.mp4", steps).
- Annealer: the annealing search one step at a time; env.CompensationEnv: a Gymnasium-shaped
  environment of the learning task (one step = one trial).

Bad arguments raise ValueError with the CLI's message; a failed run raises RuntimeError.
"""

from ._multicpg import (
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
    "film",
    "learn",
    "measure_window",
    "render",
    "tunnel",
]
