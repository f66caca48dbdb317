"""The module's surface: its namespace is its API, the environment documents its constructor,
the files its calls read must be regular files (a FIFO is refused, never waited on), and the
prior's dataset is found on the documented search path."""

import os
import pathlib
import re
import shutil

import pytest

import multicpg
from multicpg.env import CompensationEnv


def test_the_namespace_is_the_api():
    public = {name for name in dir(multicpg) if not name.startswith("_")}
    assert public == set(multicpg.__all__) - {"__version__"}
    for helper in ("Any", "Dict", "List", "Optional", "Union", "csv", "json", "os", "tempfile"):
        assert not hasattr(multicpg, helper), helper


def test_the_environment_documents_its_constructor():
    doc = CompensationEnv.__init__.__doc__
    assert doc and "disable" in doc and "render_mode" in doc


def test_a_fifo_as_the_priors_dataset_or_a_replays_run_is_refused(tmp_path):
    fifo = tmp_path / "dataset.json"
    os.mkfifo(fifo)
    # Refused before anything walks, without waiting for a writer (a hang is ctest's timeout).
    with pytest.raises(ValueError, match="is a FIFO, not a file"):
        multicpg.learn(disable="R1", mode="paper", learner="prior",
                       learner_options={"dataset": str(fifo)}, progress=False)


def test_a_replay_holds_at_most_its_documented_steps(tmp_path):
    sim = multicpg.Simulation(warmup=0, record=False)
    with pytest.raises(ValueError, match="steps"):
        multicpg.replay(sim, str(tmp_path / "x.html"), steps=10**8)
    assert list(tmp_path.iterdir()) == []


def signature_lines():
    """The first docstring line of every public function and method of the compiled module
    (pybind11's signature line, or the API's own), with its name."""
    from multicpg import _multicpg
    for name in dir(_multicpg):
        if name.startswith("_"):
            continue
        value = getattr(_multicpg, name)
        if callable(value) and not isinstance(value, type) and value.__doc__:
            yield name, value.__doc__.splitlines()[0]
        if isinstance(value, type):
            for attr, member in vars(value).items():
                if attr.startswith("__") and attr != "__init__":
                    continue
                doc = getattr(member, "__doc__", None)
                if callable(member) and doc:
                    yield f"{name}.{attr}", doc.splitlines()[0]


def test_help_types_every_parameter():
    lines = dict(signature_lines())
    assert "learn" in lines and "Simulation.step" in lines and "Simulation.__init__" in lines
    untyped = {name: line for name, line in lines.items()
               if ": object" in line or ": handle" in line}
    assert untyped == {}
    assert "disable: str | Sequence[str] | None = None" in lines["learn"]
    assert "n: int = 1" in lines["Simulation.step"]


def test_the_priors_dataset_is_looked_for_in_multicpg_data_first(tmp_path, monkeypatch):
    # docs/python.md "Datasets": a copy in $MULTICPG_DATA is the one the prior reads (damaged,
    # the run is refused naming it); a dataset no place holds names every place looked.
    source = pathlib.Path(multicpg.landscape_dataset("quadruped"))
    copy = tmp_path / "landscapes"
    copy.mkdir()
    for suffix in (".json", ".csv.gz"):
        shutil.copyfile(f"{source}{suffix}", copy / f"quadruped{suffix}")
    monkeypatch.setenv("MULTICPG_DATA", str(tmp_path))
    assert multicpg.landscape_dataset(multicpg.Robot("quadruped")) == str(copy / "quadruped")
    assert multicpg.landscape_dataset("quadruped", reflex=True) == f"{source}-reflex"
    (copy / "quadruped.json").write_text("{}")
    with pytest.raises(ValueError, match=re.escape(str(copy / "quadruped.json"))):
        multicpg.learn("quadruped", disable="L2", steering="off", learner="prior", progress=False)
    with pytest.raises(ValueError, match="no landscape dataset octopod .* in " +
                       re.escape(str(copy)) + ", .*" + re.escape(str(source.parent))):
        multicpg.landscape_dataset("octopod")
