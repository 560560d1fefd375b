#!/usr/bin/python3
"""The collapse of a dry granular column (issue 11) against Lube, Huppert, Sparks & Freundt
(Phys. Rev. E 72, 041301, 2005; quasi-2D channel): a column L0 wide and a L0 high released
against a wall spreads to a runout L_inf with (L_inf - L0) / L0 = 1.2 a for a below about 1.8
and 1.9 a^(2/3) above about 2.8. Runs cases/column_collapse_2d.yaml for several a, the
column's smaller side 20 grains across (the case's spacing), and plots the runout against a
with both laws and the final deposits. Writes docs/img/column_collapse.png and prints each
runout.

The deposit is the set of grains connected through contacts to the grain at the wall's foot
(grains thrown clear of it do not count, as in the experiments' measure of the front).

usage: /usr/bin/python3 validation/column_collapse.py [--no-run] [--aspect A ...]
"""
import glob
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from frames import read_frame
from runs import case_parser, run_case, require, save_figure, write_table

SPACING = 0.01     # the case's grain lattice [m]
SMALLER_SIDE = 20  # grains across the column's smaller side
# The 2D columns whose runs chose the rolling friction (docs/validation.md).
CALIBRATED = (0.5, 2.0)


def column_width(a):
    """L0 for aspect ratio a: the smaller side is SMALLER_SIDE grains."""
    return SMALLER_SIDE * SPACING * (1 if a >= 1 else 1 / a)


def lube(a):
    """Lube et al.'s two laws for (L_inf - L0) / L0."""
    return 1.2 * a, 1.9 * a ** (2 / 3)


def last_frame(out):
    """The grains' centres (x, y, z; y = 0 in 2D) and radii in the run's last frame."""
    frames = sorted(glob.glob(os.path.join(out, "frames", "*.vtp")))
    require(frames[-1] if frames else os.path.join(out, "frames"))
    points, fields = read_frame(frames[-1], "kind", "radius")
    fluid = fields["kind"] == 0
    return points[fluid], fields["radius"][fluid]


def deposit(points, radius):
    """The grains in contact (within a tenth of a radius), directly or through others, with the
    one nearest the wall's foot."""
    seen = np.zeros(len(points), bool)
    start = int(np.argmin(points[:, 0] + points[:, 2]))
    seen[start] = True
    stack = [start]
    while stack:
        i = stack.pop()
        near = np.linalg.norm(points - points[i], axis=1) < radius + 1.1 * radius[i]
        new = np.where(near & ~seen)[0]
        seen[new] = True
        stack.extend(new.tolist())
    return seen


def collapse(a, channel, args, ax_shape):
    """Runs (unless --no-run) the column of aspect ratio a, in 2D or (channel: its width [m])
    in 3D; returns its table row and its runout, and draws its deposit."""
    width = column_width(a)
    three_d = channel is not None
    if three_d:
        out = run_case("column_collapse_3d", args, [
            f"fluid.blocks.0.max=[{width:g},{channel:g},{a * width:g}]",
            f"domain.max=[1.0,{channel:g},0.5]", f"walls.0.max=[1.0,{channel:g},0.5]"],
            suffix=f"_3d_w{channel:g}_a{a:g}")
    else:
        out = run_case("column_collapse_2d", args,
                       [f"fluid.blocks.0.max=[{width:g},{a * width:g}]"], suffix=f"_a{a:g}")
    points, radius = last_frame(out)
    kept = deposit(points, radius)
    x, z = points[kept, 0], points[kept, 2]
    front = (x + radius[kept]).max()
    runout = (front - width) / width
    linear, power = lube(a)
    law = linear if a < 1.8 else power if a > 2.8 else None
    off = f"{100 * (runout / law - 1):+.1f} %" if law else \
        f"{100 * (runout / linear - 1):+.1f} % / {100 * (runout / power - 1):+.1f} %"
    role = "chose the rolling friction" if not three_d and a in CALIBRATED else "out of sample"
    across = "–"
    if three_d:  # the front of each slice two spacings wide across the channel
        y = points[kept, 1]
        slices = np.floor(y / (2 * SPACING)).astype(int)
        fronts = [(x + radius[kept])[slices == k].max() for k in np.unique(slices)]
        across = f"{min(fronts):.3f}-{max(fronts):.3f}"
    column = f"spheres (3D), channel {channel:g} m wide" if three_d else "discs (2D)"
    row = (f"| {column} | {a:g} | {width:g} | {len(points):,} | {kept.sum():,} | "
           f"{front:.3f} | {across} | {runout:.3f} | {linear:.3f} / {power:.3f} | {off} | {role} |")
    top = z + radius[kept]
    if three_d:  # the deposit's upper surface across the channel, in bins of one spacing
        bins = np.floor(x / SPACING).astype(int)
        surface = np.full(bins.max() + 1, np.nan)
        np.fmax.at(surface, bins, top)
        ax_shape.plot((np.arange(len(surface)) + 0.5) * SPACING / width, surface / width, "-",
                      lw=1.2, label=f"3D, channel {channel:g} m, a = {a:g} (upper surface)")
    else:
        order = np.argsort(x)
        ax_shape.plot(x[order] / width, top[order] / width, ".", ms=2, label=f"2D, a = {a:g}")
    return row, runout


def main():
    parser = case_parser("column_collapse_2d", __doc__.splitlines()[0])
    parser.add_argument("--aspect", type=float, nargs="+", default=[0.5, 1.0, 2.0, 3.0])
    parser.add_argument("--aspect-3d", type=float, nargs="+", default=[1.0])
    parser.add_argument("--channels", type=float, nargs="+", default=[0.1, 0.2],
                        help="the 3D channel's widths [m]")
    args = parser.parse_args()
    fig, (ax_runout, ax_shape) = plt.subplots(1, 2, figsize=(11, 4.2))
    rows = ["| column | a | L0 [m] | grains | in the deposit | front L_inf [m] | front of each "
            "2 cm slice across the channel [m] | (L_inf - L0)/L0 | Lube: 1.2 a / 1.9 a^(2/3) | "
            "from the law (a = 2: from each) | the run |",
            "|---|---|---|---|---|---|---|---|---|---|---|"]
    measured = {"2D": [], "3D": []}
    runs = [(a, None) for a in args.aspect] + \
        [(a, channel) for channel in args.channels for a in args.aspect_3d]
    for a, channel in runs:
        row, runout = collapse(a, channel, args, ax_shape)
        rows.append(row)
        measured["2D" if channel is None else "3D"].append((a, runout))
    write_table("validation.md", "column-collapse", "\n".join(rows))
    grid = np.linspace(0.3, 3.5, 100)
    ax_runout.plot(grid, 1.2 * grid, "k-", label="Lube et al. 2005: 1.2 a (a < 1.8)")
    ax_runout.plot(grid, 1.9 * grid ** (2 / 3), "k--", label="1.9 a^(2/3) (a > 2.8)")
    ax_runout.fill_between(grid, 0.85 * 1.2 * grid, 1.15 * 1.9 * grid ** (2 / 3), color="0.9",
                           label="15 % about the two laws")
    ax_runout.plot(*zip(*measured["2D"]), "ro", label="sluice, discs (2D)")
    if measured["3D"]:
        ax_runout.plot(*zip(*measured["3D"]), "bs", label="sluice, spheres (3D channel)")
    ax_runout.set_xlabel("aspect ratio a = H0 / L0")
    ax_runout.set_ylabel("runout (L_inf - L0) / L0")
    ax_runout.legend(fontsize=8)
    ax_runout.grid(alpha=0.3)
    ax_shape.set_xlabel("x / L0")
    ax_shape.set_ylabel("top of the grains / L0")
    ax_shape.set_title("final deposits", fontsize=10)
    ax_shape.legend(fontsize=8)
    ax_shape.grid(alpha=0.3)
    save_figure(fig, "column_collapse.png")


if __name__ == "__main__":
    main()
