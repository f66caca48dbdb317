"""Ask/tell (multicpg.Learner): driven by our own simulation it gives learn()'s trials for every
learner, in the default mode (episodes included) and in paper mode, and both examples of
docs/python.md run."""

import importlib.util
import subprocess
import sys

import pytest

import multicpg
from conftest import SOURCE_DIR
from multicpg._multicpg import DEFAULT_THRESHOLD_DEG, STEERING_MAX_EFFORT

EXAMPLES = SOURCE_DIR / "examples" / "python"
SEED = 5
MAX_TRIALS = 3  # enough for kept and rejected trials, cheap for five learners


def example(name):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def same_trials(agent, learned, learner):
    assert learned["trace"], learner
    assert len(agent.trace) == len(learned["trace"]), learner
    for mine, theirs in zip(agent.trace, learned["trace"]):
        assert mine["trial"] == theirs["trial"]
        assert list(mine["periods"].items()) == list(theirs["periods"].items()), learner
        assert mine["deviation_deg"] == theirs["deviation_deg"], learner
        assert mine["accepted"] == theirs["accepted"], learner
    # The learner's reason is its last episode's; the run's may be its own (the episode cap).
    assert agent.reason == learned["episodes"][-1]["reason"]
    assert agent.answer["periods"] == learned["episodes"][-1]["periods"]


@pytest.mark.parametrize("learner", multicpg.LEARNERS)
def test_ask_tell_from_a_users_loop_retraces_learns_default_mode(learner):
    # Robust mode with the reflex, as learn() runs by default: with a cap of 2 trials every
    # learner needs more than one episode on R1+R3+L2, so the loop's monitoring and the memory
    # next_episode() carries over are retraced too; two episodes at most keep it short, and the
    # windows after the last one are walked as the run walks them.
    learned = multicpg.learn("hexapod", disable="R1,R3,L2", learner=learner, seed=SEED,
                             max_trials=2, max_episodes=2, progress=False)
    agent = example("ask_tell_simulation").learn_in_my_loop(learner, "R1,R3,L2", SEED, 2,
                                                            max_episodes=2)
    same_trials(agent, learned, learner)
    assert agent.episode == len(learned["episodes"]) >= 2, learner


@pytest.mark.parametrize("learner", multicpg.LEARNERS)
def test_ask_tell_from_a_users_loop_retraces_learn_in_paper_mode(learner):
    learned = multicpg.learn("hexapod", disable="R1", mode="paper", learner=learner, seed=SEED,
                             max_trials=MAX_TRIALS, progress=False)
    agent = example("ask_tell_simulation").learn_in_my_loop(learner, "R1", SEED, MAX_TRIALS,
                                                            mode="paper")
    same_trials(agent, learned, learner)
    assert agent.done and agent.ask() is None and agent.episode == 1


def test_tell_judges_windows_as_the_run_does_and_refuses_misuse():
    agent = multicpg.Learner("random", failed="R1", periods=4, windows=[(20.0, 1.0)],
                             steering="off", seed=2)
    assert agent.working == ["R2", "R3", "L1", "L2", "L3"]
    periods = agent.ask()
    assert list(periods) == multicpg.Robot("hexapod").legs and periods["R1"] == 4
    with pytest.raises(ValueError, match="not told"):
        agent.ask()
    # Robust mode without the reflex: E is the worst of |yaw| and |path| over the windows.
    windows = [(3.0, -9.5), {"yaw_deg": 1.0, "path_deg": 2.0}]
    record = agent.tell(windows=windows)
    assert record["deviation_deg"] == 9.5 and record["trial"] == 1
    assert [multicpg.window_error(w, steering="off") for w in windows] == [9.5, 2.0]
    with pytest.raises(ValueError, match="no periods were asked"):
        agent.tell(deviation_deg=1.0)
    with pytest.raises(ValueError, match="one of them"):
        agent.tell()
    # Told nothing, every leg's period is searched, the lost one's too.
    blind = multicpg.Learner("random", periods=4, deviation_deg=20.0, steering="off")
    assert blind.working == multicpg.Robot("hexapod").legs
    with pytest.raises(ValueError, match="windows"):
        multicpg.Learner("random", failed="R1")
    with pytest.raises(ValueError, match="learner"):
        multicpg.Learner("simplex", failed="R1", deviation_deg=20.0)
    # A new episode only between a tell and the next ask; it numbers its trials from 1 again.
    agent.ask()
    with pytest.raises(ValueError, match="not told"):
        agent.next_episode(periods=4, deviation_deg=12.0)
    agent.tell(deviation_deg=30.0)
    with pytest.raises(ValueError, match="one of them"):
        agent.next_episode(periods=4)
    agent.next_episode(periods=4, deviation_deg=12.0)
    assert agent.episode == 2 and agent.ask() is not None
    assert agent.tell(deviation_deg=30.0)["trial"] == 1 and agent.trials == 3
    prior = multicpg.Learner("prior", failed="R1", deviation_deg=20.0, steering="off")
    assert prior.dataset.endswith("hexapod")


def test_the_trial_a_learner_is_told_of_sets_the_chance_its_model_gives():
    # A model's chance that a combination holds counts every window of the run's trial, and the
    # prior's chance that it holds on after it (docs/learning.md "Holding on after the trial").
    start = [(12.0, 3.0, 0.3)]
    records = {}
    for windows in (1, 3):
        agent = multicpg.Learner("prior", failed="R1,R3", windows=start, hold_windows=windows)
        agent.ask()
        records[windows] = agent.tell(windows=[(1.0, 1.0, 0.2)] * windows)
    one, three = records[1], records[3]
    assert 0.0 < three["predicted_keep"] <= 1.0
    assert one["predicted_hold"] != three["predicted_hold"]
    with pytest.raises(ValueError, match="hold_windows"):
        multicpg.Learner("prior", failed="R1", windows=start, hold_windows=0)


def test_a_prior_of_several_weights_says_how_far_the_trials_find_the_other_losses_carry():
    # docs/learning.md "Averaged by their evidence": each trial records the priors' weight of
    # the losses of another number of legs, averaged by how well each foretold the windows.
    start = [(20.0, 6.0)] * 3
    agent = multicpg.Learner("prior", options={"other_size_weights": [1, 0.3, 0.1, 0.03, 0]},
                             robot="quadruped", failed="R1", steering="off", windows=start)
    weights = []
    while len(weights) < 3 and agent.ask() is not None:
        weights.append(agent.tell(windows=[(15.0, 5.0)] * 3)["other_size_weight"])
    assert len(weights) == 3
    assert all(0.0 <= w <= 1.0 for w in weights)
    assert len(set(weights)) > 1  # each trial's windows move the average
    one = multicpg.Learner("prior", robot="quadruped", failed="R1", steering="off", windows=start)
    one.ask()
    assert one.tell(windows=[(15.0, 5.0)] * 3)["other_size_weight"] == 1.0
    with pytest.raises(ValueError, match="other_size_weight"):
        multicpg.Learner("prior", options={"other_size_weights": [1, 0], "other_size_weight": 1},
                         robot="quadruped", failed="R1", steering="off", windows=start)


def test_window_error_judges_a_window_as_the_learner_and_each_mode_do():
    # With the reflex its effort counts, read so that the most it may ask is the threshold.
    window = {"yaw_deg": -2.0, "path_deg": 3.0, "steering_effort": STEERING_MAX_EFFORT / 2}
    assert multicpg.window_error(window) == pytest.approx(DEFAULT_THRESHOLD_DEG / 2)
    assert multicpg.window_error(window, threshold=12.0) == pytest.approx(6.0)
    assert multicpg.window_error(window, steering="off") == 3.0
    assert multicpg.window_error(window, mode="paper") == 2.0
    # The learner told the same window judges it the same (the one criterion, C++'s).
    agent = multicpg.Learner("random", failed="R1", deviation_deg=20.0, seed=3)
    agent.ask()
    assert agent.tell(windows=[window])["deviation_deg"] == multicpg.window_error(window)
    with pytest.raises(ValueError, match="mode"):
        multicpg.window_error(window, mode="fast")
    with pytest.raises(ValueError, match="steering"):
        multicpg.window_error(window, steering="")
    with pytest.raises(ValueError, match="window"):
        multicpg.window_error((1.0,))


@pytest.mark.parametrize("script, args", [
    ("ask_tell_simulation.py", ["--learner", "greedy", "--max-trials", "2"]),
    ("ask_tell_function.py", ["--learner", "bayes", "--max-trials", "30"]),
])
def test_the_examples_run(script, args):
    done = subprocess.run([sys.executable, str(EXAMPLES / script), *args], capture_output=True,
                          text=True, check=False)
    assert done.returncode == 0, done.stderr
    assert "trial   1" in done.stdout, done.stdout
    assert " after " in done.stdout, done.stdout
