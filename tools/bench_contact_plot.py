#!/usr/bin/env python3
"""Pareto picture of `ferrodyn bench contact`: CPU time per evaluation against error.

  bench_contact_plot.py bench_contact.csv OUT.png
Needs matplotlib (Debian: /usr/bin/python3 with python3-matplotlib).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = list(csv.DictReader(open(sys.argv[1])))
    fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharey=True)
    for ax, key, title in ((axes[0], "mean_error_mu_fn", "mean error"),
                           (axes[1], "max_error_mu_fn", "max error")):
        for r in rows:
            if "reference" in r["model"]:
                continue
            t = float(r["us_per_eval"])
            e = max(float(r[key]), 1e-5)
            kind = r["model"].split()[0]
            marker = {"fastsim": "s", "mim": "o", "mim_table": "D"}.get(kind, "^")
            ax.scatter(e, t, marker=marker)
            ax.annotate(r["model"], (e, t), fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(f"{title} against converged MIM [mu Fn]")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("CPU time per evaluation [us]")
    ref = [r for r in rows if "reference" in r["model"]]
    fig.suptitle("ferrodyn bench contact: speed against error"
                 + (f" ({ref[0]['model']}, {float(ref[0]['us_per_eval']):.0f} us)" if ref else ""))
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=90)


if __name__ == "__main__":
    main()
