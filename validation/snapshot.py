#!/usr/bin/python3
"""Side views (x-z) of a sluice series at chosen times, fluid coloured by speed, rigid bodies
in red: a quick look at a run without ParaView. Writes one PNG with a panel per time.

usage: /usr/bin/python3 validation/snapshot.py SERIES.pvd OUT.png TIME [TIME ...] [--x MIN MAX]
"""
import argparse
import os
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from frames import read_frame


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pvd")
    parser.add_argument("out")
    parser.add_argument("times", type=float, nargs="+")
    parser.add_argument("--x", type=float, nargs=2, metavar=("MIN", "MAX"),
                        help="show only this range of x")
    args = parser.parse_args()
    pvd, out, times = args.pvd, args.out, args.times
    frames = [(float(d.get("timestep")), d.get("file"))
              for d in ET.parse(pvd).getroot().iter("DataSet")]
    base = os.path.dirname(os.path.abspath(pvd))
    fig, axes = plt.subplots(len(times), 1, figsize=(7, 2.3 * len(times)), squeeze=False)
    for ax, wanted in zip(axes[:, 0], times):
        time, file = min(frames, key=lambda frame: abs(frame[0] - wanted))
        points, fields = read_frame(os.path.join(base, file), "velocity", "kind")
        speed, kind = np.linalg.norm(fields["velocity"], axis=1), fields["kind"]
        if args.x:
            keep = (points[:, 0] >= args.x[0]) & (points[:, 0] <= args.x[1])
            points, speed, kind = points[keep], speed[keep], kind[keep]
        walls, fluid, bodies = kind == 1, kind == 0, kind == 2
        ax.scatter(points[walls, 0], points[walls, 2], s=0.3, c="0.75", lw=0)
        order = np.argsort(points[fluid, 1])  # draw the far side first
        shown = ax.scatter(points[fluid, 0][order], points[fluid, 2][order], s=0.8,
                           c=speed[fluid][order], cmap="viridis", vmin=0,
                           vmax=max(speed[fluid].max(initial=0), 0.1), lw=0)  # still water: 0-0.1
        ax.scatter(points[bodies, 0], points[bodies, 2], s=1.5, c="tab:red", lw=0)
        ax.set_aspect("equal")
        ax.set_title(f"t = {time:.2f} s", fontsize=9)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("z [m]")
        fig.colorbar(shown, ax=ax, label="speed [m/s]", fraction=0.03)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
