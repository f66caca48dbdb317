#!/usr/bin/env python3
"""A learner driven by a plain function of the periods: no simulation at all.

`turn` below stands for whatever measures your robot: given each leg's period it says how far
one window turned and how far its path strayed (degrees). The learner (multicpg.Learner) is told
which legs failed, asks for periods and is told what `turn` measured, until a combination walks
under the threshold.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/ask_tell_function.py --learner bayes
"""

import argparse

import multicpg
from multicpg.env import PERIOD_SET

# A made-up robot that pulls right when R1 is lost; slower left legs pull it back. Degrees per
# window for each period step up from 4 (the tripod) on each leg.
PULL_DEG = {"R1": 0.0, "R2": -1.5, "R3": -1.0, "L1": 3.0, "L2": 2.0, "L3": 2.5}
LOST_DEG = -22.0  # R1 lost, every leg at 4


def turn(periods):
    """(yaw change, path angle) of one window walked with `periods` ({leg: period})."""
    steps = {leg: PERIOD_SET.index(p) for leg, p in periods.items()}
    yaw = LOST_DEG + sum(PULL_DEG[leg] * s for leg, s in steps.items())
    return yaw, 0.5 * yaw


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--learner", default="bayes", choices=multicpg.LEARNERS)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--max-trials", type=int, default=200)
    args = parser.parse_args()
    start = {leg: 4 for leg in PULL_DEG}
    # Periods alone judge a trial here (no steering reflex): robust mode's worst of |yaw| and
    # |path|. The prior learns from the AMOSII hexapod's landscapes, not from this robot.
    agent = multicpg.Learner(args.learner, seed=args.seed, failed=["R1"], periods=start,
                             windows=[turn(start)], steering="off", max_trials=args.max_trials)
    while (periods := agent.ask()) is not None:
        record = agent.tell(windows=[turn(periods)])
        print(f"trial {record['trial']:3d}  "
              + " ".join(f"{leg}={p}" for leg, p in periods.items())
              + f"  E = {record['deviation_deg']:5.2f} deg")
    answer = agent.answer
    print(f"{agent.reason} after {agent.trials} trials, E = {answer['deviation_deg']:.2f} deg")


if __name__ == "__main__":
    main()
