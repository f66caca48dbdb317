#!/usr/bin/env python3
"""R1 fails and the hexapod learns to walk straight again (paper §4, Fig. 8), from Python.

Writes trunk_path.png (the trunk's path with R1 failed, before and after learning) and
deviation.png (each trial's deviation against the threshold) into --out.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/learn_r1.py --out r1
"""

import argparse
import math
import pathlib

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

import multicpg  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="directory for the PNGs")
    parser.add_argument("--mode", default="paper", help="paper or robust (as multicpg learn)")
    parser.add_argument("--seed", type=int, default=5, help="seed of the learning run")
    parser.add_argument("--max-trials", type=int, default=200)
    parser.add_argument("--steps", type=int, default=2000, help="steps of each path walked")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    robot = multicpg.Robot("hexapod")
    result = multicpg.learn(robot, disable="R1", mode=args.mode, seed=args.seed,
                            max_trials=args.max_trials)
    learned = [result["periods"][leg] for leg in robot.legs]
    # R1's period marked x, as the CLI's trace marks a disabled leg.
    print(f"{result['status']} after {result['trials']} trials: "
          + " ".join(f"{leg}={result['periods'][leg]}{'x' if leg == 'R1' else ''}"
                     for leg in robot.legs))

    fig, ax = plt.subplots(figsize=(6, 5))
    for label, periods in (("before learning (all 4)", 4), ("after learning", learned)):
        sim = multicpg.Simulation(robot, periods=periods, disable="R1")
        sim.step(args.steps)
        record = sim.record()
        position = record["position"]
        ax.plot(position[:, 0], position[:, 1], label=label)
    # Sideways drift of the learned gait: the distance from the line of the start heading.
    heading = math.radians(record["yaw_deg"][0])
    dx, dy = position[-1, 0] - position[0, 0], position[-1, 1] - position[0, 1]
    drift = -dx * math.sin(heading) + dy * math.cos(heading)
    forward = dx * math.cos(heading) + dy * math.sin(heading)
    print(f"after learning: {forward:.2f} m forward, {drift:+.2f} m sideways (+ = left) "
          f"in {args.steps} steps")
    if result["options"]["mode"] == "paper":
        print("paper mode judges one 400-step window's yaw change (paper §3): a gait can turn "
              "little and still crab sideways; --mode robust also judges the path")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_title(f"Hexapod trunk path, R1 failed, {args.steps} steps")
    ax.legend()
    fig.savefig(out / "trunk_path.png", dpi=100)

    trace = result["trace_arrays"]  # from trial 0: the detecting window, every leg at 4
    fig, ax = plt.subplots(figsize=(6, 4))
    colours = ["tab:grey" if trial == 0 else "tab:green" if kept else "tab:red"
               for trial, kept in zip(trace["trial"], trace["accepted"])]
    ax.bar(trace["trial"], trace["deviation_deg"], color=colours)
    threshold = result["options"]["annealing"]["threshold_deg"]
    line = ax.axhline(threshold, color="black", linestyle="--", label="threshold")
    ax.set_xticks(range(0, result["trials"] + 1))
    ax.set_xlabel("trial")
    ax.set_ylabel(f"deviation per {result['options']['window_steps']}-step window (deg)")
    ax.set_title("Deviation per trial (green kept, red rejected)")
    ax.legend(handles=[Patch(color="tab:grey", label="trial 0: detecting window"), line])
    fig.savefig(out / "deviation.png", dpi=100)
    print(f"wrote {out / 'trunk_path.png'} and {out / 'deviation.png'}")


if __name__ == "__main__":
    main()
