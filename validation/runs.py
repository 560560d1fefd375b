"""What the validation scripts share: the repository root, the standard command line of a script
that runs one case (--out, --no-run, --sluice), running that case (once, or with one model and
spacing, resumable), reading one body's CSV from its output, saving a figure to docs/img/ and
writing a table into a page of docs/."""
import argparse
import csv
import glob
import gzip
import json
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


def model_runs_parser(case, description, runs):
    """The parser of a script that runs cases/<case>.yaml with several models and spacings:
    case_parser's options (--out defaulting to out/validation/<case>), --runs (MODEL@SPACING,...,
    default `runs`), --resume and --threads."""
    parser = case_parser(case, description)
    parser.set_defaults(out=os.path.join("out", "validation", case))
    parser.add_argument("--runs", default=runs, help="MODEL@SPACING,...")
    parser.add_argument("--resume", action="store_true", help="go on from each run's checkpoint")
    parser.add_argument("--threads", type=int, default=0)
    return parser


def runs_to_tabulate(requested, default):
    """The runs (MODEL@SPACING or a script's own items) a script's table holds: every one of its
    default runs, then any requested one that is not among them. A script runs the requested
    ones alone and reads the others from their output or their kept results, so that running
    some of its runs never drops the others' rows from its table."""
    items = default.split(",")
    return items + [item for item in requested.split(",") if item not in items]


def each_run(runs):
    """(model, spacing) for each MODEL@SPACING of the comma-separated runs."""
    for item in runs.split(","):
        model, spacing = item.split("@")
        yield model, float(spacing)


def base_model(model):
    """The model a run name MODEL[+KEY=VALUE...] runs."""
    return model.split("+")[0]


def run_model(case, out, model, spacing, end, args, extra=()):
    """Runs cases/<case>.yaml into out with model MODEL[+KEY=VALUE...] (each KEY=VALUE sets
    model.KEY) at the particle spacing (the grid's cell size, for mac) to end seconds, with each
    "key=value" of extra as a --set too. With
    args.resume and a checkpoint in out it goes on from the newest. Each leg writes its
    statistics to out/stats_leg_N.json (wall_per_simulated_second adds them up); args.threads,
    where set, is the thread count. A run that diverges (exit 3) keeps what it wrote."""
    name, settings = base_model(model), model.split("+")[1:]
    # sluice runs from the repository's root, the caller reads out from its own directory: a
    # relative out must name the same place for both (read from elsewhere, the tables had
    # quietly shown the kept results instead of the run just made).
    out = os.path.abspath(out)
    command = [os.path.join(ROOT, args.sluice), "run", os.path.join(ROOT, "cases", f"{case}.yaml")]
    if args.resume and glob.glob(os.path.join(out, "checkpoints", "*.ckpt")):
        command += ["--resume", out]  # with the same --set values, which the checkpoint checks
    else:
        for old in glob.glob(os.path.join(out, "stats_leg_*.json")):
            os.remove(old)
        command += ["--out", out]
    # The cases' own model is wcsph, and their model mapping holds its settings (which it
    # keeps); another model gets a mapping of its own.
    model_set = "model.name=wcsph" if name == "wcsph" else f"model={{name: {name}}}"
    command += ["--set", f"spacing={spacing}", "--set", model_set]
    command += [item for s in settings for item in ("--set", f"model.{s}")]
    command += [item for s in extra for item in ("--set", s)]
    legs = len(glob.glob(os.path.join(out, "stats_leg_*.json")))
    command += ["--stats", os.path.join(out, f"stats_leg_{legs}.json"), "--end", f"{end:g}"]
    if args.threads:
        command += ["--threads", str(args.threads)]
    subprocess.run(command, cwd=ROOT, stdout=subprocess.DEVNULL)


def run_statistics(out):
    """The steps and wall seconds of every leg of the run in out added up, the wall seconds per
    simulated second over them, the most threads a leg ran on, and the source the last leg was
    built from: {"steps", "wall", "wall_per_simulated_second", "threads", "source_revision"}
    (None where the statistics predate it), or None where no leg finished. Reads out/stats.json
    where the run has no legs of its own."""
    paths = sorted(glob.glob(os.path.join(out, "stats_leg_*.json"))) or \
        glob.glob(os.path.join(out, "stats.json"))
    legs = []
    for path in paths:
        with open(path) as f:
            legs.append(json.load(f))
    if not legs:
        return None
    # The step count from the start where the last leg gives it: a leg stopped before it wrote
    # its statistics would be missing from a sum (its wall seconds are, from the wall column).
    steps = legs[-1].get("last_step") or sum(leg["steps"] for leg in legs)
    wall = sum(leg["wall_seconds"] for leg in legs)
    simulated = sum(leg["simulated_seconds"] - leg.get("start_seconds", 0) for leg in legs)
    return {"steps": steps, "wall": wall, "threads": max(leg["threads"] for leg in legs),
            "wall_per_simulated_second": wall / simulated if simulated > 0 else None,
            "source_revision": legs[-1].get("source_revision")}


RESULTS = os.path.join(ROOT, "validation", "results")


def keep_results(out, name, files=("probes.csv",)):
    """Keeps a run's small files (gzipped) and its statistics (run_statistics) in
    validation/results/NAME, which is committed with the tables they give: a long run's figures
    outlive the machine and the session that ran it (its frames and checkpoints do not). Does
    nothing where the run wrote none of them, and keeps nothing over a kept copy that reaches a
    later time (kept_reaches_farther)."""
    kept = os.path.join(RESULTS, name)
    if kept_reaches_farther(out, name):
        print(f"{os.path.basename(sys.argv[0])}: kept validation/results/{name}, which reaches "
              f"further than {out}")
        return
    for filename in files:
        path = os.path.join(out, filename)
        if os.path.exists(path):
            target = os.path.join(kept, filename + ".gz")  # filename may name a folder too
            os.makedirs(os.path.dirname(target), exist_ok=True)
            # mtime 0: the same file gives the same bytes, so an unchanged result is no change.
            with open(path, "rb") as f, open(target, "wb") as g:
                g.write(gzip.compress(f.read(), mtime=0))
    statistics = run_statistics(out)
    if statistics is not None:
        os.makedirs(kept, exist_ok=True)
        with open(os.path.join(kept, "statistics.json"), "w") as f:
            json.dump(statistics, f, indent=1, sort_keys=True)


def last_time(path):
    """The time of a CSV's last row (gzipped or not), where its first column is a time, or None."""
    with open_text(path) as f:
        if not f.readline().startswith("time"):
            return None
        last = None
        for line in f:
            last = line if line.strip() else last
    return float(last.split(",")[0]) if last else None


def kept_reaches_farther(out, name):
    """Whether what keep_results kept of run NAME reaches a later time than OUT's own files (a
    run begun again, or its directory restored from an earlier checkpoint, that has not yet got
    as far): compared on the first kept time series that OUT holds too. A kept run of another
    source than OUT's (both known) is another result, and never hides OUT's."""
    kept = os.path.join(RESULTS, name)
    if different_sources(kept, out):
        return False
    for path in sorted(glob.glob(os.path.join(kept, "**", "*.csv.gz"), recursive=True)):
        own = os.path.join(out, os.path.relpath(path, kept)[:-len(".gz")])
        if not os.path.exists(own):
            continue
        kept_end, own_end = last_time(path), last_time(own)
        if kept_end is not None and own_end is not None:
            return kept_end > own_end
    return False


def different_sources(kept, out):
    """Whether the kept run in KEPT and the run in OUT were built from different sources: they
    name different ones, or OUT names one and KEPT none (kept before the runs named theirs, so
    from an older build). False where OUT names none."""
    own = run_statistics(out)
    own_source = own["source_revision"] if own else None
    if own_source is None:
        return False
    kept_statistics = os.path.join(kept, "statistics.json")
    kept_source = None
    if os.path.exists(kept_statistics):
        with open(kept_statistics) as f:
            kept_source = json.load(f).get("source_revision")
    return kept_source != own_source


def result_path(out, name, filename):
    """OUT/FILENAME, or else its copy that keep_results kept for run NAME, or None; the kept
    copy first where it reaches further (kept_reaches_farther)."""
    path = os.path.join(out, filename)
    if os.path.exists(path) and not kept_reaches_farther(out, name):
        return path
    kept = os.path.join(RESULTS, name, filename + ".gz")
    return kept if os.path.exists(kept) else None


def result_statistics(out, name):
    """run_statistics(OUT), or else the statistics keep_results kept for run NAME, or None; the
    kept ones first where the kept run reaches further (kept_reaches_farther)."""
    statistics = None if kept_reaches_farther(out, name) else run_statistics(out)
    kept = os.path.join(RESULTS, name, "statistics.json")
    if statistics is None and os.path.exists(kept):
        with open(kept) as f:
            statistics = json.load(f)
    return statistics


def wall_time(statistics):
    """A table's wall-time cell from result_statistics: "235 s (1 thread)", or "" without."""
    if not statistics:
        return ""
    threads, wall = statistics["threads"], statistics["wall"]
    seconds = f"{wall:.2g}" if wall < 10 else f"{wall:.0f}"  # two figures at least
    return f"{seconds} s ({threads} thread{'' if threads == 1 else 's'})"


def wall_per_simulated(statistics, reached, threads=False):
    """A table's cell for the wall seconds per simulated second of result_statistics: "1683",
    with the thread count where asked, and the simulated seconds the rate covers where that is
    less than the run reached (a leg stopped before it wrote its statistics is not in it):
    "11966 (1; over 0.4 of 2.0 s)"; "–" without statistics."""
    rate = statistics and statistics.get("wall_per_simulated_second")
    if not rate:
        return "–"
    notes = [str(statistics["threads"])] if threads else []
    covered = statistics["wall"] / rate
    if covered < reached - 0.01:
        notes.append(f"over {covered:.1f} of {reached:.1f} s")
    return f"{rate:.0f}" + (f" ({'; '.join(notes)})" if notes else "")


def build_cell(statistics):
    """A table's cell for the source a run was built from: its commit's short hash (with
    "-dirty" where the tree held uncommitted changes), or "not recorded" for runs older than the
    statistics that name it."""
    revision = statistics and statistics.get("source_revision")
    if not revision:
        return "not recorded"
    return f"`{revision[:7]}{'-dirty' if revision.endswith('-dirty') else ''}`"


def open_text(path):
    """A text file for reading, gzipped or not (by its name)."""
    return gzip.open(path, "rt") if path.endswith(".gz") else open(path)


def read_columns(path):
    """A CSV's columns (gzipped or not) by header name, as numpy arrays."""
    with open_text(path) as f:
        rows = list(csv.reader(f))
    return {name: np.array([float(r[k]) for r in rows[1:]]) for k, name in enumerate(rows[0])}


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
