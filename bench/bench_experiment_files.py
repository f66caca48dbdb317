#!/usr/bin/python3
"""Time and peak memory of `multicpg run FILE --check` on the largest experiment files it accepts
and on the giants it refuses (README "Experiment files", docs/benchmarks.md).

    bench/bench_experiment_files.py build/multicpg [--repeat 3] [--max-runs-too]

Each file is generated in a scratch folder; each run is timed (wall clock) and its peak resident
memory read from wait4 (ru_maxrss). Prints a Markdown table: the median time and the largest peak
of the repetitions. --max-runs-too adds a sweep of 10^6 runs accepted with --max-runs 1000000
(about 9 GB of memory).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

DEPTH = 200_000


def listed(n, value):
    return "[" + ",".join([value] * n) + "]"


def quick_padded_to_1_mib(source):
    text = open(os.path.join(source, "examples", "quick.toml")).read() + "#"
    return text + "x" * ((1 << 20) - len(text) - 1) + "\n"


def cases(source):
    a = ".".join(["a"] * DEPTH)
    ok = 'scenarios = ["R1"]\n'
    grid = "[learning.annealing]\nbeta = " + listed(10_000, "0.5") + "\n"
    return [
        # (what, file text, extra flags, accepted)
        ("largest accepted: 10^5 runs (10,000 betas x 10 runs), 1 MiB with padding",
         (ok + "runs = 10\n" + grid + "#").ljust((1 << 20) - 1, "x") + "\n", [], True),
        ("10^5 runs: 24 scenarios x 4,166 runs", 'scenarios = "all"\nruns = 4166\n', [], True),
        ("quick.toml padded to 1 MiB", quick_padded_to_1_mib(source), [], True),
        ("refused: 2*10^9-run grid", ok + "runs = 2000\n[learning.annealing]\nbeta = "
         + listed(1000, "0.5") + "\nthreshold_deg = " + listed(1000, "5") + "\n", [], False),
        ("refused: 2.4*10^22-run grid (past 64 bits)",
         'scenarios = "all"\nruns = 100000\n' + "[learning.annealing]\nbeta = "
         + listed(10_000, "1") + "\nthreshold_deg = " + listed(10_000, "5") + "\nmax_trials = "
         + listed(10_000, "20") + "\n[learning]\nwindow_steps = " + listed(10_000, "400") + "\n",
         [], False),
        ("refused: 200,000-deep tables", ok + "[" + a + "]\n", [], False),
        ("refused: 200,000-deep dotted key", ok + a + " = 1\n", [], False),
        ("refused: 200,000-deep lists", ok + "x = " + "[" * DEPTH + "]" * DEPTH + "\n", [], False),
        ("refused: 200,000-deep inline tables",
         ok + "x = " + "{a=" * DEPTH + "1" + "}" * DEPTH + "\n", [], False),
        ("refused: 500,000-value list (1 MiB)",
         ok + "[learning.annealing]\nbeta = " + listed(500_000, "0") + "\n", [], False),
        ("refused: 5,000,000-value list (10 MB)",
         ok + "[learning.annealing]\nbeta = " + listed(5_000_000, "0") + "\n", [], False),
    ]


def measure(argv):
    start = time.monotonic()
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = proc.stderr.read().decode(errors="replace").strip()
    _, status, usage = os.wait4(proc.pid, 0)
    elapsed = time.monotonic() - start
    proc.stderr.close()
    return os.waitstatus_to_exitcode(status), elapsed, usage.ru_maxrss, err


class Measurer:
    """Runs the measured processes from a helper forked before anything large is made: a child's
    peak memory (ru_maxrss) counts what it shared with its parent before exec, so they must come
    from a small parent (this one's own size, about 10 MB, is the floor of what it reports)."""

    def __init__(self):
        to_helper_r, self.to_helper = os.pipe()
        self.from_helper, from_helper_w = os.pipe()
        self.pid = os.fork()
        if self.pid == 0:
            os.close(self.to_helper)
            os.close(self.from_helper)
            with os.fdopen(to_helper_r) as requests, os.fdopen(from_helper_w, "w") as answers:
                for line in requests:
                    answers.write(json.dumps(measure(json.loads(line))) + "\n")
                    answers.flush()
            os._exit(0)
        os.close(to_helper_r)
        os.close(from_helper_w)
        self.requests = os.fdopen(self.to_helper, "w")
        self.answers = os.fdopen(self.from_helper)

    def __call__(self, argv):
        self.requests.write(json.dumps(argv) + "\n")
        self.requests.flush()
        return json.loads(self.answers.readline())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("multicpg")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--max-runs-too", action="store_true")
    args = parser.parse_args()
    run = Measurer()
    source = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    todo = cases(source)
    if args.max_runs_too:
        todo.append(("largest accepted with --max-runs 1000000: 10^6 runs (10,000 betas x 100)",
                     'scenarios = ["R1"]\nruns = 100\n[learning.annealing]\nbeta = '
                     + listed(10_000, "0.5") + "\n", ["--max-runs", "1000000"], True))
    print("| file | bytes | exit | time | peak memory |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as scratch:
        for i, (what, text, extra, accepted) in enumerate(todo):
            path = os.path.join(scratch, f"case{i}.toml")
            with open(path, "w") as f:
                f.write(text)
            runs = [run([args.multicpg, "run", path, "--check"] + extra)
                    for _ in range(args.repeat)]
            codes = {r[0] for r in runs}
            if codes != {0 if accepted else 2}:
                sys.exit(f"{what}: exit {codes}: {runs[0][3]}")
            seconds = statistics.median(r[1] for r in runs)
            peak_mb = max(r[2] for r in runs) / 1024
            print(f"| {what} | {os.path.getsize(path)} | {runs[0][0]} | {seconds:.2f} s "
                  f"| {peak_mb:.0f} MB |")


if __name__ == "__main__":
    main()
