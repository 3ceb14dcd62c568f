#!/usr/bin/env python3
"""The Python side of the run overhead figure (docs/PERFORMANCE.md): one scene run through
ferrodyn.run from a fresh interpreter, the whole-process counterpart of
`ferrodyn run SCENE -o OUT.h5 --no-plots -q --overwrite` (same scene, same HDF5 output, no
plots, nothing printed). Interpreter start-up and `import ferrodyn` (NumPy included) are part of
its time.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_run.py SCENE -o OUT.h5 [--cpu]
"""
import argparse
import time

import numpy  # noqa: F401  (imported by the first result array anyway; here outside --cpu's timer)

import ferrodyn


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("scene")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--cpu", action="store_true",
                        help="print the CPU time of the ferrodyn.run call alone [s] (NumPy imported)")
    args = parser.parse_args()
    scene = ferrodyn.Scene(args.scene)
    t0 = time.process_time()
    result = ferrodyn.run(scene, output=args.output, overwrite=True)  # each repetition anew
    if args.cpu:
        print(f"ferrodyn.run CPU {time.process_time() - t0:.3f} s")
    if result.status != "completed":
        raise SystemExit(f"run {result.status}")


if __name__ == "__main__":
    main()
