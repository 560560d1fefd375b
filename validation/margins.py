#!/usr/bin/python3
"""docs/validation.md's summary and margins tables, from the physics tests' own reports.

Every physics test writes the figures it checks and their bars into its report (ctest keeps one
per test: build/PRESET/tests/reports/; tests/physics/reported_figure.hpp). This script reads the
release build's reports and the baseline build's (x86-64-v2: other rounding, which stands in for
another processor) and writes
- the summary table: each check, its tests, how many passed, and its figure closest to its bar
  (the smallest margin relative to the bar);
- the margins table: every asserted figure in both builds, the spread between them, the margin to
  its bar, and the margin in units of the spread, tightest first;
- the limits table: the figures reported against a bar the model does not meet;
- each section's table of its own checks, and the grid model's operator checks, which are unit
  tests (the release build's unit_reports/; the baseline build runs no unit tests).

Rerun after `scripts/test_all.sh` (or `ctest --preset release -L physics`) and the baseline
build's physics checks with the slowest, which CI runs in the release build alone (the baseline
preset leaves them out), in them too:
  ctest --test-dir build/baseline -j 2 -L physics
  /usr/bin/python3 validation/margins.py
A report written later replaces an earlier one's figures for the same test.
"""

import argparse
import glob
import math
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

from runs import ROOT, write_table

# The summary table's rows: the check, its case files, and the tests (a regular expression on
# SUITE.NAME) that check it.
CHECKS = [
    ("F1 hydrostatic tank (2D), `wcsph`, `mps`, `constraint`, `mac`",
     "`cases/hydrostatic_2d.yaml`, `hydrostatic_2d_mps.yaml`",
     r"^HydrostaticTank2D\.|^ConstraintFluid\.HydrostaticBottomPressure|^MacFluid\.StillTank"),
    ("F2 dam break (2D), every model, at the CI spacing and half of it",
     "`cases/dam_break_2d.yaml`", r"^F2/DamBreakFront\."),
    ("F3 dam break with an obstacle (3D), `wcsph` and `mps`, 1 s", "`cases/kleefsman_3d.yaml`",
     r"^Kleefsman3D\."),
    ("the same answer on 1 and 2 threads", "dam breaks, every model", r"SameOnOneAndTwoThreads"),
    ("`mps` walls: water under a lid", "`cases/lid_2d.yaml`", r"^MpsWalls\."),
    ("`constraint`: compression, step, density error", "`cases/hydrostatic_2d.yaml`, `dam_break_2d.yaml`",
     r"^ConstraintFluid\.(StillTank|DensityError)"),
    ("B1 floating box (2D), `wcsph`, `mps`, `constraint`, `mac`", "`cases/floating_box_2d.yaml`",
     r"^CaseFloatingBox\."),
    ("B2 falling cube, floating block (3D)", "`cases/falling_cube.yaml`, `floating_block.yaml`",
     r"^CaseFallingCube\.|^CaseFloatingBlock\."),
    ("B3 dam break with six cubes (3D)", "`cases/dam_break_cubes_6.yaml`", r"^CaseDamBreakCubes\."),
    ("B4 seed 002's penalty boundary", "`cases/seed002_*.yaml`", r"^PenaltyStudy\."),
    ("`penalty-sph`: water on a box, free grains under water", "2D boxes and beds",
     r"^PenaltySph(?!Device)"),
    ("B5 parked vehicle: the hydrostatic lift, five models", "`cases/parked_vehicle.yaml`",
     r"^ParkedVehicle\."),
    ("vehicles, towing, loads as means over their intervals", "`cases/fording.yaml`, 2D towed boxes",
     r"^Vehicle\."),
    ("C1-C7 rigid bodies and contact, no fluid; a ball on a slope", "`cases/drop_bounce.yaml` ...",
     r"^(C1/)?Case(Drop|Hertz|Incline|RestingCubes|ElasticBox|ThreeBodies|SlopeRoll)|^SubCycling\."),
    ("C6 in water: sub-cycled bodies; a prescribed paddle", "blocks dropped in a tank, a paddle",
     r"^SubCyclingInWater\.|^PrescribedPaddle\."),
    ("complementarity contact and joints", "C3-C4 again, a pendulum, a motor",
     r"^Complementarity|^Joints\."),
    ("device runs: `wcsph` on a GPU (emulated where none is lent); `mps`, `penalty-sph`, "
     "`constraint`, `granular` on the emulated device", "F1, F2, B1, the bench case, B5's vehicle",
     r"^Wcsph(Device|Gpu)\.|^(Mps|PenaltySph|Constraint|Granular)Device\."),
    ("`granular`: the pool, the column collapse (Lube et al. 2005)",
     "`cases/column_collapse_2d.yaml`", r"^Granular\."),
    ("`mac`: F2's area, F4 lid-driven cavity (Ghia et al. 1982), bodies",
     "`cases/*` with `model.name=mac`", r"^Mac"),
    ("checkpoints resume to the same answer", "every model", r"Resume\."),
    ("F7 flow past a cylinder in a channel (Schäfer & Turek 1996, 2D-1), `mac` and `wcsph`",
     "`cases/cylinder_channel_2d.yaml`, `cylinder_channel_wcsph_2d.yaml`", r"^OpenBoundaries\."),
    ("F8 waves from a piston (Biésel, Madsen), a damping zone and active absorption, `mac`",
     "`cases/wave_flume_2d.yaml`, `paddle_absorption_2d.yaml`",
     r"^Waves\.(Piston|ActiveAbsorption)"),
    ("F11 a box floating in regular waves, held to heave, `mac`",
     "`cases/floating_box_waves_2d.yaml`", r"^Waves\.FloatingBox"),
    ("F9 an open channel between an inlet and an outlet, `wcsph`",
     "`cases/open_channel_2d.yaml`", r"^OpenChannel\."),
    ("F10 plane Poiseuille flow across a periodic axis (Morris et al. 1997), every model that "
     "has one; a periodic open channel", "`cases/poiseuille_2d.yaml`", r"^Periodic\."),
]

BUILDS = ("release", "baseline")


class Figure:
    def __init__(self, test, name, text):
        fields = text.split(";")
        if len(fields) != 6:
            sys.exit(f"margins.py: {test}: figure '{name}' has '{text}', not 6 fields")
        self.test, self.name = test, name
        self.measured, self.bound, self.bar = float(fields[0]), fields[1], float(fields[2])
        self.unit, self.decimals, self.held = fields[3], int(fields[4]), fields[5] == "held"

    def margin(self):
        if self.bound == "below":
            return self.bar - self.measured
        if self.bound == "above":
            return self.measured - self.bar
        return self.bar - abs(self.measured)

    def text(self, value):
        if not math.isfinite(value):
            return "never"  # a time that was not reached within the run
        unit = f" {self.unit}" if self.unit else ""
        return number(value, self.decimals) + unit

    def bar_text(self):
        if self.bound == "within":
            return f"within ±{self.text(self.bar)}"
        return f"{self.bound} {self.text(self.bar)}"


def number(value, decimals):
    if decimals < 0:
        return f"{value:.3g}"
    return f"{value:,.{decimals}f}".replace("-0.000", "0.000") if decimals else f"{value:,.0f}"


def read_reports(folder):
    """{test: (passed, timestamp, {figure name: Figure})} from the reports under folder."""
    tests = {}
    # Oldest first, so that a test run again since (a report of its own) replaces its figures.
    for path in sorted(glob.glob(os.path.join(folder, "**", "*.xml"), recursive=True),
                       key=os.path.getmtime):
        for case in ElementTree.parse(path).getroot().iter("testcase"):
            test = f"{case.get('classname')}.{case.get('name')}"
            if case.get("result") == "skipped" or case.get("status") == "notrun":
                continue
            passed = case.find("failure") is None and case.find("error") is None
            figures = {}
            for prop in case.iter("property"):
                figures[prop.get("name")] = Figure(test, prop.get("name"), prop.get("value"))
            tests[test] = (passed, case.get("timestamp", "")[:10], figures)
    return tests


def resolution(figure):
    """Half the last printed digit: a spread below it does not show in the table."""
    return 0.5 * 10 ** -figure.decimals if figure.decimals >= 0 else 0


def margin_per_spread(release, baseline):
    """The smaller margin of the two builds over their spread, and whether the spread is below
    the printed resolution (the ratio then a lower bound, the spread taken as the resolution)."""
    spread = abs(release.measured - baseline.measured)
    margin = min(release.margin(), baseline.margin())
    below = spread < resolution(release)
    spread = max(spread, resolution(release))
    return (margin / spread if spread > 0 else math.inf), below


def spread_cells(release, baseline):
    """(baseline, spread, margin, margin / spread) cells for a figure in both builds."""
    if baseline is None:
        return "not run", "–", release.text(release.margin()), "release only"
    spread = abs(release.measured - baseline.measured)
    ratio, below = margin_per_spread(release, baseline)
    ratio_text = f"{ratio:,.2g}" if ratio < 10 else f"{ratio:,.0f}"
    if spread == 0:
        ratio_text = f"same bits (> {ratio_text})"
    elif below:
        ratio_text = f"> {ratio_text}"
    finer = Figure(release.test, release.name, f"0;below;0;{release.unit};{release.decimals + 1};held")
    spread_text = "0" if spread == 0 else (f"< {finer.text(resolution(release))}" if below
                                            else release.text(spread))
    margin = min(release.margin(), baseline.margin())
    return baseline.text(baseline.measured), spread_text, release.text(margin), ratio_text


def ratio_key(release, baseline):
    if baseline is None:
        return (1, release.margin())
    return (0, margin_per_spread(release, baseline)[0])


def margins_table(reports, held):
    rows = []
    for test, (_, _, figures) in reports["release"].items():
        other = reports["baseline"].get(test, (None, None, {}))[2]
        for name, figure in figures.items():
            if figure.held == held:
                rows.append((figure, other.get(name)))
    rows.sort(key=lambda r: (ratio_key(*r), r[0].test, r[0].name))
    if held:
        out = ["| figure | test | bar | release | baseline | spread | margin | margin / spread |",
               "|---|---|---|---|---|---|---|---|"]
        for release, baseline in rows:
            cells = spread_cells(release, baseline)
            out.append(f"| {release.name} | `{release.test}` | {release.bar_text()} | "
                       f"{release.text(release.measured)} | " + " | ".join(cells) + " |")
    else:
        out = ["| figure | test | bar | release | baseline | met (release / baseline) |",
               "|---|---|---|---|---|---|"]
        for release, baseline in rows:
            other = baseline.text(baseline.measured) if baseline else "not run"
            met = " / ".join("–" if f is None else ("yes" if f.margin() >= 0 else "no")
                             for f in (release, baseline))
            out.append(f"| {release.name} | `{release.test}` | {release.bar_text()} | "
                       f"{release.text(release.measured)} | {other} | {met} |")
    return "\n".join(out) + "\n"


def summary_table(reports):
    out = ["| check | cases | tests passed (release / baseline) | "
           "the figure closest to its bar (release) | limits reported |", "|---|---|---|---|---|"]
    claimed = set()
    for check, cases, pattern in CHECKS:
        tests = [t for t in reports["release"] if re.search(pattern, t) and t not in claimed]
        claimed.update(tests)
        if not tests:
            continue
        counts = []
        for build in BUILDS:
            ran = [reports[build][t][0] for t in tests if t in reports[build]]
            counts.append(f"{sum(ran)}/{len(ran)}" if ran else "not run")
        figures = [f for t in tests for f in reports["release"][t][2].values()]
        held = [f for f in figures if f.held]
        tightest = "no figure (bit-for-bit or yes/no checks)"
        if held:
            f = min(held, key=lambda f: f.margin() / abs(f.bar) if f.bar else f.margin())
            tightest = f"{f.name}: {f.text(f.measured)}, bar {f.bar_text()}"
        limits = sum(1 for f in figures if not f.held)
        out.append(f"| {check} | {cases} | {counts[0]} / {counts[1]} | {tightest} | "
                   f"{limits or '–'} |")
    rest = [t for t in reports["release"] if t not in claimed]
    if rest:
        out.append(f"| other physics tests | | {sum(reports['release'][t][0] for t in rest)}/"
                   f"{len(rest)} | | |")
    return "\n".join(out) + "\n"


# Tables of a section's own checks: the table's name in docs/validation.md, and the tests (a
# regular expression on SUITE.NAME) whose figures it lists.
SECTIONS = [
    ("b5-parked", r"^ParkedVehicle\."),
    ("complementarity-granular", r"^Complementarity|^Joints\.|^Granular\."),
    ("constraint-checks", r"^ConstraintFluid\.|^CaseFloatingBox\.DraftByArchimedesWithConstraintFluid$"),
]

# Tables of unit tests' figures (the release build's alone): name and tests, as above.
UNIT_SECTIONS = [
    ("mac-operators", r"^Mac(Advection|Extension|Projection|LevelSet|SurfaceMesh)\."),
]


def section_table(reports, pattern):
    """Every figure of the tests matching pattern, as both builds measured it, in test order."""
    out = ["| figure | bar | release | baseline | test |", "|---|---|---|---|---|"]
    for test in sorted(t for t in reports["release"] if re.search(pattern, t)):
        other = reports["baseline"].get(test, (None, None, {}))[2]
        for name, figure in reports["release"][test][2].items():
            baseline = other.get(name)
            mark = "" if figure.held else " (a limit)"
            out.append(f"| {name}{mark} | {figure.bar_text()} | {figure.text(figure.measured)} | "
                       f"{baseline.text(baseline.measured) if baseline else 'not run'} | "
                       f"`{test}` |")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    for build in BUILDS:
        parser.add_argument(f"--{build}", default=os.path.join(ROOT, "build", build, "tests",
                                                               "reports"),
                            help=f"the {build} build's physics test reports")
    parser.add_argument("--unit", default=os.path.join(ROOT, "build", "release", "tests",
                                                       "unit_reports"),
                        help="the release build's unit test reports")
    args = parser.parse_args()
    reports = {}
    for build in BUILDS:
        reports[build] = read_reports(getattr(args, build))
        if not reports[build]:
            sys.exit(f"margins.py: no reports in {getattr(args, build)}: run the physics tests "
                     f"(ctest --preset {build}{' -L physics' if build == 'release' else ''})")
    dates = sorted({d for build in BUILDS for (_, d, _) in reports[build].values() if d})
    when = dates[0] if len(dates) == 1 else f"{dates[0]} to {dates[-1]}"
    failed = [t for t, (ok, _, _) in reports["release"].items() if not ok]
    note = f"Tests run {when}." + (f" **Failed in the release build: {', '.join(failed)}.**"
                                   if failed else "")
    write_table("validation.md", "summary", note + "\n\n" + summary_table(reports))
    write_table("validation.md", "margins", note + "\n\n" + margins_table(reports, True))
    write_table("validation.md", "limits", note + "\n\n" + margins_table(reports, False))
    for name, pattern in SECTIONS:
        write_table("validation.md", name, note + "\n\n" + section_table(reports, pattern))
    unit = read_reports(args.unit)
    if not unit:
        sys.exit(f"margins.py: no reports in {args.unit}: run the unit tests "
                 "(ctest --preset release -LE physics)")
    unit_dates = sorted({d for (_, d, _) in unit.values() if d})
    for name, pattern in UNIT_SECTIONS:
        table = section_table({"release": unit, "baseline": {}}, pattern)
        write_table("validation.md", name, f"Tests run {unit_dates[-1]}; the baseline build runs "
                    "no unit tests.\n\n" + table)


if __name__ == "__main__":
    main()
