#!/usr/bin/env python3
"""Speed study of Manchester benchmark vehicle 1 on ERRI high-level irregularities, from the
`ferrodyn` Python module: the same scene run at several speeds (the GIL released while each
run integrates), and per speed the largest lateral wheel force Y of the leading wheelset, the
largest Y/Q (over the samples where the wheel carries load; a wheel that lifts is flagged) and
the car body's lateral acceleration (RMS). Draws speed_study.png.

    PYTHONPATH=build/python python3 examples/manchester_speed_study.py [--out DIR]
        [--speeds 30,40,50,60,70] [--t-end 10]
"""
import argparse
import pathlib

import numpy as np

import ferrodyn

SOURCE = pathlib.Path(__file__).resolve().parents[1]
SCENE = SOURCE / "scenarios" / "scenes" / "manchester_straight_erri.yaml"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="folder of speed_study.png")
    parser.add_argument("--speeds", default="30,40,50,60,70", help="speeds [m/s]")
    parser.add_argument("--t-end", type=float, default=10.0, help="simulated time per run [s]")
    args = parser.parse_args()
    speeds = [float(v) for v in args.speeds.split(",")]
    scene = ferrodyn.Scene(SCENE)
    rows = []
    print(f"{scene.name}: {len(speeds)} runs of {args.t_end} s")
    print(f"  {'V [m/s]':>8} {'max |Y| [kN]':>13} {'max Y/Q':>8} {'car ay RMS [m/s^2]':>19}"
          "  wheel lift")
    for v in speeds:
        r = ferrodyn.run(scene, speed=v, t_end=args.t_end)
        if r.status != "completed":
            raise SystemExit(f"V = {v} m/s: {r.status}: {r.message}")
        y, yq, lift = 0.0, 0.0, False
        for side in ("left", "right"):
            wheel_y, wheel_q = r[f"wheelset_1.{side}.Y"], r[f"wheelset_1.{side}.Q"]
            loaded = wheel_q > 0.0
            y = max(y, np.abs(wheel_y).max())
            yq = max(yq, (np.abs(wheel_y[loaded]) / wheel_q[loaded]).max())
            lift = lift or not loaded.all()
        ay = np.sqrt(np.mean(r["car_body.ay"] ** 2))
        rows.append((v, y, yq, ay))
        print(f"  {v:8.1f} {y / 1e3:13.2f} {yq:8.3f} {ay:19.4f}  {'yes' if lift else 'no'}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    v, y, yq, ay = map(np.array, zip(*rows))
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.4))
    axes[0].plot(v * 3.6, y / 1e3, "o-")
    axes[0].set_ylabel("max |Y|, leading wheelset [kN]")
    axes[1].plot(v * 3.6, yq, "o-")
    axes[1].set_ylabel("max Y/Q [-]")
    axes[2].plot(v * 3.6, ay, "o-")
    axes[2].set_ylabel("car body lateral acceleration, RMS [m/s$^2$]")
    for ax in axes:
        ax.set_xlabel("speed [km/h]")
        ax.grid(alpha=0.3)
    fig.suptitle("Manchester vehicle 1, ERRI high-level irregularities")
    fig.tight_layout()
    out = pathlib.Path(args.out) / "speed_study.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
