"""Dicts keyed by legs list them in leg order (R1 R2 R3 L1 L2 L3, the robot's), not sorted as
`--json` prints them (docs/python.md "Results")."""

import multicpg


def test_learn_lists_per_leg_periods_in_leg_order():
    legs = list(multicpg.Robot("hexapod").legs)
    assert legs == ["R1", "R2", "R3", "L1", "L2", "L3"]
    result = multicpg.learn("hexapod", mode="paper", disable="R1", seed=1, max_trials=2)
    assert list(result["periods"]) == legs
    assert result["trace"] and result["episodes"], "R1 disabled deviates: trials were made"
    for trial in result["trace"]:
        assert list(trial["periods"]) == legs
    for episode in result["episodes"]:
        assert list(episode["periods"]) == legs


def test_every_robot_lists_its_legs_in_its_order():
    for name in ("quadruped", "octopod"):
        legs = list(multicpg.Robot(name).legs)
        result = multicpg.learn(name, mode="paper", disable="R1", seed=1, max_trials=1)
        assert list(result["periods"]) == legs, name
