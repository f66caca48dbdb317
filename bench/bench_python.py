#!/usr/bin/env python3
"""The Python API's cost against the CLI (docs/benchmarks.md "Python").

1. One 400-step hexapod trial (cold controller): CPU time of Simulation.step(400) in this
   process, against the CLI's `walk --cold --steps 400` minus `walk --cold --steps 1` (the same
   run less the CLI's fixed cost: start, model compile), both as CPU time, alternated, medians.
2. 1, 2 and 4 Python threads each walking their own Simulation against the same walks one after
   the other: wall-time speed-up (step() releases the GIL), and the process's CPU time over wall
   time while the threads ran (n = n threads always had a core).
3. A state: Simulation.state(), pickle.dumps, pickle.loads and restore() (microseconds, medians).

    PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py [--exe build/multicpg]
"""

import argparse
import pickle
import resource
import statistics
import subprocess
import threading
import time

import multicpg

TRIAL_STEPS = 400


def child_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def cli_cpu(exe, steps):
    before = child_cpu()
    subprocess.run([exe, "walk", "--cold", "--steps", str(steps), "--json"], check=True,
                   capture_output=True)
    return child_cpu() - before


def python_cpu(robot, record):
    sim = multicpg.Simulation(robot, warmup=0, record=record)
    start = time.process_time()
    sim.step(TRIAL_STEPS)
    return time.process_time() - start


def walk(robot, trials):
    for _ in range(trials):
        multicpg.Simulation(robot, warmup=0, record=False).step(TRIAL_STEPS)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default="build/multicpg")
    parser.add_argument("--repetitions", type=int, default=7)
    parser.add_argument("--trials", type=int, default=4, help="trials per thread")
    args = parser.parse_args()
    robot = multicpg.Robot("hexapod")

    cli, py_bare, py_record = [], [], []
    for _ in range(args.repetitions):
        cli.append(cli_cpu(args.exe, TRIAL_STEPS) - cli_cpu(args.exe, 1))
        py_bare.append(python_cpu(robot, record=False))
        py_record.append(python_cpu(robot, record=True))
    m_cli = statistics.median(cli)
    for name, values in (("CLI walk (400 - 1 steps)", cli), ("Python step(400), record=False",
                                                              py_bare),
                         ("Python step(400), record=True", py_record)):
        m = statistics.median(values)
        print(f"{name:34s} median {1000 * m:7.1f} ms CPU  (min {1000 * min(values):.1f}, "
              f"max {1000 * max(values):.1f})  {100 * (m / m_cli - 1):+.1f} % vs CLI")

    threads_speed_up(robot, args)
    gil_check(robot)
    state_costs(robot, args.repetitions)


def threads_speed_up(robot, args):
    """n threads, each `trials` trials of its own Simulation, against the same one after the
    other."""
    for n in (1, 2, 4):
        sequential, parallel, concurrency = [], [], []
        for _ in range(args.repetitions):
            start = time.perf_counter()
            walk(robot, n * args.trials)
            sequential.append(time.perf_counter() - start)
            threads = [threading.Thread(target=walk, args=(robot, args.trials)) for _ in range(n)]
            start, cpu = time.perf_counter(), time.process_time()
            for t in threads:
                t.start()
            for t in threads:
                t.join()
            parallel.append(time.perf_counter() - start)
            concurrency.append((time.process_time() - cpu) / parallel[-1])
        s, p = statistics.median(sequential), statistics.median(parallel)
        print(f"{n} thread(s) x {args.trials} trials: one after the other {s:.2f} s, in threads "
              f"{p:.2f} s wall (medians): speed-up {s / p:.2f}; process CPU / wall "
              f"{statistics.median(concurrency):.2f}")


def state_costs(robot, repetitions):
    """Microseconds to take a state, pickle it, unpickle it and restore it (hexapod, 400
    steps in, record=False)."""
    sim = multicpg.Simulation(robot, record=False)
    sim.step(TRIAL_STEPS)
    other = multicpg.Simulation(robot, warmup=0, record=False)
    runs = 50 * repetitions
    costs = {"state()": [], "pickle.dumps": [], "pickle.loads": [], "restore()": []}
    for _ in range(runs):
        t0 = time.perf_counter()
        state = sim.state()
        t1 = time.perf_counter()
        data = pickle.dumps(state)
        t2 = time.perf_counter()
        again = pickle.loads(data)
        t3 = time.perf_counter()
        other.restore(again)
        t4 = time.perf_counter()
        for key, dt in zip(costs, (t1 - t0, t2 - t1, t3 - t2, t4 - t3)):
            costs[key].append(dt)
    print(f"a pickled hexapod state is {len(data)} bytes; medians of {runs}: " + ", ".join(
        f"{key} {1e6 * statistics.median(v):.0f} us" for key, v in costs.items()))


def count_while(busy):
    """Iterations of a pure-Python loop that a second thread makes while `busy` runs."""
    done = threading.Event()
    count = [0]

    def counter():
        while not done.is_set():
            count[0] += 1

    thread = threading.Thread(target=counter)
    thread.start()
    busy()
    done.set()
    thread.join()
    return count[0]


def gil_check(robot):
    sim = multicpg.Simulation(robot, warmup=0, record=False)
    released = count_while(lambda: sim.step(TRIAL_STEPS))
    held = count_while(lambda: time.sleep(0))
    print(f"a Python thread counted {released} loop iterations during one step(400) "
          f"(GIL released: it runs; {held} during a call that returns at once)")


if __name__ == "__main__":
    main()
