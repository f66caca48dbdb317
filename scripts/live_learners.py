#!/usr/bin/python3
"""Learners on the live simulation against the replay's prediction (docs/learning.md "Live physics").

Each (scenario, learner, seed) learns in the open field and walks the tunnel:
`multicpg tunnel --disable S --learn --steering off --learner L --seed K --max-trials 20
--step-budget 50000 --json`. A run counts as held when its first episode held within 20 trials
(or the start never deviated) on a combination that holds every window of the committed landscape
(data/landscapes/hexapod), the replay's own rule. The replay's predictions are `learner-benchmark`'s
shares for the same scenario and learner, with the windows a trial walks taken in the landscape's
order (`--window-order walked`: what the simulation measures) and drawn by the seed (the default:
trial noise). Resumable: finished runs are kept in OUT/runs.

    /usr/bin/python3 scripts/live_learners.py --out live --learners annealing,random,greedy,bayes,prior

runs 500 learning runs in about 29 min on 2 cores.

`--learners` and `--scenarios` choose a part (default: annealing and prior on every scenario);
`--seeds N` runs seeds 1..N (default 10); the tables list each scenario and learner pair with
the seeds 1..k that have finished, k at least 10.
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
SEEDS = 10  # per scenario and learner, the least a table row takes
# The replay's two window orders (learning/benchmark.h): the simulation's, and trial noise.
ORDERS = ["walked", "drawn"]
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


def replay_held(r):
    """Whether a replayed run (a row of runs.csv) held within the budget."""
    return (r["held_at"] != "" and int(r["held_at"]) <= BUDGET if r["deviated"] == "1"
            else r["answer_holds"] == "1")


def replayed(bench):
    """Share of a benchmark's runs held within the budget, per (scenario, learner)."""
    shares = defaultdict(lambda: [0, 0])
    for r in csv.DictReader(open(bench / "runs.csv")):
        shares[(r["scenario"], r["learner"])][0] += replay_held(r)
        shares[(r["scenario"], r["learner"])][1] += 1
    return {k: held / runs for k, (held, runs) in shares.items()}


def replay_runs(bench):
    """A benchmark's runs by (scenario, learner, live seed): run k-1 had seed k's learner."""
    return {(r["scenario"], r["learner"], int(r["run"]) + 1): r
            for r in csv.DictReader(open(bench / "runs.csv"))}


def key(scenario, periods):
    failed = scenario.split("+")
    return scenario, tuple("x" if leg in failed else str(periods[leg]) for leg in LEGS)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="folder for the runs and the tables")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--seeds", type=int, default=SEEDS,
                        help=f"seeds 1..N of each scenario and learner (at least {SEEDS})")
    parser.add_argument("--multicpg", default=str(ROOT / "build" / "multicpg"))
    parser.add_argument("--learners", default=",".join(LEARNERS),
                        help="comma-separated, of " + ", ".join(KNOWN_LEARNERS))
    parser.add_argument("--scenarios", default=",".join(SCENARIOS),
                        help="comma-separated, of " + ", ".join(SCENARIOS))
    args = parser.parse_args()
    if args.seeds < SEEDS:
        parser.error(f"--seeds must be at least {SEEDS}, got {args.seeds}")
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
    for order in ORDERS:
        bench = out / f"benchmark-{order}"
        if not (bench / "runs.csv").exists():
            # The live runs' trial cap, and with walked windows their learners' seeds, so that
            # run k-1 of the replay retraces live seed k.
            subprocess.run([args.multicpg, "learner-benchmark", "--learners",
                            ",".join(KNOWN_LEARNERS), "--window-order", order,
                            "--max-trials", str(BUDGET), *(["--live-seeds"] if order == "walked"
                                                           else []),
                            "--out", str(bench)], check=True, stdout=subprocess.DEVNULL)
    with ThreadPoolExecutor(args.jobs) as pool:
        for f in [pool.submit(run, args.multicpg, runs_dir, s, l, k)
                  for s in scenarios for l in learners for k in range(1, args.seeds + 1)]:
            f.result()

    replay = {order: replayed(out / f"benchmark-{order}") for order in ORDERS}
    retrace = replay_runs(out / "benchmark-walked")
    holds = landscape_holds()
    lines = ["| scenario | learner | runs | first episode held within 20 | and holds in the "
             "landscape | replay, windows walked | replay, windows drawn | retraced by the walked "
             "replay | robust run converged | tunnel passed | median trials (first episode) |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    pooled = defaultdict(lambda: {"held": 0, "runs": 0, "passed": 0, "converged": 0,
                                  "retraced": 0,
                                  **{order: 0.0 for order in ORDERS}})

    def finished(s, l):  # seeds 1..k of a pair have finished
        k = 0
        while (runs_dir / f"{s}_{l}_{k + 1}.json").exists():
            k += 1
        return k

    for s in SCENARIOS:
        for l in KNOWN_LEARNERS:
            n = finished(s, l)
            if n < SEEDS:
                continue
            first_held = truth = converged = passed = retraced = 0
            trials = []
            for k in range(1, n + 1):
                d = json.loads((runs_dir / f"{s}_{l}_{k}.json").read_text())
                learning = d["learning"]
                episode = learning["episodes"][0] if learning["episodes"] else None
                # A start that never deviated answers with the all-4 start.
                periods = episode["periods"] if episode else {leg: 4 for leg in LEGS}
                held = episode is None or (episode["held"] and episode["trials"] <= BUDGET)
                first_held += held
                truth += held and ":" not in s and holds[key(s, periods)]
                # The walked replay retraces the run: the same trials, the same end.
                r = retrace.get((s, l, k))
                retraced += bool(r) and (
                    (r["deviated"] == "1") == (episode is not None)
                    and (episode is None or int(r["trials"]) == episode["trials"])
                    and replay_held(r) == (held and holds[key(s, periods)]))
                converged += learning["converged"] or learning["status"] == "no deviation"
                passed += d["passed"]
                trials.append(episode["trials"] if episode else 0)
            median = sorted(trials)[n // 2]
            predicted = [f"{100 * replay[o][(s, l)]:.0f} %" if (s, l) in replay[o] else "–"
                         for o in ORDERS]
            lines.append(f"| {s} | {l} | {n} | {first_held}/{n} | "
                         f"{f'{truth}/{n}' if ':' not in s else '– (no landscape)'} | "
                         f"{' | '.join(predicted)} | "
                         f"{f'{retraced}/{n}' if ':' not in s else '–'} | {converged}/{n} | "
                         f"{passed}/{n} | {median} |")
            if ":" not in s:
                p = pooled[l]
                p["held"] += truth
                p["runs"] += n
                p["passed"] += passed
                p["converged"] += converged
                p["retraced"] += retraced
                for o in ORDERS:
                    p[o] += replay[o][(s, l)] * n
    lines += ["", "| learner | live: held within 20, holds in the landscape | replay, windows "
              "walked | difference | replay, windows drawn | difference | retraced by the walked "
              "replay | tunnel passed | robust run converged |",
              "|---|---|---|---|---|---|---|---|---|"]
    for l in KNOWN_LEARNERS:
        if l not in pooled:
            continue
        p = pooled[l]
        n = p["runs"]
        cells = [f"{100 * p[o] / n:.0f} % | {100 * (p['held'] - p[o]) / n:+.1f} pp"
                 for o in ORDERS]
        lines.append(f"| {l} | {p['held']}/{n} ({100 * p['held'] / n:.0f} %) | "
                     f"{' | '.join(cells)} | {p['retraced']}/{n} | {p['passed']}/{n} | "
                     f"{p['converged']}/{n} |")
    (out / "live.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
