"""Python agrees with the CLI: robot files by path, terrain and faults where the CLI takes them,
one default mode, trial 0 in the trace, the learner chosen by name with its options, disabled
legs marked x, readable reprs."""

import numpy as np

import multicpg
from multicpg.env import CompensationEnv
from conftest import SOURCE_DIR, cli_json

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
    assert "mode: object = 'robust'" in multicpg.learn.__doc__.splitlines()[0]


def test_learn_chooses_the_learner_as_the_cli_does():
    cli = cli_json("learn", "--mode", "paper", "--disable", "R1", "--seed", "3",
                   "--max-trials", "3", "--learner", "bayes", "--learner-option", "kappa=3",
                   "--learner-option", "acquisition=ucb")
    py = multicpg.learn(disable="R1", mode="paper", seed=3, max_trials=3, learner="bayes",
                        learner_options={"kappa": 3, "acquisition": "ucb"}, progress=False)
    assert py["options"]["learner"] == cli["options"]["learner"]
    assert py["options"]["learner"]["name"] == "bayes"
    assert py["trace"] == cli["trace"]


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
