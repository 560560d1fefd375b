"""P1's 10 ms means over 0.50-0.62 s, in kPa, as markdown rows: the experiment's (Kleefsman et
al. 2005), seed 000's MPS at 0.015 m and each run's given. docs/validation.md (F3 at 0.015 m)
prints them to show where `mps`'s P1 fell away late in the first impact and what brought it
back (the box wall's layers, then steps of equal size between outputs).

    /usr/bin/python3 validation/f3_p1_late.py LABEL=PROBES_CSV ...

PROBES_CSV is a run's probes.csv (or validation/results/'s gzipped copy)."""
import sys

import numpy as np

from kleefsman_figures import experiment, read_probes, seed000

STARTS = np.round(np.arange(0.50, 0.615, 0.01), 2)  # s, each mean over [start, start + 10 ms)


def means(series):
    t, p = series["time"], series["P1"]
    row = []
    for start in STARTS:
        inside = (t >= start - 1e-9) & (t < start + 0.01 - 1e-9)
        row.append(f"{p[inside].mean() / 1000:.1f}" if inside.any() else "–")
    return row


def main():
    print("| P1 [kPa], 10 ms from | " + " | ".join(f"{s:.2f}" for s in STARTS) + " |")
    print("|---" * (len(STARTS) + 1) + "|")
    rows = [("experiment", experiment()), ("seed 000, 0.015 m", seed000(0.015))]
    for argument in sys.argv[1:]:
        label, path = argument.split("=", 1)
        rows.append((label, read_probes(path)))
    for label, series in rows:
        print(f"| {label} | " + " | ".join(means(series)) + " |")


if __name__ == "__main__":
    main()
