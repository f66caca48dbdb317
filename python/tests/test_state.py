"""Simulation states: pickled, sent to another process and restored into a simulation of an equal
robot, a run continues bit for bit; deepcopy and pickle of whole simulations; damaged states
are refused (more in test_misuse.py)."""

import copy
import pickle
import subprocess
import sys

import numpy as np
import pytest

import multicpg

BEFORE, AFTER = 250, 400

# A second interpreter: restores the pickled state into a fresh Simulation of a new Robot
# ("hexapod"), walks AFTER steps and pickles its record and final state back.
CONTINUE = r"""
import pickle, sys
import multicpg
state = pickle.load(sys.stdin.buffer)
sim = multicpg.Simulation("hexapod", warmup=0)
sim.restore(state)
sim.step(%d)
pickle.dump((sim.record(), sim.state().to_bytes(), sim.pose()), sys.stdout.buffer)
""" % AFTER


def a_busy_run():
    """A run through everything a state holds: a fault, a recovery to come, unequal periods,
    free clients, the steering reflex, contacts."""
    sim = multicpg.Simulation("hexapod", periods={"R1": 5, "L3": 6},
                              faults=[multicpg.Fault(["R2"], 100)],
                              recoveries=[multicpg.Recovery(["R2"], BEFORE + 150)])
    sim.step(BEFORE // 2)
    sim.synchronise(False)
    sim.steer(True)
    sim.fail("L1")
    sim.step(BEFORE - BEFORE // 2)
    return sim


def test_a_pickled_state_continues_bit_for_bit_in_another_process():
    sim = a_busy_run()
    state = sim.state()
    data = pickle.dumps(state)
    sim.step(AFTER)
    here = (sim.record(), sim.state().to_bytes(), sim.pose())
    done = subprocess.run([sys.executable, "-c", CONTINUE], input=data, capture_output=True,
                          check=True)
    there = pickle.loads(done.stdout)
    # The record after restore starts at the state: its rows are the last AFTER + 1 here.
    for key in here[0]:
        np.testing.assert_array_equal(here[0][key][-(AFTER + 1):], there[0][key], err_msg=key)
    assert there[2] == here[2]
    # Every saved number, MuJoCo's included, is the same after AFTER more steps.
    assert there[1] == here[1]
    assert sim.failed == ["L1"]


def test_restoring_twice_into_fresh_simulations_gives_the_same_run():
    state = a_busy_run().state()
    runs = []
    for _ in range(2):
        sim = multicpg.Simulation(multicpg.Robot("hexapod"), warmup=0)
        sim.restore(pickle.loads(pickle.dumps(state)))
        assert sim.step_count == BEFORE and sim.steering
        sim.step(60)
        runs.append(sim.state().to_bytes())
    assert runs[0] == runs[1]


def test_deepcopy_and_pickle_of_a_simulation():
    sim = a_busy_run()
    twin = copy.deepcopy(sim)
    assert twin is not sim and twin.robot == sim.robot
    np.testing.assert_array_equal(twin.record()["position"], sim.record()["position"])
    revived = pickle.loads(pickle.dumps(sim))
    assert revived.step_count == sim.step_count and revived.recording
    assert revived.record()["time"].shape == (1,)  # a pickled simulation's record restarts
    for s in (sim, twin, revived):
        s.step(80)
    assert sim.state().to_bytes() == twin.state().to_bytes() == revived.state().to_bytes()
    np.testing.assert_array_equal(twin.record()["position"], sim.record()["position"])


def test_states_are_immutable_values():
    sim = multicpg.Simulation("quadruped", warmup=0)
    sim.step(20)
    state = sim.state()
    assert copy.deepcopy(state) is state and copy.copy(state) is state
    assert state.step_count == 20 and state.robot == multicpg.Robot("quadruped")
    assert state.time == pytest.approx(sim.time)
    sim.step(20)
    sim.restore(state)
    sim.step(20)
    sim.restore(state)  # restoring does not use the state up
    assert sim.step_count == 20
    assert multicpg.State.from_bytes(state.to_bytes()).to_bytes() == state.to_bytes()
    assert "quadruped" in repr(state) and "step 20" in repr(state)


def test_a_state_of_another_robot_or_damaged_is_refused():
    hexapod = multicpg.Simulation("hexapod", warmup=0)
    with pytest.raises(ValueError, match="state: it comes from a simulation of"):
        hexapod.restore(multicpg.Simulation("octopod", warmup=0).state())
    data = bytearray(hexapod.state().to_bytes())
    for position in (0, len(data) // 2, len(data) - 1):
        damaged = bytearray(data)
        damaged[position] ^= 0x01
        with pytest.raises(ValueError, match="data: the sealed document is damaged"):
            multicpg.State.from_bytes(bytes(damaged))
