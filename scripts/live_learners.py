#!/usr/bin/python3
"""Learners on the live simulation against the replay's prediction (docs/learning.md "Live physics").

Each (scenario, learner, seed) learns in the open field and walks the tunnel:
`multicpg tunnel --disable S --learn --steering off --learner L --seed K --max-trials 20
--step-budget 50000 --json`. A run counts as held when its first episode held within 20 trials
(or the start never deviated) on a combination that holds every window of the committed landscape
(data/landscapes/hexapod), the replay's own rule; the replay's prediction is `learner-benchmark`'s
share for the same scenario and learner. Resumable: finished runs are kept in OUT/runs.

    /usr/bin/python3 scripts/live_learners.py --out live --jobs 2    # ≈32 min on 2 cores

`--learners` and `--scenarios` choose a part (default: annealing and prior on every scenario);
the tables list the scenario and learner pairs whose seeds have all finished.
"""

import argparse
import csv
import gzip
import json
import pathlib
import subprocess
import sys
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor

ROOT = pathlib.Path(__file__).resolve().parent.parent
LEGS = ["R1", "R2", "R3", "L1", "L2", "L3"]
# The paper's three Table 1 scenarios, six more leg losses (three with a deviation to learn, the
# three symmetric losses without) and one joint fault, which has no landscape (live only).
SCENARIOS = ["R1", "R1+R3", "R1+R3+L2", "R2", "R1+L1", "R2+L2", "R3+L3", "R1+R3+L1", "R2+R3+L3",
             "R1.CTr:locked"]
LEARNERS = ["annealing", "prior"]
KNOWN_LEARNERS = ["annealing", "random", "greedy", "bayes", "prior"]
SEEDS = range(1, 11)
BUDGET = 20  # trials: the benchmark's budget (docs/learning.md "Learner benchmark")
STEP_BUDGET = 50_000  # ends a robust run that keeps starting episodes


def run(exe, out, scenario, learner, seed):
    path = out / f"{scenario}_{learner}_{seed}.json"
    if path.exists():
        return
    fault = ["--fault", f"{scenario}@0"] if ":" in scenario else ["--disable", scenario]
    result = subprocess.run([exe, "tunnel", *fault, "--learn", "--steering", "off", "--learner",
                             learner, "--seed", str(seed), "--max-trials", str(BUDGET),
                             "--step-budget", str(STEP_BUDGET), "--json"],
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"live_learners: {scenario} {learner} {seed}: {result.stderr.strip()}")
    tmp = path.with_suffix(".tmp")
    tmp.write_text(result.stdout)
    tmp.replace(path)


def landscape_holds():
    holds = {}
    with gzip.open(ROOT / "data" / "landscapes" / "hexapod.csv.gz", "rt") as f:
        for row in csv.DictReader(f):
            holds[(row["scenario"], tuple(row[leg] for leg in LEGS))] = row["holds"] == "1"
    return holds


def key(scenario, periods):
    failed = scenario.split("+")
    return scenario, tuple("x" if leg in failed else str(periods[leg]) for leg in LEGS)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="folder for the runs and the tables")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--multicpg", default=str(ROOT / "build" / "multicpg"))
    parser.add_argument("--learners", default=",".join(LEARNERS),
                        help="comma-separated, of " + ", ".join(KNOWN_LEARNERS))
    parser.add_argument("--scenarios", default=",".join(SCENARIOS),
                        help="comma-separated, of " + ", ".join(SCENARIOS))
    args = parser.parse_args()
    learners = args.learners.split(",")
    scenarios = args.scenarios.split(",")
    for name, asked, known in (("learner", learners, KNOWN_LEARNERS),
                               ("scenario", scenarios, SCENARIOS)):
        for item in asked:
            if item not in known:
                parser.error(f"unknown {name} '{item}' (known: {', '.join(known)})")
    out = pathlib.Path(args.out)
    runs_dir = out / "runs"
    runs_dir.mkdir(parents=True, exist_ok=True)
    bench = out / "benchmark"
    if not (bench / "runs.csv").exists():
        subprocess.run([args.multicpg, "learner-benchmark", "--learners",
                        ",".join(KNOWN_LEARNERS), "--out", str(bench)], check=True,
                       stdout=subprocess.DEVNULL)
    with ThreadPoolExecutor(args.jobs) as pool:
        for f in [pool.submit(run, args.multicpg, runs_dir, s, l, k)
                  for s in scenarios for l in learners for k in SEEDS]:
            f.result()

    replay = defaultdict(lambda: [0, 0])
    for r in csv.DictReader(open(bench / "runs.csv")):
        held = (r["held_at"] != "" and int(r["held_at"]) <= BUDGET if r["deviated"] == "1"
                else r["answer_holds"] == "1")
        replay[(r["scenario"], r["learner"])][0] += held
        replay[(r["scenario"], r["learner"])][1] += 1
    holds = landscape_holds()
    lines = ["| scenario | learner | runs | first episode held within 20 | and holds in the "
             "landscape | replay: held within 20 | robust run converged | tunnel passed | "
             "median trials (first episode) |", "|---|---|---|---|---|---|---|---|---|"]
    pooled = defaultdict(lambda: [0, 0, 0.0, 0, 0])
    done = [(s, l) for s in SCENARIOS for l in KNOWN_LEARNERS
            if all((runs_dir / f"{s}_{l}_{k}.json").exists() for k in SEEDS)]
    for s in SCENARIOS:
        for l in KNOWN_LEARNERS:
            if (s, l) not in done:
                continue
            first_held = truth = converged = passed = 0
            trials = []
            for k in SEEDS:
                d = json.loads((runs_dir / f"{s}_{l}_{k}.json").read_text())
                learning = d["learning"]
                episode = learning["episodes"][0] if learning["episodes"] else None
                # A start that never deviated answers with the all-4 start.
                periods = episode["periods"] if episode else {leg: 4 for leg in LEGS}
                held = episode is None or (episode["held"] and episode["trials"] <= BUDGET)
                first_held += held
                truth += held and ":" not in s and holds[key(s, periods)]
                converged += learning["converged"] or learning["status"] == "no deviation"
                passed += d["passed"]
                trials.append(episode["trials"] if episode else 0)
            n = len(SEEDS)
            median = sorted(trials)[n // 2]
            rp = replay.get((s, l))
            predicted = f"{100 * rp[0] / rp[1]:.0f} %" if rp else "–"
            lines.append(f"| {s} | {l} | {n} | {first_held}/{n} | "
                         f"{f'{truth}/{n}' if ':' not in s else '– (no landscape)'} | "
                         f"{predicted} | {converged}/{n} | {passed}/{n} | {median} |")
            if ":" not in s:
                p = pooled[l]
                p[0] += truth
                p[1] += n
                p[2] += rp[0] / rp[1] * n
                p[3] += passed
                p[4] += converged
    lines += ["", "| learner | live: held within 20, holds in the landscape | replay predicted "
              "(same scenarios) | difference | tunnel passed | robust run converged |",
              "|---|---|---|---|---|---|"]
    for l in KNOWN_LEARNERS:
        if l not in pooled:
            continue
        p = pooled[l]
        lines.append(f"| {l} | {p[0]}/{p[1]} ({100 * p[0] / p[1]:.0f} %) | "
                     f"{100 * p[2] / p[1]:.0f} % | {100 * (p[0] - p[2]) / p[1]:+.0f} pp | "
                     f"{p[3]}/{p[1]} | {p[4]}/{p[1]} |")
    (out / "live.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
