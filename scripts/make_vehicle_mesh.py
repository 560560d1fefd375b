#!/usr/bin/env python3
"""Writes cases/meshes/vehicle_chassis.obj, the chassis of cases/fording_mesh.yaml: the
primitive chassis of cases/fording.yaml (1.0 x 0.5 x 0.25 m, its origin at the box's centre) with
a raked nose and a sloped bonnet, as a closed triangle mesh. The side profile (x forward, z up)
is extruded across the 0.5 m width. Made by this project; standard library only.

usage: python3 scripts/make_vehicle_mesh.py [OUT.obj]
"""
import os
import sys

# The side profile, counter-clockwise seen from +y: bottom, raked nose, bonnet, windscreen, roof.
PROFILE = [(-0.5, -0.125), (0.38, -0.125), (0.5, -0.04), (0.5, 0.02), (0.25, 0.06),
           (0.1, 0.125), (-0.5, 0.125)]
HALF_WIDTH = 0.25


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "cases", "meshes",
                                                             "vehicle_chassis.obj")
    n = len(PROFILE)
    # Vertices 1..n on the side y = -w, n+1..2n on the side y = +w (OBJ counts from 1).
    vertices = [(x, -HALF_WIDTH, z) for x, z in PROFILE] + [(x, HALF_WIDTH, z) for x, z in PROFILE]
    a = lambda i: 1 + i % n
    b = lambda i: 1 + n + i % n
    faces = []
    for i in range(1, n - 1):  # the two sides, fans of the convex profile, wound oppositely
        faces.append((a(0), a(i), a(i + 1)))
        faces.append((b(0), b(i + 1), b(i)))
    for i in range(n):  # the band round the profile, each quad as two triangles
        faces.append((a(i + 1), a(i), b(i)))
        faces.append((a(i + 1), b(i), b(i + 1)))
    with open(out, "w") as f:
        f.write("# sluice: the fording vehicle's chassis (scripts/make_vehicle_mesh.py), metres\n")
        for v in vertices:
            f.write("v {:.4f} {:.4f} {:.4f}\n".format(*v))
        for t in faces:
            f.write("f {} {} {}\n".format(*t))
    print(f"wrote {out}: {len(vertices)} vertices, {len(faces)} triangles")


if __name__ == "__main__":
    main()
