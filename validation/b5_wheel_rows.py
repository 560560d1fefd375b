"""B5 (issue 39): where a constraint fluid's lift on the fording vehicle's wheels sits.

Reads a frame of each `constraint` run of validation/fording_convergence.py (one per spacing)
and prints, for each wheel at the frame's time, the fluid particles within 1.5 spacings of it
(their density over the rest density and their pressure, all of them and those below the axle)
and the wheel's own particles, whose density rows push on it (their rows' pressure, all of them
and those of the rim below z - 0.15 m, the part that rests on the bed).

  /usr/bin/python3 validation/b5_wheel_rows.py /work/runs/b5_constraint_0.04 \
      /work/runs/b5_constraint_0.02 --frame 30
"""
import argparse
import csv
import os

import numpy as np
from frames import read_frame

WHEELS = ("fl", "fr", "rl", "rr")
RADIUS, HALF_WIDTH = 0.2, 0.06  # cases/fording.yaml's wheels
REST_DENSITY = 1000.0


def wheel_centre(run, wheel, time):
    rows = list(csv.DictReader(open(os.path.join(run, "bodies", f"wheel_{wheel}.csv"))))
    row = min(rows, key=lambda r: abs(float(r["time"]) - time))
    return np.array([float(row["x"]), float(row["y"]), float(row["z"])])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+", help="constraint run directories of B5")
    parser.add_argument("--frame", type=int, default=30, help="frame number (30: t = 1.5 s)")
    args = parser.parse_args()
    for run in args.runs:
        spacing = float(run.rstrip("/").rsplit("_", 1)[1])
        points, fields = read_frame(os.path.join(run, "frames", f"frame_{args.frame:06d}.vtp"),
                                    "kind", "density", "pressure")
        time = args.frame * 0.05  # the case's output interval
        print(f"{run}, t = {time:g} s")
        kind, density, pressure = fields["kind"], fields["density"], fields["pressure"]
        for wheel in WHEELS:
            rel = points - wheel_centre(run, wheel, time)
            radial = np.hypot(rel[:, 0], rel[:, 2])
            reach = 1.5 * spacing
            near = ((kind == 0) & (np.abs(rel[:, 1]) < HALF_WIDTH + reach)
                    & (radial < RADIUS + reach))
            low = near & (rel[:, 2] < -0.1)
            own = (kind == 2) & (np.abs(rel[:, 1]) < HALF_WIDTH + 1e-3) & (radial < RADIUS + 1e-3)
            rim = own & (rel[:, 2] < -0.15)
            print(f"  wheel {wheel}: water near {near.sum()}, "
                  f"density {density[near].mean() / REST_DENSITY:.3f} "
                  f"(below the axle {density[low].mean() / REST_DENSITY:.3f}), "
                  f"pressure {pressure[near].mean():.0f} Pa "
                  f"(below the axle {pressure[low].mean():.0f}); "
                  f"its own rows: mean {pressure[own].mean():.0f} Pa, "
                  f"rim on the bed ({rim.sum()}) mean {pressure[rim].mean():.0f} Pa, "
                  f"max {pressure[rim].max():.0f} Pa")


if __name__ == "__main__":
    main()
