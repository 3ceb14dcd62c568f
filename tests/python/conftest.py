"""Shared fixtures of the Python module's tests: the program and the source tree, so that each
test can run the `ferrodyn` program on the same input as the module and compare the numbers."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE = pathlib.Path(os.environ.get("FERRO_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXE = os.environ.get("FERRODYN_EXE", str(SOURCE / "build" / "bin" / "ferrodyn"))
SCENES = SOURCE / "scenarios" / "scenes"


def cli(*args, cwd=None, check=True):
    """Runs `ferrodyn args...`; returns the completed process (stdout and stderr as text)."""
    p = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    if check and p.returncode != 0:
        raise AssertionError(f"ferrodyn {' '.join(map(str, args))}: exit {p.returncode}\n{p.stderr}")
    return p


def same_bits(a, b):
    """True when two float arrays hold the same doubles, bit for bit (NaN included)."""
    a, b = np.ascontiguousarray(a, dtype=np.float64), np.ascontiguousarray(b, dtype=np.float64)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.fixture
def source():
    return SOURCE


@pytest.fixture
def scenes():
    return SCENES
