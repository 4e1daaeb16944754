"""Fixtures of the package's tests. They test the installed package and its `stickslip`
command (python/ci.sh builds the wheel and installs it into a fresh virtual environment);
nothing here builds anything."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

#: The repository (scenario files, the example notebook).
ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def command() -> str:
    """The installed console script, from the same environment as this interpreter."""
    beside = Path(sys.executable).with_name("stickslip")
    path = str(beside) if beside.exists() else shutil.which("stickslip")
    assert path, "the stickslip console script is not installed"
    return path


def run(command: str, *args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    """The installed command with `args`, its output captured."""
    return subprocess.run(
        [command, *args], capture_output=True, text=True, cwd=cwd, check=False
    )


def cli_json(command: str, *args: str) -> object:
    """`json.loads` of what the installed command prints (exit code 0 required)."""
    done = run(command, *args)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)
