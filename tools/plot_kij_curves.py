#!/usr/bin/env python3
"""Pictures for `ferrodyn fe-kij`: creep curves and their derivative curves A_x, A_y
(Toumi 2016 eqs. 146-147) per configuration, modified compliance against the half-space on the
same grid (matplotlib, Agg backend).

  plot_kij_curves.py DIR        reads DIR/curves_NNNNN.csv, writes DIR/curves_NNNNN.png

Exit codes: 0 ok, 2 bad input, 3 matplotlib missing.
"""
import csv
import glob
import math
import os
import sys


def load(path):
    with open(path, newline="") as f:
        title = f.readline().lstrip("# ").strip()
        rows = list(csv.DictReader(f))
    return title, rows


def col(rows, key, scale=1.0):
    out = []
    for r in rows:
        v = float(r[key])
        out.append(v * scale if math.isfinite(v) else float("nan"))
    return out


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        print(__doc__, file=sys.stderr)
        return 2
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("plot_kij_curves.py: matplotlib missing (apt-get install python3-matplotlib)",
              file=sys.stderr)
        return 3
    files = sorted(glob.glob(os.path.join(sys.argv[1], "curves_*.csv")))
    if not files:
        print("plot_kij_curves.py: no curves_*.csv in " + sys.argv[1], file=sys.stderr)
        return 2
    for path in files:
        title, rows = load(path)
        xi = col(rows, "creepage", 1e3)
        fig, ax = plt.subplots(2, 2, figsize=(9, 6.5), sharex=True)
        for j, d in enumerate("xy"):
            ax[0][j].plot(xi, col(rows, f"F{d}_half_space_N", -1e-3), "k--", label="half-space")
            ax[0][j].plot(xi, col(rows, f"F{d}_N", -1e-3), "b-", label="modified")
            ax[1][j].plot(xi, col(rows, f"A{d}_half_space_N", -1e-3), "k--o", ms=3)
            ax[1][j].plot(xi, col(rows, f"A{d}_N", -1e-3), "b-o", ms=3)
            ax[0][j].set_ylabel(f"-F_{d} [kN]")
            ax[1][j].set_ylabel(f"-A_{d} = -dF_{d}/dxi_{d} [kN]")
            ax[1][j].set_xlabel(f"xi_{d} [per mille]")
            ax[0][j].grid(True, alpha=0.3)
            ax[1][j].grid(True, alpha=0.3)
        ax[0][0].legend()
        fig.suptitle(title, fontsize=9)
        fig.tight_layout()
        fig.savefig(path[:-4] + ".png", dpi=90)
        plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
