#!/usr/bin/python3
"""The tunnel as the score: the default run's learning, live, on every hexapod leg loss and on
joint, motor and body faults (docs/learning.md "The default run in the tunnel").

Each (scenario, learner, seed) runs `multicpg tunnel --learn` in the default mode (robust, the
steering reflex on) with every other option at its default: `multicpg tunnel --disable S --learn
--learner L --seed K --json` (a fault: `--fault SPEC@0`). The tables give, per scenario and
learner: runs that passed the tunnel; runs that needed learning (a deviation was detected); the
median trials of the first episode among them and how many stayed within 10, the same over all
the run's episodes; episodes. Resumable:
finished runs are kept in OUT/runs.

    /usr/bin/python3 scripts/tunnel_check.py --out tunnel-check --learners annealing,prior

`--robot` runs another robot: a built-in one (`quadruped`, `octopod`) in the paper's tunnel, or a
robot file (`FILE.toml`, its legs read from the file) in a tunnel scaled to it (`tunnel
--scale-tunnel`).

`--scenarios` takes leg sets and faults ("R1+R3", "R1.TC:locked") or the groups `leg-losses`
(every loss of one leg up to half the legs, at most three: the hexapod's 41, the quadruped's 10,
the octopod's 92) and `faults` (the 16 below, the hexapod's legs); `--seeds N` runs seeds 1..N
(default 10). `--learner-option LEARNER.KEY=VALUE` (repeatable, as `learner-benchmark` takes it)
gives that learner's runs `--learner-option KEY=VALUE`. The robot and the learner options are
recorded in OUT/check.json; a resume with others is refused (exit 2).
"""

import argparse
import itertools
import json
import pathlib
import statistics
import subprocess
import sys
import tomllib
from concurrent.futures import ThreadPoolExecutor

ROOT = pathlib.Path(__file__).resolve().parent.parent
# The built-in robots' legs (robot/morphology.h), right side first.
ROBOT_LEGS = {"hexapod": ["R1", "R2", "R3", "L1", "L2", "L3"],
              "quadruped": ["R1", "R2", "L1", "L2"],
              "octopod": ["R1", "R2", "R3", "R4", "L1", "L2", "L3", "L4"]}
MAX_LOST = 3  # legs lost at once: the hexapod landscape dataset's 41 scenarios


def robot_legs(robot):
    """The legs of a built-in robot or a robot file (its [[legs]] names)."""
    if robot in ROBOT_LEGS:
        return ROBOT_LEGS[robot]
    with open(robot, "rb") as f:
        return [leg["name"] for leg in tomllib.load(f)["legs"]]


def leg_losses(legs):
    """Every loss of one leg up to half the legs (at most MAX_LOST), in the CLI's leg order."""
    most = min(MAX_LOST, len(legs) // 2)
    return ["+".join(c) for n in range(1, most + 1) for c in itertools.combinations(legs, n)]


def whole_side(scenario, legs):
    """Whether a leg set loses every leg of one side (pooled apart: on the hexapod no periods walk
    those straight)."""
    lost = set(scenario.split("+"))
    return any({l for l in legs if l[0] == side} <= lost for side in "RL")

# Fourteen joint, motor and body faults (docs/faults.md "Fault kinds"): each kind at least once,
# each joint locked and passive, front, middle and hind legs on both sides; then the yaw sensor.
FAULTS = ["R1.TC:locked", "R2.CTr:locked", "L3.TC:locked", "R3.CTr:locked", "L2.FTi:locked",
          "L1.CTr:passive", "R3.FTi:passive", "R2.TC:passive", "L2.CTr:weak=0.3", "R3:weak=0.3",
          "R2:weak=0.2", "L2:short=0.5", "R1:short=0.5", "L1:slip=0.2",
          "imu:drift=0.5", "imu:noise=1"]
KNOWN_LEARNERS = ["annealing", "random", "greedy", "bayes", "prior"]
SEEDS = 10
WITHIN = 10  # trials: the bound docs/learning.md "The default run in the tunnel" sets a first episode


def run(exe, out, scenario, learner, seed, robot, options):
    path = out / f"{scenario}_{learner}_{seed}.json"
    if path.exists():
        return
    fault = ["--fault", f"{scenario}@0"] if ":" in scenario else ["--disable", scenario]
    # A robot file walks the tunnel scaled to its size (docs/robots.md "Example robots"), a
    # built-in robot the paper's.
    body = (["--robot", robot] + ([] if robot in ROBOT_LEGS else ["--scale-tunnel"])
            if robot else [])
    given = [a for o in options for a in ("--learner-option", o)]
    result = subprocess.run([exe, "tunnel", *body, *fault, "--learn", "--learner", learner,
                             *given, "--seed", str(seed), "--json"], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"tunnel_check: {scenario} {learner} {seed}: {result.stderr.strip()}")
    tmp = path.with_suffix(".tmp")
    tmp.write_text(result.stdout)
    tmp.replace(path)


def scenarios_of(text, legs):
    groups = {"leg-losses": leg_losses(legs), "faults": FAULTS}
    out = []
    for item in text.split(","):
        out += groups.get(item, [item])
    return out


def row(runs):
    """One table row's cells from a pair's finished runs (tunnel --learn --json)."""
    passed = sum(r["passed"] for r in runs)
    learned = [r["learning"]["episodes"] for r in runs if r["learning"]["episodes"]]
    first = sorted(e[0]["trials"] for e in learned)
    total = sorted(sum(x["trials"] for x in e) for e in learned)
    within = sum(t <= WITHIN for t in first)
    episodes = sorted(len(e) for e in learned)
    return {"runs": len(runs), "passed": passed, "learned": len(learned),
            "median_trials": statistics.median(first) if first else None,
            "within": within,
            "median_total": statistics.median(total) if total else None,
            "within_total": sum(t <= WITHIN for t in total),
            "median_episodes": statistics.median(episodes) if episodes else None}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="folder for the runs and the tables")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--seeds", type=int, default=SEEDS, help="seeds 1..N of each pair")
    parser.add_argument("--multicpg", default=str(ROOT / "build" / "multicpg"))
    parser.add_argument("--robot", default="",
                        help="quadruped or octopod (the paper's tunnel), or a robot file "
                             "(FILE.toml, its tunnel scaled); default: the AMOSII hexapod")
    parser.add_argument("--learners", default="annealing,prior",
                        help="comma-separated, of " + ", ".join(KNOWN_LEARNERS))
    parser.add_argument("--scenarios", default="leg-losses,faults",
                        help="comma-separated leg sets and faults, or the groups "
                             "leg-losses and faults")
    parser.add_argument("--learner-option", action="append", default=[],
                        metavar="LEARNER.KEY=VALUE",
                        help="an option of one learner's runs (repeatable)")
    args = parser.parse_args()
    if args.seeds < 1:
        parser.error(f"--seeds must be at least 1, got {args.seeds}")
    learners = args.learners.split(",")
    for name in learners:
        if name not in KNOWN_LEARNERS:
            parser.error(f"unknown learner '{name}' (known: {', '.join(KNOWN_LEARNERS)})")
    try:
        legs = robot_legs(args.robot or "hexapod")
    except (OSError, tomllib.TOMLDecodeError, KeyError, TypeError) as e:
        parser.error(f"--robot: not a built-in robot nor a readable robot file: {e}")
    scenarios = scenarios_of(args.scenarios, legs)
    for s in scenarios:
        if ":" not in s and not all(leg in legs for leg in s.split("+")):
            parser.error(f"unknown scenario '{s}' (leg sets of {', '.join(legs)} such as "
                         f"{legs[0]}+{legs[-1]}, faults such as R1.TC:locked, or the groups "
                         "leg-losses and faults)")
    options = {l: [] for l in learners}
    for given in args.learner_option:
        name, dot, rest = given.partition(".")
        if not dot or "=" not in rest or not rest.split("=", 1)[0]:
            parser.error(f"--learner-option must be LEARNER.KEY=VALUE, got '{given}'")
        if name not in learners:
            parser.error(f"--learner-option '{given}' names '{name}', which is not among "
                         f"--learners ({', '.join(learners)})")
        options[name].append(rest)
    out = pathlib.Path(args.out)
    runs_dir = out / "runs"
    runs_dir.mkdir(parents=True, exist_ok=True)
    # What decides a run besides its scenario, learner and seed: a resume must keep it.
    check = {"robot": args.robot, "learner_options": {l: o for l, o in options.items() if o}}
    record = out / "check.json"
    if record.exists():
        kept = json.loads(record.read_text())
        if kept != check:
            parser.error(f"{record} records {json.dumps(kept)}; these runs would be "
                         f"{json.dumps(check)} (another --out, or the same options)")
    else:
        record.write_text(json.dumps(check, indent=1) + "\n")
    with ThreadPoolExecutor(args.jobs) as pool:
        for f in [pool.submit(run, args.multicpg, runs_dir, s, l, k, args.robot, options[l])
                  for s in scenarios for l in learners for k in range(1, args.seeds + 1)]:
            f.result()

    lines = [f"| scenario | learner | runs | tunnel passed | learning needed | median trials "
             f"(first episode) | within {WITHIN} | median trials (all episodes) | within {WITHIN} "
             f"| median episodes |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    pooled = {}
    for s in scenarios:
        for l in learners:
            runs = [json.loads((runs_dir / f"{s}_{l}_{k}.json").read_text())
                    for k in range(1, args.seeds + 1)]
            c = row(runs)
            lines.append(f"| {s} | {l} | {c['runs']} | {c['passed']}/{c['runs']} | "
                         f"{c['learned']}/{c['runs']} | "
                         f"{'–' if c['median_trials'] is None else c['median_trials']} | "
                         f"{c['within']}/{c['learned']} | "
                         f"{'–' if c['median_total'] is None else c['median_total']} | "
                         f"{c['within_total']}/{c['learned']} | "
                         f"{'–' if c['median_episodes'] is None else c['median_episodes']} |")
            group = ("faults" if ":" in s
                     else "whole side" if whole_side(s, legs) else "leg losses")
            p = pooled.setdefault((group, l), {"runs": 0, "passed": 0, "trials": [], "total": [],
                                               "within": 0, "learned": 0})
            p["runs"] += c["runs"]
            p["passed"] += c["passed"]
            for r in runs:
                if r["learning"]["episodes"]:
                    p["trials"].append(r["learning"]["episodes"][0]["trials"])
                    p["total"].append(sum(e["trials"] for e in r["learning"]["episodes"]))
            p["within"] += c["within"]
            p["learned"] += c["learned"]
    lines += ["", f"| scenarios | learner | runs | tunnel passed | median trials where learning "
              f"was needed (first episode) | within {WITHIN} | median trials (all episodes) | "
              f"within {WITHIN} |", "|---|---|---|---|---|---|---|---|"]

    def share_of(count, of):
        return f"{count}/{of} ({100 * count / of:.0f} %)" if of else "–"

    for (group, l), p in sorted(pooled.items()):
        share = 100 * p["passed"] / p["runs"]
        median = statistics.median(p["trials"]) if p["trials"] else "–"
        total = statistics.median(p["total"]) if p["total"] else "–"
        within_total = sum(t <= WITHIN for t in p["total"])
        lines.append(f"| {group} | {l} | {p['runs']} | {p['passed']}/{p['runs']} ({share:.0f} %) "
                     f"| {median} | {share_of(p['within'], p['learned'])} | {total} | "
                     f"{share_of(within_total, p['learned'])} |")
    (out / "tunnel-check.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
