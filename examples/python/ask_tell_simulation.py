#!/usr/bin/env python3
"""A learner driven from your own loop: the Simulation stands in for an external simulator.

The loop walks the robot, measures its own windows and only asks the learner (multicpg.Learner)
for the next periods and tells it what they measured. It walks the trials as `multicpg learn
--mode paper` does (paper §3: a cold start, one window of 400 steps a trial after the settle),
so with the same seed it gives the trials of `learn --mode paper --learner NAME`.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/ask_tell_simulation.py \\
        --learner prior --disable R1 --max-trials 20
"""

import argparse

import multicpg
from multicpg.env import DEFAULT_THRESHOLD_DEG, DEFAULT_WINDOW_STEPS, DETECTION_WINDOWS


def learn_in_my_loop(learner="annealing", disable="R1", seed=1, max_trials=200,
                     robot="hexapod"):
    """Walks until a window deviates, then learns; returns the multicpg.Learner (None when no
    window deviated)."""
    robot = multicpg.Robot(robot)
    settle = robot.default_settle_steps  # paper mode's settle after every period change
    sim = multicpg.Simulation(robot, disable=disable, warmup=0, record=False)
    sim.step(settle, progress=False)
    for _ in range(DETECTION_WINDOWS):
        window = sim.walk_window(DEFAULT_WINDOW_STEPS)
        if abs(window["yaw_deg"]) > DEFAULT_THRESHOLD_DEG:
            break
    else:
        return None
    sim.synchronise(False)  # paper §2.3: a deviation frees every client CPG
    agent = multicpg.Learner(learner, seed=seed, robot=robot, failed=disable,
                             periods=sim.periods, windows=[window], mode="paper",
                             max_trials=max_trials)
    while (periods := agent.ask()) is not None:
        sim.set_periods(periods)
        sim.step(settle, progress=False)
        agent.tell(windows=[sim.walk_window(DEFAULT_WINDOW_STEPS)])
    return agent


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--learner", default="annealing", choices=multicpg.LEARNERS)
    parser.add_argument("--disable", default="R1", help="the legs that fail, e.g. R1,R3")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--max-trials", type=int, default=200)
    args = parser.parse_args()
    agent = learn_in_my_loop(args.learner, args.disable, args.seed, args.max_trials)
    if agent is None:
        print("no window deviated: nothing to learn")
        return
    for t in agent.trace:
        periods = " ".join(f"{leg}={p}" for leg, p in t["periods"].items())
        print(f"trial {t['trial']:3d}  {periods}  E = {t['deviation_deg']:6.2f} deg"
              + ("  new answer" if t["accepted"] else ""))
    answer = agent.answer
    print(f"{agent.reason} after {agent.trials} trials: "
          + " ".join(f"{leg}={p}" for leg, p in answer["periods"].items())
          + f", E = {answer['deviation_deg']:.2f} deg")


if __name__ == "__main__":
    main()
