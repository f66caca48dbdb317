"""Type stubs of the compiled module multicpg._multicpg (python/module.cpp), for editors
and type checkers. Every name here is re-exported by the multicpg package; the docstrings are
the module's own (help(multicpg.Simulation) shows them at run time)."""

import os
from typing import (Any, Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple,
                    Union)

import numpy as np
import numpy.typing as npt

__version__: str

DEFAULT_THRESHOLD_DEG: float
DEFAULT_WINDOW_STEPS: int
DEFAULT_MAX_TRIALS: int
DEFAULT_BETA: float
DEFAULT_HOLD_WINDOWS: int
DEFAULT_MONITOR_WINDOWS: int
DEFAULT_MAX_EPISODES: int
DETECTION_WINDOWS: int
STEERING_MAX_EFFORT: float
PERIOD_SET: Tuple[int, ...]
LEARNERS: Tuple[str, ...]
GAIT_PERIODS: Tuple[int, ...]
MAX_STEPS: int
FRAME_SIDE_LIMITS: Tuple[int, int]

# Periods: an int (every leg), {"R1": 5}, one per leg in leg order, or the CLI's "R1=5,L1=6".
Periods = Union[int, np.integer, Mapping[str, int], Sequence[int], npt.NDArray[np.integer], str]
# Legs: None (no leg), "R1,R3" / "R1+R3", or leg names.
Legs = Union[None, str, Iterable[str]]
# A fault timeline: one item or a list of Fault, Recovery or "LEGS@STEP".
Faults = Union[None, str, "Fault", Iterable[Union[str, "Fault"]]]
Pose = Tuple[float, float, float]
PathLike = Union[str, "os.PathLike[str]"]
Observer = Optional[Callable[[Dict[str, Any]], Any]]
# A long call's progress: a bar (True), none (False), or a callable given a dict per report
# (stage, steps, total, trials, deviation_deg, finished).
Progress = Union[bool, Callable[[Dict[str, Any]], Any]]

def build_info() -> Dict[str, str]:
    """What this module is: version, git_commit, mujoco_version, compiler, pybind11_version."""

def landscape_dataset(robot: Union[Robot, str] = "hexapod", *, reflex: bool = False) -> str:
    """The prior's default landscape dataset of `robot`, found on the search path."""

class Fault:
    """What breaks before controller step `step` of a run (paper §4; docs/faults.md)."""

    def __init__(self, legs: Legs = None, step: int = 0, *, kind: str = "leg",
                 joint: Optional[str] = None, value: Optional[float] = None) -> None: ...
    @property
    def kind(self) -> str:
        """What breaks: leg, locked, passive, weak, short, slip, drift or noise."""
    @property
    def legs(self) -> Tuple[str, ...]:
        """The legs, as named (empty for the yaw sensor)."""
    @property
    def joint(self) -> Optional[str]:
        """The joint of each leg (TC, CTr, FTi), or None for whole legs."""
    @property
    def value(self) -> Optional[float]:
        """The kind's value, or None."""
    @property
    def step(self) -> int:
        """The controller step it comes before."""
    @property
    def recover(self) -> bool:
        """True for a Recovery: what broke works again."""
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

class Recovery(Fault):
    """What broke works again before controller step `step`."""

    def __init__(self, legs: Legs = None, step: int = 0, *, kind: str = "leg",
                 joint: Optional[str] = None, value: Optional[float] = None) -> None: ...

class Terrain:
    """The ground: flat, a slope, rough ground or steps (robot/terrain.h)."""

    def __init__(self, text: str = "flat") -> None: ...
    @staticmethod
    def flat() -> "Terrain":
        """Level ground."""
    @staticmethod
    def slope(deg: float, heading_deg: float = 0.0) -> "Terrain":
        """A plane rising `deg` (0..30) towards `heading_deg`."""
    @staticmethod
    def rough(height_m: float, seed: int = 1) -> "Terrain":
        """Random bumps up to `height_m` (0.001..0.05 m)."""
    @staticmethod
    def steps(height_m: float, depth_m: float) -> "Terrain":
        """Stairs of `height_m` rises and `depth_m` treads."""
    @property
    def kind(self) -> str:
        """flat, slope, rough or steps."""
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

class Robot:
    """A robot (a name or a robot file FILE.toml) and its MuJoCo model; robots are equal when
    made of the same name and options."""

    def __init__(self, name: Union[str, "os.PathLike[str]"] = "hexapod", *, tunnel: bool = False,
                 control_dt: float = 0.037,
                 physics_dt: Optional[float] = None, servo_gain: Optional[float] = None,
                 terrain: Union["Terrain", str] = "flat", model: str = "paper-sim",
                 body: Optional[Mapping[str, Any]] = None) -> None: ...
    @staticmethod
    def from_file(path: str) -> "Robot":
        """The robot of a robot file (docs/robots.md); ValueError for a bad file."""
    @property
    def file(self) -> Optional[str]:
        """The robot file it was read from, or None for a built-in robot."""
    @property
    def name(self) -> str:
        """Robot name."""
    @property
    def legs(self) -> List[str]:
        """Leg names R1..Rn, L1..Ln (the order of every per-leg array)."""
    @property
    def joints(self) -> List[str]:
        """Joint names of a leg: TC, CTr, FTi."""
    @property
    def joint_names(self) -> List[str]:
        """Every joint's MJCF name."""
    @property
    def tunnel(self) -> bool:
        """Whether the corridor of paper §5 is in the scene."""
    @property
    def terrain(self) -> "Terrain":
        """The ground."""
    @property
    def model(self) -> str:
        """The body model its parameters started from: 'paper-sim' or 'real'."""
    @property
    def body(self) -> Dict[str, Any]:
        """The body's parameters."""
    @property
    def control_dt(self) -> float:
        """Simulated seconds per controller step."""
    @property
    def physics_dt(self) -> float:
        """MuJoCo time step, s."""
    @property
    def default_settle_steps(self) -> int:
        """Unmeasured steps after a period change in paper mode."""
    def settle_steps(self, periods: Periods) -> int:
        """Unmeasured steps robust mode walks after setting these periods."""
    def mjcf(self) -> str:
        """The MJCF text of the model."""
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

class State:
    """A complete, immutable, picklable copy of a Simulation at one step."""

    @property
    def robot(self) -> Robot:
        """The Robot it walks."""
    @property
    def step_count(self) -> int:
        """Controller steps walked (warm-up excluded)."""
    @property
    def time(self) -> float:
        """Simulated time, s."""
    def to_bytes(self) -> bytes:
        """The state as bytes (what pickle stores)."""
    @staticmethod
    def from_bytes(data: Union[bytes, bytearray, memoryview]) -> "State":
        """The State to_bytes() gave; ValueError for damaged or foreign bytes."""

class Simulation:
    """A simulated robot walking under its controller."""

    def __init__(self, robot: Union[Robot, str] = "hexapod", *, periods: Periods = 4,
                 terrain: Union[None, "Terrain", str] = None, disable: Legs = None,
                 disable_at: int = 0, faults: Faults = None, recoveries: Faults = None,
                 warmup: int = 1000, record: bool = True, seed: int = 1) -> None: ...
    def step(self, n: int = 1, *, progress: Progress = True) -> None:
        """Walks n controller steps. Releases the GIL; Ctrl-C raises KeyboardInterrupt."""
    def set_periods(self, periods: Periods) -> None:
        """Sets CPG periods (legs not named keep theirs) and resets every CPG."""
    def fail(self, legs: Legs) -> None:
        """These legs fail from the next step on."""
    def recover(self, legs: Legs) -> None:
        """These failed legs work again from the next step on."""
    def synchronise(self, on: bool) -> None:
        """True: every client CPG follows the master; False: every CPG runs free."""
    def steer(self, on: bool) -> None:
        """Starts (on the course of now) or stops the orientation reflex."""
    @property
    def steering(self) -> bool:
        """Whether the reflex steers."""
    def walk_window(self, steps: int = 400) -> Dict[str, float]:
        """Walks one window and measures it as the learner does."""
    def state(self) -> State:
        """A complete copy of the run."""
    def restore(self, state: State) -> None:
        """Continues from `state` (of a Simulation of an equal Robot)."""
    def record(self) -> Dict[str, np.ndarray]:
        """Every step as NumPy arrays (time, position, yaw_deg, command, target, actual,
        contact, cpg)."""
    def measure(self, settle: int = 0, window: int = 400) -> Dict[str, Any]:
        """What `multicpg walk --json` reports of the record from row `settle` on."""
    def pose(self) -> Pose:
        """(x m, y m, yaw deg) of the trunk now."""
    @property
    def periods(self) -> List[int]:
        """Each leg's CPG period."""
    @property
    def failed(self) -> List[str]:
        """Legs failed now."""
    @property
    def step_count(self) -> int:
        """Controller steps walked (warm-up excluded)."""
    @property
    def time(self) -> float:
        """Simulated time, s."""
    @property
    def recording(self) -> bool:
        """Whether it keeps a per-step record."""
    @property
    def robot(self) -> Robot:
        """The Robot walking."""
    def __copy__(self) -> "Simulation": ...
    def __deepcopy__(self, memo: Any) -> "Simulation": ...

def render(sim: Simulation, width: int = 640, height: int = 480,
           caption: str = "") -> npt.NDArray[np.uint8]:
    """The simulation now as an H x W x 3 uint8 RGB array (sides 16..4096 px)."""

def film(sim: Simulation, out: PathLike, steps: int, *, speed: int = 1, width: int = 640,
         height: int = 480) -> int:
    """Walks `steps` more steps filming them into `out` (.mp4 or .png); returns frames."""

def measure_window(start: Pose, end: Pose) -> Dict[str, float]:
    """Yaw change and path angle of a window between two poses."""

def learn(robot: Union[Robot, str] = "hexapod", *, terrain: Union[None, "Terrain", str] = None,
          disable: Legs = None, disable_at: int = 0, faults: Faults = None,
          recoveries: Faults = None, mode: str = "robust", learner: Optional[str] = None,
          learner_options: Optional[Mapping[str, Any]] = None, steering: str = "reflex",
          hold_windows: int = 3, monitor_windows: int = 6, max_episodes: int = 10,
          period_learning: bool = True, beta: float = 0.5, threshold: float = 8.0,
          window: int = 400, settle: Optional[int] = None, max_trials: int = 200,
          step_budget: int = 1000000, tell_fault: bool = True, seed: int = 1,
          record: bool = False, hardware: Optional[PathLike] = None, lock_step: bool = False,
          observer: Observer = None, progress: Progress = True) -> Dict[str, Any]:
    """`multicpg learn`: the dict of `learn --json` plus trace_arrays (a model-based learner's
    forecast of each trial among them: predicted_e_deg, ...), model_arrays for a model-based
    learner (its map after the last trial) and path; with hardware, on the real robot of that
    hardware file (its hardware record under 'hardware')."""

def tunnel(*, robot: Union[Robot, str] = "hexapod", disable: Legs = None, disable_at: int = 0,
           faults: Faults = None, recoveries: Faults = None, periods: Optional[Periods] = None, learn: bool = False, max_steps: int = 12000,
           video: Optional[PathLike] = None, mode: str = "robust", learner: Optional[str] = None,
           learner_options: Optional[Mapping[str, Any]] = None, steering: str = "reflex",
           hold_windows: int = 3, monitor_windows: int = 6, max_episodes: int = 10,
           period_learning: bool = True, beta: float = 0.5, threshold: float = 8.0,
           window: int = 400, settle: Optional[int] = None, max_trials: int = 200,
           step_budget: int = 1000000, tell_fault: bool = True, seed: int = 1,
           control_dt: float = 0.037, physics_dt: Optional[float] = None,
           servo_gain: Optional[float] = None, terrain: Union["Terrain", str] = "flat",
           model: str = "paper-sim", body: Optional[Mapping[str, Any]] = None,
           hardware: Optional[PathLike] = None, lock_step: bool = False,
           observer: Observer = None, progress: Progress = True,
           scale_tunnel: bool = False) -> Dict[str, Any]:
    """`multicpg tunnel`: the dict of `tunnel --json` plus path (and trace_arrays, and
    model_arrays for a model-based learner); with hardware, on the real robot of that hardware
    file (no path)."""

class Annealer:
    """The simulated annealing of paper §3, one call per step."""

    def __init__(self, robot: Union[Robot, str], periods: Periods, disabled: Legs, e_ref: float,
                 *, seed: int = 1, beta: float = 0.5, threshold: float = 8.0,
                 max_trials: int = 200) -> None: ...
    def propose(self) -> Optional[List[int]]:
        """The next combination to try, or None when the search is over."""
    def decide(self, deviation_deg: float) -> Dict[str, Any]:
        """Keeps or rejects the proposed combination; accepted, probability, stop."""
    @property
    def stop(self) -> str:
        """running, below threshold, trial cap or search space exhausted."""
    @property
    def trials(self) -> int:
        """Trials decided."""
    @property
    def accepted(self) -> List[int]:
        """The accepted combination C(n)."""
    @property
    def e_ref(self) -> float:
        """Its deviation."""
    @property
    def working(self) -> List[str]:
        """Legs whose period may change."""
    @property
    def robot(self) -> Robot:
        """The Robot it learns for."""
    @property
    def trace(self) -> List[Dict[str, Any]]:
        """One dict per decided trial."""

def window_error(window: Union[Sequence[float], Dict[str, float]], *, mode: str = "robust",
                 steering: str = "reflex", threshold: float = 8.0) -> float:
    """E of one window (deg) as a run of that mode and steering judges it."""

class Learner:
    """A learner asked for the next periods and told what each trial measured (ask/tell)."""

    def __init__(self, learner: Optional[str] = None, *, options: Any = None, seed: int = 1,
                 robot: Union[Robot, str] = "hexapod", failed: Legs = None, periods: Periods = 4,
                 windows: Any = None, deviation_deg: Optional[float] = None,
                 mode: str = "robust", steering: str = "reflex", period_set: Any = None,
                 threshold: float = 8.0, max_trials: int = 200,
                 hold_windows: int = 3) -> None: ...
    def ask(self) -> Optional[Dict[str, int]]:
        """The next periods, {leg: period} in leg order, or None when it is done."""
    def tell(self, *, windows: Any = None,
             deviation_deg: Optional[float] = None) -> Dict[str, Any]:
        """What the asked periods measured (windows or E); the trial's record."""
    def next_episode(self, *, periods: Periods, windows: Any = None,
                     deviation_deg: Optional[float] = None) -> None:
        """Starts the next episode from C0 = periods, told every trial since forget()."""
    def forget(self) -> None:
        """The next episode is told none of the trials so far (a fault came)."""
    @property
    def episode(self) -> int:
        """The episode asked now, from 1."""
    @property
    def done(self) -> bool:
        """Whether it wants no more trials."""
    @property
    def reason(self) -> str:
        """running, below threshold, trial cap or search space exhausted."""
    @property
    def answer(self) -> Dict[str, Any]:
        """The combination it ends with: periods and deviation_deg."""
    @property
    def trials(self) -> int:
        """Trials told."""
    @property
    def trace(self) -> List[Dict[str, Any]]:
        """One record per trial told."""
    @property
    def working(self) -> List[str]:
        """Legs whose period it may change."""
    @property
    def name(self) -> str:
        """The learner's name."""
    @property
    def options(self) -> Dict[str, Any]:
        """Its options, every default filled."""
    @property
    def dataset(self) -> Optional[str]:
        """The dataset it learned from (the prior's), or None."""

def _learning_options(*, mode: str = "robust", learner: Optional[str] = None,
                      learner_options: Optional[Mapping[str, Any]] = None,
                      steering: str = "reflex", hold_windows: int = 3, monitor_windows: int = 6,
                      max_episodes: int = 10, period_learning: bool = True, beta: float = 0.5,
                      threshold: float = 8.0, window: int = 400, settle: Optional[int] = None,
                      max_trials: int = 200, step_budget: int = 1000000,
                      tell_fault: bool = True, seed: int = 1) -> Dict[str, Any]: ...
def _run_experiment(file_or_dict: Union[str, PathLike], is_document: bool, jobs: Optional[int],
                    out: PathLike) -> None: ...
def _test_mujoco_error(message: str) -> None: ...
def _replay_simulation(state: bytes, steps: int, out: Optional[PathLike],
                       title: str) -> Tuple[str, Pose]: ...
def _replay_result(result: str, robot: Optional[str], out: Optional[PathLike],
                   title: Optional[str]) -> str: ...
