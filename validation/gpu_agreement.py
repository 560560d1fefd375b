#!/usr/bin/python3
"""The GPU's answers against the CPU's over time (issue 16): F2's surge front at two spacings
with Koshizuka & Oka's experiment, and the bench case's fluid energy, from the runs that
bench/run_gpu_agreement.sh makes on a GPU machine (by default the H100's, kept in
validation/data/gpu_h100/). Writes docs/img/gpu_cpu_agreement.png and prints, for each pair, the
largest difference between the GPU's and the CPU's curves and each front's RMS error against the
experiment.

usage: /usr/bin/python3 validation/gpu_agreement.py [DIR]
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from dam_break_2d import read_reference, rms_error
from probes_csv import read_probe
from runs import ROOT, require, save_figure

SPACINGS = ("0.025", "0.0125")
DEVICES = (("gpu", "-", "GPU (H100)"), ("cpu", "--", "CPU (16 threads)"))


def read_column(path, name):
    """Time and one column of an energy.csv, by its header name."""
    times, values = [], []
    with open(path) as f:
        for row in csv.DictReader(f):
            times.append(float(row["time"]))
            values.append(float(row[name]))
    return times, values


def largest_difference(a, b):
    """The largest |a - b| over the rows the two runs share (both write the same times)."""
    return max(abs(x - y) for x, y in zip(a, b))


def both_devices(folder, name, read):
    """{device: (times, values)} of FOLDER/NAME_DEVICE.csv for the GPU and the CPU, each file read
    by read(path)."""
    runs = {}
    for device, _, _ in DEVICES:
        path = os.path.join(folder, f"{name}_{device}.csv")
        require(path)
        runs[device] = read(path)
    return runs


def finish_axes(axes, ylabel, title, fontsize):
    axes.set_xlabel("time [s]")
    axes.set_ylabel(ylabel)
    axes.set_title(title)
    axes.legend(loc="upper left", fontsize=fontsize)
    axes.grid(alpha=0.3)


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "validation", "data",
                                                                  "gpu_h100")
    reference = read_reference()
    fig, (front_axes, energy_axes) = plt.subplots(1, 2, figsize=(11, 4.2))
    front_axes.plot([t for t, _ in reference], [x for _, x in reference], "ko", ms=4,
                    label="experiment (Koshizuka & Oka 1996)")
    for spacing, colour in zip(SPACINGS, ("tab:blue", "tab:orange")):
        fronts = both_devices(folder, f"f2_{spacing}", lambda path: read_probe(path, "front"))
        for device, style, label in DEVICES:
            times, front = fronts[device]
            rms, _ = rms_error(times, front, reference)
            print(f"F2, {spacing} m, {device}: front RMS {rms:.4f} m against the experiment")
            front_axes.plot(times, front, style, color=colour, lw=1.2,
                            label=f"{label}, dx = {spacing} m (RMS {rms:.3f} m)")
        apart = largest_difference(fronts["gpu"][1], fronts["cpu"][1])
        print(f"F2, {spacing} m: GPU and CPU fronts at most {apart * 1000:.1f} mm apart")
    finish_axes(front_axes, "surge front x [m]", "F2: 2D dam break, GPU and CPU", 7)

    energies = both_devices(folder, "bench_0.02",
                            lambda path: read_column(path, "fluid_kinetic"))
    for device, style, label in DEVICES:
        times, kinetic = energies[device]
        energy_axes.plot(times, kinetic, style, color="tab:blue" if device == "gpu" else "k",
                         lw=1.2, label=label)
    apart = largest_difference(energies["gpu"][1], energies["cpu"][1])
    print(f"bench case, 0.02 m: GPU and CPU kinetic energy at most {apart:.3f} J apart "
          f"(peak {max(energies['cpu'][1]):.2f} J)")
    finish_axes(energy_axes, "fluid kinetic energy [J]", "3D bench case at 0.02 m, GPU and CPU",
                8)
    save_figure(fig, "gpu_cpu_agreement.png")


if __name__ == "__main__":
    main()
