#!/usr/bin/env python3
"""Pictures of MIM results (needs numpy, matplotlib, h5py; on Debian: /usr/bin/python3).

  mim_plot.py fields RESULT.h5 OUT.png [--title TEXT]
      pressure map, traction vectors over |tau|, adhesion/slip areas of a file written by
      `ferrodyn contact mim -o` (contact::mim::write_hdf5).
  mim_plot.py timing BENCH.json OUT.png
      time against number of elements from `ferro_bench_mim --benchmark_out=BENCH.json`, with an
      N log N guide and the thesis's Table 2.1 (Toumi 2016) for comparison.
  mim_plot.py curve TEST_OUTPUT.txt OUT.png
      creep curve from the "creep curve xi_x ..." lines printed by
      `ferro_contact_tests --gtest_filter=MimRolling.thesis_creep_curve_25_points`, with Kalker's
      linear law and the Shen-Hedrick-Elkins cubic (C11 from annex A.2 for a/b = 1, nu = 0.28).
"""
import argparse
import json
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def fields(args):
    import h5py

    with h5py.File(args.input, "r") as f:
        p = f["pressure_Pa"][()] / 1e6
        tx = f["traction_x_Pa"][()] / 1e6
        ty = f["traction_y_Pa"][()] / 1e6
        state = f["state"][()]
        dx, dy = f.attrs["dx_m"] * 1e3, f.attrs["dy_m"] * 1e3
        x0, y0 = f.attrs["x0_m"] * 1e3, f.attrs["y0_m"] * 1e3
        fx, fy, fn = f.attrs["force_x_N"], f.attrs["force_y_N"], f.attrs["normal_force_N"]
    ny, nx = p.shape
    x = x0 + dx * np.arange(nx)
    y = y0 + dy * np.arange(ny)
    ext = [x[0] - dx / 2, x[-1] + dx / 2, y[0] - dy / 2, y[-1] + dy / 2]
    fig, ax = plt.subplots(1, 3, figsize=(13, 4.2))
    im = ax[0].imshow(np.ma.masked_where(p <= 0, p), origin="lower", extent=ext, cmap="viridis")
    fig.colorbar(im, ax=ax[0], label="p_n [MPa]")
    ax[0].set_title("pressure, Fn = %.4g N" % fn, fontsize=9)
    tt = np.hypot(tx, ty)
    im = ax[1].imshow(np.ma.masked_where(p <= 0, tt), origin="lower", extent=ext, cmap="magma")
    fig.colorbar(im, ax=ax[1], label="|tau| [MPa]")
    step = max(1, nx // 20)
    X, Y = np.meshgrid(x, y)
    ax[1].quiver(X[::step, ::step], Y[::step, ::step], tx[::step, ::step], ty[::step, ::step],
                 color="w", scale=None)
    ax[1].set_title("traction, Fx = %.4g N, Fy = %.4g N" % (fx, fy), fontsize=9)
    cmap = matplotlib.colors.ListedColormap(["white", "tab:blue", "tab:red"])
    ax[2].imshow(state, origin="lower", extent=ext, cmap=cmap, vmin=0, vmax=2)
    ax[2].set_title("adhesion (blue) / slip (red), rolling to +x", fontsize=9)
    for a in ax:
        a.set_xlabel("x [mm]")
        a.set_ylabel("y [mm]")
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.output, dpi=80)


# Toumi (2016) Table 2.1: elements per side -> seconds (2016 hardware).
THESIS_TABLE = {
    "MIM GC+GS (thesis)": {20: 0.1, 35: 3, 50: 24, 70: 142, 100: 1278},
    "CONTACT (thesis)": {20: 0.1, 35: 0.3, 50: 1.1, 70: 1.1, 100: 17},
}


def timing(args):
    with open(args.input) as f:
        data = json.load(f)
    pts = {}
    for b in data["benchmarks"]:
        name = b["name"]
        if not name.startswith("BM_MimNormalRolling/") or b.get("aggregate_name", "median") != "median":
            continue
        n = int(name.split("/")[1])
        scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
        pts[n] = (b["real_time"] * scale, b["cpu_time"] * scale)
    ns = sorted(pts)
    elems = np.array([n * n for n in ns], float)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.loglog(elems, [pts[n][1] for n in ns], "o-", label="ferrodyn MIM, CPU time")
    ax.loglog(elems, [pts[n][0] for n in ns], "s--", alpha=0.6, label="ferrodyn MIM, wall time")
    ref = elems * np.log(elems)
    k = pts[ns[-1]][1] / ref[-1]
    ax.loglog(elems, k * ref, "k:", label="N log N (through the largest grid)")
    for label, table in THESIS_TABLE.items():
        ax.loglog([n * n for n in table], list(table.values()), "x-", label=label)
    for n, lim in ((50, 0.02), (100, 0.2), (200, 1.5)):
        ax.plot([n * n], [lim], "rv")
    ax.plot([], [], "rv", label="speed targets")
    ax.set_xlabel("elements N")
    ax.set_ylabel("normal + steady rolling solve [s]")
    ax.set_title("Sphere case, xi_x = 3 per mille, one core")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=80)


def curve(args):
    xi, f = [], []
    with open(args.input) as fh:
        for line in fh:
            if line.startswith("creep curve xi_x"):
                parts = line.split()
                xi.append(float(parts[3]))
                f.append(float(parts[-1]))
    xi = np.array(xi)
    f = np.array(f)
    # Sphere case of the thesis: G = 82.03 GPa, a = 8.5224 mm, mu F_n = 0.2 x 517.9 kN.
    g, a, mufn, c11 = 210e9 / 2.56, 8.5224e-3, 0.2 * 517925.0, 4.2306
    x = np.linspace(xi.min(), xi.max(), 400)
    lin = -g * a * a * c11 * x * 1e-3 / mufn
    t = np.abs(lin)
    cubic = np.where(t < 3, 1 - (1 - np.minimum(t, 3) / 3) ** 3, 1.0) * np.sign(lin)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.plot(x, np.clip(lin, -1.5, 1.5), "k:", label="Kalker linear theory (C11)")
    ax.plot(x, cubic, "g--", label="Shen-Hedrick-Elkins cubic")
    ax.plot(xi, f, "o-", label="ferrodyn MIM, dx = 0.5 mm (25 points)")
    ax.set_xlabel("xi_x [per mille]")
    ax.set_ylabel("Fx / (mu Fn)")
    ax.set_ylim(-1.2, 1.2)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Creep curve, spheres 300/460 mm, mu = 0.2 (thesis fig. 2.13 case)")
    fig.tight_layout()
    fig.savefig(args.output, dpi=80)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["fields", "timing", "curve"])
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--title", default="")
    args = ap.parse_args()
    {"fields": fields, "timing": timing, "curve": curve}[args.kind](args)


if __name__ == "__main__":
    main()
