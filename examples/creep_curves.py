#!/usr/bin/env python3
"""Lateral creep curves of three fast tangential models against MIM (the exact rolling-contact
solution of Kalker's theory on a boundary-element grid), from the `ferrodyn` Python module.

One Hertzian contact (steel wheel on steel rail, a = 6.0 mm, b = 4.5 mm, F_n = 80 kN, mu = 0.3):
F_y / (mu F_n) against the lateral creepage xi_y for FASTSIM, FaStrip and Polach, each model
evaluated on the whole array of creepages in one call. Prints each model's largest deviation
from MIM and draws creep_curves.png.

    PYTHONPATH=build/python python3 examples/creep_curves.py [--out DIR] [--points N]
"""
import argparse
import pathlib

import numpy as np

import ferrodyn

CASE = {"a": 6.0e-3, "b": 4.5e-3, "fn": 80e3, "mu": 0.3}
MODELS = {"fastsim": {}, "fastrip": {}, "polach": {}}
REFERENCE = ("mim", {"elements": "30"})


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="folder of creep_curves.png")
    parser.add_argument("--points", type=int, default=41, help="creepages from 0 to 8e-3")
    args = parser.parse_args()
    xi_y = np.linspace(0.0, 8e-3, args.points)
    scale = -1.0 / (CASE["mu"] * CASE["fn"])  # the force on the wheel opposes the creepage
    curves = {name: scale * ferrodyn.contact.tangential(name, options=opt, xi_y=xi_y,
                                                        **CASE)["force_y"]
              for name, opt in [REFERENCE, *MODELS.items()]}
    reference = curves.pop(REFERENCE[0])
    print(f"lateral creep curve, {args.points} creepages in [0, 8e-3]; largest |F_y - F_y,MIM| "
          "/ (mu F_n):")
    for name, curve in curves.items():
        print(f"  {name:<8} {np.max(np.abs(curve - reference)):.4f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(xi_y * 1e3, reference, "k-", lw=2.5, label="MIM (30 elements)")
    for name, curve in curves.items():
        ax.plot(xi_y * 1e3, curve, "--", label=name)
    ax.set_xlabel(r"lateral creepage $\xi_y$ [$10^{-3}$]")
    ax.set_ylabel(r"$F_y / (\mu F_n)$ [-]")
    ax.set_title("a = 6.0 mm, b = 4.5 mm, F$_n$ = 80 kN, $\\mu$ = 0.3")
    ax.grid(alpha=0.3)
    ax.legend()
    out = pathlib.Path(args.out) / "creep_curves.png"
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
