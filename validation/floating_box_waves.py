#!/usr/bin/python3
"""F11: a box floating in regular waves, held to heave, against linear theory.

Runs cases/floating_box_waves_2d.yaml: a piston makes waves of steepness 0.02 at kh = 0.75 in
water 0.5 m deep (T = 2.055 s, L = 4.189 m) towards a box 0.6 m long at a draft of 0.1 m. From
the last five periods of each run: the incident amplitude (Goda & Suzuki 1976, from the two
gauges ahead of the box), the box's heave at the wave's frequency, and their ratio, the heave
response, against the Froude–Krylov prediction for a box long compared with its draft
(sluice::waves::box_heave_response's form, restated below) without added mass
and with an added mass of ADDED_MASS_DEPTH, a bracket of what the approximation leaves out.
Writes docs/validation.md's table f11-floating-box and docs/img/f11_floating_box.png; each
run's probes.csv and bodies/box.csv are kept in validation/results/.

usage: /usr/bin/python3 validation/floating_box_waves.py [--no-run] [--runs MODEL@SPACING,...]
"""
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from runs import (each_run, keep_results, model_runs_parser, read_columns, result_path,
                  result_statistics, run_model, runs_to_tabulate, save_figure, wall_time,
                  write_table)
from wave_flume import goda_suzuki, harmonic, wave

CASE = "floating_box_waves_2d"
G, DEPTH, END = 9.81, 0.5, 18.0
K, PERIOD, _, _, _ = wave(0.75)  # the F8 flume's wave at kh = 0.75, as the case lays it out
BEAM, DRAFT, REST = 0.6, 0.1, 0.5  # the box's length, draft and centre's height at rest
GAUGES = (2.294, 3.341)  # half a wavelength from the paddle's face, and a quarter beyond
# The bracket's other end: the heave added mass of a flat plate of the box's beam on the
# surface at high frequency, rho pi B^2 / 8 (Newman 1977, "Marine Hydrodynamics", ch. 4), as a
# depth of water over the beam.
ADDED_MASS_DEPTH = math.pi * BEAM / 8


def predicted_response(added_mass_depth=0.0):
    """The heave per unit incident amplitude: the bottom's Froude-Krylov force over the beam
    against the waterplane's stiffness less the box's inertia (and the added mass's)."""
    omega = 2 * math.pi / PERIOD
    half = 0.5 * K * BEAM
    force = math.cosh(K * (DEPTH - DRAFT)) / math.cosh(K * DEPTH) * math.sin(half) / half
    w = omega * omega / G
    return force / (1 - w * DRAFT / (1 - w * added_mass_depth))


def figures(out, name):
    """The incident amplitude, the reflection, the heave amplitude, the mean draft and the
    late records of one run (None where it did not reach its end)."""
    probes = read_columns(result_path(out, name, "probes.csv"))
    box = read_columns(result_path(out, name, os.path.join("bodies", "box.csv")))
    if probes["time [s]"][-1] < END * (1 - 1e-4) or box["time"][-1] < END * (1 - 1e-4):
        return None
    omega = 2 * math.pi / PERIOD
    late = probes["time [s]"] >= END - 5 * PERIOD
    t = probes["time [s]"][late]
    z1 = harmonic(t, probes["half_wavelength [m]"][late] - DEPTH, omega)
    z2 = harmonic(t, probes["quarter_beyond [m]"][late] - DEPTH, omega)
    incident, reflected = goda_suzuki(z1, GAUGES[0], z2, GAUGES[1], K)
    body_late = box["time"] >= END - 5 * PERIOD
    heave = abs(harmonic(box["time"][body_late], box["z"][body_late], omega))
    return {"incident": incident, "reflection": reflected / incident, "heave": heave,
            "draft": DRAFT + REST - box["z"][body_late].mean(), "time": box["time"],
            "z": box["z"] - REST, "gauge_time": probes["time [s]"],
            "gauge": probes["half_wavelength [m]"] - DEPTH}


RUNS = "mac@0.04,mac@0.02,wcsph@0.02"


def main():
    parser = model_runs_parser(CASE, __doc__.split("\n")[0], RUNS)
    args = parser.parse_args()
    bare, bracketed = predicted_response(), predicted_response(ADDED_MASS_DEPTH)
    rows = []
    for item in runs_to_tabulate(args.runs, RUNS):
        [(model, spacing)] = each_run(item)
        name = f"f11_{model}_{spacing:g}"
        out = os.path.join(args.out, name)
        if not args.no_run and item in args.runs.split(","):
            run_model(CASE, out, model, spacing, END, args, [f"output_interval={END / 4:g}"])
            keep_results(out, name, ("probes.csv", os.path.join("bodies", "box.csv")))
        rows.append((model, spacing, figures(out, name), result_statistics(out, name) or {}))

    lines = ["| model | cells or spacing | incident H [m] | reflection | heave amplitude [m] | "
             f"response | from {bare:.3f} (no added mass) | from {bracketed:.3f} (added mass) | "
             "mean draft [m] (0.1) | steps | wall time |", "|---" * 11 + "|"]
    for model, spacing, f, s in rows:
        wall = wall_time(s)
        if f is None:
            lines.append(f"| `{model}` | {spacing:g} m | did not reach {END:g} s | | | | | | | | |")
            continue
        response = f["heave"] / f["incident"]
        lines.append(f"| `{model}` | {spacing:g} m | {2 * f['incident']:.4f} | "
                     f"{100 * f['reflection']:.1f} % | {f['heave']:.4f} | {response:.3f} | "
                     f"{100 * (response / bare - 1):+.1f} % | "
                     f"{100 * (response / bracketed - 1):+.1f} % | {f['draft']:.4f} | "
                     f"{s.get('steps', '')} | {wall} |")
    write_table("validation.md", "f11-floating-box", "\n".join(lines))

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.2), gridspec_kw={"width_ratios": [2, 1]})
    for model, spacing, f, _ in rows:
        if f is None:
            continue
        late = f["time"] >= END - 3 * PERIOD
        axes[0].plot(f["time"][late], f["z"][late], label=f"{model} {spacing:g} m: box heave")
        axes[1].plot([spacing], [f["heave"] / f["incident"]], "o" if model == "mac" else "s",
                     label=f"{model} {spacing:g} m")
    first = next((f for _, _, f, _ in rows if f is not None), None)
    if first is not None:
        late = first["gauge_time"] >= END - 3 * PERIOD
        axes[0].plot(first["gauge_time"][late], first["gauge"][late], "k--", lw=0.8,
                     label=f"{rows[0][0]} {rows[0][1]:g} m: water at x = {GAUGES[0]} m")
    axes[0].set(xlabel="t [s]", ylabel="[m]", title="heave and the incident wave, last 3 periods")
    axes[0].legend(fontsize=8)
    axes[1].axhspan(0.9 * bare, 1.1 * bare, color="tab:green", alpha=0.3,
                    label="±10 % of linear theory")
    axes[1].axhline(bare, color="tab:green", label="Froude–Krylov, no added mass")
    axes[1].axhline(bracketed, color="tab:green", ls="--", label="with added mass ρπB²/8")
    axes[1].set(xlabel="cells or spacing [m]", ylabel="heave / incident amplitude",
                title="heave response", xlim=(0, 0.05))
    axes[1].legend(fontsize=8, loc="lower right")
    save_figure(fig, "f11_floating_box.png")


if __name__ == "__main__":
    main()
