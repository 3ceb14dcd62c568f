"""Runs from Python against the program's output for the same input: every signal the same to
the last bit, the HDF5 file the same, units and metadata; Ctrl-C (SIGINT) during a run raises
KeyboardInterrupt and keeps every sample computed."""
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import ferrodyn
from conftest import EXE, SOURCE, cli, same_bits

CASES = [
    ("wheelset_hunting.yaml", ["--t-end", "3", "--speed", "45"], {"t_end": 3.0, "speed": 45.0}),
    ("manchester_straight_erri.yaml", ["--t-end", "0.5"], {"t_end": 0.5}),
]


@pytest.mark.parametrize("scene,args,kwargs", CASES, ids=[c[0] for c in CASES])
def test_run_matches_the_program_bitwise(scenes, tmp_path, scene, args, kwargs):
    cli_out = tmp_path / "cli.h5"
    cli("run", scenes / scene, "-o", cli_out, "--no-plots", "-q", *args, cwd=SOURCE)
    py_out = tmp_path / "py.h5"
    os.chdir(SOURCE)  # the scenes name their table files relative to the working folder
    r = ferrodyn.run(ferrodyn.Scene(scenes / scene), output=py_out, **kwargs)
    assert r.status == "completed"
    ref = ferrodyn.read(cli_out)
    assert same_bits(r.time, ref.time)
    assert list(ref.signals) == sorted(r.names) or set(ref.signals) == set(r.names)
    for name in r.names:
        assert same_bits(r[name], ref.signals[name]), name
        assert r.units[name] == ref.units[name]
    # The file written from Python holds the same samples as the program's.
    written = ferrodyn.read(py_out)
    for name in r.names:
        assert same_bits(written.signals[name], ref.signals[name]), name
    assert written.attrs["status"] == "completed"
    assert r.metadata["integrator"] == ref.attrs["integrator"]
    assert r.samples == len(ref.time) and r.steps == ref.attrs["steps"]
    for key in ("rhs_evaluations", "jacobians", "newton_iterations", "step_splits"):
        assert getattr(r, key) == ref.attrs[key], key


def test_run_without_file_and_dataframe(scenes):
    r = ferrodyn.run(ferrodyn.Scene(scenes / "wheelset_hunting.yaml"), t_end=1.0)
    assert r.output_file is None and r.samples == 1001
    assert r.signals["wheelset.y"].base is not None  # a view of one buffer: no copy per signal
    assert "wheelset.y" in str(r)  # the run's summary, as the program prints it
    pandas = pytest.importorskip("pandas")
    frame = r.to_dataframe()
    assert isinstance(frame, pandas.DataFrame) and frame.shape == (1001, len(r.names))


INTERRUPTED = textwrap.dedent("""
    import json, os, sys
    import ferrodyn
    os.chdir(sys.argv[1])
    scene = ferrodyn.Scene("scenarios/scenes/cooperrider_tread_hunting.yaml")
    print("started", flush=True)
    try:
        ferrodyn.run(scene, output=sys.argv[2], t_end=10000.0)
        print(json.dumps({"interrupted": False}))
    except KeyboardInterrupt as e:
        r = e.result
        y = r["wheelset_1.y"]
        print(json.dumps({"interrupted": True, "status": r.status, "samples": r.samples,
                          "t_reached": r.t_reached, "len": len(y), "finite": bool((y == y).all()),
                          "last_time": float(r.time[-1])}))
""")


def test_sigint_raises_keyboardinterrupt_and_keeps_the_samples(tmp_path):
    out = tmp_path / "interrupted.h5"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    p = subprocess.Popen([sys.executable, "-c", INTERRUPTED, str(SOURCE), str(out)],
                         stdout=subprocess.PIPE, text=True, env=env)
    assert p.stdout.readline().strip() == "started"
    time.sleep(2.0)  # the run is under way (the model is built in well under a second)
    p.send_signal(signal.SIGINT)
    stdout, _ = p.communicate(timeout=60)
    import json
    result = json.loads(stdout.strip().splitlines()[-1])
    assert result["interrupted"], "the run ended before the signal"
    assert result["status"] == "interrupted"
    assert result["samples"] > 10 and result["len"] == result["samples"] and result["finite"]
    assert result["last_time"] == result["t_reached"] < 10000.0
    # The file keeps the same samples, with the status.
    f = ferrodyn.read(out)
    assert f.attrs["status"] == "interrupted"
    assert len(f.time) == result["samples"]
