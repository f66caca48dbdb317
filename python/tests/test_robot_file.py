"""Robot files from Python: Robot.from_file reads what `multicpg model --robot hexapod --out DIR`
writes; the robot walks, learns and crosses the tunnel as the built-in one, and its results
record the file as the CLI's do."""

import pickle
import shutil

import pytest

import multicpg
from conftest import cli_json, run_cli

LEARN = dict(mode="paper", disable="R1", seed=5, max_trials=3)
LEARN_FLAGS = ("--mode", "paper", "--disable", "R1", "--seed", "5", "--max-trials", "3")


@pytest.fixture(scope="module")
def robot_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("robots")
    run_cli("model", "--robot", "hexapod", "--out", str(out))
    return out


def walk(robot):
    sim = multicpg.Simulation(robot, periods="R1=5,L2=6", disable="R3", disable_at=100)
    sim.step(600)
    return sim.measure(window=200)


def test_from_file_walks_as_the_built_in_robot(robot_dir):
    path = str(robot_dir / "hexapod.toml")
    robot = multicpg.Robot.from_file(path)
    builtin = multicpg.Robot("hexapod")
    assert robot.name == "hexapod" and robot.file == path and builtin.file is None
    assert robot.legs == builtin.legs and robot.joint_names == builtin.joint_names
    assert robot != builtin
    assert repr(robot) == f"multicpg.Robot('{path}')"
    assert walk(robot) == walk(builtin)
    # A file name is a robot argument too.
    assert multicpg.Simulation(path, warmup=0).robot == robot


def test_learn_and_tunnel_equal_the_cli_and_record_the_file(robot_dir):
    path = str(robot_dir / "hexapod.toml")
    robot = multicpg.Robot.from_file(path)
    cli = cli_json("learn", "--robot", path, *LEARN_FLAGS)
    py = multicpg.learn(robot, **LEARN)
    py.pop("trace_arrays")
    assert py == cli
    record = cli["robot_file"]
    assert cli["robot"] == "hexapod"
    assert record["path"] == path and record["name"] == "hexapod"
    assert record["checksum_toml"].startswith("fnv1a64:")
    assert record["checksum_model"].startswith("fnv1a64:")
    builtin = multicpg.learn("hexapod", **LEARN)
    builtin.pop("trace_arrays")
    del py["robot_file"]
    assert py == builtin

    cli = cli_json("tunnel", "--robot", path, "--disable", "R1", "--max-steps", "400")
    py = multicpg.tunnel(robot=path, disable="R1", max_steps=400)
    py.pop("path")
    assert py == cli and py["robot_file"] == record

    cli = cli_json("tunnel", "--robot", path, "--disable", "R1", "--max-steps", "400",
                   "--scale-tunnel")
    py = multicpg.tunnel(robot=robot, disable="R1", max_steps=400, scale_tunnel=True)
    py.pop("path")
    assert py == cli and py["tunnel"]["scale"]["factor"] == 1.0


def test_the_environment_takes_a_robot_of_a_file(robot_dir):
    robot = multicpg.Robot.from_file(str(robot_dir / "hexapod.toml"))
    env = multicpg.env.CompensationEnv(robot, disable="R1", mode="paper")
    assert env.robot == robot
    assert multicpg.env.CompensationEnv(robot.file, disable="R1").robot == robot


def test_a_pickled_robot_reads_its_file_again_and_refuses_a_changed_one(robot_dir, tmp_path):
    for name in ("hexapod.toml", "hexapod.xml"):
        shutil.copy(robot_dir / name, tmp_path / name)
    robot = multicpg.Robot.from_file(str(tmp_path / "hexapod.toml"))
    data = pickle.dumps(robot)
    assert pickle.loads(data) == robot
    sim = multicpg.Simulation(robot, warmup=0)
    sim.step(10)
    other = multicpg.Simulation(robot, warmup=0)
    other.restore(pickle.loads(pickle.dumps(sim.state())))
    assert other.step_count == 10 and other.pose() == sim.pose()
    with open(tmp_path / "hexapod.toml", "a") as f:
        f.write("# edited\n")
    # One reader of the record (experiments/run_robot.h) names the field that changed.
    with pytest.raises(ValueError, match="robot_file.checksum_toml: '.*' has changed since it was"
                                         " recorded"):
        pickle.loads(data)


def test_a_bad_file_raises_value_error_with_one_line_naming_file_and_key(robot_dir, tmp_path):
    text = (robot_dir / "hexapod.toml").read_text()
    shutil.copy(robot_dir / "hexapod.xml", tmp_path / "hexapod.xml")
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace('trunk = "trunk"', 'trunk = "torso"'))
    with pytest.raises(ValueError) as e:
        multicpg.Robot.from_file(str(bad))
    assert str(e.value).startswith(f"{bad}: trunk")
    assert "\n" not in str(e.value)
    with pytest.raises(ValueError, match=r"nosuch.toml: cannot read \(No such file"):
        multicpg.Robot.from_file(str(tmp_path / "nosuch.toml"))
