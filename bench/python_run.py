#!/usr/bin/env python3
"""The Python side of the run overhead figure (docs/PERFORMANCE.md): one scene run through
ferrodyn.run from a fresh interpreter, the whole-process counterpart of
`ferrodyn run SCENE -o OUT.h5 --no-plots -q` (same scene, same HDF5 output, no plots, nothing
printed). Interpreter start-up and `import ferrodyn` (NumPy included) are part of its time.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_run.py SCENE -o OUT.h5
"""
import argparse

import ferrodyn


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("scene")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    result = ferrodyn.run(ferrodyn.Scene(args.scene), output=args.output)
    if result.status != "completed":
        raise SystemExit(f"run {result.status}")


if __name__ == "__main__":
    main()
