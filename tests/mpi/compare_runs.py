#!/usr/bin/python3
"""Compares two runs' output of one case, the second split over ranks (tests/mpi): every CSV
table the first wrote (probes, energy, loads, each body's) must be in the second with the same
header and rows, each value within TOLERANCE of the first's, relative to the largest magnitude
of its column (a column of zeros: absolutely). The last frame of the second must be a .pvtp
whose pieces hold as many particles as the first's last frame (RANKS 1, a split run resumed
on one rank: a frame that does). Prints the largest relative
difference found, and exits 1 on any failure.

usage: compare_runs.py ONE_RANK_OUT SPLIT_OUT RANKS TOLERANCE
"""
import glob
import os
import re
import sys

import numpy as np


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def quantity(name):
    """The quantity a column is a component of: a vector's components (x, y, z; a quaternion's
    w too) and a body's drag, lift and side force are compared on the largest of them, since a
    component that should vanish (the sideways force on a box that floats upright) is noise.
    A moment goes with its force, as if over a metre (the bodies of these cases are a metre or
    less across)."""
    for load in ("_drag", "_lift", "_side"):
        if name.endswith(load):
            return name[: -len(load)] + " load"
    if len(name) > 1 and name[-1] in "xyzw":
        stem = name[:-1]
        return (stem[:-2] + "_f" if stem.endswith("_m") else stem) + " vector"
    return name


def read_table(path):
    with open(path) as f:
        header = f.readline().strip()
    return header, np.atleast_2d(np.genfromtxt(path, delimiter=",", skip_header=1))


def points_in(vtp):
    with open(vtp, "rb") as f:
        head = f.read(4096).decode("latin-1")
    return int(re.search(r'NumberOfPoints="(\d+)"', head).group(1))


def last_series_file(out):
    pvd = glob.glob(os.path.join(out, "*.pvd"))
    if len(pvd) != 1:
        fail(f"{out}: expected one .pvd, found {len(pvd)}")
    files = re.findall(r'file="([^"]+)"', open(pvd[0]).read())
    return os.path.join(out, files[-1])


def main():
    one, split, ranks, tolerance = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4])
    tables = [os.path.relpath(p, one) for p in glob.glob(os.path.join(one, "**", "*.csv"),
                                                         recursive=True)]
    if not tables:
        fail(f"{one} holds no table")
    worst = (0.0, "")
    for table in sorted(tables):
        other = os.path.join(split, table)
        if not os.path.exists(other):
            fail(f"the split run wrote no {table}")
        header, a = read_table(os.path.join(one, table))
        other_header, b = read_table(other)
        if header != other_header or a.shape != b.shape:
            fail(f"{table}: header or shape differs ({a.shape} against {b.shape})")
        names = header.split(",")
        largest = np.nanmax(np.abs(a), axis=0)
        scale = np.array([max(largest[k] for k in range(len(names))
                              if quantity(names[k]) == quantity(name)) for name in names])
        scale[scale == 0] = 1.0
        relative = np.nanmax(np.abs(a - b), axis=0) / scale
        column = int(np.argmax(relative))
        if relative[column] > worst[0]:
            worst = (float(relative[column]), f"{table} column {names[column]}")
    print(f"largest difference: {worst[0]:.3g} of its quantity's largest magnitude ({worst[1]})")
    if worst[0] > tolerance:
        fail(f"over the tolerance {tolerance:g}")

    whole, joined = last_series_file(one), last_series_file(split)
    if ranks == 1:  # a split run resumed on one rank
        if points_in(joined) != points_in(whole):
            fail(f"the last frame holds {points_in(joined)} particles, the one rank's {points_in(whole)}")
        print(f"last frame: {points_in(joined)} particles, as on one rank")
        return
    if not joined.endswith(".pvtp"):
        fail(f"the split run's last frame is {joined}, not a .pvtp")
    pieces = re.findall(r'Source="([^"]+)"', open(joined).read())
    if len(pieces) != ranks:
        fail(f"{joined} joins {len(pieces)} pieces, not {ranks}")
    count = sum(points_in(os.path.join(os.path.dirname(joined), p)) for p in pieces)
    if count != points_in(whole):
        fail(f"the pieces hold {count} particles, the one rank's frame {points_in(whole)}")
    print(f"last frame: {ranks} pieces, {count} particles, as on one rank")


if __name__ == "__main__":
    main()
