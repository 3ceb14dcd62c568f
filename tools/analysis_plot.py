#!/usr/bin/python3
"""Plots of the analysis files of ferrodyn (docs/ANALYSES.md), by their 'kind' attribute:
assessment, ramp, bifurcation, kij_study, sweep. Called through ferroplot.py
(`ferroplot.py auto FILE.h5 --out DIR`), which `ferrodyn` runs after each analysis verb.
"""
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

KINDS = ("assessment", "ramp", "bifurcation", "kij_study", "sweep")
OUTCOMES = ["decayed", "steady", "diverged", "growing", "decaying", "approaching"]


def _attr(obj, name, default=""):
    v = obj.attrs.get(name, default)
    return v.decode() if isinstance(v, bytes) else v


def _num(obj, name):
    try:
        return float(obj.attrs.get(name, float("nan")))
    except (TypeError, ValueError):
        return float("nan")


def assessment(f, save):
    """One figure per assessed quantity along the track: every wheel / axle / body, its limit
    (dashed, +- when the quantity is signed), the track sections (dotted)."""
    g = f["assessment"]
    sec = g["sections"]
    bounds = sorted(set(list(sec["start"][:]) + list(sec["end"][:])))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    by_quantity = {}
    for k in sorted(g["signals"]):
        s = g["signals"][k]
        by_quantity.setdefault(_attr(s, "quantity"), []).append(s)
    signed = {"sum Y 2 m", "Y/Q 2 m", "car body lateral acc.", "car body vertical acc."}
    for quantity, items in by_quantity.items():
        fig, ax = plt.subplots(figsize=(9, 4))
        unit = _attr(items[0], "unit")
        scale, shown_unit = (1e-3, "kN") if unit == "N" else (1.0, unit)
        for i, s in enumerate(items):
            c = colors[i % len(colors)]
            ax.plot(s["position"][:], s["value"][:] * scale, color=c, lw=0.8, label=_attr(s, "item"))
            lim = _num(s, "limit")
            if lim == lim:
                ax.axhline(lim * scale, color=c, ls="--", lw=0.8)
                if quantity in signed:
                    ax.axhline(-lim * scale, color=c, ls="--", lw=0.8)
        lo, hi = ax.get_xlim()
        for b in bounds:
            if lo < b < hi:
                ax.axvline(b, color="grey", ls=":", lw=0.7)
        ax.set_xlim(lo, hi)
        ax.set_xlabel("position of the wheel / axle / body along the track [m]")
        ax.set_ylabel(f"{quantity} [{shown_unit}]")
        ax.set_title(f"{quantity}: {_attr(f, 'source')} ({_attr(f, 'vehicle')}, {_attr(f, 'category')}); "
                     "limits dashed, sections dotted", fontsize=8)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=6, ncol=3)
        stem = "assess_" + "".join(ch if ch.isalnum() else "_" for ch in quantity).strip("_").lower()
        save(fig, stem)


def ramp(f, save):
    g = f["ramp"]
    t, v = g["time"][:], g["speed"][:]
    sig = g["signal"][:]
    sig = sig.reshape(len(t), -1) if sig.ndim == 2 or sig.size == 0 else sig[:, None]
    names = str(_attr(g, "wheelsets", _attr(g, "signal_name"))).split(",")
    fig, ax = plt.subplots(figsize=(9, 4))
    for j in range(sig.shape[1]):
        ax.plot(t, sig[:, j] * 1e3, lw=0.5, label=names[j] if j < len(names) else f"state {j}")
    ax.plot(t, g["envelope"][:] * 1e3, lw=1.0, color="k", label="vehicle envelope (largest wheelset's)")
    thr = _num(g, "threshold") * 1e3
    ax.axhline(thr, color="grey", ls=":", lw=0.8, label=f"threshold {thr:g} mm")
    vd = _num(g, "decay_speed")
    if vd == vd:
        td = (_num(g, "speed_initial") - vd) / _num(g, "deceleration")
        ax.axvline(td, color="r", ls="--", lw=0.9,
                   label=f"dies out at {vd:.2f} m/s = {vd * 3.6:.1f} km/h ({_attr(g, 'holder')} last)")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("lateral displacement [mm]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="upper right")
    top = ax.secondary_xaxis("top", functions=(lambda x: (v[0] + (v[-1] - v[0]) * (x - t[0]) / max(t[-1] - t[0], 1e-12)) * 3.6,
                                               lambda s: t[0] + (s / 3.6 - v[0]) * (t[-1] - t[0]) / (v[-1] - v[0])))
    top.set_xlabel("speed [km/h]")
    ax.set_title(f"ramping: {_attr(f, 'scene_name')}, K11 = {_num(g, 'k11'):g}, K22 = {_num(g, 'k22'):g}", fontsize=9)
    save(fig, "ramp")


def bifurcation(f, save):
    g = f["branch"]
    v = g["speed"][:]
    amp = np.atleast_2d(g["amplitude"][:])
    out = g["outcome"][:].astype(int)
    holder = g["holder"][:].astype(int) if "holder" in g else np.zeros(len(v), dtype=int)
    held = amp[np.arange(len(v)), holder]
    names = str(_attr(g, "wheelsets")).split(",")
    order = np.argsort(v)
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for j, n in enumerate(names):
        # The branch: settled cycles, cycles predicted by the amplitude equation and decayed runs
        # (amplitude 0); other unsettled runs are markers.
        a = np.where(out == 0, 0.0, np.where((out == 1) | (out == 5), amp[:, j], np.nan))
        ax.plot(v[order] * 3.6, a[order] * 1e3, "o-", ms=3, lw=0.8, label=f"{n} (steady / approaching / decayed)")
    for code, marker in ((2, "^"), (3, "2"), (4, "v"), (5, "s")):
        sel = out == code
        if sel.any():
            ax.plot(v[sel] * 3.6, held[sel] * 1e3, marker, color="k", ms=5, ls="none",
                    label=f"{OUTCOMES[code]} (holding wheelset)")
    lo, hi = _num(g, "bracket_low"), _num(g, "bracket_high")
    if lo == lo and hi == hi:
        ax.axvspan(lo * 3.6, hi * 3.6, color="r", alpha=0.25,
                   label=f"fold in [{lo * 3.6:.2f}, {hi * 3.6:.2f}] km/h, cycle held by {_attr(g, 'holder')}")
    hopf = _num(g, "hopf_speed")
    if hopf == hopf:
        ax.axvline(hopf * 3.6, color="g", ls="--", lw=0.9, label=f"Hopf (eigenvalues) {hopf * 3.6:.1f} km/h")
    ax.set_xlabel("speed [km/h]")
    ax.set_ylabel("limit-cycle amplitude [mm]")
    ax.set_title(f"bifurcation diagram: {_attr(f, 'scene_name')}, K11 = {_num(g, 'k11'):g}, K22 = {_num(g, 'k22'):g}", fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, "bifurcation")


def kij_study(f, save):
    g = f["kij"]
    k = g["k22"][:]
    vc = g["critical_speed"][:]
    hopf = g["hopf_speed"][:]
    tk, tv = g["thesis_k"][:], g["thesis_critical_speed"][:]
    ref = vc[np.argmin(np.abs(k - 1.0))] if np.any(np.abs(k - 1.0) < 1e-9) else vc[0]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(k, vc / ref, "o-", label="ferrodyn: nonlinear Vc(K)/Vc(1)")
    if np.isfinite(hopf).any():
        ax.plot(k, hopf / ref, "s--", ms=4, label="ferrodyn: Hopf speed / Vc(1)")
    ax.plot(tk, tv / tv[0], "k^:", label="Toumi 2016 Table 4.1")
    ax.set_xlabel("reduction factor K [-]")
    ax.set_ylabel("critical speed ratio [-]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title(f"reduction factors: {_attr(f, 'scene_name')}", fontsize=9)
    save(fig, "kij_study")


def sweep(f, save):
    g = f["sweep"]
    v, k11, k22 = g["speed"][:], g["k11"][:], g["k22"][:]
    amp = np.atleast_2d(g["amplitude"][:])
    out = g["outcome"][:].astype(int)
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for kk in sorted(set(zip(k11, k22)), reverse=True):
        sel = (k11 == kk[0]) & (k22 == kk[1])
        order = np.argsort(v[sel])
        a = np.where(out[sel] == 0, 0.0, np.nanmax(amp[sel], axis=1))
        ax.plot(v[sel][order] * 3.6, a[order] * 1e3, "o-", ms=3, lw=0.8, label=f"K = ({kk[0]:g}, {kk[1]:g})")
    ax.set_xlabel("speed [km/h]")
    ax.set_ylabel("largest wheelset amplitude [mm]")
    ax.set_title(f"sweep from a lateral disturbance: {_attr(f, 'scene_name')}", fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, "sweep")


def plot(f, kind, save):
    {"assessment": assessment, "ramp": ramp, "bifurcation": bifurcation,
     "kij_study": kij_study, "sweep": sweep}[kind](f, save)
    return 0


if __name__ == "__main__":
    print(__doc__, file=sys.stderr)
    sys.exit(2)
