"""Python reaches a real robot through the same run description as the CLI (docs/python.md
"A real robot"): learn(hardware=...) drives `multicpg emulate` and learns what the simulation
learns (docs/hardware.md "Rehearse on the emulator")."""

import re
import subprocess
import time

import pytest

from conftest import EXE, SOURCE_DIR, cli_json

# Lock-step rehearsals wait this long for an answer: never a timeout on a busy machine.
TIMEOUT_MS = 5000
STARTUP_S = 60


@pytest.fixture
def rehearsal(tmp_path):
    """`multicpg emulate` on the Dynamixel example; yields the rehearsal file."""
    example = (SOURCE_DIR / "examples" / "hardware" / "dynamixel-hexapod.toml").read_text()
    hardware = tmp_path / "hardware.toml"
    hardware.write_text(re.sub(r"timeout_ms = \d+", f"timeout_ms = {TIMEOUT_MS}", example))
    rehearsal_file = tmp_path / "rehearsal.toml"
    emulator = subprocess.Popen(
        [str(EXE), "emulate", "--hardware", str(hardware), "--rehearsal", str(rehearsal_file),
         "--runs", "1"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + STARTUP_S
    while not rehearsal_file.exists():
        assert emulator.poll() is None, emulator.stderr.read()
        assert time.monotonic() < deadline, "the emulator did not start"
        time.sleep(0.05)
    yield rehearsal_file
    try:
        emulator.wait(timeout=STARTUP_S)
    finally:
        if emulator.poll() is None:
            emulator.kill()


def test_learn_on_the_emulator_learns_what_the_simulation_learns(rehearsal):
    import multicpg
    wire = multicpg.learn(disable="R1", mode="paper", hardware=str(rehearsal), lock_step=True,
                          progress=False)
    sim = cli_json("learn", "--mode", "paper", "--disable", "R1")
    assert wire["status"] == sim["status"]
    assert wire["periods"] == sim["periods"]
    assert [t["periods"] for t in wire["trace"]] == [t["periods"] for t in sim["trace"]]
    assert wire["hardware"]["protocol"] == "dynamixel"
    assert wire["trace_arrays"]["deviation_deg"].shape == (len(wire["trace"]) + 1,)


def test_hardware_arguments_are_checked_before_a_port_opens(tmp_path):
    import multicpg
    with pytest.raises(ValueError, match="lock_step"):
        multicpg.learn(disable="R1", lock_step=True)
    with pytest.raises(ValueError, match="hardware"):
        multicpg.learn(disable="R1", hardware=str(tmp_path / "none.toml"))
