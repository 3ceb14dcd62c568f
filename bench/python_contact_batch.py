#!/usr/bin/env python3
"""The Python side of the contact-batch overhead figure (docs/PERFORMANCE.md): the 10^5 FaStrip
cases of bench/contact_batch.cpp (the same doubles) through ferrodyn.contact.tangential from
NumPy arrays, timed by process CPU time per batch over repeated batches (min and median). The
numbers themselves are checked bit for bit against the program's batch in tests/python.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_contact_batch.py [--repeat 7]
"""
import argparse
import statistics
import time

import numpy as np

import ferrodyn

N = 100_000


def spread(lo, hi, g):
    return lo + (hi - lo) * np.fmod(np.arange(N, dtype=np.float64) * g, 1.0)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    cases = {"a": spread(4e-3, 8e-3, 0.41421356237309503),
             "b": spread(3e-3, 7e-3, 0.7320508075688772),
             "fn": spread(4e4, 1e5, 0.2360679774997898), "mu": np.full(N, 0.3),
             "xi_x": spread(-3e-3, 3e-3, 0.6457513110645907),
             "xi_y": spread(-3e-3, 3e-3, 0.3166247903554),
             "spin": spread(-0.5, 0.5, 0.6055512754639891)}
    ferrodyn.contact.tangential("fastrip", **cases)  # warm-up
    cpu = []
    for _ in range(args.repeat):
        t0 = time.process_time()
        r = ferrodyn.contact.tangential("fastrip", **cases)
        cpu.append(time.process_time() - t0)
    print(f"fastrip, {N} cases from NumPy arrays: CPU per batch min {min(cpu) * 1e3:.1f} ms, "
          f"median {statistics.median(cpu) * 1e3:.1f} ms over {args.repeat} batches; "
          f"force_y[0:3] = {r['force_y'][:3]}")


if __name__ == "__main__":
    main()
