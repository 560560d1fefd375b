#!/usr/bin/python3
"""F2 of VALIDATION.md: runs cases/dam_break_2d.yaml with the wcsph and mps models (or the granular
one) at the CI spacing and finer, and plots the surge front against Koshizuka & Oka (1996). Writes
docs/img/f2_dam_break_front.png and prints the RMS difference over t in [0, 0.70] s for each
model and spacing, and the delay of the experiment that would bring each run closest to it (the
RMS against the experiment's times minus that delay, searched in steps of 5 ms).

usage: /usr/bin/python3 validation/dam_break_2d.py [SPACING ...]   (default: 0.025 0.0125)
       /usr/bin/python3 validation/dam_break_2d.py --granular [SPACING ...]   (default: 0.05 0.025)
       (the granular model alone, into docs/img/f2_granular_front.png)
"""
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from probes_csv import read_probe
from runs import ROOT, save_figure

SLUICE = os.path.join(ROOT, "build", "release", "sluice")
REFERENCE = os.path.join(ROOT, "validation", "data", "dam_break_front_koshizuka_oka_1996.tsv")


def read_reference():
    rows = []
    with open(REFERENCE) as f:
        for line in f:
            parts = line.split()
            try:
                rows.append((float(parts[0]), float(parts[1])))
            except (ValueError, IndexError):
                continue
    return rows


def run(model, spacing):
    out = os.path.join(ROOT, "out", "validation", f"dam_break_2d_{model}_{spacing}")
    subprocess.run([SLUICE, "run", os.path.join(ROOT, "cases", "dam_break_2d.yaml"), "--out", out,
                    "--end", "0.75", "--set", f"spacing={spacing}", "--set",
                    f"model.name={model}"], check=True, stdout=subprocess.DEVNULL)
    return read_probe(os.path.join(out, "probes.csv"), "front")


def interpolate(times, values, t):
    for k in range(1, len(times)):
        if times[k] >= t:
            w = (t - times[k - 1]) / (times[k] - times[k - 1])
            return values[k - 1] + w * (values[k] - values[k - 1])
    return values[-1]


def rms_error(times, fronts, reference, delay=0.0):
    errors = [interpolate(times, fronts, max(t - delay, 0.0)) - x for t, x in reference
              if t <= 0.70]
    return math.sqrt(sum(e * e for e in errors) / len(errors)), len(errors)


def best_delay(times, fronts, reference):
    return min((rms_error(times, fronts, reference, 0.005 * k)[0], 0.005 * k) for k in range(21))


def main():
    granular = "--granular" in sys.argv
    spacings = [float(s) for s in sys.argv[1:] if s != "--granular"]
    spacings = spacings or ([0.05, 0.025] if granular else [0.025, 0.0125])
    models = (("granular", "tab:green"),) if granular else (("wcsph", "tab:blue"),
                                                            ("mps", "tab:red"))
    reference = read_reference()
    fig = plt.figure(figsize=(6.4, 4.4))
    plt.plot([t for t, _ in reference], [x for _, x in reference], "ko",
             label="experiment (Koshizuka & Oka 1996)")
    for model, colour in models:
        for spacing, style in zip(spacings, ("-", "--", ":")):
            times, fronts = run(model, spacing)
            rms, count = rms_error(times, fronts, reference)
            shifted, delay = best_delay(times, fronts, reference)
            print(f"{model}, spacing {spacing} m: front RMS error {rms:.3f} m over {count} "
                  f"points; {shifted:.3f} m against the experiment {delay:.3f} s earlier")
            plt.plot(times, fronts, style, color=colour,
                     label=f"sluice {model}, dx = {spacing} m (RMS {rms:.2f} m)")
    plt.axvline(0.70, color="0.7", lw=0.8)
    plt.xlabel("time [s]")
    plt.ylabel("surge front x [m]")
    plt.title("F2: 2D dam break, column 1 m x 2 m")
    plt.legend(loc="upper left", fontsize=8)
    plt.grid(alpha=0.3)
    save_figure(fig, "f2_granular_front.png" if granular else "f2_dam_break_front.png")


if __name__ == "__main__":
    main()
