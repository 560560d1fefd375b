#!/usr/bin/python3
"""F1 of VALIDATION.md: runs cases/hydrostatic_2d.yaml for 2 s and plots the particle pressures
of the last frame against rho g (H - z), and the bottom-pressure probe over time.
Writes docs/img/f1_hydrostatic.png and prints the relative errors.

usage: /usr/bin/python3 validation/hydrostatic_2d.py
"""
import math
import os
import subprocess
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from frames import read_frame
from probes_csv import read_probe
from runs import ROOT, save_figure

SLUICE = os.path.join(ROOT, "build", "release", "sluice")
RHO, G, H = 1000.0, 9.81, 1.0


def main():
    out = os.path.join(ROOT, "out", "validation", "hydrostatic_2d")
    subprocess.run([SLUICE, "run", os.path.join(ROOT, "cases", "hydrostatic_2d.yaml"), "--out", out],
                   check=True, stdout=subprocess.DEVNULL)
    last = list(ET.parse(os.path.join(out, "hydrostatic_2d.pvd")).getroot().iter("DataSet"))[-1]
    points, fields = read_frame(os.path.join(out, last.get("file")), "pressure", "kind")
    z, p = points[:, 2], fields["pressure"]
    fluid = fields["kind"] == 0
    expected = RHO * G * (H - z[fluid])
    l2 = math.sqrt(((p[fluid] - expected) ** 2).mean()) / (RHO * G * H)
    print(f"t = {last.get('timestep')} s: pressure L2 error {100 * l2:.2f} % of rho g H")

    times, bottom = read_probe(os.path.join(out, "probes.csv"), "bottom")
    print(f"bottom pressure at the end: {bottom[-1]:.0f} Pa "
          f"({100 * (bottom[-1] / (RHO * G * H) - 1):+.2f} % of rho g H)")

    fig, (left, right) = plt.subplots(1, 2, figsize=(9.6, 4.2))
    left.plot(p[fluid] / 1000, z[fluid], ".", ms=2, label="fluid particles")
    left.plot(p[~fluid & (z < H)] / 1000, z[~fluid & (z < H)], ".", ms=2, color="0.6",
              label="wall particles (Adami)")
    zz = [0, H]
    left.plot([RHO * G * (H - v) / 1000 for v in zz], zz, "k-", label="rho g (H - z)")
    left.set_xlabel("pressure [kPa]")
    left.set_ylabel("z [m]")
    left.set_title(f"profile at t = {float(last.get('timestep')):.1f} s (L2 {100 * l2:.2f} %)")
    left.legend(fontsize=8)
    right.plot(times, [b / 1000 for b in bottom], "-", label="bottom probe")
    right.axhline(RHO * G * H / 1000, color="k", lw=0.8, label="rho g H")
    right.axhspan(0.97 * RHO * G * H / 1000, 1.03 * RHO * G * H / 1000, color="0.9",
                  label="3 % band")
    right.set_xlabel("time [s]")
    right.set_ylabel("pressure [kPa]")
    right.set_title("bottom pressure")
    right.legend(fontsize=8)
    fig.suptitle("F1: 2D hydrostatic tank, 1 m of water, wcsph, dx = 0.025 m")
    save_figure(fig, "f1_hydrostatic.png")


if __name__ == "__main__":
    main()
