"""CompensationEnv, its Gymnasium spaces, and the annealing and random agents on it."""

import inspect
import os
import subprocess
import sys

import numpy as np
import pytest

import multicpg
from multicpg import spaces
from multicpg.env import HAVE_GYMNASIUM, AnnealingAgent, CompensationEnv
from conftest import SOURCE_DIR, cli_json

SEED = 5  # 8 trials to converge: kept, rejected and probabilistic decisions
MAX_TRIALS = 6  # stops the run at the trial cap
SAMPLES = 1000


def test_the_annealing_agent_gives_the_trace_of_learn_paper():
    cli = cli_json("learn", "--mode", "paper", "--disable", "R1", "--seed", str(SEED),
                   "--max-trials", str(MAX_TRIALS))
    env = CompensationEnv("hexapod", disable="R1", mode="paper", max_trials=MAX_TRIALS)
    annealer = AnnealingAgent().run(env, seed=SEED)
    legs = env.robot.legs
    assert [[t["periods"][leg] for leg in legs] for t in cli["trace"]] == \
        [t["periods"] for t in annealer.trace]
    assert [t["deviation_deg"] for t in cli["trace"]] == \
        [t["deviation_deg"] for t in annealer.trace]
    assert [t["accepted"] for t in cli["trace"]] == [t["accepted"] for t in annealer.trace]
    assert [cli["periods"][leg] for leg in legs] == annealer.accepted
    assert annealer.stop == cli["reason"] == "trial cap"


def check_observation(env, obs):
    assert isinstance(obs, np.ndarray) and obs.dtype == env.observation_space.dtype
    assert obs.shape == env.observation_space.shape
    assert env.observation_space.contains(obs), obs


def check_step(env, result):
    """Gymnasium's step rules: (obs, reward, terminated, truncated, info) of these types."""
    assert isinstance(result, tuple) and len(result) == 5
    obs, reward, terminated, truncated, info = result
    check_observation(env, obs)
    assert isinstance(reward, float) and np.isfinite(reward)
    assert isinstance(terminated, bool) and isinstance(truncated, bool)
    assert isinstance(info, dict)
    return result


def test_the_environment_follows_gymnasiums_rules():
    env = CompensationEnv("hexapod", disable="R1", mode="paper", max_trials=2)
    if HAVE_GYMNASIUM:
        import gymnasium
        assert isinstance(env, gymnasium.Env)
    assert "seed" in inspect.signature(env.reset).parameters
    assert "options" in inspect.signature(env.reset).parameters
    assert env.unwrapped is env
    assert env.metadata["render_modes"] == ["rgb_array"]
    result = env.reset(seed=0)
    assert isinstance(result, tuple) and len(result) == 2
    obs, info = result
    check_observation(env, obs)
    assert isinstance(info, dict) and info["detected"]
    assert info["deviation_deg"] > env.threshold
    assert info["working_legs"] == ["R2", "R3", "L1", "L2", "L3"]
    action = env.action_for([4, 5, 4, 4, 4, 4])
    assert env.action_space.contains(action)
    obs, reward, terminated, truncated, info = check_step(env, env.step(action))
    assert list(obs[3:]) == [4, 5, 4, 4, 4, 4]
    assert reward == -info["deviation_deg"] and reward <= 0
    assert terminated == (info["deviation_deg"] < env.threshold)
    assert not truncated
    _, _, _, truncated, _ = check_step(env, env.step(env.action_space.sample()))
    assert truncated  # max_trials
    env.close()


def test_spaces_sample_inside_themselves_and_seed_through_reset():
    env = CompensationEnv("hexapod", disable="R1,L2", mode="paper")
    space = env.action_space
    assert space.shape == (4,) and space.dtype == np.int64
    assert list(space.nvec) == [len(multicpg.env.PERIOD_SET)] * 4
    assert all(space.contains(space.sample()) for _ in range(SAMPLES))
    box = env.observation_space
    assert box.shape == (3 + 6,) and box.dtype == np.float64 and box.is_bounded()
    assert all(box.contains(box.sample()) for _ in range(SAMPLES))
    assert not space.contains(np.array([0, 0, 0, 5])) and not space.contains([0, 0, 0])
    assert not box.contains(np.zeros(9)) and box.contains(np.array([0.0, 0.0, 0.0] + [4.0] * 6))
    # reset(seed=) seeds both spaces (the reset itself walks; seed the spaces the same way).
    draws = []
    for _ in range(2):
        space.seed(11)
        box.seed(11)
        draws.append((space.sample(), box.sample()))
    np.testing.assert_array_equal(draws[0][0], draws[1][0])
    np.testing.assert_array_equal(draws[0][1], draws[1][1])


def test_the_fallback_spaces_draw_as_gymnasium_does():
    md = spaces.MultiDiscrete([5, 5, 2], seed=3)
    rng = np.random.Generator(np.random.PCG64(np.random.SeedSequence(3)))
    expected = (rng.random(3) * np.array([5, 5, 2])).astype(np.int64)
    np.testing.assert_array_equal(md.sample(), expected)
    box = spaces.Box(-1.0, 1.0, shape=(4,), dtype=np.float64, seed=3)
    rng = np.random.Generator(np.random.PCG64(np.random.SeedSequence(3)))
    np.testing.assert_array_equal(box.sample(), rng.uniform(-1.0, 1.0, size=(4,)))
    assert [0] in spaces.MultiDiscrete([1]) and [1] not in spaces.MultiDiscrete([1])
    assert spaces.Box(0, 1, (2,)) == spaces.Box(0.0, 1.0, (2,))
    assert not spaces.Box(0, 1, (2,), dtype=np.float64).contains(np.array(["a", "b"]))
    with pytest.raises(ValueError):
        spaces.MultiDiscrete([0, 2])


def run_episode(seed, steps):
    env = CompensationEnv("hexapod", disable="R1", max_trials=steps)
    obs, info = env.reset(seed=seed)
    history = [obs]
    for _ in range(steps):
        obs, reward, terminated, truncated, _ = check_step(env, env.step(env.action_space.sample()))
        history.extend([obs, reward, terminated, truncated])
        if terminated or truncated:
            break
    return history


def test_a_random_agent_gives_the_same_episode_for_the_same_seed():
    first, again = run_episode(seed=7, steps=2), run_episode(seed=7, steps=2)
    assert len(first) == len(again)
    for a, b in zip(first, again):
        np.testing.assert_array_equal(a, b)


def test_robust_mode_steers_and_judges_over_several_windows():
    env = CompensationEnv("hexapod", disable="R1", mode="robust", hold_windows=2, max_trials=2,
                          render_mode="rgb_array", render_size=(64, 48))
    assert env.action_space.shape == (6,) and env.action_space.nvec[-1] == 2
    obs, info = env.reset(seed=1)
    check_observation(env, obs)
    assert env.sim.steering
    frame = env.render()
    assert frame.shape == (48, 64, 3) and frame.dtype == np.uint8
    off = env.action_for([4, 5, 4, 4, 4, 4], steering=False)
    assert off[-1] == 0
    _, _, _, _, info = check_step(env, env.step(off))
    assert not env.sim.steering and info["steering_effort"] == 0
    _, _, _, truncated, info = check_step(env, env.step(env.action_for([4] * 6)))
    assert env.sim.steering and info["steering_effort"] > 0 and truncated


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
