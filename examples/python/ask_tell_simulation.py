#!/usr/bin/env python3
"""A learner driven from your own loop: the Simulation stands in for an external simulator.

The loop walks the robot, measures its own windows and only asks the learner (multicpg.Learner)
for the next periods and tells it what they measured. It walks as `multicpg learn` does, so
with the same seed it gives learn()'s trials:

- robust mode (the default, as learn's): the steering reflex holds the course; a window over
  the threshold starts an episode; a trial walks up to DEFAULT_HOLD_WINDOWS windows after the
  settle, stopping at the first over; after an episode the answer walks on, and a window over
  the threshold starts the next episode (the learner told what the earlier ones walked), until
  DEFAULT_MONITOR_WINDOWS windows hold (docs/learning.md "Compensation that holds"); once an
  episode has found nothing left to try, none starts again.
- paper mode (paper §3): a cold start, one window of 400 steps a trial after the settle.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/ask_tell_simulation.py \\
        --learner prior --disable R1,R3 --max-trials 20
"""

import argparse

import multicpg
from multicpg.env import (DEFAULT_HOLD_WINDOWS, DEFAULT_MAX_EPISODES, DEFAULT_MONITOR_WINDOWS,
                          DEFAULT_THRESHOLD_DEG, DEFAULT_WINDOW_STEPS, DETECTION_WINDOWS)


def learn_in_my_loop(learner=None, disable="R1,R3", seed=1, max_trials=200, robot="hexapod",
                     mode="robust", max_episodes=DEFAULT_MAX_EPISODES):
    """Walks until a window deviates, then learns; returns the multicpg.Learner (None when no
    window deviated). max_episodes: robust mode's, as learn()'s."""
    if mode == "paper":
        return _paper_loop(learner, disable, seed, max_trials, multicpg.Robot(robot))
    return _robust_loop(learner, disable, seed, max_trials, multicpg.Robot(robot), max_episodes)


def _robust_loop(learner, disable, seed, max_trials, robot, max_episodes):
    sim = multicpg.Simulation(robot, disable=disable, record=False)
    sim.steer(True)
    sim.walk_window(DEFAULT_WINDOW_STEPS)  # the window the legs failed in: their transient

    def over(window):
        return multicpg.window_error(window) > DEFAULT_THRESHOLD_DEG

    agent = None
    held = 0  # windows walked on since the last episode, each under the threshold
    nothing_left = False  # an episode tried nothing: every combination was told
    while held < DEFAULT_MONITOR_WINDOWS:
        window = sim.walk_window(DEFAULT_WINDOW_STEPS)
        episodes = agent.episode if agent is not None else 0
        if not over(window) or episodes == max_episodes or nothing_left:
            held += 1
            continue
        held = 0
        sim.synchronise(False)  # paper §2.3: a deviation frees every client CPG
        if agent is None:
            agent = multicpg.Learner(learner, seed=seed, robot=robot, failed=disable,
                                     periods=sim.periods, windows=[window],
                                     max_trials=max_trials)
        else:
            agent.next_episode(periods=sim.periods, windows=[window])
        told = agent.trials
        while (periods := agent.ask()) is not None:
            sim.set_periods(periods)
            sim.step(robot.settle_steps(sim.periods), progress=False)
            windows = []
            while len(windows) < DEFAULT_HOLD_WINDOWS and not (windows and over(windows[-1])):
                windows.append(sim.walk_window(DEFAULT_WINDOW_STEPS))
            agent.tell(windows=windows)
        nothing_left = agent.trials == told and agent.reason == "search space exhausted"
        answer = list(agent.answer["periods"].values())  # leg order, as sim.periods
        if answer != sim.periods:
            sim.set_periods(answer)
            sim.step(robot.settle_steps(sim.periods), progress=False)
    return agent


def _paper_loop(learner, disable, seed, max_trials, robot):
    settle = robot.default_settle_steps  # paper mode's settle after every period change
    sim = multicpg.Simulation(robot, disable=disable, warmup=0, record=False)
    sim.step(settle, progress=False)
    for _ in range(DETECTION_WINDOWS):
        window = sim.walk_window(DEFAULT_WINDOW_STEPS)
        if multicpg.window_error(window, mode="paper") > DEFAULT_THRESHOLD_DEG:
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
    parser.add_argument("--learner", default=None, choices=multicpg.LEARNERS,
                        help="default: learn()'s for the mode (robust: the prior where the "
                             "robot's dataset is)")
    parser.add_argument("--disable", default="R1,R3", help="the legs that fail, e.g. R1,R3")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--max-trials", type=int, default=200)
    parser.add_argument("--mode", default="robust", choices=("robust", "paper"))
    args = parser.parse_args()
    agent = learn_in_my_loop(args.learner, args.disable, args.seed, args.max_trials,
                             mode=args.mode)
    if agent is None:
        print("no window deviated: nothing to learn")
        return
    for t in agent.trace:
        periods = " ".join(f"{leg}={p}" for leg, p in t["periods"].items())
        print(f"trial {t['trial']:3d}  {periods}  E = {t['deviation_deg']:6.2f} deg"
              + ("  new answer" if t["accepted"] else ""))
    answer = agent.answer
    print(f"{agent.name}: {agent.reason} after {agent.trials} trials in {agent.episode} "
          "episodes: " + " ".join(f"{leg}={p}" for leg, p in answer["periods"].items())
          + f", E = {answer['deviation_deg']:.2f} deg")


if __name__ == "__main__":
    main()
