#!/usr/bin/python3
"""Plots of `ferrodyn geometry pair PAIR.yaml` outputs.

Usage: geometry_plot.py OUT_DIR [IMG_DIR]

Reads OUT_DIR/contact_points.csv, conicity.csv, profiles.csv and writes
geometry_contact_points.png (contact-point diagram: points on wheel and rail profiles against
lateral shift), geometry_delta_r.png (rolling-radius difference) and geometry_conicity.png
(equivalent conicity against amplitude) into IMG_DIR (default OUT_DIR).

Needs Debian's python3-matplotlib (tools/install-deps.sh installs it).
"""
import csv
import os
import sys


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return rows


def col(rows, name, kind=None):
    return [float(r[name]) for r in rows if kind is None or r["kind"] == kind]


# ----------------------------------------------------------------------------------------------
# Minimal renderer (fallback)

def matplotlib_figures(plt, cp, con, prof, img_dir):
    y = col(cp, "y_mm")
    fig, axs = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    axs[0].plot(y, col(cp, "right_wheel_y_mm"), ".", ms=3, label="right wheel")
    axs[0].plot(y, col(cp, "left_wheel_y_mm"), ".", ms=3, label="left wheel")
    axs[0].set_ylabel("contact on wheel profile y_w (mm)")
    axs[0].legend()
    axs[1].plot(y, col(cp, "right_rail_y_mm"), ".", ms=3, label="right rail")
    axs[1].plot(y, col(cp, "left_rail_y_mm"), ".", ms=3, label="left rail")
    axs[1].set_ylabel("contact on rail profile y_r (mm)")
    axs[1].set_xlabel("lateral shift y (mm)")
    axs[1].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(img_dir, "geometry_contact_points.png"), dpi=90)
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(y, col(cp, "delta_r_mm"))
    ax.set_xlabel("lateral shift y (mm)")
    ax.set_ylabel("delta r (mm)")
    ax.grid(True)
    fig.tight_layout()
    fig.savefig(os.path.join(img_dir, "geometry_delta_r.png"), dpi=90)
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(col(con, "amplitude_mm"), col(con, "equivalent_conicity"), "o-")
    ax.set_xlabel("amplitude (mm)")
    ax.set_ylabel("equivalent conicity")
    ax.grid(True)
    fig.tight_layout()
    fig.savefig(os.path.join(img_dir, "geometry_conicity.png"), dpi=90)


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    out_dir = sys.argv[1]
    img_dir = sys.argv[2] if len(sys.argv) > 2 else out_dir
    os.makedirs(img_dir, exist_ok=True)
    cp = read_csv(os.path.join(out_dir, "contact_points.csv"))
    con = read_csv(os.path.join(out_dir, "conicity.csv"))
    prof = read_csv(os.path.join(out_dir, "profiles.csv"))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    matplotlib_figures(plt, cp, con, prof, img_dir)
    print("wrote geometry_contact_points.png, geometry_delta_r.png, geometry_conicity.png in",
          img_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
