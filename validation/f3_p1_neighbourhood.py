"""What the fluid within reach of F3's sensor P1 is doing, frame by frame, in a particle model's
run of cases/kleefsman_3d.yaml (issue 39: why `mps`'s P1 falls at 0.015 m): the fluid particles
within r_e = 2.1 l0 of P1, their mean pressure, the share flagged as free surface, their mean
number density / n0 (n0 from the first frame), the nearest one's distance from the obstacle's
face in spacings and their mean speed; the wall particles in reach and their mean pressure; and
the top of the water in a box 4 spacings wide in front of P1; and, a spacing-free comparison
between runs, in slices 0.05 m long and 0.1 m across centred on y = 0.529 m: the mean pressure
under z = 0.05 m against the face (x 0.825-0.875 m), and the flow coming at it at x = 1 m (its
mean x velocity under z = 0.1 m and the 90th percentile of its particles' heights); and, 2 m
from the obstacle, the reservoir's (x > 2.5 m): the mean pressure under z = 0.05 m against the
weight of the water over it (rho g h, h the gauge at 2.638 m from the run's probes.csv), and the
share of its fluid off the free surface whose pressure is clamped at zero, and that fluid's mean
number density / n0. First, how far
behind the face the obstacle's outermost wall layer lies, and in each frame how many fluid
particles rest on the face's plane (within a hundredth of a spacing of it).

    /usr/bin/python3 validation/f3_p1_neighbourhood.py RUN_DIR SPACING [FROM TO]

RUN_DIR holds an `mps` run's .pvd and frames (which carry number_density and free_surface)."""
import os
import sys

import numpy as np

from frames import frame_series, read_frame
from kleefsman_figures import read_probes

P1 = np.array([0.8245, 0.529, 0.021])
FACE_X = 0.8245  # the obstacle's face towards the water; the obstacle (the case's box wall):
OBSTACLE_BACK_X, OBSTACLE_Y, OBSTACLE_HALF_WIDTH, OBSTACLE_TOP = 0.6635, 0.4965, 0.2015, 0.161
RESERVOIR_X = 2.5  # the water beyond it is the reservoir's, far from the obstacle
RHO_G = 1000 * 9.81


def mean_or_zero(values):
    return values.mean() if values.size else 0.0


def in_slice(points, fluid, x):
    """The fluid in the slice 0.05 m long about x, 0.1 m across about P1's y."""
    return fluid & (np.abs(points[:, 0] - x) < 0.025) & (np.abs(points[:, 1] - P1[1]) < 0.05)


def reservoir_figures(points, v, fluid, n0, weight):
    """The reservoir's part of a frame's line: its bottom pressure against the weight of the water
    over it, and the share of its fluid off the surface at p = 0 and that fluid's n / n0."""
    reservoir = fluid & (points[:, 0] > RESERVOIR_X)
    bottom = reservoir & (points[:, 2] < 0.05)
    interior = reservoir & (v["free_surface"] == 0)
    return (f"; reservoir: p under 0.05 m {mean_or_zero(v['pressure'][bottom]):5.0f} Pa "
            f"against rho g h {weight:5.0f} Pa, {mean_or_zero(v['pressure'][interior] <= 0):.3f} of it at p = 0, "
            f"n/n0 {mean_or_zero(v['number_density'][interior]) / n0:.4f}")


def main():
    run, spacing = sys.argv[1], float(sys.argv[2])
    start, end = (float(sys.argv[3]), float(sys.argv[4])) if len(sys.argv) > 4 else (0, 1e9)
    reach = 2.1 * spacing
    series = frame_series(run)
    points, v = read_frame(series[0][1], "kind", "number_density")
    n0 = np.median(v["number_density"][v["kind"] == 0])
    across = np.abs(points[:, 1] - OBSTACLE_Y) < OBSTACLE_HALF_WIDTH
    obstacle = (v["kind"] != 0) & (points[:, 0] < FACE_X) & (points[:, 0] > OBSTACLE_BACK_X) \
        & across & (points[:, 2] > 0) & (points[:, 2] < OBSTACLE_TOP)
    print(f"the obstacle's outermost wall layer: {(FACE_X - points[obstacle, 0].max()) / spacing:.2f} "
          "spacings behind the face")
    probes = read_probes(os.path.join(run, "probes.csv"))
    fields = ("pressure", "kind", "velocity", "number_density", "free_surface")
    for time, path in series:
        if not start <= time <= end:
            continue
        points, v = read_frame(path, *fields)
        fluid = v["kind"] == 0
        near = np.linalg.norm(points - P1, axis=1) < reach
        mine, walls = near & fluid, near & ~fluid
        box = fluid & (np.abs(points[:, 0] - FACE_X - 2 * spacing) < 2 * spacing) \
            & (np.abs(points[:, 1] - P1[1]) < 2 * spacing)
        top = points[box, 2].max() if box.any() else 0.0
        against, coming = in_slice(points, fluid, FACE_X + 0.025), in_slice(points, fluid, 1.0)
        bed = against & (points[:, 2] < 0.05)
        on_face = fluid & (np.abs(points[:, 0] - FACE_X) < 0.01 * spacing) \
            & (np.abs(points[:, 1] - OBSTACLE_Y) < OBSTACLE_HALF_WIDTH) & (points[:, 2] < OBSTACLE_TOP)
        low = coming & (points[:, 2] < 0.1)
        weight = RHO_G * np.interp(time, probes["time"], probes["g2638"])
        far = reservoir_figures(points, v, fluid, n0, weight)
        approach = (f"{on_face.sum()} fluid particles on the face's plane; against the face: p under 0.05 m {mean_or_zero(v['pressure'][bed]):5.0f} Pa; "
                    f"at x = 1 m: u_x {mean_or_zero(v['velocity'][low, 0]):+.2f} m/s, "
                    f"height {np.percentile(points[coming, 2], 90) if coming.any() else 0:.3f} m" + far)
        if not mine.any():
            print(f"t = {time:.3f} s: no fluid within reach of P1; " + approach)
            continue
        surface = v["free_surface"][mine].mean()
        density = v["number_density"][mine].mean() / n0
        print(f"t = {time:.3f} s: {mine.sum():3d} fluid particles, p {v['pressure'][mine].mean():6.0f} Pa, "
              f"surface {surface:.2f}, n/n0 {density:.3f}, nearest {(points[mine, 0] - FACE_X).min() / spacing:+.2f} "
              f"spacings off the face, speed {np.linalg.norm(v['velocity'][mine], axis=1).mean():.2f} m/s; "
              f"{walls.sum()} wall particles, p {mean_or_zero(v['pressure'][walls]):6.0f} Pa; "
              f"water's top in front {top:.3f} m; " + approach)


if __name__ == "__main__":
    main()
