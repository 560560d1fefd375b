#!/usr/bin/python3
"""Reading a finished run: its probes (probes.csv) with numpy and its frames (the ParaView
series' .vtp files) with VTK, outside sluice.

Runs cases/dam_break_2d.yaml into OUT with sluice.Simulation where OUT holds no run yet, or with
--rerun (0.05 m particles to 0.6 s: a few seconds), then reads what it wrote: the surge front
from probes.csv, and from the series' frames the water's particles at three times, coloured by
pressure. Writes OUT/read_a_run.png (or FIGURE) and prints the front's last reading.

usage: /usr/bin/python3 examples/python/read_a_run.py [--out DIR] [--figure PNG] [--rerun]
"""
import argparse
import os
import xml.etree.ElementTree as ElementTree

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import sluice
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def series(out, name):
    """[(time, path)] of the frames the series OUT/NAME.pvd lists."""
    root = ElementTree.parse(os.path.join(out, f"{name}.pvd")).getroot()
    return [(float(d.get("timestep")), os.path.join(out, d.get("file")))
            for d in root.iter("DataSet")]


def read_frame(path):
    """A frame's points (n x 3) and its point fields, by name."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    fields = data.GetPointData()
    return (vtk_to_numpy(data.GetPoints().GetData()),
            {fields.GetArrayName(k): vtk_to_numpy(fields.GetArray(k))
             for k in range(fields.GetNumberOfArrays())})


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "examples", "read_a_run"))
    parser.add_argument("--figure", help="the plot's path (default OUT/read_a_run.png)")
    parser.add_argument("--rerun", action="store_true", help="run the case even where OUT has it")
    args = parser.parse_args()
    case = sluice.Case.from_yaml(os.path.join(ROOT, "cases", "dam_break_2d.yaml"),
                                 set={"spacing": 0.05, "end_time": 0.6, "output_interval": 0.1})
    if args.rerun or not os.path.exists(os.path.join(args.out, f"{case.name}.pvd")):
        sluice.Simulation(case, out=args.out).run()

    probes = np.genfromtxt(os.path.join(args.out, "probes.csv"), delimiter=",", names=True)
    time, front = probes["time_s"], probes["front_m"]
    frames = series(args.out, case.name)
    picks = [frames[0], frames[len(frames) // 2], frames[-1]]

    fig, axes = plt.subplots(1, 4, figsize=(16, 3.6), gridspec_kw={"width_ratios": [1, 1, 1, 1.1]})
    axes[0].plot(time, front)
    axes[0].set_xlabel("t [s]")
    axes[0].set_ylabel("surge front [m] (probes.csv)")
    for ax, (t, path) in zip(axes[1:], picks):
        points, fields = read_frame(path)
        water = fields["kind"] == 0
        shown = ax.scatter(points[water, 0], points[water, 2], c=fields["pressure"][water],
                           s=4, cmap="viridis", vmin=0, vmax=20000)
        ax.set_title(f"t = {t:.2f} s")
        ax.set_aspect("equal")
        ax.set_xlim(0, 4)
        ax.set_ylim(0, 2.2)
    fig.colorbar(shown, ax=axes[-1], label="pressure [Pa]")
    fig.tight_layout()
    path = args.figure or os.path.join(args.out, "read_a_run.png")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=100)
    print(f"front at t = {time[-1]:.2f} s: {front[-1]:.3f} m; {len(frames)} frames; wrote {path}")


if __name__ == "__main__":
    main()
