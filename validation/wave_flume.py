#!/usr/bin/python3
"""F8: waves from a paddle against linear wavemaker theory, with the grid model (mac) and wcsph.

Runs cases/wave_flume_2d.yaml (water 0.5 m deep) re-laid for each wave: regular waves of steepness
H/L = 0.02 at kh = 0.5, 1 and 2, from a piston (Biésel's stroke with Madsen's 1971 second order)
and from a flap hinged at the bed (Biésel's with Schäffer's 1996 second order), the paddle's face
at x = 0.2 m, gauges two wavelengths from it and a quarter wavelength beyond, and a damping zone
from 2.5 to 4 wavelengths (the flume's end). From the last five periods of each run: the incident
height and the reflection coefficient (Goda & Suzuki 1976) from the two gauges' harmonics at the
wave's frequency. And a JONSWAP sea (H_m0 0.04 m, T_p 1.6 s, gamma 3.3, 64 components that repeat
after 41 s) from the piston, its H_m0 and T_p at a gauge 3 m from the paddle over one whole repeat.
Writes docs/validation.md's tables f8-regular and f8-jonswap and docs/img/f8_waves.png. Each run's
probes.csv is kept in validation/results/.

usage: /usr/bin/python3 validation/wave_flume.py [--no-run] [--runs piston@1@0.02[@MODEL],...]
(MODEL: mac unless named; wcsph, mps and penalty-sph take the same paddle and damping zone).
"""
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from runs import (keep_results, model_runs_parser, read_columns, result_path,
                  result_statistics, run_model, runs_to_tabulate, save_figure, wall_time,
                  write_table)

CASE = "wave_flume_2d"
G, DEPTH, FACE, STEEPNESS = 9.81, 0.5, 0.2, 0.02
JONSWAP = {"significant_height": 0.04, "peak_period": 1.6, "components": 64}


def wave(kh):
    """Wavenumber, period, wavelength, height and group velocity of the regular wave at kh."""
    k = kh / DEPTH
    omega = math.sqrt(G * k * math.tanh(kh))
    length = 2 * math.pi / k
    group = 0.5 * (1 + 2 * kh / math.sinh(2 * kh)) * omega / k
    return k, 2 * math.pi / omega, length, STEEPNESS * length, group


def flume(length, spacing):
    """The flume's length: 4 wavelengths past the paddle's face, a whole number of cells."""
    return round((FACE + 4 * length) / spacing) * spacing


def regular_settings(paddle, kh, spacing):
    """The --set values and the end time of one regular-wave run."""
    k, period, length, height, group = wave(kh)
    end_x = flume(length, spacing)
    x1, x2 = FACE + 2 * length, FACE + 2.25 * length
    # Ramped over two periods; the waves' front goes 3 wavelengths (into the damping zone)
    # and what the zone returns comes back past the gauges; then five periods are analysed.
    end = 2 * period + 4 * length / group + 5 * period
    sets = [f"domain.max=[{end_x:.4f}, 0.8]", f"walls.0.max=[{end_x:.4f}, 0.8]",
            f"fluid.blocks.0.max=[{end_x:.4f}, 0.5]",
            f"damping.0.from={FACE + 2.5 * length:.4f}", f"damping.0.to={end_x:.4f}",
            f"bodies.0.prescribed.paddle={paddle}", f"bodies.0.prescribed.height={height:.6f}",
            f"bodies.0.prescribed.period={period:.6f}",
            "bodies.0.prescribed.order=2",
            f"probes.1.point=[{x1:.4f}, 0]", f"probes.2.point=[{x2:.4f}, 0]",
            f"output_interval={end / 4:.4f}"]
    return sets, end


def jonswap_settings(spacing):
    """The --set values and end time of the JONSWAP run (the kh = 1 flume, a gauge at 3 m)."""
    tp = JONSWAP["peak_period"]
    repeat = JONSWAP["components"] / (2.5 / tp)  # 1 / df over [0.5, 3] f_p
    end = 2 * tp + 8 + repeat
    sets = ["bodies.0.prescribed={type: wavemaker, paddle: piston, water_depth: 0.5, "
            f"wave: jonswap, significant_height: {JONSWAP['significant_height']}, "
            f"peak_period: {tp}, components: {JONSWAP['components']}}}",
            "probes.0.point=[3.0, 0]", f"output_interval={end / 4:.4f}"]
    return sets, end, repeat


def harmonic(t, e, omega):
    """The complex amplitude of e's part at omega (a least-squares fit with a mean)."""
    a = np.vstack([np.cos(omega * t), np.sin(omega * t), np.ones_like(t)]).T
    c = np.linalg.lstsq(a, e, rcond=None)[0]
    return c[0] + 1j * c[1]


def goda_suzuki(z1, x1, z2, x2, k):
    """Incident and reflected amplitudes from the harmonics at two gauges."""
    det = np.exp(1j * k * (x1 - x2)) - np.exp(1j * k * (x2 - x1))
    incident = (z1 * np.exp(-1j * k * x2) - z2 * np.exp(-1j * k * x1)) / det
    reflected = (z2 * np.exp(1j * k * x1) - z1 * np.exp(1j * k * x2)) / det
    return abs(incident), abs(reflected)


def regular_figures(out, name, kh, end):
    k, period, length, height, _ = wave(kh)
    probes = read_columns(result_path(out, name, "probes.csv"))
    t = probes["time [s]"]
    if t[-1] < end * (1 - 1e-4):
        return {"target": height, "stopped": t[-1]}  # the run stopped early (its log says why)
    late = t >= end - 5 * period
    omega = 2 * math.pi / period
    z1 = harmonic(t[late], probes["two_wavelengths [m]"][late] - DEPTH, omega)
    z2 = harmonic(t[late], probes["quarter_beyond [m]"][late] - DEPTH, omega)
    incident, reflected = goda_suzuki(z1, FACE + 2 * length, z2, FACE + 2.25 * length, k)
    eta = probes["two_wavelengths [m]"] - DEPTH
    crest_to_trough = np.mean([eta[(t >= end - (j + 1) * period) & (t < end - j * period)].ptp()
                               for j in range(5)])
    return {"target": height, "first_harmonic": 2 * incident, "height": crest_to_trough,
            "reflection": reflected / incident, "ursell": height * length ** 2 / DEPTH ** 3,
            "period": period}


def jonswap_figures(out, name, end, repeat):
    probes = read_columns(result_path(out, name, "probes.csv"))
    t = probes["time [s]"]
    late = t > end - repeat + 1e-9
    eta = probes["near [m]"][late] - DEPTH
    eta -= eta.mean()
    dt = t[1] - t[0]
    power = np.abs(np.fft.rfft(eta)) ** 2
    f = np.fft.rfftfreq(len(eta), dt)
    band = np.convolve(power, np.ones(3) / 3, mode="same")  # three ordinates averaged
    return {"hm0": 4 * eta.std(), "tp": 1 / f[1:][np.argmax(band[1:])],
            "f": f, "density": band * 2 * dt / len(eta)}


RUNS = ("piston@1@0.02,piston@0.5@0.02,piston@2@0.01,flap@1@0.02,jonswap@1@0.02,"
        "flap@0.5@0.02,flap@2@0.01,piston@1@0.02@wcsph")


def main():
    parser = model_runs_parser(CASE, __doc__.split("\n")[0], RUNS)
    args = parser.parse_args()
    regular, irregular = [], []
    for item in runs_to_tabulate(args.runs, RUNS):
        paddle, kh, spacing, *rest = item.split("@")
        model = rest[0] if rest else "mac"
        kh, spacing = float(kh), float(spacing)
        name = f"f8_{paddle}_kh{kh:g}_{spacing:g}" + ("" if model == "mac" else f"_{model}")
        out = os.path.join(args.out, name)
        if paddle == "jonswap":
            sets, end, repeat = jonswap_settings(spacing)
        else:
            sets, end = regular_settings(paddle, kh, spacing)
        if not args.no_run and item in args.runs.split(","):
            run_model(CASE, out, model, spacing, end, args, sets)
            keep_results(out, name, ("probes.csv",))
        statistics = result_statistics(out, name) or {}
        if paddle == "jonswap":
            irregular.append((spacing, jonswap_figures(out, name, end, repeat), statistics))
        else:
            regular.append((paddle, kh, spacing, model, regular_figures(out, name, kh, end),
                            statistics))

    lines = ["| model | paddle | kh | Ursell H L²/h³ | cells or spacing | target H [m] | "
             "crest to trough [m] | from target | incident, 1st harmonic [m] | from target | "
             "reflection | steps | wall time |", "|---" * 13 + "|"]
    for paddle, kh, spacing, model, f, s in regular:
        order = f"{paddle}, 2nd order"
        if "stopped" in f:
            lines.append(f"| `{model}` | {order} | {kh:g} | | {spacing:g} m | {f['target']:.4f} | "
                         f"stopped at t = {f['stopped']:.2f} s | | | | | | |")
            continue
        lines.append(f"| `{model}` | {order} | {kh:g} | {f['ursell']:.0f} | {spacing:g} m "
                     f"({f['target'] / spacing:.1f} a height) | {f['target']:.4f} | "
                     f"{f['height']:.4f} | {100 * (f['height'] / f['target'] - 1):+.1f} % | "
                     f"{f['first_harmonic']:.4f} | "
                     f"{100 * (f['first_harmonic'] / f['target'] - 1):+.1f} % | "
                     f"{100 * f['reflection']:.1f} % | {s.get('steps', '')} | {wall_time(s)} |")
    write_table("validation.md", "f8-regular", "\n".join(lines))
    lines = ["| cells | H_m0 [m] (target 0.04) | from target | T_p [s] (target 1.6) | from target "
             "| steps | wall time |", "|---" * 7 + "|"]
    for spacing, f, s in irregular:
        lines.append(f"| {spacing:g} m | {f['hm0']:.4f} | {100 * (f['hm0'] / 0.04 - 1):+.1f} % | "
                     f"{f['tp']:.3f} | {100 * (f['tp'] / 1.6 - 1):+.1f} % | {s.get('steps', '')} "
                     f"| {wall_time(s)} |")
    write_table("validation.md", "f8-jonswap", "\n".join(lines))

    fig, axes = plt.subplots(1, 3, figsize=(13, 4.8))
    models = sorted({model for _, _, _, model, _, _ in regular})
    for paddle, marker in (("piston", "o"), ("flap", "s")):
        for model in models:
            rows = sorted(((kh, f) for p, kh, _, m, f, _ in regular
                           if p == paddle and m == model and "stopped" not in f),
                          key=lambda row: row[0])
            if not rows:
                continue
            label = f"{model} {paddle}"
            axes[0].plot([kh for kh, _ in rows], [f["height"] / f["target"] for _, f in rows],
                         marker + "-", label=f"{label}: crest to trough")
            axes[0].plot([kh for kh, _ in rows],
                         [f["first_harmonic"] / f["target"] for _, f in rows], marker + "--",
                         label=f"{label}: incident 1st harmonic")
            axes[1].plot([kh for kh, _ in rows], [100 * f["reflection"] for _, f in rows],
                         marker + "-", label=label)
    axes[0].axhspan(0.95, 1.05, color="tab:green", alpha=0.3, label="±5 % of Biésel")
    axes[0].set(xlabel="kh", ylabel="H / Biésel's", title="wave height, 2 L from the paddle")
    axes[1].axhline(10, color="tab:red", ls="--", label="10 % bar")
    axes[1].set(xlabel="kh", ylabel="reflection [%]", title="reflection (Goda & Suzuki)")
    axes[0].legend(fontsize=7, ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.16))
    axes[1].legend(fontsize=8)
    for spacing, f, _ in irregular:
        fp = 1 / JONSWAP["peak_period"]
        ff = np.linspace(0.5 * fp, 3 * fp, 400)
        sigma = np.where(ff <= fp, 0.07, 0.09)
        shape = ff ** -5 * np.exp(-1.25 * (fp / ff) ** 4) * 3.3 ** np.exp(
            -((ff - fp) ** 2) / (2 * sigma ** 2 * fp ** 2))
        shape *= (JONSWAP["significant_height"] / 4) ** 2 / np.trapz(shape, ff)
        axes[2].plot(ff, shape, color="tab:green", label="JONSWAP target")
        axes[2].plot(f["f"], f["density"], color="tab:blue", label=f"mac {spacing:g} m, x = 3 m")
    axes[2].set(xlim=(0, 2.2), xlabel="f [Hz]", ylabel="S(f) [m²/Hz]", title="irregular sea")
    axes[2].legend(fontsize=8)
    save_figure(fig, "f8_waves.png")


if __name__ == "__main__":
    main()
