"""3D replays of runs (docs/replay.md): one self-contained HTML page that opens offline in any
browser, and shows itself inline in Jupyter.

``replay(sim, "run.html", steps=400)`` walks a Simulation 400 more steps (as ``film`` does) and
writes them; ``replay(multicpg.learn(...), "learn.html")`` makes the learning run of a result
again (runs are deterministic; the result is checked to come out the same) and writes it.
"""

import html
import json
from typing import Any, Dict, Optional, Union

from ._multicpg import Robot, Simulation, _replay_result, _replay_simulation

__all__ = ["Replay", "replay"]

# Keys learn() adds to the JSON of `learn --json` (NumPy arrays): not part of the saved result.
_ARRAY_KEYS = ("trace_arrays", "path")
# The height of the inline view in Jupyter, in CSS pixels: the 3D view, timeline, gait strip and
# the start of the trials' table.
_INLINE_HEIGHT_PX = 900


class Replay:
    """A replay page: ``html`` (the whole page), ``path`` (where it was written, or None).

    In Jupyter it shows itself in an iframe (``srcdoc``), so the notebook needs no server.
    """

    def __init__(self, page: str, path: Optional[str]):
        self.html = page
        self.path = path

    def _repr_html_(self) -> str:
        return ('<iframe srcdoc="{}" style="width: 100%; height: {}px; border: 0" '
                'sandbox="allow-scripts"></iframe>').format(html.escape(self.html, quote=True),
                                                           _INLINE_HEIGHT_PX)

    def __repr__(self) -> str:
        where = repr(self.path) if self.path else "not written"
        return "<multicpg.Replay {:.1f} MB, {}>".format(len(self.html) / 1e6, where)


def replay(sim_or_result: Union[Simulation, Dict[str, Any]], path: Optional[Any] = None, *,
           steps: Optional[int] = None, robot: Optional[Robot] = None,
           title: Optional[str] = None) -> Replay:
    """A 3D replay of a run, written to ``path`` (FILE.html) when given.

    ``sim_or_result``: a ``Simulation``, whose next ``steps`` steps are walked and recorded (the
    simulation walks them, as ``film`` does); or the dict ``learn()`` returns, whose run is made
    again with the simulation of ``robot`` (the Robot the result was learned with; None: the
    result's robot with default options) and must come out as saved. ``title`` names the page.
    """
    if isinstance(sim_or_result, Simulation):
        if steps is None:
            raise TypeError("steps: replay(sim, ...) walks `steps` more steps; give their number")
        if robot is not None:
            raise TypeError("robot: a Simulation has its robot; give robot only with a result")
        sim = sim_or_result
        start = sim.step_count
        page, end = _replay_simulation(sim.state().to_bytes(), steps, path,
                                       title or "multicpg.Simulation, steps {}-{}".format(
                                           start, start + steps))
        sim.step(steps)
        if sim.pose() != end:
            raise RuntimeError("the replay's copy of the simulation ended at {}, the simulation "
                               "at {}".format(end, sim.pose()))
    elif isinstance(sim_or_result, dict):
        if steps is not None:
            raise TypeError("steps: a result's run is replayed whole; give steps only with a "
                            "Simulation")
        if robot is not None and not isinstance(robot, Robot):
            raise TypeError("robot: expected a multicpg.Robot, got {}".format(
                type(robot).__name__))
        if "touched_wall" in sim_or_result:
            raise ValueError("result: a tunnel() result does not record the legs that failed: "
                             "replay a Simulation, or run `multicpg tunnel ... --replay "
                             "FILE.html`")
        saved = {k: v for k, v in sim_or_result.items() if k not in _ARRAY_KEYS}
        page = _replay_result(json.dumps(saved), None if robot is None else robot.__getstate__(),
                              path, title)
    else:
        raise TypeError("sim_or_result: expected a multicpg.Simulation or the dict learn() "
                        "returns, got {}".format(type(sim_or_result).__name__))
    return Replay(page, None if path is None else str(path))
