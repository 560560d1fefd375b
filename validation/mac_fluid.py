#!/usr/bin/python3
"""The grid model (mac) in F2 and F4 of VALIDATION.md.

F2: runs cases/dam_break_2d.yaml with mac at cells of 0.05 and 0.025 m to 0.75 s and plots their
surge fronts beside those of the particle models (the runs of validation/constraint_fluid.py,
reused when present, else run) and Koshizuka & Oka's (1996) into docs/img/f2_mac_front.png,
printing each RMS difference over t in [0, 0.70] s and the water's area lost by 0.7 s.

F4: runs cases/lid_driven_cavity_2d.yaml (Re = 100) to 15 s on 32 x 32, 64 x 64 and 128 x 128
cells, reads the last grid frame and plots u on x = 0.5 and v on y = 0.5 against Ghia, Ghia &
Shin (1982) into docs/img/f4_mac_profiles.png, and writes the largest difference at their points,
the steps and the wall time into docs/validation.md's table f4-mac.

usage: /usr/bin/python3 validation/mac_fluid.py [--no-run] [--f4-only | --f2-only]
"""
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from constraint_fluid import MODELS, out_dir
from constraint_fluid import run as run_particle_model
from dam_break_2d import read_reference, rms_error
from probes_csv import read_probe
from runs import ROOT, require, save_figure, write_table
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLImageDataReader

SLUICE = os.path.join(ROOT, "build", "release", "sluice")
F2_CELLS = (0.05, 0.025)
F4_CELLS = (32, 64, 128)


def run(case, out, sets, no_run):
    """Runs cases/<case>.yaml into out with the --set items (unless no_run); returns its
    statistics."""
    stats = os.path.join(out, "stats.json")
    if not no_run:
        command = [SLUICE, "run", os.path.join(ROOT, "cases", case), "--out", out, "--stats", stats]
        command += [item for s in sets for item in ("--set", s)]
        subprocess.run(command, cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    require(stats)
    with open(stats) as f:
        return json.load(f)


def last_grid(out):
    """The cell arrays of the last .vti listed in the output's .pvd: (cells per axis, origin,
    spacing, velocity [n, 3])."""
    pvd = [name for name in os.listdir(out) if name.endswith(".pvd")]
    require(os.path.join(out, pvd[0] if pvd else "*.pvd"))
    grids = [d.get("file") for d in ElementTree.parse(os.path.join(out, pvd[0])).getroot()
             .iter("DataSet") if d.get("file").endswith(".vti")]
    reader = vtkXMLImageDataReader()
    reader.SetFileName(os.path.join(out, grids[-1]))
    reader.Update()
    image = reader.GetOutput()
    extent = image.GetExtent()
    cells = (extent[1] - extent[0], extent[5] - extent[4])  # x and z (a 2D grid)
    velocity = vtk_to_numpy(image.GetCellData().GetArray("velocity"))
    return cells, velocity.reshape(cells[1], cells[0], 3)  # [z, x, component]


def read_ghia():
    rows = [line.split() for line in open(os.path.join(ROOT, "validation", "data",
                                                       "ghia_1982_re100.tsv"))
            if line.strip() and not line.startswith("#")]
    u = np.array([(float(c), float(v)) for line, c, v in rows if line == "u"])
    v = np.array([(float(c), float(v)) for line, c, v in rows if line == "v"])
    return u, v


def centre_lines(velocity, n):
    """u on x = 0.5 and v on z = 0.5 from the cell-centred velocities (the mean of the two
    middle columns or rows), at the cell centres."""
    centres = (np.arange(n) + 0.5) / n
    u = 0.5 * (velocity[:, n // 2 - 1, 0] + velocity[:, n // 2, 0])
    v = 0.5 * (velocity[n // 2 - 1, :, 2] + velocity[n // 2, :, 2])
    return centres, u, v


def threads(stats):
    """'1 thread', '2 threads' from a run's statistics."""
    n = stats.get("threads", 0)
    return f"{n} thread" + ("" if n == 1 else "s")


def f4(no_run):
    ghia_u, ghia_v = read_ghia()
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.4))
    left.plot(ghia_u[:, 1], ghia_u[:, 0], "ko", label="Ghia, Ghia & Shin 1982")
    right.plot(ghia_v[:, 0], ghia_v[:, 1], "ko", label="Ghia, Ghia & Shin 1982")
    rows = ["| cells | largest difference | steps | wall time |", "|---|---|---|---|"]
    for n, colour in zip(F4_CELLS, ("tab:orange", "tab:blue", "tab:green")):
        out = os.path.join(ROOT, "out", "validation", f"mac_f4_{n}")
        stats = run("lid_driven_cavity_2d.yaml", out, [f"model.cell_size={1 / n}"], no_run)
        _, velocity = last_grid(out)
        centres, u, v = centre_lines(velocity, n)
        inner_u = ghia_u[(ghia_u[:, 0] > 0) & (ghia_u[:, 0] < 1)]
        inner_v = ghia_v[(ghia_v[:, 0] > 0) & (ghia_v[:, 0] < 1)]
        worst = max(np.abs(np.interp(inner_u[:, 0], centres, u) - inner_u[:, 1]).max(),
                    np.abs(np.interp(inner_v[:, 0], centres, v) - inner_v[:, 1]).max())
        print(f"F4 mac {n} x {n}: largest difference from Ghia {worst:.4f} of the lid speed; "
              f"wall {stats['wall_seconds']:.1f} s, {stats['steps']} steps")
        rows.append(f"| {n} x {n} | {worst:.4f} | {stats['steps']} | "
                    f"{stats['wall_seconds']:.1f} s ({threads(stats)}) |")
        left.plot(u, centres, "-", color=colour, label=f"sluice mac, {n} x {n} (largest diff. "
                                                      f"{worst:.3f})")
        right.plot(centres, v, "-", color=colour, label=f"sluice mac, {n} x {n}")
    left.set_xlabel("u on x = 0.5 [lid speed]")
    left.set_ylabel("y")
    right.set_xlabel("x")
    right.set_ylabel("v on y = 0.5 [lid speed]")
    for axis in (left, right):
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    fig.suptitle("F4: lid-driven cavity, Re = 100, grid model (mac) at 15 s")
    save_figure(fig, "f4_mac_profiles.png")
    write_table("validation.md", "f4-mac", "\n".join(rows) + "\n")


def f2(no_run):
    reference = read_reference()
    fig = plt.figure(figsize=(6.4, 4.4))
    plt.plot([t for t, _ in reference], [x for _, x in reference], "ko",
             label="experiment (Koshizuka & Oka 1996)")
    for model, spacing, colour in MODELS:
        # validation/constraint_fluid.py's runs, reused when they are there.
        done = os.path.exists(os.path.join(out_dir(model, spacing), "stats.json"))
        out, _ = run_particle_model(model, spacing, no_run or done)
        times, fronts = read_probe(os.path.join(out, "probes.csv"), "front")
        rms, _ = rms_error(times, fronts, reference)
        plt.plot(times, fronts, "-", color=colour, lw=1,
                 label=f"sluice {model}, dx = {spacing} m (RMS {rms:.2f} m)")
    for cell, style in zip(F2_CELLS, ("--", "-")):
        out = os.path.join(ROOT, "out", "validation", f"mac_f2_{cell}")
        stats = run("dam_break_2d.yaml", out, ["model.name=mac", f"spacing={cell}",
                                               "end_time=0.75", "probe_interval=0.005"], no_run)
        times, fronts = read_probe(os.path.join(out, "probes.csv"), "front")
        rms, count = rms_error(times, fronts, reference)
        print(f"F2 mac, cells of {cell} m: front RMS {rms:.3f} m over {count} points; wall "
              f"{stats['wall_seconds']:.1f} s, {stats['steps']} steps")
        plt.plot(times, fronts, style, color="k", lw=1.6,
                 label=f"sluice mac, cells of {cell} m (RMS {rms:.2f} m)")
    plt.axvline(0.70, color="0.7", lw=0.8)
    plt.xlabel("time [s]")
    plt.ylabel("surge front x [m]")
    plt.title("F2: 2D dam break, the grid model beside the particle models")
    plt.legend(loc="upper left", fontsize=7)
    plt.grid(alpha=0.3)
    save_figure(fig, "f2_mac_front.png")


def main():
    no_run = "--no-run" in sys.argv
    if "--f2-only" not in sys.argv:
        f4(no_run)
    if "--f4-only" not in sys.argv:
        f2(no_run)


if __name__ == "__main__":
    main()
