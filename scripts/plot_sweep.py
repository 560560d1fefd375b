#!/usr/bin/python3
"""Plots of a `sluice sweep`: reads OUT/summary.csv and draws, for every measurement, its value
against the first swept key, one line per combination of the other swept keys (a logarithmic
axis where the values span a factor of ten or more). Writes OUT/summary_MEASUREMENT.png.

usage: /usr/bin/python3 scripts/plot_sweep.py OUT
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def main():
    out = sys.argv[1]
    with open(os.path.join(out, "summary.csv")) as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    status = header.index("status")
    keys = header[1:status]
    measurements = header[status + 1:]
    if not keys or not body:
        print("plot_sweep: nothing swept, no plot")
        return
    xs = [number(r[1]) for r in body]
    if any(x is None for x in xs):
        print(f"plot_sweep: {keys[0]} is not a number, no plot")
        return
    groups = {}
    for r, x in zip(body, xs):
        label = ", ".join(f"{k}={v}" for k, v in zip(keys[1:], r[2:status]))
        groups.setdefault(label, []).append((x, r))
    logarithmic = min(xs) > 0 and max(xs) >= 10 * min(xs)
    for m, name in enumerate(measurements, start=status + 1):
        fig = plt.figure(figsize=(6.0, 4.0))
        for label, points in groups.items():
            pairs = sorted((x, number(r[m])) for x, r in points if number(r[m]) is not None)
            if pairs:
                plt.plot([p[0] for p in pairs], [p[1] for p in pairs], "o-", label=label or None)
        if logarithmic:
            plt.xscale("log")
        plt.xlabel(keys[0])
        plt.ylabel(name)
        plt.grid(alpha=0.3)
        if len(groups) > 1:
            plt.legend(fontsize=8)
        fig.tight_layout()
        path = os.path.join(out, "summary_" + re.sub(r"[^A-Za-z0-9_]+", "_", name).strip("_")
                            + ".png")
        fig.savefig(path, dpi=110)
        plt.close(fig)
    print(f"plots: {len(measurements)} in {out}/summary_*.png")


if __name__ == "__main__":
    main()
