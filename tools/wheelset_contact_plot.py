#!/usr/bin/python3
"""Picture of `ferrodyn contact wheelset CASES.yaml -o OUT.h5`.

Usage: wheelset_contact_plot.py OUT.h5 [IMG_DIR]

Reads the /patches table of OUT.h5 and writes wheelset_contact_positions.png into IMG_DIR
(default: OUT_plots/ next to OUT.h5): for each wheel, the contact reference point on the rail
profile (penetration-weighted centre) with the lateral extent of the loaded area as a bar and
the deepest interpenetration point, against the wheelset's lateral shift; below, the normal
force and the peak pressure.

Needs Debian's python3-matplotlib and python3-h5py (tools/install-deps.sh installs them).
"""
import os
import sys


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    path = sys.argv[1]
    stem = os.path.splitext(path)[0]
    img_dir = sys.argv[2] if len(sys.argv) > 2 else stem + "_plots"
    os.makedirs(img_dir, exist_ok=True)
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with h5py.File(path, "r") as f:
        t = {k: f["patches"][k][()] for k in f["patches"].keys()}
    fig, axs = plt.subplots(3, 2, figsize=(11, 9), sharex=True,
                            gridspec_kw={"height_ratios": [3, 1, 1]})
    for col, (side, name) in enumerate([(0, "left"), (1, "right")]):
        sel = t["side"] == side
        y = t["y_mm"][sel]
        ax = axs[0][col]
        lo, hi = t["rail_y_min_mm"][sel], t["rail_y_max_mm"][sel]
        ax.vlines(y, lo, hi, colors="0.6", lw=5, label="loaded area (lateral extent)")
        ax.plot(y, t["rail_y_mm"][sel], "o", color="C0", ms=5,
                label="reference point (penetration-weighted centre)")
        ax.plot(y, t["deepest_rail_y_mm"][sel], "x", color="C3", ms=5,
                label="deepest interpenetration")
        ax.set_title(f"{name} wheel")
        ax.set_ylabel("position on the rail profile y_r (mm)")
        ax.grid(alpha=0.3)
        if col == 0:
            ax.legend(fontsize=8, loc="best")
        axs[1][col].plot(y, t["normal_force_n"][sel] * 1e-3, "o-", ms=3)
        axs[1][col].set_ylabel("normal force (kN)")
        axs[1][col].grid(alpha=0.3)
        axs[2][col].plot(y, t["peak_pressure_mpa"][sel], "o-", ms=3, color="C1")
        axs[2][col].set_ylabel("peak pressure (MPa)")
        axs[2][col].set_xlabel("wheelset lateral shift y (mm)")
        axs[2][col].grid(alpha=0.3)
    fig.suptitle("Wheel-rail contact positions and patches against lateral shift")
    fig.tight_layout()
    out = os.path.join(img_dir, "wheelset_contact_positions.png")
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
