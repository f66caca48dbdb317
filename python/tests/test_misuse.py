"""Python misuse never takes the interpreter down: the cases run one after another in two
interpreters, each of which must catch every case's expected ValueError, TypeError or
RuntimeError and go on to the next case and exit normally; the message names the parameter as
the call wrote it (never a CLI flag, never a pybind11 cast message). A case that crashes the
interpreter ends it by a signal and fails with every case it had not yet reported."""

import concurrent.futures
import json
import os
import subprocess
import sys

import pytest

# Runs its cases in turn: `setup` then `call`; prints what each raised, one JSON line per case.
# Any other exception exits 1, a crash ends the process by a signal; both fail the cases left.
WRAPPER = r"""
import json, pickle, sys
import numpy as np
import multicpg
from multicpg import *
from multicpg.env import CompensationEnv

def fnv1a64(data):
    h = 0xcbf29ce484222325
    for b in data:
        h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h

def sealed(payload):
    return payload + fnv1a64(payload).to_bytes(8, "little")

for case in json.loads(sys.argv[1]):
    scope = dict(globals())
    exec(case["setup"], scope)
    try:
        exec(case["call"], scope)
        raised = {"type": None, "message": ""}
    except (ValueError, TypeError, RuntimeError) as e:
        raised = {"type": type(e).__name__, "message": str(e)}
    print(json.dumps({"id": case["id"], **raised}), flush=True)
"""

SIM = "sim = Simulation('hexapod', warmup=0)"
WALKED = SIM + "; sim.step(3)"
STATE = "state = Simulation('hexapod', warmup=0).state()"
ANNEALER = "a = Annealer('hexapod', 4, 'R1', 20.0)"
V, T, R = "ValueError", "TypeError", "RuntimeError"

# (id, setup, call, exception, what the message must name)
CASES = [
    # Robot
    ("robot-unknown", "", "Robot('snake')", V, "name"),
    ("robot-none", "", "Robot(None)", T, "name"),
    ("robot-int", "", "Robot(5)", T, "name"),
    ("robot-nan-dt", "", "Robot('hexapod', control_dt=float('nan'))", V, "control_dt"),
    ("robot-zero-dt", "", "Robot('hexapod', control_dt=0)", V, "control_dt"),
    ("robot-physics-not-dividing", "", "Robot('hexapod', physics_dt=0.01)", V, "physics_dt"),
    ("robot-physics-text", "", "Robot('hexapod', physics_dt='fast')", T, "physics_dt"),
    ("robot-negative-gain", "", "Robot('hexapod', servo_gain=-1)", V, "servo_gain"),
    ("robot-tunnel-text", "", "Robot('hexapod', tunnel='yes')", T, "tunnel"),
    ("robot-unknown-keyword", "", "Robot('hexapod', legs=6)", T, "legs"),
    # Simulation arguments
    ("sim-robot-none", "", "Simulation(None)", T, "robot"),
    ("sim-robot-float", "", "Simulation(3.5)", T, "robot"),
    ("sim-robot-unknown", "", "Simulation('snake')", V, "robot"),
    ("periods-no-gait", "", "Simulation(periods=7)", V, "periods"),
    ("periods-none", "", "Simulation(periods=None)", T, "periods"),
    ("periods-nan", "", "Simulation(periods=float('nan'))", T, "periods"),
    ("periods-float", "", "Simulation(periods=4.0)", T, "periods"),
    ("periods-bool", "", "Simulation(periods=True)", T, "periods"),
    ("periods-two", "", "Simulation(periods=[4, 4])", V, "periods"),
    ("periods-item-none", "", "Simulation(periods=[4] * 5 + [None])", T, "periods[5]"),
    ("periods-item-no-gait", "", "Simulation(periods=[4] * 5 + [7])", V, "periods[5]"),
    ("periods-item-nan", "", "Simulation(periods=np.full(6, np.nan))", T, "periods[0]"),
    ("periods-dict-unknown-leg", "", "Simulation(periods={'X9': 5})", V, "periods"),
    ("periods-dict-text-value", "", "Simulation(periods={'R1': '5'})", T, "periods['R1']"),
    ("periods-dict-int-key", "", "Simulation(periods={1: 5})", T, "periods"),
    ("periods-text-bad", "", "Simulation(periods='R1=x')", V, "periods"),
    ("periods-set", "", "Simulation(periods={4, 5})", T, "periods"),
    ("periods-huge", "", "Simulation(periods=10**30)", V, "periods"),
    ("disable-unknown", "", "Simulation(disable='X9')", V, "disable"),
    ("disable-item-int", "", "Simulation(disable=['R1', 3])", T, "disable[1]"),
    ("disable-twice", "", "Simulation(disable=['R1', 'R1'])", V, "disable"),
    ("disable-int", "", "Simulation(disable=5)", T, "disable"),
    ("disable-every-leg", "", "Simulation(disable=['R1', 'R2', 'R3', 'L1', 'L2', 'L3'])", V,
     "disable"),
    ("disable-at-negative", "", "Simulation(disable='R1', disable_at=-1)", V, "disable_at"),
    ("disable-at-huge", "", "Simulation(disable='R1', disable_at=10**9)", V, "disable_at"),
    ("faults-bad-text", "", "Simulation(faults=['R1@x'])", V, "faults[0]"),
    ("faults-item-int", "", "Simulation(faults=[42])", T, "faults[0]"),
    ("faults-int", "", "Simulation(faults=5)", T, "faults"),
    ("recovery-unfailed", "", "Simulation(recoveries=['R1@10'])", V, "recoveries"),
    ("recovery-given-a-fault", "", "Simulation(recoveries=[Fault(['R1'], 5)])", V,
     "recoveries[0]"),
    ("fault-unknown-leg", "", "Simulation(faults=[Fault(['X9'], 0)])", V, "faults[0]"),
    ("fault-leg-of-another-robot", "", "Simulation('quadruped', faults=[Fault(['R3'], 0)])", V,
     "faults[0]"),
    ("fault-no-legs", "", "Fault([], 0)", V, "legs"),
    ("fault-negative-step", "", "Fault(['R1'], -5)", V, "step"),
    ("fault-unknown-kind", "", "Fault(['R1'], 0, kind='motor')", V, "kind"),
    ("fault-float-step", "", "Fault(['R1'], 1.5)", T, "step"),
    ("fault-legs-none", "", "Fault(None)", T, "legs"),
    ("warmup-huge", "", "Simulation(warmup=10**9)", V, "warmup"),
    ("warmup-negative", "", "Simulation(warmup=-1)", V, "warmup"),
    ("warmup-text", "", "Simulation(warmup='long')", T, "warmup"),
    ("record-text", "", "Simulation(record='yes')", T, "record"),
    ("sim-unknown-keyword", "", "Simulation(perods=4)", T, "perods"),
    # Simulation methods, and calls in the wrong order
    ("step-negative", SIM, "sim.step(-1)", V, "n"),
    ("step-billion", SIM, "sim.step(10**9)", V, "n"),
    ("step-float", SIM, "sim.step(1.5)", T, "n"),
    ("step-none", SIM, "sim.step(None)", T, "n"),
    ("step-past-the-run", WALKED, "sim.step(10**8)", V, "n"),
    ("fail-unknown", SIM, "sim.fail('R9')", V, "legs"),
    ("fail-nothing", SIM, "sim.fail([])", V, "legs"),
    ("fail-none", SIM, "sim.fail(None)", V, "legs"),
    ("fail-failed", "sim = Simulation(disable='R1', warmup=0)", "sim.fail('R1')", V, "legs"),
    ("recover-working", SIM, "sim.recover('R2')", V, "legs"),
    ("set-periods-no-gait", SIM, "sim.set_periods(7)", V, "periods"),
    ("set-periods-one", SIM, "sim.set_periods([5])", V, "periods"),
    ("synchronise-text", SIM, "sim.synchronise('yes')", T, "on"),
    ("steer-none", SIM, "sim.steer(None)", T, "on"),
    ("walk-window-zero", SIM, "sim.walk_window(0)", V, "steps"),
    ("record-without-record", "sim = Simulation(warmup=0, record=False)", "sim.record()", V,
     "record"),
    ("measure-before-step", SIM, "sim.measure()", V, "settle"),
    ("measure-settle-huge", WALKED, "sim.measure(settle=10**9)", V, "settle"),
    ("measure-window-zero", WALKED, "sim.measure(window=0)", V, "window"),
    # States
    ("restore-none", SIM, "sim.restore(None)", T, "state"),
    ("restore-quadruped", SIM, "sim.restore(Simulation('quadruped', warmup=0).state())", V,
     "state"),
    ("restore-other-time-step", SIM,
     "sim.restore(Simulation(Robot('hexapod', control_dt=0.05), warmup=0).state())", V, "state"),
    ("state-tampered-bytes", STATE + "; b = bytearray(state.to_bytes()); b[len(b) // 2] ^= 1",
     "State.from_bytes(bytes(b))", V, "data"),
    ("state-tampered-pickle",
     STATE + "; p = pickle.dumps(state); raw = state.to_bytes(); i = p.index(raw) + len(raw) // 3;"
     " p = p[:i] + bytes([p[i] ^ 0x40]) + p[i + 1:]", "pickle.loads(p)", V, "state"),
    ("state-truncated", STATE, "State.from_bytes(state.to_bytes()[:100])", V, "data"),
    ("state-foreign-bytes", "", "State.from_bytes(b'hello, world')", V, "data"),
    ("state-not-bytes", "", "State.from_bytes(5)", T, "data"),
    ("state-sealed-empty-map", "", "State.from_bytes(sealed(b'\\xa0'))", V, "data"),
    ("state-sealed-deep-nesting", "", "State.from_bytes(sealed(b'\\x81' * 200000 + b'\\x00'))",
     V, "data"),
    ("robot-pickle-forged", "", "pickle.loads(pickle.dumps(Robot('hexapod')).replace("
     "b'hexapod', b'hexapox'))", V, "Robot"),
    # Rendering and films
    ("render-huge", SIM, "render(sim, 100000, 100000)", V, "width"),
    ("render-tall", SIM, "render(sim, 640, 5000)", V, "height"),
    ("render-zero", SIM, "render(sim, 0, 10)", V, "width"),
    ("render-none", "", "render(None)", T, "sim"),
    ("render-float", SIM, "render(sim, 640.5)", T, "width"),
    ("film-gif", SIM, "film(sim, 'x.gif', 2)", V, "out"),
    ("film-speed-zero", SIM, "film(sim, 'x.mp4', 2, speed=0)", V, "speed"),
    ("film-out-none", SIM, "film(sim, None, 2)", T, "out"),
    ("film-huge", SIM, "film(sim, 'x.png', 1, width=100000)", V, "width"),
    # learn
    ("learn-robot-none", "", "learn(None, disable='R1')", T, "robot"),
    ("learn-mode", "", "learn(disable='R1', mode='greedy')", V, "mode"),
    ("learn-beta-nan", "", "learn(disable='R1', beta=float('nan'))", V, "beta"),
    ("learn-beta-negative", "", "learn(disable='R1', beta=-1)", V, "beta"),
    ("learn-seed-negative", "", "learn(disable='R1', seed=-1)", V, "seed"),
    ("learn-seed-huge", "", "learn(disable='R1', seed=2**64)", V, "seed"),
    ("learn-max-trials-zero", "", "learn(disable='R1', max_trials=0)", V, "max_trials"),
    ("learn-window-zero", "", "learn(disable='R1', window=0)", V, "window"),
    ("learn-settle-negative", "", "learn(disable='R1', settle=-1)", V, "settle"),
    ("learn-threshold-none", "", "learn(disable='R1', threshold=None)", T, "threshold"),
    ("learn-observer-int", "", "learn(disable='R1', observer=5)", T, "observer"),
    ("learn-nothing-fails", "", "learn()", V, "disable"),
    ("learn-paper-steering", "", "learn(disable='R1', mode='paper', steering='off')", V,
     "steering"),
    ("learn-hold-zero", "", "learn(disable='R1', hold_windows=0)", V, "hold_windows"),
    # every numeric option of the CLI's (learning/number_options.h), with its limits
    ("learn-episodes-zero", "", "learn(disable='R1', max_episodes=0)", V, "max_episodes"),
    ("learn-budget-zero", "", "learn(disable='R1', step_budget=0)", V, "step_budget"),
    ("learn-paper-episodes", "", "learn(disable='R1', mode='paper', max_episodes=2)", V, "mode"),
    ("learn-paper-two-faults", "", "learn(disable='R1', mode='paper', faults=['R2@500'])", V,
     "mode"),
    # mistyped keywords: named, with the nearest known one
    ("keyword-learn-mode", "", "learn(disable='R1', mdoe='paper')", T, "did you mean 'mode'"),
    ("keyword-learn-max-trial", "", "learn(disable='R1', max_trial=3)", T,
     "did you mean 'max_trials'"),
    ("keyword-simulation-disabled", "", "Simulation(disabled='R1')", T,
     "did you mean 'disable'"),
    ("keyword-tunnel-learn", "", "tunnel(lern=True)", T, "did you mean 'learn'"),
    ("keyword-robot-terrain", "", "Robot(terain='flat')", T, "did you mean 'terrain'"),
    ("keyword-env-mode", "", "CompensationEnv(mdoe='paper')", T, "did you mean 'mode'"),
    ("keyword-learn-unlike-any", "", "learn(disable='R1', colour='red')", T, "'colour'"),
    ("keyword-learn-twice", "", "learn('hexapod', robot='hexapod', disable='R1')", T, "twice"),
    ("keyword-learn-positional", "", "learn('hexapod', 'R1')", T, "positional"),
    # learners
    ("learner-unknown", "", "learn(disable='R1', learner='oracle')", V, "learner"),
    ("learner-option-unknown", "", "learn(disable='R1', learner_options={'depth': 2})", V,
     "learner_options['depth']"),
    ("learner-options-not-dict", "", "learn(disable='R1', learner_options=5)", T,
     "learner_options"),
    ("learner-options-not-data", "", "learn(disable='R1', learner_options={'x': object()})",
     T, "learner_options"),
    # tunnel
    ("tunnel-learning-argument-without-learn", "", "tunnel(beta=0.5)", V, "beta"),
    ("tunnel-steps-negative", "", "tunnel(max_steps=-1)", V, "max_steps"),
    ("tunnel-steps-zero", "", "tunnel(max_steps=0)", V, "max_steps"),
    ("tunnel-periods", "", "tunnel(periods=7)", V, "periods"),
    ("tunnel-learn-and-periods", "", "tunnel(learn=True, periods=4)", V, "periods"),
    ("tunnel-video-avi", "", "tunnel(video='x.avi')", V, "video"),
    ("tunnel-control-dt", "", "tunnel(control_dt=-1)", V, "control_dt"),
    # Annealer
    ("annealer-robot-none", "", "Annealer(None, 4, 'R1', 10.0)", T, "robot"),
    ("annealer-two-periods", "", "Annealer('hexapod', [4, 4], 'R1', 10.0)", V, "periods"),
    ("annealer-nan-periods", "", "Annealer('hexapod', [float('nan')] * 6, 'R1', 10.0)", T,
     "periods[0]"),
    ("annealer-periods-none", "", "Annealer('hexapod', None, 'R1', 10.0)", T, "periods"),
    ("annealer-e-ref-nan", "", "Annealer('hexapod', 4, 'R1', float('nan'))", V, "e_ref"),
    ("annealer-period-outside-set", "", "Annealer('hexapod', 1, 'R1', 10.0)", V, "periods"),
    ("annealer-every-leg", "", "Annealer('hexapod', 4, 'R1,R2,R3,L1,L2,L3', 10.0)", V,
     "disabled"),
    ("annealer-beta", "", "Annealer('hexapod', 4, 'R1', 10.0, beta=200)", V, "beta"),
    ("annealer-decide-first", ANNEALER, "a.decide(5.0)", V, "decide"),
    ("annealer-propose-twice", ANNEALER, "a.propose(); a.propose()", V, "propose"),
    ("annealer-decide-nan", ANNEALER, "a.propose(); a.decide(float('nan'))", V, "deviation_deg"),
    # experiment
    ("experiment-none", "", "experiment(None)", T, "file_or_dict"),
    ("experiment-jobs-zero", "", "experiment({'robot': 'hexapod', 'scenarios': ['R1']}, jobs=0)",
     V, "jobs"),
    ("experiment-nan", "", "experiment({'robot': float('nan')})", T, "file_or_dict"),
    ("experiment-missing-file", "", "experiment('missing.toml')", V, "missing.toml"),
    # measure_window
    ("measure-window-none", "", "measure_window(None, (0, 0, 0))", T, "start"),
    ("measure-window-nan", "", "measure_window((0, 0, float('nan')), (0, 0, 0))", V, "start[2]"),
    # the Gymnasium environment
    ("env-mode", "", "CompensationEnv(mode='greedy')", V, "mode"),
    ("env-learner", "", "CompensationEnv(learner='random')", V, "learner"),
    ("env-paper-hold-windows", "", "CompensationEnv(mode='paper', hold_windows=2)", V, "mode"),
    ("env-terrain", "", "CompensationEnv(terrain='lava')", V, "terrain"),
    ("sim-terrain", "", "Simulation(terrain='lava')", V, "terrain"),
    ("env-disable", "", "CompensationEnv(disable='X9')", V, "disable"),
    ("env-render-mode", "", "CompensationEnv(render_mode='human')", V, "render_mode"),
    ("env-step-before-reset", "env = CompensationEnv()", "env.step([0] * 6)", R, "reset"),
    ("env-action-out-of-space", "env = CompensationEnv()", "env.step([9] * 6)", V, "action"),
    ("env-action-floats", "env = CompensationEnv()", "env.step([0.5] * 6)", V, "action"),
    # MuJoCo's fatal error comes back as an exception
    ("mujoco-fatal-error", "", "multicpg._multicpg._test_mujoco_error('boom')", R, "MuJoCo error: boom"),
]


def run_cases(cases):
    payload = [{"id": c[0], "setup": c[1], "call": c[2]} for c in cases]
    return subprocess.run([sys.executable, "-c", WRAPPER, json.dumps(payload)],
                          capture_output=True, text=True, timeout=300)


@pytest.fixture(scope="module")
def outcomes():
    # Two interpreters at a time, each importing multicpg once and taking every other case.
    halves = [CASES[0::2], CASES[1::2]]
    with concurrent.futures.ThreadPoolExecutor(max_workers=len(halves)) as pool:
        done = list(pool.map(run_cases, halves))
    reported = {}
    for process in done:
        for line in process.stdout.splitlines():
            raised = json.loads(line)
            reported[raised.pop("id")] = raised
    return reported, done


def test_the_table_is_large_and_its_ids_unique():
    assert len(CASES) >= 60
    assert len({case[0] for case in CASES}) == len(CASES)


def test_every_interpreter_survives_its_cases(outcomes):
    _, processes = outcomes
    for p in processes:
        assert p.returncode == 0, f"exit {p.returncode}\n{p.stderr}"


@pytest.mark.parametrize("case", CASES, ids=[case[0] for case in CASES])
def test_misuse_raises_naming_the_parameter(case, outcomes):
    name, _, call, expected, mention = case
    reported, processes = outcomes
    assert name in reported, f"{call}: never reported\n" + "\n".join(
        f"exit {p.returncode}: {p.stderr}" for p in processes)
    raised = reported[name]
    assert raised["type"] == expected, f"{call}: {raised}"
    message = raised["message"]
    assert mention in message, f"{call}: {message!r} does not name {mention!r}"
    assert "--" not in message, f"{call}: {message!r} names a CLI flag"
    for pybind_text in ("Unable to cast", "incompatible function arguments",
                        "C++ type", "std::"):
        assert pybind_text not in message, f"{call}: {message!r}"


def test_after_a_mujoco_error_the_module_still_walks_and_renders():
    import multicpg
    with pytest.raises(RuntimeError, match="MuJoCo error: twice"):
        multicpg._multicpg._test_mujoco_error("twice")
    sim = multicpg.Simulation(warmup=0)
    sim.step(5)
    assert sim.step_count == 5
    image = multicpg.render(sim, 64, 48)
    assert image.shape == (48, 64, 3)
