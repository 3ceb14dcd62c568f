#!/usr/bin/env python3
"""Plots of `ferrodyn geometry PAIR.yaml` outputs.

Usage: geometry_plot.py OUT_DIR [IMG_DIR]

Reads OUT_DIR/contact_points.csv, conicity.csv, profiles.csv and writes
geometry_contact_points.png (contact-point diagram: points on wheel and rail profiles against
lateral shift), geometry_delta_r.png (rolling-radius difference) and geometry_conicity.png
(equivalent conicity against amplitude) into IMG_DIR (default OUT_DIR).

Uses matplotlib when it is installed; otherwise a small built-in PNG line-plot renderer
(standard library only) so that the figures can be produced on a bare machine.
"""
import csv
import math
import os
import struct
import sys
import zlib


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return rows


def col(rows, name, kind=None):
    return [float(r[name]) for r in rows if kind is None or r["kind"] == kind]


# ----------------------------------------------------------------------------------------------
# Minimal renderer (fallback)

FONT = {
    "0": ["01110", "10001", "10011", "10101", "11001", "10001", "01110"],
    "1": ["00100", "01100", "00100", "00100", "00100", "00100", "01110"],
    "2": ["01110", "10001", "00001", "00010", "00100", "01000", "11111"],
    "3": ["11111", "00010", "00100", "00010", "00001", "10001", "01110"],
    "4": ["00010", "00110", "01010", "10010", "11111", "00010", "00010"],
    "5": ["11111", "10000", "11110", "00001", "00001", "10001", "01110"],
    "6": ["00110", "01000", "10000", "11110", "10001", "10001", "01110"],
    "7": ["11111", "00001", "00010", "00100", "01000", "01000", "01000"],
    "8": ["01110", "10001", "10001", "01110", "10001", "10001", "01110"],
    "9": ["01110", "10001", "10001", "01111", "00001", "00010", "01100"],
    ".": ["00000", "00000", "00000", "00000", "00000", "01100", "01100"],
    ",": ["00000", "00000", "00000", "00000", "01100", "00100", "01000"],
    "-": ["00000", "00000", "00000", "11111", "00000", "00000", "00000"],
    "+": ["00000", "00100", "00100", "11111", "00100", "00100", "00000"],
    "=": ["00000", "00000", "11111", "00000", "11111", "00000", "00000"],
    "(": ["00010", "00100", "01000", "01000", "01000", "00100", "00010"],
    ")": ["01000", "00100", "00010", "00010", "00010", "00100", "01000"],
    "/": ["00001", "00001", "00010", "00100", "01000", "10000", "10000"],
    ":": ["00000", "01100", "01100", "00000", "01100", "01100", "00000"],
    " ": ["00000"] * 7,
    "A": ["01110", "10001", "10001", "11111", "10001", "10001", "10001"],
    "B": ["11110", "10001", "10001", "11110", "10001", "10001", "11110"],
    "C": ["01110", "10001", "10000", "10000", "10000", "10001", "01110"],
    "D": ["11100", "10010", "10001", "10001", "10001", "10010", "11100"],
    "E": ["11111", "10000", "10000", "11110", "10000", "10000", "11111"],
    "F": ["11111", "10000", "10000", "11110", "10000", "10000", "10000"],
    "G": ["01110", "10001", "10000", "10111", "10001", "10001", "01111"],
    "H": ["10001", "10001", "10001", "11111", "10001", "10001", "10001"],
    "I": ["01110", "00100", "00100", "00100", "00100", "00100", "01110"],
    "J": ["00111", "00010", "00010", "00010", "00010", "10010", "01100"],
    "K": ["10001", "10010", "10100", "11000", "10100", "10010", "10001"],
    "L": ["10000", "10000", "10000", "10000", "10000", "10000", "11111"],
    "M": ["10001", "11011", "10101", "10101", "10001", "10001", "10001"],
    "N": ["10001", "10001", "11001", "10101", "10011", "10001", "10001"],
    "O": ["01110", "10001", "10001", "10001", "10001", "10001", "01110"],
    "P": ["11110", "10001", "10001", "11110", "10000", "10000", "10000"],
    "Q": ["01110", "10001", "10001", "10001", "10101", "10010", "01101"],
    "R": ["11110", "10001", "10001", "11110", "10100", "10010", "10001"],
    "S": ["01111", "10000", "10000", "01110", "00001", "00001", "11110"],
    "T": ["11111", "00100", "00100", "00100", "00100", "00100", "00100"],
    "U": ["10001", "10001", "10001", "10001", "10001", "10001", "01110"],
    "V": ["10001", "10001", "10001", "10001", "10001", "01010", "00100"],
    "W": ["10001", "10001", "10001", "10101", "10101", "10101", "01010"],
    "X": ["10001", "10001", "01010", "00100", "01010", "10001", "10001"],
    "Y": ["10001", "10001", "10001", "01010", "00100", "00100", "00100"],
    "Z": ["11111", "00001", "00010", "00100", "01000", "10000", "11111"],
}

COLORS = [(31, 119, 180), (214, 39, 40), (44, 160, 44), (255, 127, 14), (148, 103, 189)]


class Canvas:
    def __init__(self, w, h):
        self.w, self.h = w, h
        self.px = bytearray([255] * (w * h * 3))

    def set(self, x, y, c):
        x, y = int(round(x)), int(round(y))
        if 0 <= x < self.w and 0 <= y < self.h:
            i = (y * self.w + x) * 3
            self.px[i:i + 3] = bytes(c)

    def line(self, x0, y0, x1, y1, c, width=1):
        x0, y0, x1, y1 = int(round(x0)), int(round(y0)), int(round(x1)), int(round(y1))
        dx, dy = abs(x1 - x0), -abs(y1 - y0)
        sx, sy = (1 if x0 < x1 else -1), (1 if y0 < y1 else -1)
        err = dx + dy
        while True:
            for ox in range(width):
                for oy in range(width):
                    self.set(x0 + ox - width // 2, y0 + oy - width // 2, c)
            if x0 == x1 and y0 == y1:
                break
            e2 = 2 * err
            if e2 >= dy:
                err += dy
                x0 += sx
            if e2 <= dx:
                err += dx
                y0 += sy

    def text(self, x, y, s, c=(0, 0, 0), scale=2, anchor="left", vertical=False):
        s = s.upper()
        n = len(s) * 6 * scale
        if anchor == "center":
            x -= n // 2 if not vertical else 0
            y += n // 2 if vertical else 0
        elif anchor == "right":
            x -= n
        for k, ch in enumerate(s):
            g = FONT.get(ch, FONT[" "])
            for r, row in enumerate(g):
                for q, bit in enumerate(row):
                    if bit == "1":
                        for a in range(scale):
                            for b in range(scale):
                                if vertical:
                                    self.set(x + r * scale + a, y - (k * 6 + q) * scale - b, c)
                                else:
                                    self.set(x + (k * 6 + q) * scale + a, y + r * scale + b, c)

    def png(self, path):
        raw = b"".join(b"\x00" + bytes(self.px[y * self.w * 3:(y + 1) * self.w * 3])
                       for y in range(self.h))

        def chunk(t, d):
            return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
        data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", self.w, self.h, 8, 2, 0, 0, 0))
        data += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
        with open(path, "wb") as f:
            f.write(data)


def nice_ticks(lo, hi, n=6):
    span = hi - lo
    raw = span / max(n, 1)
    mag = 10 ** math.floor(math.log10(raw))
    step = min((m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw), default=10 * mag)
    t = math.ceil(lo / step) * step
    out = []
    while t <= hi + 1e-9 * step:
        out.append(round(t, 10))
        t += step
    return out


def fmt_tick(v):
    if abs(v) < 1e-12:
        return "0"
    s = ("%.3f" % v).rstrip("0").rstrip(".")
    return s


class Axes:
    def __init__(self, canvas, box, xlim, ylim, title, xlabel, ylabel):
        self.c, self.box = canvas, box
        self.xlim, self.ylim = xlim, ylim
        x0, y0, x1, y1 = box
        for t in nice_ticks(*xlim):
            X = self.X(t)
            canvas.line(X, y1, X, y0, (225, 225, 225))
            canvas.line(X, y1, X, y1 + 5, (0, 0, 0))
            canvas.text(X, y1 + 9, fmt_tick(t), anchor="center")
        for t in nice_ticks(*ylim):
            Y = self.Y(t)
            canvas.line(x0, Y, x1, Y, (225, 225, 225))
            canvas.line(x0 - 5, Y, x0, Y, (0, 0, 0))
            canvas.text(x0 - 8, Y - 7, fmt_tick(t), anchor="right")
        for a, b, c_, d in ((x0, y0, x1, y0), (x0, y1, x1, y1), (x0, y0, x0, y1), (x1, y0, x1, y1)):
            canvas.line(a, b, c_, d, (0, 0, 0))
        canvas.text((x0 + x1) // 2, y0 - 26, title, anchor="center")
        canvas.text((x0 + x1) // 2, y1 + 32, xlabel, anchor="center")
        canvas.text(x0 - 95, (y0 + y1) // 2, ylabel, anchor="center", vertical=True)
        self.legend_y = y0 + 8

    def X(self, v):
        x0, _, x1, _ = self.box
        return x0 + (v - self.xlim[0]) / (self.xlim[1] - self.xlim[0]) * (x1 - x0)

    def Y(self, v):
        _, y0, _, y1 = self.box
        return y1 - (v - self.ylim[0]) / (self.ylim[1] - self.ylim[0]) * (y1 - y0)

    def plot(self, xs, ys, color, label=None, marker=False, width=2):
        pts = [(self.X(x), self.Y(y)) for x, y in zip(xs, ys)
               if self.xlim[0] <= x <= self.xlim[1] and self.ylim[0] <= y <= self.ylim[1]]
        if marker:
            for X, Y in pts:
                for a in range(-2, 3):
                    self.c.line(X - 2, Y + a, X + 2, Y + a, color)
        else:
            for (a, b), (c_, d) in zip(pts, pts[1:]):
                self.c.line(a, b, c_, d, color, width)
        if label:
            x1 = self.box[2]
            n = len(label) * 12
            self.c.line(x1 - n - 50, self.legend_y + 7, x1 - n - 20, self.legend_y + 7, color, 3)
            self.c.text(x1 - n - 12, self.legend_y, label)
            self.legend_y += 20


def fallback_figures(cp, con, prof, img_dir):
    y = col(cp, "y_mm")
    # Contact-point diagram: two panels (wheel and rail positions vs shift), right wheel/rail.
    cv = Canvas(900, 700)
    ax = Axes(cv, (130, 50, 870, 300), (min(y), max(y)),
              (-50, 30), "CONTACT POINTS ON THE WHEEL PROFILE", "LATERAL SHIFT Y (MM)",
              "WHEEL Y (MM)")
    ax.plot(y, col(cp, "right_wheel_y_mm"), COLORS[0], "RIGHT WHEEL", marker=True)
    ax.plot(y, col(cp, "left_wheel_y_mm"), COLORS[1], "LEFT WHEEL", marker=True)
    ax2 = Axes(cv, (130, 400, 870, 640), (min(y), max(y)), (-50, 30),
               "CONTACT POINTS ON THE RAIL PROFILE", "LATERAL SHIFT Y (MM)", "RAIL Y (MM)")
    ax2.plot(y, col(cp, "right_rail_y_mm"), COLORS[0], "RIGHT RAIL", marker=True)
    ax2.plot(y, col(cp, "left_rail_y_mm"), COLORS[1], "LEFT RAIL", marker=True)
    cv.png(os.path.join(img_dir, "geometry_contact_points.png"))

    cv = Canvas(900, 520)
    dr = col(cp, "delta_r_mm")
    lim = max(abs(v) for v in dr)
    ax = Axes(cv, (130, 50, 870, 440), (min(y), max(y)), (-lim * 1.05, lim * 1.05),
              "ROLLING RADIUS DIFFERENCE", "LATERAL SHIFT Y (MM)", "DELTA R (MM)")
    ax.plot(y, dr, COLORS[0], "RIGID WHEELSET")
    cv.png(os.path.join(img_dir, "geometry_delta_r.png"))

    cv = Canvas(900, 520)
    a = col(con, "amplitude_mm")
    lam = col(con, "equivalent_conicity")
    ax = Axes(cv, (130, 50, 870, 440), (0, max(a)), (0, max(lam) * 1.1),
              "EQUIVALENT CONICITY (HARMONIC LINEARISATION)", "AMPLITUDE (MM)", "CONICITY")
    ax.plot(a, lam, COLORS[0], "EQUIVALENT CONICITY")
    ax.plot(a, lam, COLORS[0], marker=True)
    cv.png(os.path.join(img_dir, "geometry_conicity.png"))


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
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        matplotlib_figures(plt, cp, con, prof, img_dir)
    except ImportError:
        fallback_figures(cp, con, prof, img_dir)
    print("wrote geometry_contact_points.png, geometry_delta_r.png, geometry_conicity.png in",
          img_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
