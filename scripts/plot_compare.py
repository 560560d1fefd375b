#!/usr/bin/python3
"""Plots of a `sluice compare`: for each model's run in OUT/MODEL, the drag and lift on all the
bodies against time (OUT/compare_forces.png, from loads.csv; their running mean over 0.05 s, as
the table's peaks, since a particle model's forces carry acoustic spikes) and each probe against
time (OUT/compare_probes.png, from probes.csv), one line per model. A run that wrote no such file
is left out of that plot.

usage: /usr/bin/python3 scripts/plot_compare.py OUT MODEL [MODEL ...]
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_columns(path):
    """The CSV file's columns by name, as lists of floats, its time column named "time"; None
    when there is no file or no row."""
    if not os.path.exists(path):
        return None
    with open(path) as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        return None
    names = ["time" if n == "time [s]" else n for n in rows[0]]
    return {name: [float(r[k]) for r in rows[1:]] for k, name in enumerate(names)}


def running_mean(time, values, window):
    """The mean of `values` over `window` seconds centred on each time."""
    out = []
    for t in time:
        inside = [v for s, v in zip(time, values) if abs(s - t) <= window / 2]
        out.append(sum(inside) / len(inside))
    return out


def plot_panels(out, models, file_name, panels, image, title, window=0.0):
    """One panel per (column, label) of `panels`, one line per model that has the file; with a
    window, each line is the running mean over it."""
    runs = [(m, read_columns(os.path.join(out, m, file_name))) for m in models]
    runs = [(m, c) for m, c in runs if c is not None]
    if not runs or not panels:
        return
    fig, axes = plt.subplots(len(panels), 1, figsize=(7.0, 2.6 * len(panels) + 0.6), sharex=True,
                             squeeze=False)
    for ax, (column, label) in zip(axes[:, 0], panels):
        for model, columns in runs:
            if column in columns:
                values = columns[column]
                if window > 0:
                    values = running_mean(columns["time"], values, window)
                ax.plot(columns["time"], values, label=model, linewidth=1.2)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0, 0].set_title(title)
    axes[0, 0].legend(fontsize=8, ncol=3)
    axes[-1, 0].set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(os.path.join(out, image), dpi=120)
    plt.close(fig)
    print(f"plot: {os.path.join(out, image)}")


def main():
    out, models = sys.argv[1], sys.argv[2:]
    name = os.path.basename(os.path.normpath(out))
    plot_panels(out, models, "loads.csv",
                [("all_bodies_drag", "drag [N]"), ("all_bodies_lift", "lift [N]")],
                "compare_forces.png",
                f"{name}: the fluid's force on all the bodies (0.05 s running mean)", window=0.05)
    probes = next((read_columns(os.path.join(out, m, "probes.csv")) for m in models
                   if read_columns(os.path.join(out, m, "probes.csv"))), None)
    if probes:
        panels = [(c, c) for c in probes if c != "time"]
        plot_panels(out, models, "probes.csv", panels, "compare_probes.png", f"{name}: the probes")


if __name__ == "__main__":
    main()
