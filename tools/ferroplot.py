#!/usr/bin/python3
"""Plots of ferrodyn HDF5 output (docs/OUTPUT.md), through Debian's python3-matplotlib and
python3-h5py. Called by `ferrodyn run`, `ferrodyn eig` and `ferrodyn plot`; usable alone:

  ferroplot.py timeseries OUT.h5 [--signals A B ...] --out DIR [--format png,svg]
  ferroplot.py eigen OUT_eig.h5 --out DIR
  ferroplot.py auto FILE.h5 ...      (picks by the file's 'kind' attribute)

Exit status: 0 ok, 2 bad input (unknown signal, unreadable file), 1 other failure.
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analysis_plot  # noqa: E402


def attr(f, name, default=""):
    v = f.attrs.get(name, default)
    return v.decode() if isinstance(v, bytes) else str(v)


def save(fig, out, stem, formats):
    os.makedirs(out, exist_ok=True)
    paths = []
    for fmt in formats:
        p = os.path.join(out, f"{stem}.{fmt}")
        fig.savefig(p, dpi=120, bbox_inches="tight")
        paths.append(p)
    plt.close(fig)
    return paths


def plot_timeseries(f, signals, out, formats):
    if "time" not in f or "signals" not in f:
        print(f"ferroplot: {f.filename} has no /time and /signals (not a time simulation)", file=sys.stderr)
        return 2
    names = list(f["signals"].keys())
    chosen = signals or names
    unknown = [s for s in chosen if s not in names]
    if unknown:
        print(f"ferroplot: unknown signal(s) {', '.join(unknown)}; available: {', '.join(names)}", file=sys.stderr)
        return 2
    t = f["time"][:]
    status = attr(f, "status", "?")
    title = f"{attr(f, 'scene_name')} — {attr(f, 'integrator')}, V = {float(f.attrs.get('speed', float('nan'))):.2f} m/s ({status})"
    for name in chosen:
        d = f["signals"][name]
        unit = attr(d, "unit")
        fig, ax = plt.subplots(figsize=(8, 3.2))
        ax.plot(t, d[:], lw=0.9)
        ax.set_xlabel("time [s]")
        ax.set_ylabel(f"{name} [{unit}]")
        ax.set_title(title, fontsize=9)
        ax.grid(True, alpha=0.3)
        for p in save(fig, out, name.replace("/", "_"), formats):
            print(p)
    return 0


def plot_eigen(f, out, formats):
    if "eigen" not in f:
        print(f"ferroplot: {f.filename} has no /eigen group", file=sys.stderr)
        return 2
    g = f["eigen"]
    v = g["speed"][:]
    vc = float(g.attrs.get("critical_speed", float("nan")))
    vcf = float(g.attrs.get("closed_form_critical_speed", float("nan")))
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    # Classified modes: the hunting mode and the least damped contact / track modes apart;
    # otherwise the least damped mode.
    series = []
    if "hunting_mode" in g:
        series.append(("hunting mode", g["hunting_mode"]))
        for cls in ("contact", "track"):
            if cls in g and (g[cls]["damping_ratio"][:] == g[cls]["damping_ratio"][:]).any():
                series.append((f"least damped {cls} mode", g[cls]))
    else:
        series.append(("least damped mode", g))
    for label, s in series:
        a1.plot(v * 3.6, s["damping_ratio"][:], lw=1.2, label=label)
        a2.plot(v * 3.6, s["frequency"][:], lw=1.2, label=label)
    a1.axhline(0.0, color="k", lw=0.6)
    if vc == vc:
        a1.axvline(vc * 3.6, color="r", ls="--", lw=0.9, label=f"Hopf speed Vc = {vc * 3.6:.1f} km/h")
    if vcf == vcf:
        a1.axvline(vcf * 3.6, color="g", ls=":", lw=1.2, label=f"eq. (151) Vc = {vcf * 3.6:.1f} km/h")
    a1.set_ylabel("damping ratio [-]")
    a1.legend(fontsize=8)
    a1.grid(True, alpha=0.3)
    a1.set_title(attr(f, "scene_name"), fontsize=9)
    a2.set_yscale("log" if len(series) > 1 else "linear")
    a2.set_xlabel("speed [km/h]")
    a2.set_ylabel("frequency [Hz]")
    a2.grid(True, alpha=0.3)
    for p in save(fig, out, "eigen_damping", formats):
        print(p)
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mode", choices=["timeseries", "eigen", "auto"])
    ap.add_argument("file")
    ap.add_argument("--signals", nargs="*", default=[])
    ap.add_argument("--out", required=True)
    ap.add_argument("--format", default="png,svg")
    a = ap.parse_args()
    formats = [x for x in a.format.split(",") if x]
    try:
        f = h5py.File(a.file, "r")
    except OSError as e:
        print(f"ferroplot: cannot read {a.file}: {e}", file=sys.stderr)
        return 2
    with f:
        mode = a.mode
        if mode == "auto" and attr(f, "kind") in analysis_plot.KINDS:
            return analysis_plot.plot(f, attr(f, "kind"), lambda fig, stem: [print(p) for p in save(fig, a.out, stem, formats)])
        if mode == "auto":
            mode = "eigen" if attr(f, "kind") == "eigen_analysis" else "timeseries"
        if mode == "eigen":
            return plot_eigen(f, a.out, formats)
        return plot_timeseries(f, a.signals, a.out, formats)


if __name__ == "__main__":
    sys.exit(main())
