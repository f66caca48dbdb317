"""The README's commands print what the README shows: each command as the README writes it, run
from a scratch folder, against the output block the README gives for it (its data paths written
as <repository>)."""

import re
import subprocess
import sys

import pytest

from conftest import EXE, SOURCE_DIR

README = (SOURCE_DIR / "README.md").read_text()
OUTPUTS = re.findall(r"```text\n(.*?)```", README, re.S)

# The README's commands, as it writes them, and the first line of the output block it shows
# for them (two commands: both outputs, a blank line between).
CASES = [
    (["build/multicpg learn --robot hexapod --disable R1,R3,L2"],
     "hexapod, robust mode (steering reflex, 3 windows to hold), faults R1+R3+L2 fail@0"),
    (["build/multicpg walk --disable R1"], "hexapod: 1200 steps measured"),
    (["build/multicpg learn --mode paper --disable R1 --plot r1.png"],
     "hexapod, paper mode, faults R1 fail@0"),
    (["build/multicpg learn --mode paper --disable R1,R3,L2 --learner prior"],
     "hexapod, paper mode, faults R1+R3+L2 fail@0"),
    (["build/multicpg tunnel --disable R1 --plot tunnel.png",
      "build/multicpg tunnel --disable R1 --learn --plot tunnel.png"],
     "hexapod, tunnel 3.00 m x 1.20 m, disabled R1"),
]


def shown(first_line):
    blocks = [b for b in OUTPUTS if b.startswith(first_line)]
    assert len(blocks) == 1, f"the README shows {len(blocks)} outputs starting {first_line!r}"
    return blocks[0]


@pytest.mark.parametrize("commands,first_line", CASES, ids=[c[0][15:] for c, _ in CASES])
def test_each_command_prints_what_the_readme_shows(commands, first_line, tmp_path):
    outputs = []
    for command in commands:
        assert command in README, f"the README no longer runs {command!r}"
        args = command.split()[1:]
        done = subprocess.run([str(EXE), *args], capture_output=True, text=True, cwd=tmp_path,
                              check=False)
        assert done.returncode == 0, f"{command}: {done.stderr}"
        outputs.append(done.stdout.replace(str(SOURCE_DIR), "<repository>"))
    assert "\n".join(outputs) == shown(first_line)


def test_the_python_example_prints_what_the_readme_shows(tmp_path):
    m = re.search(r"PYTHONPATH=build/python /usr/bin/python3 -c '(.*?)'\n```\n+```text\n(.*?)```",
                  README, re.S)
    assert m, "the README's Python example and its output"
    done = subprocess.run([sys.executable, "-c", m.group(1)], capture_output=True, text=True,
                          cwd=tmp_path, check=True)
    assert done.stdout == m.group(2)
