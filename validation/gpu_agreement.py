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


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "validation", "data",
                                                                  "gpu_h100")
    reference = read_reference()
    fig, (front_axes, energy_axes) = plt.subplots(1, 2, figsize=(11, 4.2))
    front_axes.plot([t for t, _ in reference], [x for _, x in reference], "ko", ms=4,
                    label="experiment (Koshizuka & Oka 1996)")
    for spacing, colour in zip(SPACINGS, ("tab:blue", "tab:orange")):
        fronts = {}
        for device, style, label in DEVICES:
            path = os.path.join(folder, f"f2_{spacing}_{device}.csv")
            require(path)
            times, front = read_probe(path, "front")
            fronts[device] = front
            rms, _ = rms_error(times, front, reference)
            print(f"F2, {spacing} m, {device}: front RMS {rms:.4f} m against the experiment")
            front_axes.plot(times, front, style, color=colour, lw=1.2,
                            label=f"{label}, dx = {spacing} m (RMS {rms:.3f} m)")
        print(f"F2, {spacing} m: GPU and CPU fronts at most "
              f"{largest_difference(fronts['gpu'], fronts['cpu']) * 1000:.1f} mm apart")
    front_axes.set_xlabel("time [s]")
    front_axes.set_ylabel("surge front x [m]")
    front_axes.set_title("F2: 2D dam break, GPU and CPU")
    front_axes.legend(loc="upper left", fontsize=7)
    front_axes.grid(alpha=0.3)

    energies = {}
    for device, style, label in DEVICES:
        path = os.path.join(folder, f"bench_0.02_{device}.csv")
        require(path)
        times, kinetic = read_column(path, "fluid_kinetic")
        energies[device] = kinetic
        energy_axes.plot(times, kinetic, style, color="tab:blue" if device == "gpu" else "k",
                         lw=1.2, label=label)
    peak = max(energies["cpu"])
    print(f"bench case, 0.02 m: GPU and CPU kinetic energy at most "
          f"{largest_difference(energies['gpu'], energies['cpu']):.3f} J apart "
          f"(peak {peak:.2f} J)")
    energy_axes.set_xlabel("time [s]")
    energy_axes.set_ylabel("fluid kinetic energy [J]")
    energy_axes.set_title("3D bench case at 0.02 m, GPU and CPU")
    energy_axes.legend(loc="upper left", fontsize=8)
    energy_axes.grid(alpha=0.3)
    save_figure(fig, "gpu_cpu_agreement.png")


if __name__ == "__main__":
    main()
