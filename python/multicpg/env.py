"""Malfunction compensation (paper §3) as a Gymnasium environment: CompensationEnv.

One step is one learning trial: the working legs get the action's periods, the robot walks the
settling steps unmeasured, then the trial's windows are measured. ``mode="paper"`` is
``multicpg learn --mode paper`` exactly (one 400-step window judges a trial by its yaw change);
``mode="robust"`` (the default, as ``multicpg learn``'s) judges as robust mode does (the worse
of yaw change and path angle, up to hold_windows windows, the steering reflex's effort) and lets
the action switch the reflex. The learning keywords are learn()'s, checked by the same
description (mode, threshold, window, settle, hold_windows, max_trials; the others are the
agent's choice); faults and terrain are Simulation's.

When ``gymnasium`` is importable the environment is a ``gymnasium.Env`` with gymnasium's spaces;
otherwise it has the same interface with multicpg.spaces (Debian 12 ships no gymnasium).
AnnealingAgent runs the paper's simulated annealing (multicpg.Annealer) on the environment and
gives the trace ``multicpg learn --mode paper`` gives for the same seed.
"""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Sequence, SupportsFloat, Tuple, Union

import numpy as np

from ._multicpg import (DETECTION_WINDOWS, PERIOD_SET, Annealer, Robot, Simulation,
                        _learning_options, render, window_error)
# The defaults of the learning keywords, for code written against the environment.
from ._multicpg import (DEFAULT_BETA, DEFAULT_HOLD_WINDOWS, DEFAULT_MAX_TRIALS,  # noqa: F401
                        DEFAULT_MAX_EPISODES, DEFAULT_MONITOR_WINDOWS, DEFAULT_THRESHOLD_DEG,
                        DEFAULT_WINDOW_STEPS)

try:  # gymnasium is not in Debian 12; its spaces and Env are used where it is installed
    import gymnasium as _gymnasium
    from gymnasium.spaces import Box, MultiDiscrete
    _EnvBase = _gymnasium.Env
    HAVE_GYMNASIUM = True
except ImportError:  # pragma: no cover - which branch runs depends on the machine
    from .spaces import Box, MultiDiscrete
    _gymnasium = None
    HAVE_GYMNASIUM = False

    class _EnvBase:  # type: ignore[no-redef]
        """What gymnasium.Env gives an environment: np_random seeded by reset(seed=)."""

        metadata: Dict[str, Any] = {"render_modes": []}
        render_mode: Optional[str] = None
        spec = None
        _np_random: Optional[np.random.Generator] = None

        @property
        def np_random(self) -> np.random.Generator:
            """The environment's generator (gymnasium.Env.np_random)."""
            if self._np_random is None:
                self._np_random = np.random.default_rng()
            return self._np_random

        @property
        def unwrapped(self) -> "_EnvBase":
            """The environment itself (no wrappers here)."""
            return self

        def reset(self, *, seed: Optional[int] = None,
                  options: Optional[dict] = None) -> Any:  # noqa: D102
            if seed is not None:
                self._np_random = np.random.Generator(
                    np.random.PCG64(np.random.SeedSequence(seed)))

        def close(self) -> None:  # noqa: D102
            pass

        def __enter__(self) -> "_EnvBase":
            return self

        def __exit__(self, *args: Any) -> bool:
            self.close()
            return False

__all__ = ["AnnealingAgent", "CompensationEnv", "HAVE_GYMNASIUM", "MODES"]

# Learning modes the environment has (learn()'s mode argument).
MODES = ("paper", "robust")
# The learning keywords an environment uses; learn()'s others (learner, beta, seed, steering,
# ...) are what an agent on it decides.
_ENV_LEARNING = ("mode", "threshold", "window", "settle", "hold_windows", "max_trials")
# Reflex choices, the last action element in robust mode.
STEERING_OFF, STEERING_ON = 0, 1
# Bounds of an observation: a window's yaw change and path angle are wrapped angles (deg), the
# reflex cuts at most a whole side's swing, a CPG period is 1..9 (paper §2.1).
_ANGLE_DEG = 180.0
_MAX_EFFORT = 1.0
_MIN_PERIOD, _MAX_PERIOD = 1.0, 9.0
# Frames play at the controller's rate: 27 Hz (paper §4).
_RENDER_FPS = 27


class CompensationEnv(_EnvBase):
    """The learning task as an environment.

    action (``action_space``, MultiDiscrete): for each working leg, in ``working_legs`` order,
    an index into ``PERIOD_SET`` (4, 5, 6, 8, 9); in robust mode one more element, the steering
    reflex off (0) or on (1). ``action_for(periods)`` and ``periods_of(action)`` convert.

    observation (``observation_space``, Box of float64): the last window's yaw change and path
    angle (deg, + = left), the reflex's mean swing cut (0..1), then every leg's period.

    reward: minus the trial's deviation E (paper: |yaw change| of the window; robust: the worse
    of yaw change, path angle and the reflex effort scaled to the threshold, over the windows
    walked). terminated: E is below the threshold; truncated: max_trials trials were walked.
    info: deviation_deg, yaw_deg, path_deg, steering_effort, periods (list in leg order),
    working_legs, step, trials; reset's also detected and detection_step.

    reset() walks the robot as the learning run does before it learns: paper mode from a cold
    controller (docs/learning.md "Where the authors' code differs"), robust mode from a running
    one with the reflex on; windows are walked until one deviates more than the threshold (or
    DETECTION_WINDOWS after the failure do not), and the CPGs are desynchronised. reset(seed=)
    seeds np_random and both spaces' sample().
    render_mode="rgb_array": render() returns the frame multicpg.render draws.
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": _RENDER_FPS}

    def __init__(self, robot: Union[str, Robot] = "hexapod", disable: Any = "R1",
                 disable_at: int = 0, *, faults: Any = None, terrain: Any = None,
                 render_mode: Optional[str] = None, render_size: Tuple[int, int] = (320, 240),
                 **learning: Any):
        """An environment of ``robot`` (a Robot, a robot name or a robot file) whose legs
        ``disable`` fail from step ``disable_at`` (or the ``faults`` timeline, as Simulation
        takes it), on ``terrain``.

        learning: the learning keywords of learn() an environment keeps (mode, threshold,
        window, settle, hold_windows, max_trials); the others are the agent's to decide and are
        refused. render_mode None or "rgb_array", render_size (width, height) of render()'s
        frames. Every argument is checked here, before anything walks: TypeError or ValueError
        naming the parameter, as learn() raises them.
        """
        # learn()'s description of the learning keywords: unknown ones are named, values checked.
        options = _learning_options(**learning)
        for name in options["given"]:
            if name not in _ENV_LEARNING:
                raise ValueError(f"{name}: learn() takes it, an environment does not (its "
                                 f"agent decides; it takes {', '.join(_ENV_LEARNING)})")
        mode = options["mode"]
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode: expected None or 'rgb_array', got {render_mode!r}")
        # A Robot, a robot name or a robot file FILE.toml.
        self.robot = robot if isinstance(robot, Robot) else Robot(robot)
        self.mode = mode
        # A Simulation checks every argument (names, ranges) before anything walks.
        probe = Simulation(self.robot, disable=disable, disable_at=disable_at, faults=faults,
                           terrain=terrain, warmup=0, record=False)
        self.robot = probe.robot  # on the terrain asked for
        del probe
        self.disable = disable
        self.disable_at = disable_at
        self.faults = faults
        self.threshold = options["threshold"]
        self.window = options["window"]
        self.settle = options["settle"]
        self.hold_windows = options["hold_windows"] if mode == "robust" else 1
        self.max_trials = options["max_trials"]
        self.render_mode = render_mode
        self.render_size = render_size
        self.sim: Optional[Simulation] = None
        self.trials = 0
        working = len(self.working_legs)
        choices = len(PERIOD_SET)
        nvec = [choices] * working + ([2] if mode == "robust" else [])
        self.action_space = MultiDiscrete(np.array(nvec, dtype=np.int64))
        legs = len(self.robot.legs)
        low = np.array([-_ANGLE_DEG, -_ANGLE_DEG, 0.0] + [_MIN_PERIOD] * legs)
        high = np.array([_ANGLE_DEG, _ANGLE_DEG, _MAX_EFFORT] + [_MAX_PERIOD] * legs)
        self.observation_space = Box(low, high, dtype=np.float64)
        # Validate the learning numbers as learn() does, without walking.
        Annealer(self.robot, 4, self.disabled_legs, 0.0, threshold=self.threshold,
                 max_trials=self.max_trials)

    def __repr__(self) -> str:
        return (f"<multicpg.env.CompensationEnv {self.mode} mode: {self.robot!r}, disable="
                f"{self.disable!r} at step {self.disable_at}, {self.trials} trials>")

    # ---- legs and actions ----------------------------------------------------------------

    @property
    def disabled_legs(self) -> List[str]:
        """The legs that fail (they keep their period)."""
        if self.disable is None:
            return []
        legs = self.disable.replace("+", ",").split(",") if isinstance(self.disable, str) \
            else list(self.disable)
        return [leg for leg in legs if leg]

    @property
    def working_legs(self) -> List[str]:
        """The legs whose period the action sets, in leg order."""
        return [leg for leg in self.robot.legs if leg not in self.disabled_legs]

    def action_for(self, periods: Union[Sequence[int], Dict[str, int]],
                   steering: bool = True) -> np.ndarray:
        """The action that gives the working legs these periods (every leg's in leg order, or a
        dict by leg name); in robust mode with the reflex on or off."""
        if isinstance(periods, dict):
            by_leg = periods
        else:
            by_leg = dict(zip(self.robot.legs, periods))
        try:
            action = [PERIOD_SET.index(int(by_leg[leg])) for leg in self.working_legs]
        except (KeyError, ValueError) as e:
            raise ValueError(f"periods: every working leg needs a period of {PERIOD_SET}: "
                             f"{e}") from None
        if self.mode == "robust":
            action.append(STEERING_ON if steering else STEERING_OFF)
        return np.array(action, dtype=np.int64)

    def periods_of(self, action: Any) -> List[int]:
        """Every leg's period (leg order) after `action`; failed legs keep theirs."""
        action = self._checked(action)
        current = self.sim.periods if self.sim is not None else [4] * len(self.robot.legs)
        periods = dict(zip(self.robot.legs, current))
        periods.update(zip(self.working_legs, (PERIOD_SET[i] for i in action)))
        return [periods[leg] for leg in self.robot.legs]

    def _checked(self, action: Any) -> np.ndarray:
        try:
            values = np.asarray(action)
        except (TypeError, ValueError):
            values = None
        if values is None or values.dtype.kind not in "iu" or not self.action_space.contains(
                values.astype(np.int64)):
            raise ValueError(f"action: expected whole numbers in {self.action_space}, "
                             f"got {action!r}")
        return values.astype(np.int64)

    # ---- the environment ------------------------------------------------------------------

    def _settle(self) -> int:
        if self.settle is not None:
            return self.settle
        if self.mode == "paper":
            return self.robot.default_settle_steps
        return self.robot.settle_steps(self.sim.periods)

    def _window(self) -> Dict[str, float]:
        m = self.sim.walk_window(self.window)
        m["deviation_deg"] = window_error(m, mode=self.mode,
                                          steering="reflex" if self.sim.steering else "off",
                                          threshold=self.threshold)
        return m

    def _observation(self, m: Dict[str, float]) -> np.ndarray:
        return np.array([m["yaw_deg"], m["path_deg"], m["steering_effort"], *self.sim.periods],
                        dtype=np.float64)

    def _info(self, m: Dict[str, float]) -> Dict[str, Any]:
        return {"deviation_deg": m["deviation_deg"], "yaw_deg": m["yaw_deg"],
                "path_deg": m["path_deg"], "steering_effort": m["steering_effort"],
                "periods": self.sim.periods, "working_legs": self.working_legs,
                "step": self.sim.step_count, "trials": self.trials}

    def reset(self, *, seed: Optional[int] = None,
              options: Optional[dict] = None) -> Tuple[np.ndarray, Dict[str, Any]]:
        """Walks to the first deviating window; returns (observation, info)."""
        super().reset(seed=seed)
        if seed is not None:
            self.action_space.seed(seed)
            self.observation_space.seed(seed)
        self.trials = 0
        paper = self.mode == "paper"
        # Paper mode starts cold (as the authors' code); robust mode from a running controller,
        # steering.
        self.sim = Simulation(self.robot, disable=self.disable, disable_at=self.disable_at,
                              faults=self.faults, record=False,
                              **({"warmup": 0} if paper else {}))
        if not paper:
            self.sim.steer(True)
        self.sim.step(self._settle(), progress=False)
        windows_since_failure = 0
        while True:
            m = self._window()
            if m["deviation_deg"] > self.threshold:
                break
            # After the failure: DETECTION_WINDOWS windows without a deviation end the run.
            if self.sim.step_count > self.disable_at:
                windows_since_failure += 1
                if windows_since_failure >= DETECTION_WINDOWS:
                    break
        info = self._info(m)
        info["detected"] = m["deviation_deg"] > self.threshold
        info["detection_step"] = self.sim.step_count if info["detected"] else None
        if info["detected"]:
            self.sim.synchronise(False)  # Paper §2.3: a deviation frees every client CPG
        return self._observation(m), info

    def step(self, action: Any) -> Tuple[np.ndarray, SupportsFloat, bool, bool, Dict[str, Any]]:
        """One trial with the periods (and in robust mode the reflex) of `action`."""
        values = self._checked(action)
        if self.sim is None:
            raise RuntimeError("step(): call reset() first")
        if self.mode == "robust":
            on = bool(values[-1] == STEERING_ON)
            if on != self.sim.steering:
                self.sim.steer(on)
        self.sim.set_periods(self.periods_of(values))
        self.sim.step(self._settle(), progress=False)
        worst = None
        for _ in range(self.hold_windows):
            m = self._window()
            if worst is None or m["deviation_deg"] >= worst["deviation_deg"]:
                worst = m
            if m["deviation_deg"] > self.threshold:
                break
        self.trials += 1
        deviation = worst["deviation_deg"]
        terminated = bool(deviation < self.threshold)
        truncated = bool(self.trials >= self.max_trials)
        return (self._observation(worst), -float(deviation), terminated, truncated,
                self._info(worst))

    def render(self) -> Optional[np.ndarray]:
        """The robot now as an H x W x 3 uint8 array (render_mode="rgb_array"), else None."""
        if self.render_mode != "rgb_array" or self.sim is None:
            return None
        width, height = self.render_size
        return render(self.sim, width, height)

    def close(self) -> None:
        """Frees the simulation (and its renderer)."""
        self.sim = None


class AnnealingAgent:
    """The paper's simulated annealing as an agent on CompensationEnv (multicpg.Annealer)."""

    def __init__(self, beta: float = DEFAULT_BETA):
        self.beta = beta

    def run(self, env: CompensationEnv, seed: int = 1) -> Annealer:
        """Learns on `env` from reset(seed); returns the annealer (trace, accepted, stop)."""
        _, info = env.reset(seed=seed)
        annealer = Annealer(env.robot, info["periods"], env.disabled_legs, info["deviation_deg"],
                            seed=seed, beta=self.beta, threshold=env.threshold,
                            max_trials=env.max_trials)
        while True:
            candidate = annealer.propose()
            if candidate is None:
                break
            _, reward, _, _, _ = env.step(env.action_for(candidate))
            if annealer.decide(-reward)["stop"] != "running":
                break
        return annealer
