#!/usr/bin/python3
"""Why `penalty-sph` has no open boundaries: its walls drag a current to a stop (issue 43).

Runs cases/open_channel_2d.yaml's water (0.3 m deep, 3 m long, moving at 0.3 m/s at the start)
with its inlet and outlet replaced by a periodic x and no force along the channel, so that a
bed without friction keeps the water's speed: with `wcsph` (its free-slip bed), with
`penalty-sph` (seed 002's penalty walls), and with `penalty-sph` with no no-slip traction
(model.wall_friction 1e-12 Pa s), to 3 s. Writes docs/validation.md's table
penalty-bed-drag: the water's mean speed along the channel every half second.

usage: /usr/bin/python3 validation/penalty_bed_drag.py [--no-run]
"""
import glob
import os

import numpy as np
from frames import read_frame
from runs import case_parser, run_model, write_table

CASE = "open_channel_2d"
END, EVERY = 3.0, 0.5
PERIODIC = ["walls=[{type: tank, min: [0, 0], max: [3, 0.6], open: [x-, x+]}]",
            "boundaries=[{type: periodic, axis: x}]", "probes=[]", f"output_interval={EVERY}"]
RUNS = [("`wcsph`, free-slip bed", "wcsph"),
        ("`penalty-sph`", "penalty-sph"),
        ("`penalty-sph`, no no-slip traction", "penalty-sph+wall_friction=1.0e-12")]


def mean_speeds(out):
    """The fluid's mean velocity along x in each frame of the run in out."""
    speeds = []
    for path in sorted(glob.glob(os.path.join(out, "frames", "frame_*.vtp"))):
        _, fields = read_frame(path, "kind", "velocity")
        speeds.append(float(np.mean(fields["velocity"][fields["kind"] == 0, 0])))
    return speeds


def main():
    parser = case_parser(CASE, __doc__)
    parser.set_defaults(out=os.path.join("out", "validation", "penalty_bed_drag"))
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()
    args.resume = False
    columns = []
    for label, model in RUNS:
        out = os.path.join(args.out, model.replace("+", "_").replace("=", "_"))
        if not args.no_run:
            run_model(CASE, out, model, 0.02, END, args, PERIODIC)
        columns.append(mean_speeds(out))
    frames = min(len(c) for c in columns)
    lines = ["| t [s] | " + " | ".join(label for label, _ in RUNS) + " |",
             "|---|" + "---|" * len(RUNS)]
    for k in range(frames):
        lines.append(f"| {k * EVERY:.1f} | " + " | ".join(f"{c[k]:.3f}" for c in columns) + " |")
    write_table("validation.md", "penalty-bed-drag", "\n".join(lines))


if __name__ == "__main__":
    main()
