"""Long calls can be stopped and watched: Ctrl-C (SIGINT) raises KeyboardInterrupt out of learn(),
Simulation.step() and experiment() while they walk, and the objects walk on afterwards; a progress bar shows in
a run's stderr, none with progress=False, and a callable gets the reports instead."""

import os
import signal
import subprocess
import sys
import time

import multicpg

# Prints "ready CALL" before each long call (each far longer than the test waits), then what ended it.
INTERRUPTED = r"""
import sys, time
import multicpg
robot = multicpg.Robot("hexapod")
print("ready learn", flush=True)
try:
    multicpg.learn(robot, disable="R1", mode="paper", threshold=0.001, max_trials=100000,
                   progress=False)
    print("learn finished", flush=True)
except KeyboardInterrupt:
    print("interrupted learn", flush=True)
sim = multicpg.Simulation(robot, warmup=0, record=False)
print("ready step", flush=True)
try:
    sim.step(50_000_000, progress=False)
    print("step finished", flush=True)
except KeyboardInterrupt:
    print("interrupted step", flush=True)
endless = {"robot": "hexapod", "scenarios": ["R1"], "runs": 2,
           "learning": {"mode": "paper", "steering": "off",
                        "annealing": {"threshold_deg": 0.001, "max_trials": 100000}}}
print("ready experiment", flush=True)
try:
    multicpg.experiment(endless, jobs=1)
    print("experiment finished", flush=True)
except KeyboardInterrupt:
    print("interrupted experiment", flush=True)
before = sim.step_count
sim.step(10, progress=False)
print("stepped on", sim.step_count - before, flush=True)
small = {"robot": "quadruped", "scenarios": ["R1"], "runs": 1, "seed": 4,
         "learning": {"mode": "paper", "steering": "off", "annealing": {"max_trials": 2}}}
print("experiment rows", len(multicpg.experiment(small, jobs=1)), flush=True)
"""


def test_ctrl_c_stops_learn_and_step_and_the_simulation_steps_on():
    process = subprocess.Popen([sys.executable, "-c", INTERRUPTED], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True, env=os.environ.copy())
    try:
        for call in ("learn", "step", "experiment"):
            assert process.stdout.readline().strip() == f"ready {call}"
            time.sleep(1.0)  # well inside the call
            process.send_signal(signal.SIGINT)
            # Each call runs far longer than the test (its "finished" line would fail it); a
            # hang is caught by ctest's timeout: no time is asserted.
            line = process.stdout.readline().strip()
            assert line == f"interrupted {call}", process.stderr.read()
        assert process.stdout.readline().strip() == "stepped on 10"
        # The stop asked of the experiment is forgotten once it has stopped.
        assert process.stdout.readline().strip() == "experiment rows 1"
        assert process.wait(timeout=60) == 0
    finally:
        process.kill()
        process.wait()


STEPS = r"""
import sys, multicpg
sim = multicpg.Simulation(warmup=0, record=False)
sim.step(int(sys.argv[1]), progress=sys.argv[2] == "bar")
print(sim.step_count)
"""


def walk(progress, steps):
    return subprocess.run([sys.executable, "-c", STEPS, str(steps), progress],
                          capture_output=True, text=True, check=True)


def steps_for(seconds):
    """Steps this machine walks in about `seconds`."""
    sim = multicpg.Simulation(warmup=0, record=False)
    started = time.monotonic()
    sim.step(200, progress=False)
    per_step = (time.monotonic() - started) / 200
    return int(seconds / per_step) + 1


def test_a_progress_bar_shows_on_stderr_and_none_with_progress_false():
    steps = steps_for(2.0)  # past the half second after which a bar appears
    bar = walk("bar", steps)
    assert bar.stdout.strip() == str(steps)
    assert "step" in bar.stderr and "|" in bar.stderr, bar.stderr
    quiet = walk("none", steps)
    assert quiet.stdout.strip() == str(steps) and quiet.stderr == ""


def test_a_progress_callable_gets_the_reports():
    reports = []
    sim = multicpg.Simulation(warmup=0, record=False)
    sim.step(steps_for(0.5), progress=reports.append)
    assert reports and reports[-1]["finished"] and reports[-1]["stage"] == "step"
    assert reports[-1]["steps"] == reports[-1]["total"] == sim.step_count
    assert [r["steps"] for r in reports] == sorted(r["steps"] for r in reports)
    learned = []
    multicpg.learn(disable="R1", mode="paper", seed=5, max_trials=3, progress=learned.append)
    assert learned[-1]["finished"] and learned[-1]["stage"] == "learn"
    assert learned[-1]["trials"] == 3 and learned[-1]["total"] is None


# A replay far longer than the test waits (docs/replay.md: at most 1000000 steps).
REPLAY_INTERRUPTED = r"""
import os, sys
import multicpg
sim = multicpg.Simulation(warmup=0, record=False)
page = os.path.join(sys.argv[1], "x.html")
print("ready replay", flush=True)
try:
    multicpg.replay(sim, page, steps=1_000_000)
    print("replay finished", flush=True)
except KeyboardInterrupt:
    print("interrupted replay", "page written" if os.path.exists(page) else "no page", flush=True)
"""


def test_ctrl_c_stops_a_replay_and_writes_no_page(tmp_path):
    process = subprocess.Popen([sys.executable, "-c", REPLAY_INTERRUPTED, str(tmp_path)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env=os.environ.copy())
    try:
        assert process.stdout.readline().strip() == "ready replay", process.stderr.read()
        time.sleep(1.0)  # well inside the call
        process.send_signal(signal.SIGINT)
        # A hang is caught by ctest's timeout: no time is asserted.
        assert process.stdout.readline().strip() == "interrupted replay no page", \
            process.stderr.read()
        assert process.wait(timeout=60) == 0
        assert list(tmp_path.iterdir()) == []  # not even a temporary file
    finally:
        process.kill()
        process.wait()
