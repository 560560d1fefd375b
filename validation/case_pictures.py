#!/usr/bin/python3
"""A picture of each case of docs/validation.md, drawn by `sluice render` (issue 44).

Runs each case below with the settings shown (its own spacing; a grid model where the section
is about one) to the time shown, writing frames at the start and at that time only, then draws
that frame with `sluice render OUT --time T` into docs/img/render/ID.png, which the section of
docs/validation.md shows. A look at the run, not a check: the checks are the sections' own.

usage: /usr/bin/python3 validation/case_pictures.py [--only ID,...] [--no-run] [--sluice PATH]
"""
import argparse
import os
import shutil
import subprocess
import time

from runs import ROOT

# (id, case, time [s], view, field, settings): one per section of docs/validation.md.
PICTURES = [
    ("c4_resting_cubes", "resting_cubes", 1.0, "iso", "velocity", []),
    ("b1_floating_box_2d", "floating_box_2d", 2.0, "side", "pressure", []),
    ("b3_dam_break_cubes_6", "dam_break_cubes_6", 1.0, "iso", "velocity", []),
    ("f1_hydrostatic_2d", "hydrostatic_2d", 1.0, "side", "pressure", []),
    ("f2_dam_break_2d", "dam_break_2d", 0.4, "side", "velocity", []),
    ("f3_kleefsman_3d", "kleefsman_3d", 0.6, "iso", "velocity", []),
    ("dam_break_3d", "dam_break_3d", 0.5, "iso", "velocity", []),
    ("b4_seed002_water_concrete", "seed002_water_concrete", 0.5, "top", "velocity", []),
    ("granular_floating_box_2d", "granular_floating_box_2d", 4.0, "side", "velocity", []),
    ("constraint_dam_break_2d", "dam_break_2d", 0.4, "side", "velocity",
     ["model={name: constraint}"]),
    ("mac_dam_break_2d", "dam_break_2d", 0.4, "side", "velocity", ["model={name: mac}"]),
    ("f7_cylinder_channel_2d", "cylinder_channel_2d", 8.0, "side", "velocity", []),
    ("f8_wave_flume_2d", "wave_flume_2d", 10.0, "side", "velocity", []),
    ("f9_open_channel_2d", "open_channel_2d", 3.0, "side", "velocity", []),
    ("f10_poiseuille_2d", "poiseuille_2d", 1.5, "side", "velocity", []),
    ("f11_floating_box_waves_2d", "floating_box_waves_2d", 10.0, "side", "velocity", []),
    ("a1_broadside_vehicle", "broadside_vehicle", 1.5, "iso", "velocity", []),
    ("b5_fording", "fording", 1.0, "iso", "velocity", []),
]
WIDTH = 720


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--only", help="ID,...: these pictures alone")
    parser.add_argument("--no-run", action="store_true", help="draw the runs already in --out")
    parser.add_argument("--out", default=os.path.join("out", "validation", "case_pictures"))
    parser.add_argument("--sluice", default=os.path.join("build", "release", "sluice"))
    args = parser.parse_args()
    wanted = set(args.only.split(",")) if args.only else None
    known = {p[0] for p in PICTURES}
    if wanted and wanted - known:
        parser.error(f"--only: unknown {', '.join(sorted(wanted - known))}; "
                     f"known: {', '.join(p[0] for p in PICTURES)}")
    sluice = os.path.join(ROOT, args.sluice)
    target = os.path.join(ROOT, "docs", "img", "render")
    os.makedirs(target, exist_ok=True)
    for name, case, end, view, field, settings in PICTURES:
        if wanted and name not in wanted:
            continue
        out = os.path.join(ROOT, args.out, name)
        start = time.perf_counter()
        if not args.no_run:
            sets = [f"output_interval={end}"] + settings
            subprocess.run([sluice, "run", os.path.join("cases", f"{case}.yaml"), "--out", out,
                            "--end", str(end)] + [a for s in sets for a in ("--set", s)],
                           cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
        ran = time.perf_counter() - start
        drawn = subprocess.run([sluice, "render", out, "--time", str(end), "--view", view,
                                "--field", field, "--width", str(WIDTH)],
                               cwd=ROOT, check=True, capture_output=True, text=True)
        # "render: OUT/render/FIELD_VIEW_NNNNNN.png (t = T s)"
        picture = drawn.stdout.split("render: ", 1)[1].split(" (t = ")[0]
        shutil.copyfile(picture, os.path.join(target, f"{name}.png"))
        print(f"{name}: {case} to {end} s in {ran:.0f} s -> docs/img/render/{name}.png",
              flush=True)


if __name__ == "__main__":
    main()
