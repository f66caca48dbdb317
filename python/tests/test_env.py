"""CompensationEnv and the annealing agent on it (issue 11)."""

import os
import subprocess
import sys

import numpy as np

from multicpg.env import AnnealingAgent, CompensationEnv
from conftest import SOURCE_DIR, cli_json

SEED = 5  # 8 trials to converge: kept, rejected and probabilistic decisions
MAX_TRIALS = 6  # stops the run at the trial cap


def test_the_annealing_agent_gives_the_trace_of_learn_paper():
    cli = cli_json("learn", "--mode", "paper", "--disable", "R1", "--seed", str(SEED),
                   "--max-trials", str(MAX_TRIALS))
    env = CompensationEnv("hexapod", disable="R1", max_trials=MAX_TRIALS)
    annealer = AnnealingAgent().run(env, seed=SEED)
    legs = env.robot.legs
    assert [[t["periods"][leg] for leg in legs] for t in cli["trace"]] == \
        [t["periods"] for t in annealer.trace]
    assert [t["deviation_deg"] for t in cli["trace"]] == \
        [t["deviation_deg"] for t in annealer.trace]
    assert [t["accepted"] for t in cli["trace"]] == [t["accepted"] for t in annealer.trace]
    assert [cli["periods"][leg] for leg in legs] == annealer.accepted
    assert annealer.stop == cli["reason"] == "trial cap"


def test_env_steps_are_gymnasium_shaped():
    env = CompensationEnv("hexapod", disable="R1", max_trials=1)
    obs, info = env.reset(seed=0)
    assert obs.shape == (2 + 6,) and obs.dtype == np.float64
    assert info["detected"] and info["deviation_deg"] > env.threshold
    assert info["working_legs"] == ["R2", "R3", "L1", "L2", "L3"]
    obs, reward, terminated, truncated, info = env.step([5, 4, 4, 4, 4])
    assert list(obs[2:]) == [4, 5, 4, 4, 4, 4]
    assert reward == -info["deviation_deg"] and reward <= 0
    assert terminated == (info["deviation_deg"] < env.threshold)
    assert truncated


def test_the_example_learns_r1_and_draws_non_blank_pngs(tmp_path):
    import matplotlib.image
    script = SOURCE_DIR / "examples" / "python" / "learn_r1.py"
    env = dict(os.environ, MPLBACKEND="Agg")
    subprocess.run([sys.executable, str(script), "--out", str(tmp_path),
                    "--max-trials", "3", "--steps", "800"],
                   check=True, env=env, capture_output=True)
    for name in ("trunk_path.png", "deviation.png"):
        image = matplotlib.image.imread(tmp_path / name)
        assert image.shape[0] > 100 and image.std() > 0.01, name
