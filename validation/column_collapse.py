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
from runs import case_parser, run_case, require, save_figure

SPACING = 0.01     # the case's grain lattice [m]
SMALLER_SIDE = 20  # grains across the column's smaller side


def column_width(a):
    """L0 for aspect ratio a: the smaller side is SMALLER_SIDE grains."""
    return SMALLER_SIDE * SPACING * (1 if a >= 1 else 1 / a)


def lube(a):
    """Lube et al.'s two laws for (L_inf - L0) / L0."""
    return 1.2 * a, 1.9 * a ** (2 / 3)


def last_frame(out):
    frames = sorted(glob.glob(os.path.join(out, "frames", "*.vtp")))
    require(frames[-1] if frames else os.path.join(out, "frames"))
    points, fields = read_frame(frames[-1], "kind", "radius")
    fluid = fields["kind"] == 0
    return points[fluid, 0], points[fluid, 2], fields["radius"][fluid]


def deposit(x, z, radius):
    """The grains in contact (within a tenth of a radius), directly or through others, with the
    one nearest the wall's foot."""
    seen = np.zeros(len(x), bool)
    start = int(np.argmin(x + z))
    seen[start] = True
    stack = [start]
    while stack:
        i = stack.pop()
        near = np.hypot(x - x[i], z - z[i]) < radius + 1.1 * radius[i]
        new = np.where(near & ~seen)[0]
        seen[new] = True
        stack.extend(new.tolist())
    return seen


def main():
    parser = case_parser("column_collapse_2d", __doc__.splitlines()[0])
    parser.add_argument("--aspect", type=float, nargs="+", default=[0.5, 1.0, 2.0, 3.0])
    args = parser.parse_args()
    fig, (ax_runout, ax_shape) = plt.subplots(1, 2, figsize=(11, 4.2))
    measured = []
    for a in args.aspect:
        width = column_width(a)
        out = run_case("column_collapse_2d", args,
                       [f"fluid.blocks.0.max=[{width:g},{a * width:g}]"], suffix=f"_a{a:g}")
        x, z, radius = last_frame(out)
        kept = deposit(x, z, radius)
        front = (x[kept] + radius[kept]).max()
        runout = (front - width) / width
        linear, power = lube(a)
        print(f"a = {a:g}: L0 = {width:g} m, {len(x)} grains; (L_inf - L0)/L0 = {runout:.3f} "
              f"(Lube: 1.2 a = {linear:.3f}, 1.9 a^(2/3) = {power:.3f}); {kept.sum()} grains in "
              f"the deposit")
        measured.append((a, runout))
        order = np.argsort(x[kept])
        ax_shape.plot(x[kept][order] / width, (z[kept] + radius[kept])[order] / width, ".",
                      ms=2, label=f"a = {a:g}")
    grid = np.linspace(0.3, 3.5, 100)
    ax_runout.plot(grid, 1.2 * grid, "k-", label="Lube et al. 2005: 1.2 a (a < 1.8)")
    ax_runout.plot(grid, 1.9 * grid ** (2 / 3), "k--", label="1.9 a^(2/3) (a > 2.8)")
    ax_runout.fill_between(grid, 0.85 * 1.2 * grid, 1.15 * 1.9 * grid ** (2 / 3), color="0.9",
                           label="15 % about the two laws")
    ax_runout.plot([a for a, _ in measured], [r for _, r in measured], "ro", label="sluice")
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
