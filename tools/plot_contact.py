#!/usr/bin/env python3
"""Pictures for `ferrodyn contact curve|patch` (matplotlib, Agg backend).

  plot_contact.py curves CURVES.csv OUT.png [TITLE]   creep curves, every model overlaid
  plot_contact.py patch  PATCH.csv  OUT.png [TITLE]   pressure, traction vectors, adhesion/slip

Exit codes: 0 ok, 2 bad input, 3 matplotlib missing.
"""
import csv
import sys


def load(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def plot_curves(rows, out, title, plt):
    panels = [("longitudinal", "xi_x [-]", "force_x", "F_x [kN]", 1e-3),
              ("lateral", "xi_y [-]", "force_y", "F_y [kN]", 1e-3),
              ("spin", "phi [1/m]", "moment_z", "M_z [N m]", 1.0),
              ("combined", "|xi| [-]", "force_t", "|F_t| [kN]", 1e-3)]
    present = [p for p in panels if any(r["curve"] == p[0] for r in rows)]
    if not present:
        print("plot_contact.py: no curves in the CSV", file=sys.stderr)
        sys.exit(2)
    fig, axes = plt.subplots(1, len(present), figsize=(4.2 * len(present), 3.8), squeeze=False)
    models = []
    for r in rows:
        if r["model"] not in models:
            models.append(r["model"])
    for ax, (curve, xl, col, yl, scale) in zip(axes[0], present):
        for m in models:
            pts = [(float(r["creepage"]), float(r[col]) * scale) for r in rows
                   if r["curve"] == curve and r["model"] == m]
            if pts:
                ax.plot([p[0] for p in pts], [p[1] for p in pts], label=m, lw=1.3)
        ax.set_xlabel(xl)
        ax.set_ylabel(yl)
        ax.set_title(curve)
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    if title:
        fig.suptitle(title + "  (forces on the wheel from the rail)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=90)


def plot_patch(rows, out, title, plt):
    x = [float(r["x"]) * 1e3 for r in rows]
    y = [float(r["y"]) * 1e3 for r in rows]
    p = [float(r["pressure"]) * 1e-6 for r in rows]
    tx = [float(r["traction_x"]) * 1e-6 for r in rows]
    ty = [float(r["traction_y"]) * 1e-6 for r in rows]
    slip = [int(r["slip"]) for r in rows]
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    sc = axes[0].scatter(x, y, c=p, s=6, marker="s", cmap="viridis")
    fig.colorbar(sc, ax=axes[0], label="p_n [MPa]")
    axes[0].set_title("pressure")
    step = max(1, len(x) // 600)
    axes[1].quiver(x[::step], y[::step], tx[::step], ty[::step], angles="xy")
    axes[1].set_title("traction on the wheel")
    colors = ["tab:blue" if s == 0 else "tab:red" for s in slip]
    axes[2].scatter(x, y, c=colors, s=6, marker="s")
    axes[2].set_title("adhesion (blue) / slip (red)")
    for ax in axes:
        ax.set_xlabel("x (rolling) [mm]")
        ax.set_ylabel("y [mm]")
        ax.set_aspect("equal", adjustable="datalim")
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=90)


def main():
    if len(sys.argv) < 4 or sys.argv[1] not in ("curves", "patch"):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("plot_contact.py: matplotlib is not available to " + sys.executable, file=sys.stderr)
        sys.exit(3)
    rows = load(sys.argv[2])
    title = sys.argv[4] if len(sys.argv) > 4 else ""
    (plot_curves if sys.argv[1] == "curves" else plot_patch)(rows, sys.argv[3], title, plt)


if __name__ == "__main__":
    main()
