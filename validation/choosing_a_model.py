#!/usr/bin/python3
"""The table of docs/choosing-a-model.md: each model's figures from the validation runs the other
scripts made, side by side. Runs nothing; reads
  - F2: validation/dam_break_2d.py's runs at each model's CI spacing: (a) the front's RMS as
    measured, (b) with the experiment's clock delayed by the fitted delay;
  - B1: validation/compare_models.py's B1 runs: the draft's error against Archimedes;
  - F3: validation/kleefsman_3d.py's runs at 0.03 m (mac's at 0.02 m): P1-P4 RMS over what
    the run reached (up to 6 s), seed 000's over the same span beside them;
  - B5: validation/fording_convergence.py's runs: the mean drag at 0.04 and 0.02 m, and the
    wall time per simulated second at 0.04 m.
and writes the table `choosing` into docs/choosing-a-model.md.

usage: /usr/bin/python3 validation/choosing_a_model.py [--f3 PREFIX] [--b5 PREFIX]
       (PREFIX: the --out each of those scripts ran with)
"""
import argparse
import os

import compare_models
import dam_break_2d
import fording_convergence
import kleefsman_figures as f3
from probes_csv import read_probe
from runs import ROOT, result_path, write_table

MODELS = ("wcsph", "mps", "penalty-sph", "constraint", "mac", "granular")
F2_SPACING = {"wcsph": 0.025, "mps": 0.025, "penalty-sph": 0.025, "constraint": 0.05,
              "mac": 0.05, "granular": 0.05}
F3_SPACING = {"mac": 0.02}  # the others at 0.03 m


def f2_cell(model):
    path = dam_break_2d.probes_path(model, F2_SPACING[model])
    if path is None:
        return "–"
    reference = dam_break_2d.read_reference()
    times, fronts = read_probe(path, "front")
    measured = dam_break_2d.rms_error(times, fronts, reference)[0]
    delayed, delay = dam_break_2d.best_delay(times, fronts, reference)
    if delay == 0:  # behind the experiment: no delay brings it closer
        return f"{measured:.3f} / – ({F2_SPACING[model]:g} m; behind the experiment)"
    return f"{measured:.3f} / {delayed:.3f} ({F2_SPACING[model]:g} m)"


def b1_cell(model):
    try:
        return f"{100 * (compare_models.b1_draft(model) - 0.7) / 0.7:+.2f} %"
    except OSError:
        return "–"


def f3_cell(model, prefix):
    spacing = F3_SPACING.get(model, 0.03)
    path = result_path(os.path.join(ROOT, f"{prefix}_{model}_{spacing:g}"),
                       f"kleefsman_3d/{model}_{spacing:g}", "probes.csv")
    if path is None:
        return "not run"
    series = f3.read_probes(path)
    span = (0.0, min(6.0, float(series["time"][-1])))
    if span[1] < 1.0:  # short of the first impact's end: nothing to compare yet
        return f"– (reached {span[1]:.2f} s)"
    mine = f3.figures(series, f3.experiment(), span)
    seed = f3.figures(f3.seed000(0.03), f3.experiment(), span)
    pressures = " / ".join(f"{mine['rms_' + s]:,.0f}" for s in f3.SENSORS[:4])
    seeds = " / ".join(f"{seed['rms_' + s]:,.0f}" for s in f3.SENSORS[:4])
    return f"{pressures} to {span[1]:.2f} s, {spacing:g} m (seed 000: {seeds})"


def b5_cells(model, prefix):
    """The mean drags and the wall time; a run that stopped says where, and for mac the
    prescribed vehicle's figures follow (its wheels roll on the bed; the prescribed ones slide)."""
    drags, wall = [], "–"
    for spacing in fording_convergence.SPACINGS:
        f = fording_convergence.figures(os.path.join(ROOT, f"{prefix}_{model}_{spacing:g}"),
                                        f"fording/{model}_{spacing:g}")
        if f is None:
            drags.append("–")
            continue
        if f["reached"] < fording_convergence.END:
            drags.append(f"to {f['reached']:.2f} s only")
            continue
        drags.append(f"{f['mean_drag']:.0f}")
        if spacing == fording_convergence.SPACINGS[0]:
            wall = f["wall"]
    if model == "mac":
        prescribed, prescribed_wall = b5_cells("mac-prescribed", prefix)
        return (f"{' / '.join(drags)}; every part prescribed: {prescribed}",
                wall if wall != "–" else f"{prescribed_wall} (prescribed)")
    return " / ".join(drags), wall


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--f3", default=os.path.join("out", "validation", "kleefsman_3d"))
    parser.add_argument("--b5", default=os.path.join("out", "validation", "fording"))
    args = parser.parse_args()
    lines = ["| model | F2 front RMS (a) / (b) [m] | B1 draft error | F3 P1 / P2 / P3 / P4 RMS "
             "[Pa] | B5 mean drag at 0.04 / 0.02 m [N] | B5 wall s per simulated s (threads), 0.04 m |",
             "|---|---|---|---|---|---|"]
    for model in MODELS:
        drag, wall = b5_cells(model, args.b5)
        lines.append(f"| `{model}` | {f2_cell(model)} | {b1_cell(model)} | "
                     f"{f3_cell(model, args.f3)} | {drag} | {wall} |")
    write_table("choosing-a-model.md", "choosing", "\n".join(lines))


if __name__ == "__main__":
    main()
