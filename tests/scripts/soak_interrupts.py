#!/usr/bin/python3
"""Soak: runs and analyses of ferrodyn stopped by SIGINT or SIGTERM at random times.

Each trial starts one job (a run or an analysis lasting longer than the longest delay), sends
SIGINT or SIGTERM after a random delay in [0, MAX_DELAY] s, and checks what the program left:

  - exit code 128 + signal (130 for SIGINT, 143 for SIGTERM);
  - the stop within STOP_LIMIT s of the signal;
  - every output file opens (h5py); a run's output says `interrupted`, and its `t_reached` and
    `samples` agree with its /time dataset (a run stopped while it prepares, before its first
    integrator step, removes its unfinished output, docs/OUTPUT.md); an analysis stopped before
    its end leaves no output;
  - no temporary output (*.part) left behind.

  soak_interrupts.py --exe build/bin/ferrodyn [--trials 200] [--seed 1] [--max-delay 3]

Prints one line per failure and a summary (counts per job and signal, stop latency
percentiles); exit status 0 when every trial passed. Run from the repository root.
"""
import argparse
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import h5py

STOP_LIMIT = 1.5  # [s]: the 0.4 s grace plus scheduling on a loaded machine

# Jobs: (name, arguments after the program, kind). Each lasts well beyond the longest delay.
JOBS = [
    ("run wheelset (paced)", ["run", "scenarios/scenes/wheelset_hunting.yaml", "--t-end", "100",
                              "--pace", "5", "--no-plots", "-q"], "run"),
    ("run wheelset (tiny steps)", ["run", "scenarios/scenes/wheelset_hunting.yaml", "--integrator",
                                   "odeint_bs3", "--fixed-step", "1e-7", "--no-plots", "-q"], "run"),
    ("run vehicle ERRI (paced)", ["run", "scenarios/scenes/manchester_straight_erri.yaml",
                                  "--pace", "2", "--no-plots", "-q"], "run"),
    ("run vehicle curve 150 m/s (tiny steps)", ["run", "scenarios/scenes/manchester_curve_1200.yaml",
                                                "--speed", "150", "--t-end", "1", "--fixed-step",
                                                "1e-9", "--no-plots", "-q"], "run"),
    ("run vehicle with CSV", ["run", "scenarios/scenes/manchester_straight_erri.yaml",
                              "--pace", "2", "--csv", "all", "--no-plots", "-q"], "run"),
    ("eig vehicle", ["eig", "scenarios/scenes/thesis_critical_speed.yaml", "--points", "2000",
                     "--no-plots"], "analysis"),
    ("critical-speed eigen", ["critical-speed", "eigen", "scenarios/scenes/thesis_critical_speed.yaml",
                              "--points", "2000", "--no-plots"], "analysis"),
]


def check_run_file(path):
    with h5py.File(path, "r") as f:
        status = f.attrs["status"]
        status = status.decode() if isinstance(status, bytes) else str(status)
        t = f["time"][:]
        samples = int(f.attrs["samples"])
        t_reached = float(f.attrs["t_reached"])
    problems = []
    if status != "interrupted":
        problems.append(f"status {status}")
    if samples != len(t):
        problems.append(f"samples {samples} but {len(t)} times")
    if len(t) and t_reached != t[-1]:
        problems.append(f"t_reached {t_reached} but last sample {t[-1]}")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--trials", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--max-delay", type=float, default=3.0)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    work = tempfile.mkdtemp(prefix="ferro_soak_")
    failures, latencies = [], []
    counts = {}
    for trial in range(a.trials):
        name, args, kind = rng.choice(JOBS)
        sig = rng.choice([signal.SIGINT, signal.SIGTERM])
        delay = rng.uniform(0.0, a.max_delay)
        folder = os.path.join(work, f"t{trial:03d}")
        os.makedirs(folder)
        out = os.path.join(folder, "out.h5")
        p = subprocess.Popen([a.exe] + args + ["-o", out], stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE)
        time.sleep(delay)
        sent = time.monotonic()
        p.send_signal(sig)
        try:
            _, err = p.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            p.kill()
            _, err = p.communicate()
        latency = time.monotonic() - sent
        latencies.append(latency)
        key = (name, signal.Signals(sig).name)
        counts[key] = counts.get(key, 0) + 1
        problems = []
        if p.returncode != 128 + sig:
            problems.append(f"exit {p.returncode}")
        if latency > STOP_LIMIT:
            problems.append(f"stopped {latency:.3f} s after the signal")
        left = [f for f in os.listdir(folder) if f.endswith(".part")]
        if left:
            problems.append(f"temporary files left: {left}")
        for f in os.listdir(folder):
            if not f.endswith((".h5",)):
                continue
            path = os.path.join(folder, f)
            try:
                if kind == "run" and f == "out.h5":
                    problems += check_run_file(path)
                else:
                    with h5py.File(path, "r"):
                        pass
                    if kind == "analysis" and f == "out.h5":
                        problems.append("an interrupted analysis left an output")
            except OSError as e:
                problems.append(f"{f} does not open: {e}")
        if problems:
            failures.append(f"trial {trial} ({name}, {signal.Signals(sig).name} after "
                            f"{delay:.3f} s): {'; '.join(problems)}; stderr: "
                            f"{err.decode(errors='replace').strip()[-300:]}")
            print(failures[-1], flush=True)
        shutil.rmtree(folder)
    shutil.rmtree(work)
    latencies.sort()
    pct = lambda q: latencies[min(len(latencies) - 1, int(q * len(latencies)))]
    print(f"soak: {a.trials} trials, {len(failures)} failed; stop latency median "
          f"{pct(0.5) * 1e3:.0f} ms, 95 % {pct(0.95) * 1e3:.0f} ms, max {latencies[-1] * 1e3:.0f} ms")
    for (name, sig), n in sorted(counts.items()):
        print(f"  {n:4d}  {name}, {sig}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
