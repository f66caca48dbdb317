"""The Python API: shapes, equality with the CLI, Pythonic arguments, exact continuations,
threads, errors, rendering."""

import copy
import pickle
import re
import threading

import numpy as np
import pytest

import multicpg
from conftest import SOURCE_DIR, cli_json, run_cli

STEPS = 120


def test_robots_name_their_legs_and_joints():
    for name, legs in [("hexapod", 6), ("quadruped", 4), ("octopod", 8)]:
        robot = multicpg.Robot(name)
        assert robot.name == name
        assert len(robot.legs) == legs
        assert robot.legs[0] == "R1"
        assert robot.joints == ["TC", "CTr", "FTi"]
        assert robot.joint_names[:3] == ["R1_TC", "R1_CTr", "R1_FTi"]
        assert len(robot.joint_names) == 3 * legs
    hexapod = multicpg.Robot("hexapod")
    assert hexapod.mjcf().lstrip().startswith("<mujoco")
    assert "R1_TC" in hexapod.mjcf()
    assert hexapod.default_settle_steps == 337


def test_record_has_the_documented_shapes_and_dtypes(hexapod):
    sim = multicpg.Simulation(hexapod, disable="R1")
    sim.step(STEPS)
    r = sim.record()
    rows, legs = STEPS + 1, 6
    assert r["time"].shape == (rows,) and r["time"].dtype == np.float64
    assert r["position"].shape == (rows, 3) and r["position"].dtype == np.float64
    assert r["yaw_deg"].shape == (rows,)
    for key in ("command", "target", "actual"):
        assert r[key].shape == (rows, legs, 3) and r[key].dtype == np.float64
    assert r["contact"].shape == (rows, legs) and r["contact"].dtype == np.bool_
    assert r["cpg"].shape == (rows, legs, 2) and r["cpg"].dtype == np.float64
    assert np.all(np.diff(r["time"]) > 0)
    assert r["contact"].any()
    assert sim.failed == ["R1"]
    assert sim.step_count == STEPS


def test_walk_equals_the_cli(hexapod):
    cli = cli_json("walk", "--robot", "hexapod", "--periods", "R1=5,L2=6", "--disable", "R3",
                   "--disable-at", "100", "--steps", "800", "--settle", "50", "--window", "200")
    sim = multicpg.Simulation(hexapod, periods="R1=5,L2=6", disable="R3", disable_at=100)
    sim.step(850)
    m = sim.measure(settle=50, window=200)
    assert m["distance_m"] == cli["distance_m"]
    assert m["lateral_m"] == cli["lateral_m"]
    assert m["window_deviations_deg"] == cli["window_deviations_deg"]
    assert [w["path_deg"] for w in m["windows"]] == [w["path_deg"] for w in cli["windows"]]
    assert m["final_yaw_deg"] == cli["final_yaw_deg"]


def test_state_restore_continues_identically(hexapod):
    sim = multicpg.Simulation(hexapod, faults=["R2@150"], recoveries=["R2@190"])
    sim.step(100)
    sim.set_periods([5, 4, 4, 6, 4, 4])
    sim.synchronise(False)
    saved = sim.state()
    sim.step(60)
    sim.fail("L1")
    sim.step(80)
    first = sim.record()
    sim.restore(saved)
    assert sim.step_count == 100
    sim.step(60)
    sim.fail("L1")
    sim.step(80)
    second = sim.record()
    # The restored record starts at the saved state; row 0 is taken after set_periods reset
    # the CPGs, which the first record's row 100 was not, so compare the steps walked.
    for key in first:
        np.testing.assert_array_equal(first[key][-140:], second[key][1:], err_msg=key)
    assert sim.failed == ["L1"]


def test_threads_give_what_one_after_the_other_gives(hexapod):
    def run(out, i):
        sim = multicpg.Simulation(hexapod, periods=[4, 5][i], disable=["R1", "L3"][i])
        sim.step(300)
        out[i] = sim.record()

    sequential, parallel = [None, None], [None, None]
    for i in range(2):
        run(sequential, i)
    threads = [threading.Thread(target=run, args=(parallel, i)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for i in range(2):
        for key in sequential[i]:
            np.testing.assert_array_equal(sequential[i][key], parallel[i][key])


def test_threads_sharing_one_simulation_take_turns(hexapod):
    shared = multicpg.Simulation(hexapod, disable="R2")
    threads = [threading.Thread(target=lambda: [shared.step(10) for _ in range(15)])
               for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    alone = multicpg.Simulation(hexapod, disable="R2")
    alone.step(300)
    assert shared.step_count == 300
    np.testing.assert_array_equal(shared.record()["position"], alone.record()["position"])


def test_learn_equals_the_cli_and_calls_the_observer():
    args = ("--mode", "paper", "--disable", "R1", "--seed", "5", "--max-trials", "3")
    cli = cli_json("learn", *args)
    seen = []
    py = multicpg.learn("hexapod", mode="paper", disable="R1", seed=5, max_trials=3,
                        observer=seen.append)
    arrays = py.pop("trace_arrays")
    assert py == cli
    assert [t["trial"] for t in seen] == [t["trial"] for t in cli["trace"]]
    assert [t["deviation_deg"] for t in seen] == [t["deviation_deg"] for t in cli["trace"]]
    assert arrays["periods"].shape == (len(cli["trace"]) + 1, 6)  # from trial 0
    assert arrays["deviation_deg"][0] == cli["initial_deviation_deg"]
    assert list(arrays["deviation_deg"][1:]) == [t["deviation_deg"] for t in cli["trace"]]


def test_tunnel_equals_the_cli():
    cli = cli_json("tunnel", "--disable", "R1", "--periods", "R2=5", "--max-steps", "500")
    py = multicpg.tunnel(disable="R1", periods="R2=5", max_steps=500)
    path = py.pop("path")
    assert py == cli
    assert path["x"].shape == (cli["steps"] + 1,)

    learn = ("--mode", "paper", "--max-trials", "2", "--max-steps", "500")
    cli = cli_json("tunnel", "--disable", "R1", "--learn", *learn)
    trials = []
    py = multicpg.tunnel(disable=["R1"], learn=True, mode="paper", max_trials=2, max_steps=500,
                         observer=trials.append)
    del py["path"]
    arrays = py.pop("trace_arrays")
    assert py == cli
    assert len(trials) == len(arrays["trial"]) - 1 == cli["learning"]["trials"]  # and trial 0


def test_bad_arguments_raise_value_error_naming_the_argument(hexapod):
    cases = [
        (lambda: multicpg.Robot("snake"), "snake"),
        (lambda: multicpg.Simulation(hexapod, periods=7), "periods: "),
        (lambda: multicpg.Simulation(hexapod, disable="R1,R2,R3,L1,L2,L3"), "every leg"),
        (lambda: multicpg.learn(disable="R1", mode="greedy"), "greedy"),
        (lambda: multicpg.Simulation(hexapod, faults=["R1@x"]), "faults[0]: "),
        (lambda: multicpg.Simulation(hexapod, warmup=-1), "warmup: "),
    ]
    for call, mention in cases:
        with pytest.raises(ValueError) as e:
            call()
        assert mention in str(e.value)
        assert "--" not in str(e.value), "a Python error names no CLI flag"
    sim = multicpg.Simulation(hexapod, disable="R1")
    with pytest.raises(ValueError, match="already failed"):
        sim.fail("R1")
    with pytest.raises(ValueError, match="has not failed"):
        sim.recover("R2")
    with pytest.raises(ValueError):
        sim.fail("R9")
    with pytest.raises(ValueError):
        sim.step(-1)
    with pytest.raises(ValueError):
        sim.restore(multicpg.Simulation("quadruped").state())
    with pytest.raises(ValueError):
        multicpg.Simulation(hexapod, periods=[4, 4]).step(1)
    with pytest.raises(ValueError):
        multicpg.Simulation(hexapod, record=False).record()
    with pytest.raises(ValueError):
        multicpg.Robot("hexapod", control_dt=0.037, physics_dt=0.01)


def test_a_physics_blow_up_raises_runtime_error_with_the_cli_message():
    done = run_cli("walk", "--steps", "50", "--physics-dt", "0.037", check=False)
    assert done.returncode == 1
    sim = multicpg.Simulation(multicpg.Robot("hexapod", physics_dt=0.037))
    with pytest.raises(RuntimeError) as e:
        sim.step(50)
    assert str(e.value) == done.stderr.strip().removeprefix("multicpg: ")
    assert "unstable at step" in str(e.value)


def test_an_observer_that_raises_stops_the_run_with_its_error():
    def observer(trial):
        raise KeyError("stop here")

    with pytest.raises(KeyError, match="stop here"):
        multicpg.learn(mode="paper", disable="R1", max_trials=2, observer=observer)


def test_render_and_film(hexapod, tmp_path):
    sim = multicpg.Simulation(hexapod, disable="R1")
    sim.step(5)
    image = multicpg.render(sim, 160, 120)
    assert image.shape == (120, 160, 3) and image.dtype == np.uint8
    assert image.std() > 5  # a picture, not a blank frame
    frames = multicpg.film(sim, str(tmp_path / "walk.mp4"), 6, speed=2, width=160, height=120)
    assert frames == 3
    assert (tmp_path / "walk.mp4").stat().st_size > 0
    with pytest.raises(ValueError):
        multicpg.film(sim, str(tmp_path / "walk.gif"), 2)


# A small sweep: two leg sets x a grid of two trial caps, one short paper-mode run each.
SMALL_SWEEP = {"robot": "quadruped", "scenarios": ["R1", "L2"], "runs": 1, "seed": 4,
               "learning": {"mode": "paper", "steering": "off",
                            "annealing": {"max_trials": [2, 3]}}}
SMALL_SWEEP_TOML = """robot = "quadruped"
scenarios = ["R1", "L2"]
runs = 1
seed = 4
[learning]
mode = "paper"
steering = "off"
[learning.annealing]
max_trials = [2, 3]
"""


def test_experiment_equals_multicpg_run(tmp_path):
    file = tmp_path / "small.toml"
    file.write_text(SMALL_SWEEP_TOML)
    run_cli("run", str(file), "--jobs", "1", "--out", str(tmp_path / "cli"))
    from_dict = multicpg.experiment(SMALL_SWEEP, jobs=2)
    from_file = multicpg.experiment(file, jobs=1, out=tmp_path / "py")
    assert (tmp_path / "py" / "runs.csv").read_bytes() == (tmp_path / "cli" / "runs.csv").read_bytes()
    rows = from_dict if isinstance(from_dict, list) else from_dict.to_dict("records")
    again = from_file if isinstance(from_file, list) else from_file.to_dict("records")
    assert rows == again
    assert len(rows) == 4  # 2 leg sets x 2 trial caps
    assert {r["scenario"] for r in rows} == {"R1", "L2"}
    assert all(isinstance(r["trials"], int) and r["trials"] <= 3 for r in rows)


def test_experiment_bad_values_raise_value_error_naming_the_key(tmp_path):
    bad_beta = dict(SMALL_SWEEP, learning={"annealing": {"beta": -1}})
    with pytest.raises(ValueError, match="learning.annealing.beta must be in 0..100, got -1"):
        multicpg.experiment(bad_beta)
    with pytest.raises(ValueError, match="robots"):
        multicpg.experiment(dict(SMALL_SWEEP, robots="hexapod"))
    with pytest.raises(ValueError, match="scenarios"):
        multicpg.experiment({"robot": "hexapod"})
    with pytest.raises(ValueError, match="missing.toml"):
        multicpg.experiment(tmp_path / "missing.toml")


def test_periods_as_int_dict_sequence_array_or_text_are_the_same_run(hexapod):
    expected = [5, 4, 4, 4, 6, 4]
    forms = [{"R1": 5, "L2": 6}, expected, tuple(expected), np.array(expected), "R1=5,L2=6"]
    positions = []
    for periods in forms:
        sim = multicpg.Simulation(hexapod, periods=periods, warmup=0)
        assert sim.periods == expected, periods
        sim.step(40)
        positions.append(sim.record()["position"])
    for p in positions[1:]:
        np.testing.assert_array_equal(positions[0], p)
    assert multicpg.Simulation(hexapod, periods=np.int64(5), warmup=0).periods == [5] * 6
    # set_periods: legs a dict or text does not name keep their period.
    sim = multicpg.Simulation(hexapod, periods=expected, warmup=0)
    sim.set_periods({"R2": 8})
    assert sim.periods == [5, 8, 4, 4, 6, 4]
    sim.set_periods("L3=9")
    assert sim.periods == [5, 8, 4, 4, 6, 9]
    sim.set_periods(4)
    assert sim.periods == [4] * 6


def test_faults_as_objects_or_text_give_the_same_timeline(hexapod):
    from_text = multicpg.Simulation(hexapod, faults=["R2,L1@30"], recoveries=["R2@60"], warmup=0)
    from_objects = multicpg.Simulation(hexapod, faults=[multicpg.Fault(["R2", "L1"], 30),
                                                        multicpg.Recovery(["R2"], 60)],
                                       warmup=0)
    mixed = multicpg.Simulation(hexapod, disable=("R2", "L1"), disable_at=30,
                                recoveries=multicpg.Recovery("R2", step=60), warmup=0)
    for sim in (from_text, from_objects, mixed):
        sim.step(45)
        assert sim.failed == ["R2", "L1"]
        sim.step(45)
        assert sim.failed == ["L1"]
    np.testing.assert_array_equal(from_text.record()["actual"], from_objects.record()["actual"])
    np.testing.assert_array_equal(from_text.record()["actual"], mixed.record()["actual"])


def test_faults_are_values():
    fault = multicpg.Fault(["R1", "R3"], 600)
    assert fault == multicpg.Fault("R1,R3", step=600) == multicpg.Fault(("R1", "R3"), 600)
    assert hash(fault) == hash(multicpg.Fault("R1+R3", 600))
    assert fault != multicpg.Recovery(["R1", "R3"], 600)
    assert isinstance(multicpg.Recovery("R1"), multicpg.Fault)
    assert (fault.kind, fault.legs, fault.step, fault.recover) == ("leg", ("R1", "R3"), 600, False)
    assert str(fault) == "R1,R3@600"
    assert repr(multicpg.Recovery("R1", 5)) == "multicpg.Recovery(legs=['R1'], step=5)"
    for f in (fault, multicpg.Recovery("L2", 7)):
        again = pickle.loads(pickle.dumps(f))
        assert again == f and type(again) is type(f)


def test_robots_are_equal_by_what_they_are():
    a, b = multicpg.Robot("hexapod"), multicpg.Robot("hexapod")
    assert a == b and hash(a) == hash(b) and len({a, b}) == 1
    assert a != multicpg.Robot("quadruped")
    assert a != multicpg.Robot("hexapod", control_dt=0.05)
    assert a != multicpg.Robot("hexapod", tunnel=True)
    assert pickle.loads(pickle.dumps(a)) == a
    assert copy.deepcopy(a) == a
    assert repr(multicpg.Robot("quadruped", servo_gain=20)) == \
        "multicpg.Robot('quadruped', servo_gain=20.0)"
    # A state of one restores into a simulation of the other.
    sim = multicpg.Simulation(a, warmup=0)
    sim.step(10)
    other = multicpg.Simulation(b, warmup=0)
    other.restore(sim.state())
    assert other.step_count == 10 and other.pose() == sim.pose()


def test_version_and_build_info_name_the_project_and_commit():
    text = (SOURCE_DIR / "CMakeLists.txt").read_text()
    version = re.search(r"project\(multicpg VERSION ([0-9.]+)", text).group(1)
    assert multicpg.__version__ == version
    info = multicpg.build_info()
    assert info["version"] == version
    assert re.fullmatch(r"[0-9a-f]{40}(\+dirty)?|unknown", info["git_commit"])
    assert info["mujoco_version"] == "2.2.2"


def test_every_public_name_has_a_docstring():
    names = [getattr(multicpg, n) for n in multicpg.__all__ if not n.startswith("__")]
    for obj in names + [multicpg.env.CompensationEnv, multicpg.env.AnnealingAgent,
                        multicpg.spaces.Box, multicpg.spaces.MultiDiscrete]:
        assert obj.__doc__ and obj.__doc__.strip(), obj
        for attr, member in vars(obj).items() if isinstance(obj, type) else []:
            if attr.startswith("_") or not callable(member) and not isinstance(member, property):
                continue
            assert getattr(obj, attr).__doc__, f"{obj.__name__}.{attr}"


def test_every_fault_kind_and_terrain_as_objects_equal_the_cli():
    faults = ["R2.CTr:locked@100", "L1:weak=0.3@100", "R1:short=0.5@200", "L2:slip=0.2@200",
              "R3.FTi:passive@300", "imu:drift=0.5@300", "imu:noise=1@300"]
    flags = [a for f in faults for a in ("--fault", f)]
    cli = cli_json("walk", "--steps", "800", "--settle", "0", "--window", "400",
                   "--terrain", "slope:5", "--model", "real", *flags)
    objects = [multicpg.Fault("R2", 100, kind="locked", joint="CTr"),
               multicpg.Fault(["L1"], 100, kind="weak", value=0.3),
               multicpg.Fault("R1", 200, kind="short", value=0.5),
               multicpg.Fault("L2", 200, kind="slip", value=0.2),
               multicpg.Fault("R3", 300, kind="passive", joint="FTi"),
               multicpg.Fault(step=300, kind="drift", value=0.5),
               multicpg.Fault(step=300, kind="noise", value=1)]
    assert [str(f) for f in objects] == faults
    robot = multicpg.Robot(terrain=multicpg.Terrain.slope(5), model="real")
    assert robot.terrain == multicpg.Terrain("slope:5") and robot.model == "real"
    assert robot == multicpg.Robot(terrain="slope:5", model="real")
    sim = multicpg.Simulation(robot, faults=objects)
    sim.step(800)
    m = sim.measure(settle=0, window=400)
    assert m["distance_m"] == cli["distance_m"]
    assert m["window_deviations_deg"] == cli["window_deviations_deg"]
    for f in objects + [multicpg.Recovery("R2", 5, kind="locked", joint="CTr")]:
        again = pickle.loads(pickle.dumps(f))
        assert again == f and hash(again) == hash(f) and type(again) is type(f)
    assert repr(objects[0]) == "multicpg.Fault(legs=['R2'], step=100, kind='locked', joint='CTr')"
    # A state holding every kind in force restores bit for bit (its own model, the sensor).
    state = sim.state()
    sim.step(50)
    again = multicpg.Simulation(robot)
    again.restore(pickle.loads(pickle.dumps(state)))
    again.step(50)
    np.testing.assert_array_equal(again.record()["actual"][-50:], sim.record()["actual"][-50:])


def test_fault_terrain_and_body_misuse_names_the_parameter():
    cases = [(lambda: multicpg.Fault("R1", kind="locked"), ValueError, "joint"),
             (lambda: multicpg.Fault("R1", kind="weak", value=2), ValueError, "kind"),
             (lambda: multicpg.Fault("R1", kind="noise", value=1), ValueError, "legs"),
             (lambda: multicpg.Fault("R1", kind="leg", joint="XX"), ValueError, "joint"),
             (lambda: multicpg.Fault("R1", kind="weak", value="a"), TypeError, "value"),
             (lambda: multicpg.Terrain("slope:90"), ValueError, "text"),
             (lambda: multicpg.Terrain.rough(1.0), ValueError, "height_m"),
             (lambda: multicpg.Robot(terrain=3), TypeError, "terrain"),
             (lambda: multicpg.Robot(model="marble"), ValueError, "model"),
             (lambda: multicpg.Robot(body={"slip": 5.0}), ValueError, "body['slip']"),
             (lambda: multicpg.Robot(body={"colour": 1}), ValueError, "body['colour']"),
             (lambda: multicpg.Robot(body=[1]), TypeError, "body"),
             (lambda: multicpg.Simulation(seed=-1), ValueError, "seed")]
    for make, error, name in cases:
        with pytest.raises(error) as raised:
            make()
        assert str(raised.value).startswith(name), (name, str(raised.value))


def test_a_robot_carries_its_body():
    real = multicpg.Robot(model="real", body={"slip": 0.01, "disabled_posture": (0, 1, -1)})
    assert real.body["slip"] == 0.01
    assert real.body["disabled_posture"] == {"tc": 0.0, "ctr": 1.0, "fti": -1.0}
    assert real != multicpg.Robot(model="real")
    assert pickle.loads(pickle.dumps(real)) == real
    cli = cli_json("walk", "--model", "real", "--slip", "0.01", "--disabled-posture", "0,1,-1",
                   "--disable", "R1", "--steps", "400", "--settle", "0")
    sim = multicpg.Simulation(real, disable="R1")
    sim.step(400)
    assert sim.measure(settle=0, window=400)["distance_m"] == cli["distance_m"]


def test_the_default_learner_is_the_prior_where_the_robots_dataset_is():
    """learner=None is robust mode's default (docs/learning.md "Which learner a run uses"): the
    prior on the AMOSII hexapod's leg losses, the annealing in paper mode and with a beta, as the
    CLI's; Learner() stands for such a run. One window after the trials: the learner is chosen
    before the walk."""
    run = multicpg.learn("hexapod", disable="R1,R3", max_trials=1, max_episodes=1,
                         monitor_windows=1)
    assert run["options"]["learner"]["name"] == "prior"
    assert run["learned_from"]["walked"] == "the steering reflex"
    paper = multicpg.learn("hexapod", disable="R1,R3", mode="paper", max_trials=1)
    assert "learner" not in paper["options"]
    beta = multicpg.learn("hexapod", disable="R1,R3", beta=2, max_trials=1, max_episodes=1,
                          monitor_windows=1)
    assert "learner" not in beta["options"] and beta["options"]["annealing"]["beta"] == 2
    assert multicpg.Learner(failed="R1,R3", periods=4, windows=[(-20.0, -10.0, 0.5)]).name == "prior"
    # Told nothing of the fault (the CLI's --no-tell-fault), the default is the annealing; the
    # run records it, and its learner may change a failed leg's period.
    blind = multicpg.learn("hexapod", disable="R1,R3,L2", tell_fault=False, learner="prior",
                           max_trials=2, max_episodes=1, monitor_windows=1)
    assert blind["options"]["tell_fault"] is False
    assert any(t["periods"][leg] != 4 for t in blind["trace"] for leg in ("R1", "R3", "L2"))
    assert "tell_fault" not in run["options"]
    told_nothing = multicpg.learn("hexapod", disable="R1,R3", tell_fault=False, max_trials=1,
                                  max_episodes=1, monitor_windows=1)
    assert "learner" not in told_nothing["options"]
    assert multicpg.Learner(periods=4, windows=[(-20.0, -10.0, 0.5)]).name == "annealing"
    assert multicpg.Learner(failed="R1,R3", periods=4, windows=[(-20.0, -10.0)],
                            mode="paper").name == "annealing"
