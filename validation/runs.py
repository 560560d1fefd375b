"""What the validation scripts share: the repository root, the standard command line of a script
that runs one case (--out, --no-run, --sluice), running that case, reading one body's CSV from
its output, and saving a figure to docs/img/."""
import argparse
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def case_parser(case, description):
    """The parser of a script for cases/<case>.yaml: --out (default out/<case>), --no-run and
    --sluice. Returned before parsing, so that a script can add its own options."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--out", default=os.path.join("out", case), help="run directory")
    parser.add_argument("--no-run", action="store_true", help="use the existing output in --out")
    parser.add_argument("--sluice", default=os.path.join("build", "release", "sluice"))
    return parser


def run_case(case, args, overrides=(), suffix=""):
    """Runs cases/<case>.yaml from the repository root into args.out + suffix, with each
    "key=value" of overrides as a --set, unless args.no_run; returns the output directory."""
    out = os.path.join(ROOT, args.out + suffix)
    if not args.no_run:
        sets = [item for o in overrides for item in ("--set", o)]
        subprocess.run([os.path.join(ROOT, args.sluice), "run",
                        os.path.join("cases", f"{case}.yaml"), "--out", out] + sets,
                       cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    return out


def require(path):
    """Exits, naming the file, if path does not exist."""
    if not os.path.exists(path):
        sys.exit(f"{os.path.basename(sys.argv[0])}: {path} is missing")


def read_body(out, name):
    """OUT/bodies/<name>.csv as a numpy record array, columns by their header names."""
    path = os.path.join(out, "bodies", f"{name}.csv")
    require(path)
    return np.genfromtxt(path, delimiter=",", names=True)


def save_figure(fig, name, rect=None):
    """Lays the figure out (within rect, figure coordinates, where given: room for a legend
    below), saves it as docs/img/<name> at 120 dpi and prints where."""
    fig.tight_layout(rect=rect)
    path = os.path.join(ROOT, "docs", "img", name)
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")


def write_table(doc, name, text):
    """Replaces the lines between '<!-- table NAME: ... -->' and '<!-- end of table NAME -->' in
    docs/<doc> with text (the first marker names the script that writes it), so that a rerun of
    the script, not a retyping, brings the page up to date. Prints the table too."""
    print(text)
    path = os.path.join(ROOT, "docs", doc)
    with open(path) as f:
        lines = f.read().split("\n")
    begin = next((k for k, line in enumerate(lines)
                  if line.startswith(f"<!-- table {name}:")), None)
    end = next((k for k, line in enumerate(lines) if line == f"<!-- end of table {name} -->"),
               None)
    if begin is None or end is None or end < begin:
        sys.exit(f"{os.path.basename(sys.argv[0])}: docs/{doc} has no markers for table {name}")
    lines[begin + 1:end] = text.rstrip("\n").split("\n")
    with open(path, "w") as f:
        f.write("\n".join(lines))
    print(f"wrote table {name} in {path}")
