"""scripts/tunnel_check.py (docs/learning.md "The default run in the tunnel"): a learner's options
reach its runs, are recorded beside them, and a resume with others is refused."""

import json
import subprocess
import sys

from conftest import EXE, SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "tunnel_check.py"
WEIGHTS = "other_size_weights=[1,0.3,0.1,0.03,0]"


def check(out, *args):
    # R1 alone: the reflex holds it, so a run is one tunnel walk of a few seconds.
    return subprocess.run([sys.executable, str(SCRIPT), "--out", str(out), "--multicpg", str(EXE),
                           "--learners", "prior", "--scenarios", "R1", "--seeds", "1", *args],
                          capture_output=True, text=True, check=False)


def test_a_learners_options_reach_its_runs_and_a_resume_keeps_them(tmp_path):
    done = check(tmp_path, "--learner-option", "prior." + WEIGHTS)
    assert done.returncode == 0, done.stderr
    run = json.loads((tmp_path / "runs" / "R1_prior_1.json").read_text())
    assert run["options"]["learner"]["options"]["other_size_weights"] == [1, 0.3, 0.1, 0.03, 0]
    assert json.loads((tmp_path / "check.json").read_text()) == {
        "robot": "", "learner_options": {"prior": [WEIGHTS]}}
    assert "| R1 | prior | 1 | 1/1 |" in (tmp_path / "tunnel-check.md").read_text()
    again = check(tmp_path, "--learner-option", "prior." + WEIGHTS)
    assert again.returncode == 0, again.stderr
    # Other options would mix runs of two settings in one table.
    other = check(tmp_path)
    assert other.returncode == 2
    assert "check.json records" in other.stderr.splitlines()[-1]


def test_a_malformed_or_foreign_learner_option_is_refused(tmp_path):
    for given, says in (("prior=1", "must be LEARNER.KEY=VALUE"),
                        ("annealing.beta=1", "not among --learners")):
        done = check(tmp_path, "--learner-option", given)
        assert done.returncode == 2, given
        assert says in done.stderr.splitlines()[-1], done.stderr
        assert not (tmp_path / "runs").exists() or not any((tmp_path / "runs").iterdir())
