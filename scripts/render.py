#!/usr/bin/python3
"""`sluice render OUT`: PNG pictures of a run's frames, and with --movie an MP4 (ffmpeg).

Reads the series OUT/CASE.pvd and draws each frame's points: the water coloured by a field
(its magnitude, for a vector), walls light grey behind everything, bodies in darker greys (one
each, shaded), seen from the side (x-z), the top (x-y) or an isometric corner, the nearest
points drawn last. The points are splatted as discs into an image of their own (numpy), which
matplotlib frames with the time and a colour bar: 0.3 s for the 262,000 particles of the
benchmark case seen from the side, 0.5 s isometric (docs/performance.md). The colour scale
spans the field's 1st to 99th percentile over every frame's water, so that colours mean the
same in every picture. A grid model's (mac) frames are drawn from its grid: the water's cells
(level_set below 0) coloured by the field, the solid cells as walls.

Writes OUT/render/FIELD_VIEW_NNNNNN.png, and with --movie OUT/render/FIELD_VIEW.mp4.
Exit codes as sluice's: 2 for bad input (no series in OUT, an unknown field, no ffmpeg, a
--time that is not a number).

With --time T, one picture: the frame nearest T, its colour scale over that frame alone.

usage: /usr/bin/python3 scripts/render.py OUT [--field F] [--view side|top|iso] [--movie]
                                              [--width PIXELS] [--fps N] [--time T]
"""
import argparse
import glob
import os
import subprocess
import sys
import time
import xml.etree.ElementTree as ElementTree

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPPolyDataReader, vtkXMLPolyDataReader

# validation/frames.py reads a grid model's cells.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "validation"))
import frames as validation_frames  # noqa: E402

WALL, BACKGROUND = (0.82, 0.82, 0.82), (1.0, 1.0, 1.0)
BODY_GREYS = np.array([0.30, 0.46, 0.38, 0.54, 0.34])  # one per body, in turn
WATER = (0.16, 0.44, 0.78)  # where the frames hold no field
AIR = -1  # a grid's cell that is neither water nor solid: framed, not drawn
COS30, SIN30 = np.cos(np.pi / 6), np.sin(np.pi / 6)


class BadInput(Exception):
    pass


def series(out):
    """(case name, [(time, frame path)]) of the series in OUT."""
    found = sorted(glob.glob(os.path.join(out, "*.pvd")))
    if not found:
        raise BadInput(f"{out}: no run's series (CASE.pvd) here")
    if len(found) > 1:
        raise BadInput(f"{out}: several series ({', '.join(map(os.path.basename, found))}): "
                       "one run's output directory holds one")
    try:
        root = ElementTree.parse(found[0]).getroot()
    except ElementTree.ParseError as problem:
        raise BadInput(f"{found[0]}: not a readable series ({problem})")
    # A grid model's series lists its grid (.vti) beside each surface (.vtp): the grid, whose
    # cells hold the fields, stands for the time.
    by_time = {}
    for d in root.iter("DataSet"):
        t, path = float(d.get("timestep")), os.path.join(out, d.get("file"))
        if t not in by_time or path.endswith(".vti"):
            by_time[t] = path
    frames = sorted(by_time.items())
    if not frames:
        raise BadInput(f"{found[0]}: the series lists no frame")
    return os.path.splitext(os.path.basename(found[0]))[0], frames


def read_grid(path):
    """A grid model's frame as points: its cells' centres, `kind` 0 for the water's cells
    (level_set below 0), 1 for the solid ones and AIR for the rest, with the cells' fields."""
    centres, fields = validation_frames.read_grid(path, "pressure", "velocity", "level_set",
                                                  "solid")
    solid = fields.pop("solid") > 0
    water = (fields.pop("level_set") < 0) & ~solid
    fields["kind"] = np.where(water, 0, np.where(solid, 1, AIR)).astype(np.int32)
    return centres, fields


def read_frame(path):
    """A frame's points (n x 3) and its point fields by name (n or n x 3)."""
    if path.endswith(".vti"):
        return read_grid(path)
    reader = vtkXMLPPolyDataReader() if path.endswith(".pvtp") else vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    fields = data.GetPointData()
    points = data.GetPoints()
    if points is None:
        return np.zeros((0, 3)), {}
    return (vtk_to_numpy(points.GetData()).astype(np.float64),
            {fields.GetArrayName(k): vtk_to_numpy(fields.GetArray(k))
             for k in range(fields.GetNumberOfArrays())})


def projection(points, view):
    """The points' image coordinates (u right, v up) and their depth (larger: farther)."""
    x, y, z = points[:, 0], points[:, 1], points[:, 2]
    if view == "side":
        return x, z, y
    if view == "top":
        return x, y, -z
    return (x - y) * COS30, z + (x + y) * SIN30, x + y - z  # iso, from the low x and y corner


def scalar(values):
    return np.linalg.norm(values, axis=1) if values.ndim == 2 else values.astype(np.float64)


def lattice_spacing(points, fields):
    """The particles' spacing: the middle distance from a sample of the first frame's water
    (of every point, where there is no water: bodies alone) to its nearest other water point;
    a lattice's spacing, and a settled pool's (granular) too."""
    kind = fields.get("kind")
    if kind is not None and np.any(kind == 0):
        points = points[kind == 0]
    if len(points) < 2:
        return 0.01
    sample = points[np.linspace(0, len(points) - 1, min(len(points), 400)).astype(int)]
    nearest = np.full(len(sample), np.inf)
    for start in range(0, len(points), 20000):  # in blocks: 400 x 20000 distances at a time
        d = np.linalg.norm(sample[:, None, :] - points[None, start:start + 20000, :], axis=2)
        d[d < 1e-9] = np.inf  # the point itself
        nearest = np.minimum(nearest, d.min(axis=1))
    return float(np.median(nearest[np.isfinite(nearest)])) if np.isfinite(nearest).any() else 0.01


class Canvas:
    """The image's framing: every frame drawn over the first frame's extent."""

    def __init__(self, points, view, width, spacing):
        u, v, _ = projection(points, view)
        pad = 2 * spacing
        self.u0, self.v0 = u.min() - pad, v.min() - pad
        extent_u, extent_v = u.max() + pad - self.u0, v.max() + pad - self.v0
        self.width = width
        self.scale = width / extent_u  # pixels a metre
        self.height = max(1, int(np.ceil(extent_v * self.scale)))
        self.radius = max(1, int(np.ceil(0.6 * spacing * self.scale)))
        self.extent = (self.u0, self.u0 + extent_u, self.v0, self.v0 + self.height / self.scale)

    def draw(self, points, colours, behind, view):
        """An image (height x width x 3) of the points as discs: those `behind` (the walls) first,
        as a backdrop, then the others, the nearest drawn last. Each pixel takes the colour of
        the last point in that order whose disc covers it."""
        u, v, depth = projection(points, view)
        # Farthest first, so that the nearest overwrite them; the walls before everything, or
        # a 3D tank's near walls would hide the water.
        order = np.lexsort((-depth, ~behind))
        col = ((u[order] - self.u0) * self.scale).astype(np.int64)
        row = self.height - 1 - ((v[order] - self.v0) * self.scale).astype(np.int64)
        rank = np.arange(len(order))
        # The latest rank that covers each pixel, over the disc's offsets one at a time: within
        # one offset a pixel written twice keeps the later write, the larger rank.
        latest = np.full(self.height * self.width, -1, dtype=np.int64)
        r = self.radius
        for dr in range(-r, r + 1):
            for dc in range(-r, r + 1):
                if dr * dr + dc * dc > r * r:
                    continue
                rr, cc = row + dr, col + dc
                inside = (rr >= 0) & (rr < self.height) & (cc >= 0) & (cc < self.width)
                pixel = rr[inside] * self.width + cc[inside]
                latest[pixel] = np.maximum(latest[pixel], rank[inside])
        image = np.empty((self.height * self.width, 3))
        image[:] = BACKGROUND
        drawn = latest >= 0
        image[drawn] = colours[order][latest[drawn]]
        return image.reshape(self.height, self.width, 3)


def body_shades(points, index):
    """Each body point's lightness, 0.45 to 1: lit from above and in front, its normal taken
    from its offset from its body's centre over the body's half size along each axis."""
    light = np.array([-0.4, -0.7, 1.0]) / np.linalg.norm([-0.4, -0.7, 1.0])
    shade = np.ones(len(points))
    for b in np.unique(index):
        mine = index == b
        p = points[mine]
        centre = 0.5 * (p.min(axis=0) + p.max(axis=0))
        half = 0.5 * (p.max(axis=0) - p.min(axis=0))
        offset = np.divide(p - centre, half, out=np.zeros_like(p), where=half > 1e-12)
        # Raised to a power, so that a box's faces read flat (their offset's largest component
        # is 1, the others below it) while curved surfaces still shade smoothly.
        offset = np.sign(offset) * np.abs(offset) ** 6
        normal = offset / np.maximum(np.linalg.norm(offset, axis=1), 1e-12)[:, None]
        shade[mine] = 0.45 + 0.55 * np.clip(normal @ light, 0, 1)
    return shade


def colours_of(points, fields, field, norm, cmap):
    """Each point's colour: water by the field (a grid model's surface, which has none, in one
    blue), walls light grey, bodies in darker greys, a grey of their own each (by the frame's
    `body` index) and shaded, so that bodies side by side or stacked read."""
    n = len(points)
    kind = fields.get("kind", np.zeros(n, dtype=np.int32))
    colours = np.empty((n, 3))
    water = kind == 0
    colours[water] = cmap(norm(scalar(fields[field])[water]))[:, :3] if field else WATER
    colours[kind == 1] = WALL
    body = (kind == 2) | (kind == 3)
    if np.any(body):
        index = fields.get("body", np.zeros(n, dtype=np.int32))[body].astype(np.int64)
        # At most 0.54 x 1.45 = 0.78: darker than the walls (0.82) wherever lit.
        grey = BODY_GREYS[index % len(BODY_GREYS)] * 1.45 * body_shades(points[body], index)
        colours[body] = np.clip(grey, 0, 1)[:, None]
    return colours


def first_with_water(frames, first_points, first_fields):
    """The path, points and fields of the first frame with water (a case an inlet fills starts
    without); the first frame where none has any (bodies alone: one colour, no colour scale)."""
    for k, (_, path) in enumerate(frames):
        points, fields = (first_points, first_fields) if k == 0 else read_frame(path)
        if np.any(fields.get("kind", np.zeros(len(points), np.int32)) == 0):
            return path, points, fields
    return frames[0][1], first_points, first_fields


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", help="a run's output directory")
    parser.add_argument("--field", default="velocity", help="the field that colours the water")
    parser.add_argument("--view", default="side", choices=("side", "top", "iso"))
    parser.add_argument("--movie", action="store_true", help="an MP4 of the frames (ffmpeg)")
    parser.add_argument("--width", type=int, default=1280, help="the pictures' width [px]")
    parser.add_argument("--fps", type=int, default=10, help="the movie's frames a second")
    parser.add_argument("--time", help="one picture: the frame nearest this time [s]")
    args = parser.parse_args()
    if args.width < 16:
        raise BadInput(f"--width: {args.width} pixels is too narrow (16 at least)")
    name, frames = series(args.out)
    first_points, first_fields = read_frame(frames[0][1])
    # The first frame with water gives the fields and the particles' spacing.
    water_path, water_points, water_fields = first_with_water(frames, first_points, first_fields)
    kind = water_fields.get("kind", np.zeros(len(water_points), np.int32))
    field = args.field if np.any(kind == 0) and set(water_fields) - {"kind", "body"} else None
    if field and field not in water_fields:
        raise BadInput(f"--field: {water_path} has no field '{args.field}'; it has "
                       + ", ".join(sorted(water_fields)))
    if args.movie and subprocess.run(["which", "ffmpeg"], capture_output=True).returncode:
        raise BadInput("--movie: ffmpeg not found (Debian's ffmpeg; scripts/setup.sh installs it)")
    # Each frame keeps its place in the series: its picture's number.
    shown_frames = list(enumerate(frames))
    if args.time is not None:
        if args.movie:
            raise BadInput("--time: one picture makes no movie; give --time or --movie")
        try:
            wanted = float(args.time)
        except ValueError:
            raise BadInput(f"--time: expected a time in seconds, got '{args.time}'")
        if not np.isfinite(wanted):
            raise BadInput(f"--time: expected a finite time in seconds, got '{args.time}'")
        shown_frames = [min(shown_frames, key=lambda item: abs(item[1][0] - wanted))]
    # The colour scale over every drawn frame's water.
    samples = [np.zeros(0)]
    for _, (_, path) in shown_frames if field else []:
        _, fields = read_frame(path)
        water = fields.get("kind", np.zeros(len(fields[field]), np.int32)) == 0
        samples.append(scalar(fields[field])[water])
    values = np.concatenate(samples)
    low, high = (np.percentile(values, [1, 99]) if values.size else (0.0, 1.0))
    norm = matplotlib.colors.Normalize(vmin=low, vmax=max(high, low + 1e-12))
    cmap = matplotlib.colormaps["viridis"]
    canvas = Canvas(first_points, args.view, args.width,
                    lattice_spacing(water_points, water_fields))
    target = os.path.join(args.out, "render")
    os.makedirs(target, exist_ok=True)
    stem = f"{field or 'points'}_{args.view}"
    if args.time is None:
        for old in glob.glob(os.path.join(target, f"{stem}_*.png")):
            os.remove(old)
    dpi = 100
    seconds = []
    written = []
    for k, (t, path) in shown_frames:
        start = time.perf_counter()
        points, fields = read_frame(path)
        kind = fields.get("kind", np.zeros(len(points), np.int32))
        shown = kind != AIR
        colours = colours_of(points, fields, field, norm, cmap)
        image = canvas.draw(points[shown], colours[shown], kind[shown] == 1, args.view)
        fig = plt.figure(figsize=((canvas.width + 160) / dpi, (canvas.height + 70) / dpi), dpi=dpi)
        ax = fig.add_axes([0, 0, canvas.width / (canvas.width + 160),
                           canvas.height / (canvas.height + 70)])
        ax.imshow(image, extent=canvas.extent, interpolation="nearest")
        ax.set_axis_off()
        fig.text(0.01, 0.985, f"{name}   t = {t:.3f} s   ({args.view})", va="top")
        if field:
            bar = fig.add_axes([canvas.width / (canvas.width + 160) + 0.02, 0.1, 0.025, 0.75])
            fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), cax=bar,
                         label=field)
        written.append(os.path.join(target, f"{stem}_{k:06d}.png"))
        fig.savefig(written[-1], dpi=dpi)
        plt.close(fig)
        seconds.append(time.perf_counter() - start)
    if args.time is not None:
        print(f"render: {written[0]} (t = {shown_frames[0][1][0]:.6g} s)")
    else:
        print(f"render: {len(frames)} frames of {name} into {target}/{stem}_*.png "
              f"({np.median(seconds):.2f} s a frame, median; {len(first_points)} points in the "
              "first)")
    if args.movie:
        movie = os.path.join(target, f"{stem}.mp4")
        subprocess.run(["ffmpeg", "-y", "-loglevel", "error", "-framerate", str(args.fps), "-i",
                        os.path.join(target, f"{stem}_%06d.png"), "-vf",
                        "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", movie],
                       check=True)
        print(f"render: {movie}")


if __name__ == "__main__":
    try:
        main()
    except BadInput as problem:
        print(f"error: {problem}", file=sys.stderr)
        sys.exit(2)
