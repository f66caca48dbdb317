"""A Gymnasium-shaped environment of malfunction compensation (paper §3), without gymnasium.

One step is one trial of `multicpg learn --mode paper`: the working legs get the action's
periods, the robot walks the settling steps unmeasured, then one 400-step window is measured.
reset() walks the robot from a cold controller as the paper's run does (SPEC §6): the legs fail,
windows are walked until one deviates more than the threshold, and the CPGs are desynchronised.

AnnealingAgent runs the paper's simulated annealing (multicpg.Annealer) on the environment and
gives the trace `multicpg learn --mode paper` gives for the same seed.
"""

import numpy as np

from ._multicpg import (DEFAULT_BETA, DEFAULT_MAX_TRIALS, DEFAULT_THRESHOLD_DEG,
                        DEFAULT_WINDOW_STEPS, DETECTION_WINDOWS, Annealer, Robot, Simulation,
                        measure_window)


class CompensationEnv:
    """The learning task as an environment: action = the working legs' periods.

    Observation (float64 array): the last window's yaw change and path angle (deg, + = left),
    then every leg's current period. Reward: minus the deviation E = |yaw change| of the window
    (SPEC §6). terminated: E is below the threshold; truncated: max_trials trials were walked.
    info: deviation_deg, periods, working_legs, step and (reset) detected, detection_step.
    The environment itself draws no random numbers: reset's seed is kept in info for the agent.
    """

    def __init__(self, robot="hexapod", disable="R1", disable_at=0,
                 threshold=DEFAULT_THRESHOLD_DEG, window=DEFAULT_WINDOW_STEPS, settle=None,
                 max_trials=DEFAULT_MAX_TRIALS):
        self.robot = robot if isinstance(robot, Robot) else Robot(robot)
        self.disable = disable
        self.disable_at = disable_at
        self.threshold = threshold
        self.window = window
        self.settle = self.robot.default_settle_steps if settle is None else settle
        self.max_trials = max_trials
        self.sim = None
        self.trials = 0
        self.seed = None

    @property
    def disabled_legs(self):
        legs = self.disable.split(",") if isinstance(self.disable, str) else list(self.disable)
        return [leg for leg in legs if leg]

    @property
    def working_legs(self):
        return [leg for leg in self.robot.legs if leg not in self.disabled_legs]

    def _measure(self):
        start = self.sim.pose()
        self.sim.step(self.window)
        return measure_window(start, self.sim.pose())

    def _observation(self, measure):
        return np.array([measure["yaw_deg"], measure["path_deg"], *self.sim.periods],
                        dtype=np.float64)

    def _info(self, measure):
        return {"deviation_deg": abs(measure["yaw_deg"]), "periods": self.sim.periods,
                "working_legs": self.working_legs, "step": self.sim.step_count,
                "seed": self.seed}

    def reset(self, seed=None, options=None):
        """Walks to the first deviating window; returns (observation, info)."""
        del options  # no options: the constructor's arguments say what the run is
        self.seed = seed
        self.trials = 0
        self.sim = Simulation(self.robot, disable=self.disable, disable_at=self.disable_at,
                              warmup=0, record=False)
        self.sim.step(self.settle)
        windows_since_failure = 0
        while True:
            measure = self._measure()
            if abs(measure["yaw_deg"]) > self.threshold:
                break
            # After the failure: DETECTION_WINDOWS windows without a deviation end the run.
            if self.sim.step_count > self.disable_at:
                windows_since_failure += 1
                if windows_since_failure >= DETECTION_WINDOWS:
                    break
        info = self._info(measure)
        info["detected"] = info["deviation_deg"] > self.threshold
        info["detection_step"] = self.sim.step_count if info["detected"] else None
        if info["detected"]:
            self.sim.synchronise(False)  # SPEC §5: a deviation frees every client CPG
        return self._observation(measure), info

    def step(self, action):
        """One trial: the working legs take the periods of `action` (in working_legs order)."""
        if self.sim is None:
            raise RuntimeError("call reset() before step()")
        action = [int(p) for p in action]
        working = self.working_legs
        if len(action) != len(working):
            raise ValueError(f"expected {len(working)} periods (for {','.join(working)}), "
                             f"got {len(action)}")
        periods = dict(zip(self.robot.legs, self.sim.periods))
        periods.update(zip(working, action))
        self.sim.set_periods([periods[leg] for leg in self.robot.legs])
        self.sim.step(self.settle)
        measure = self._measure()
        self.trials += 1
        deviation = abs(measure["yaw_deg"])
        terminated = deviation < self.threshold
        truncated = self.trials >= self.max_trials
        return self._observation(measure), -deviation, terminated, truncated, self._info(measure)


class AnnealingAgent:
    """The paper's simulated annealing as an agent on CompensationEnv (multicpg.Annealer)."""

    def __init__(self, beta=DEFAULT_BETA):
        self.beta = beta

    def run(self, env, seed=1):
        """Learns on `env` from reset(seed); returns the annealer (trace, accepted, stop)."""
        _, info = env.reset(seed=seed)
        annealer = Annealer(env.robot, info["periods"], env.disabled_legs, info["deviation_deg"],
                            seed=seed, beta=self.beta, threshold=env.threshold,
                            max_trials=env.max_trials)
        while True:
            candidate = annealer.propose()
            if candidate is None:
                break
            action = [candidate[env.robot.legs.index(leg)] for leg in env.working_legs]
            _, reward, _, _, _ = env.step(action)
            if annealer.decide(-reward)["stop"] != "running":
                break
        return annealer
