"""Python agrees with the CLI: robot files by path, terrain and faults where the CLI takes them,
one default mode, trial 0 in the trace, the learner chosen by name with its options, disabled
legs marked x, readable reprs."""

import numpy as np

import multicpg
from multicpg.env import CompensationEnv
import json

from conftest import SOURCE_DIR, cli_json, run_cli

ROBOT_FILE = str(SOURCE_DIR / "examples" / "robots" / "hobby_hexapod.toml")


def test_robot_takes_a_robot_files_path():
    robot = multicpg.Robot(ROBOT_FILE)
    assert robot == multicpg.Robot.from_file(ROBOT_FILE)
    assert robot.file == ROBOT_FILE
    assert repr(robot) == f"multicpg.Robot('{ROBOT_FILE}')"
    sloped = multicpg.Robot(ROBOT_FILE, terrain="slope:5")
    assert sloped.terrain == multicpg.Terrain("slope:5") and sloped.file == ROBOT_FILE
    assert eval(repr(sloped), {"multicpg": multicpg}) == sloped


def test_simulation_and_env_take_terrain_and_faults():
    sim = multicpg.Simulation(terrain="slope:5", faults=["R2.CTr:locked@0"], warmup=0)
    assert sim.robot.terrain == multicpg.Terrain.slope(5)
    assert multicpg.Simulation(warmup=0).robot.terrain == multicpg.Terrain.flat()
    env = CompensationEnv(terrain="rough:0.01", faults=["imu:noise=1@0"], max_trials=1)
    assert env.robot.terrain == multicpg.Terrain("rough:0.01")
    env.reset(seed=1)
    assert env.sim.robot.terrain == multicpg.Terrain("rough:0.01")


def test_one_default_mode_robust_as_the_cli():
    env = CompensationEnv(max_trials=1)
    assert env.mode == "robust"
    assert "mode: str = 'robust'" in multicpg.learn.__doc__.splitlines()[0]


def test_learn_chooses_the_learner_as_the_cli_does():
    cli = cli_json("learn", "--mode", "paper", "--disable", "R1", "--seed", "3",
                   "--max-trials", "3", "--learner", "bayes", "--learner-option", "kappa=3",
                   "--learner-option", "acquisition=ucb")
    py = multicpg.learn(disable="R1", mode="paper", seed=3, max_trials=3, learner="bayes",
                        learner_options={"kappa": 3, "acquisition": "ucb"}, progress=False)
    assert py["options"]["learner"] == cli["options"]["learner"]
    assert py["options"]["learner"]["name"] == "bayes"
    assert py["trace"] == cli["trace"]


def test_a_model_learners_forecasts_come_as_arrays():
    # Each trial's forecast (docs/learning.md "Inside the model") as an array from trial 0, which
    # has none; the model's map after the last trial as model_arrays, best first.
    result = multicpg.learn(disable="R1", mode="paper", seed=3, max_trials=3, learner="bayes",
                            progress=False)
    arrays = result["trace_arrays"]
    for key in ("predicted_e_deg", "predicted_e_low_deg", "predicted_e_high_deg",
                "predicted_yaw_deg", "predicted_yaw_sd_deg", "predicted_path_deg",
                "predicted_hold", "predicted_keep", "may_hold", "untried"):
        assert np.isnan(arrays[key][0]), key
        assert list(arrays[key][1:]) == [t[key] for t in result["trace"]], key
    # Paper mode has no reflex: no effort forecast.
    assert np.all(np.isnan(arrays["predicted_effort_deg"]))
    assert np.all(arrays["predicted_e_low_deg"][1:] < arrays["predicted_e_deg"][1:])
    assert np.all(arrays["predicted_e_deg"][1:] < arrays["predicted_e_high_deg"][1:])
    model = result["model_arrays"]
    rows = len(model["hold"])
    assert rows == 20
    assert model["periods"].shape == (rows, 6)
    assert np.all(model["periods"][:, 0] == 4)  # R1 failed: its period never changes
    assert np.all(np.diff(model["hold"]) <= 0)
    assert model["tried"].dtype == np.bool_
    assert np.all(model["keep"] == 1.0)  # bayes has no data of holding on after a trial
    assert np.all(model["e_low_deg"] < model["e_deg"]) and np.all(model["e_deg"] < model["e_high_deg"])
    tried = {tuple(t["periods"][leg] for leg in ("R1", "R2", "R3", "L1", "L2", "L3"))
             for t in result["trace"]}
    for periods, walked in zip(model["periods"], model["tried"]):
        if tuple(periods) in tried:
            assert walked
    # The annealing has no model.
    plain = multicpg.learn(disable="R1", mode="paper", seed=3, max_trials=1, progress=False)
    assert "model_arrays" not in plain
    assert "predicted_e_deg" not in plain["trace_arrays"]


def test_trace_arrays_start_at_trial_0_as_the_cli_and_fig_8():
    result = multicpg.learn(disable="R1", mode="paper", seed=5, max_trials=3, progress=False)
    arrays = result["trace_arrays"]
    assert list(arrays["trial"]) == [0, 1, 2, 3]
    assert list(arrays["periods"][0]) == [4] * 6
    assert arrays["deviation_deg"][0] == result["initial_deviation_deg"]
    assert arrays["accepted"][0]
    assert np.isnan(arrays["acceptance_probability"][0])
    assert [t["deviation_deg"] for t in result["trace"]] == list(arrays["deviation_deg"][1:])


def test_reprs_say_what_an_object_is():
    sim = multicpg.Simulation(disable="R1", warmup=0)
    sim.step(2)
    text = repr(sim)
    assert text.startswith("<multicpg.Simulation of multicpg.Robot('hexapod') at step 2:")
    assert "R1=4x R2=4" in text  # a disabled leg marked as the CLI's trace marks it
    annealer = multicpg.Annealer("hexapod", 4, "R1", 20.0)
    assert repr(annealer).startswith("<multicpg.Annealer of multicpg.Robot('hexapod'): 0 trials")
    assert repr(CompensationEnv(max_trials=1)).startswith(
        "<multicpg.env.CompensationEnv robust mode")


def test_a_drifting_yaw_sensor_reads_the_same_from_the_cli_python_and_an_experiment_file(
        tmp_path):
    """One way to measure: every window is what the robot senses (a drifting sensor's error
    included), from the CLI, Python's Simulation and learn(), and an experiment file."""
    drift = "imu:drift=1@0"
    walked = cli_json("walk", "--disable", "R1", "--fault", drift)
    sim = multicpg.Simulation(disable="R1", faults=[drift])
    windows = [sim.walk_window(400) for _ in walked["windows"]]
    for mine, cli in zip(windows, walked["windows"]):
        assert mine["yaw_deg"] == cli["yaw_deg"]
        assert mine["path_deg"] == cli["path_deg"]
    assert sim.measure()["windows"] == walked["windows"]
    straight = multicpg.Simulation(disable="R1")
    assert straight.walk_window(400)["yaw_deg"] != windows[0]["yaw_deg"], "the drift is read"

    # An experiment file's run and the same run from the CLI and Python (bayes draws nothing, so
    # the experiment's seed of its own is no matter; one episode: the drift never lets it hold).
    experiment = tmp_path / "drift.toml"
    experiment.write_text('''robot = "hexapod"
scenarios = [{ name = "R1+R3-drift", faults = [{ step = 0, legs = ["R1", "R3"] },
                                               { step = 0, kind = "drift", value = 1.0 }] }]
runs = 1
seed = 1

[learning]
learner = { name = "bayes" }
monitor_windows = 2
max_episodes = 1

[learning.annealing]
max_trials = 3
''')
    run_cli("run", str(experiment), "--out", str(tmp_path / "out"), "--jobs", "1")
    runs = sorted((tmp_path / "out" / "runs").glob("*.json"))
    assert len(runs) == 1
    run = json.loads(runs[0].read_text())
    cli = cli_json("learn", "--disable", "R1,R3", "--fault", drift, "--learner", "bayes",
                   "--max-trials", "3", "--monitor-windows", "2", "--max-episodes", "1")
    mine = multicpg.learn(disable="R1,R3", faults=[drift], learner="bayes", max_trials=3,
                          monitor_windows=2, max_episodes=1, progress=False)
    assert cli["trace"], "the drift makes the robot learn"
    assert mine["trace"] == cli["trace"]
    assert mine["final_windows"] == cli["final_windows"]
    assert run["result"]["trace"] == cli["trace"]
    assert run["result"]["final_windows"] == cli["final_windows"]
