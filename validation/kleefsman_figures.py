"""F3's figures as VALIDATION.md defines them, for one series against the experiment of Kleefsman
et al. (2005): every pressure series (a run's, the experiment's, seed 000's) first gets a 5 ms
running mean (centred, over whole samples); a series is interpolated linearly onto the experiment's times; RMS per sensor over
the span both cover; the three downstream gauges' first-wet times (height above 0.02 m); P1's
first rise above 2 kPa, its peak and its impulse over the first impact (0.35-0.6 s).

tests/physics/test_kleefsman.cpp holds the CI run to the same definitions."""
import os

import numpy as np
from runs import ROOT, open_text

DATA = os.path.join(ROOT, "validation", "data")
SENSORS = [f"P{k}" for k in range(1, 9)]
# The gauges by their x in millimetres, as cases/kleefsman_3d.yaml names its probes; the last
# stands in the reservoir.
GAUGES = ["g496", "g992", "g1488", "g2638"]
DOWNSTREAM = GAUGES[:3]
WINDOW = 0.005  # s, the running mean's width
WET = 0.02  # m, a gauge is wet above this height
RISE = 2000.0  # Pa, P1's first rise
IMPACT = (0.35, 0.6)  # s, the first impact, for P1's peak and impulse
# The bore thrown back from the end wall (x = 0): when it lifts the reservoir gauge above
# 0.18 m after 2.4 s, and P1 above 2 kPa again after 4.3 s (not VALIDATION.md's figures: they
# show how a late first front carries over to the water's return).
BORE_HEIGHT, BORE_AFTER, SECOND_RISE_AFTER = 0.18, 2.4, 4.3


def read_tsv(path):
    """A tab-separated file with '#' comments and one header line: {column: numpy array}, the
    columns renamed to the case's probe names (P1 ... P8, g496 ... g2638, time)."""
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    header = lines[0].split()
    values = np.array([[float(x) for x in line.split()] for line in lines[1:] if line.strip()])
    columns = {}
    for k, name in enumerate(header):
        if name == "time_s":
            name = "time"
        elif name.startswith("h_x"):  # h_x1.488_m -> g1488
            name = "g" + str(round(1000 * float(name[3:-2])))
        else:  # P1_Pa -> P1
            name = name.split("_")[0]
        columns[name] = values[:, k]
    return columns


def experiment():
    return read_tsv(os.path.join(DATA, "kleefsman_2005_experiment.tsv"))


def seed000(spacing):
    """Seed 000's MPS pressures at l0 = spacing, or None where the seed has no run at it."""
    path = os.path.join(DATA, f"seed000_mps_kleefsman_l0_{spacing:g}.tsv")
    return read_tsv(path) if os.path.exists(path) else None


def read_probes(path):
    """OUT/probes.csv (or its gzipped copy): {probe name: numpy array}, with 'time'."""
    with open_text(path) as f:
        header = [title.split(" ")[0] for title in f.readline().strip().split(",")]
        values = np.array([[float(x) for x in line.split(",")] for line in f if line.strip()])
    return {name: values[:, k] for k, name in enumerate(header)}


def running_mean(t, v, width=WINDOW):
    """The centred mean over the n = round(width / dt) samples around each one (dt the median
    spacing of t; zeros beyond the ends), as numpy's convolve(mode="same") gives it: this is the
    definition that reproduces VALIDATION.md's figures for seed 000 to the pascal."""
    n = max(1, round(width / float(np.median(np.diff(t)))))
    return np.convolve(v, np.ones(n) / n, mode="same")


def first_crossing(t, v, level, after=0.0):
    """The first time after `after` at which v exceeds level (linear between samples), or nan."""
    above = np.nonzero((v > level) & (t >= after))[0]
    if len(above) == 0:
        return float("nan")
    k = above[0]
    if k == 0 or v[k - 1] == v[k]:  # at the start, or a jump from exactly the level
        return float(t[k])
    return float(t[k - 1] + (level - v[k - 1]) / (v[k] - v[k - 1]) * (t[k] - t[k - 1]))


def read_every(series, interval):
    """The series read at every multiple of interval [s] within its span (linear between its
    samples), as a probe written every interval reads it: one reading, no mean, per interval."""
    t = series["time"]
    at = np.arange(np.ceil(t[0] / interval), np.floor(t[-1] / interval + 1e-9) + 1) * interval
    return {name: at if name == "time" else np.interp(at, t, values)
            for name, values in series.items()}


def smoothed(series, name):
    """A sensor's series with the running mean, or a gauge's as it is."""
    t = series["time"]
    return running_mean(t, series[name]) if name in SENSORS else series[name]


def rms_against(series, name, reference, span):
    """RMS of series[name] (smoothed as defined) against reference[name] at the reference's
    times within span."""
    t_ref = reference["time"]
    keep = (t_ref >= span[0]) & (t_ref <= span[1])
    mine = np.interp(t_ref[keep], series["time"], smoothed(series, name))
    theirs = smoothed(reference, name)[keep]
    return float(np.sqrt(np.mean((mine - theirs) ** 2)))


def p1_impact(series):
    """P1's first rise above 2 kPa [s], its peak over the first impact [Pa] and its impulse
    over it [Pa s], from the running mean."""
    t = series["time"]
    p1 = running_mean(t, series["P1"])
    rise = first_crossing(t, p1, RISE)
    inside = (t >= IMPACT[0]) & (t <= IMPACT[1])
    peak = float(p1[inside].max()) if inside.any() else float("nan")
    impulse = float(np.trapz(p1[inside], t[inside])) if inside.sum() > 1 else float("nan")
    return rise, peak, impulse


def figures(series, reference, span):
    """Every figure of F3 for one series (a run's or seed 000's) against the experiment: a dict
    of first-wet times, gauge RMS, P1's rise, peak and impulse, P1-P4 RMS over span. An event
    after span, and the first impact's peak and impulse where span ends inside it, are nan."""
    out = {"span": span}
    t = series["time"]
    if "g496" in series:
        for gauge in DOWNSTREAM:
            out[f"wet_{gauge}"] = first_crossing(t, series[gauge], WET)
        for gauge in GAUGES:
            out[f"rms_{gauge}"] = rms_against(series, gauge, reference, span)
    out["p1_rise"], out["p1_peak"], out["p1_impulse"] = p1_impact(series)
    if span[1] < IMPACT[1]:
        out["p1_peak"] = out["p1_impulse"] = float("nan")
    if "g2638" in series:
        out["bore"] = first_crossing(t, series["g2638"], BORE_HEIGHT, BORE_AFTER)
    out["p1_second_rise"] = first_crossing(t, running_mean(t, series["P1"]), RISE,
                                           SECOND_RISE_AFTER)
    events = [f"wet_{gauge}" for gauge in DOWNSTREAM] + ["p1_rise", "bore", "p1_second_rise"]
    for key in events:  # an event beyond the span is not the run's
        if out.get(key, 0) > span[1]:
            out[key] = float("nan")
    for sensor in SENSORS[:4]:
        out[f"rms_{sensor}"] = rms_against(series, sensor, reference, span)
    return out
