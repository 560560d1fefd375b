#!/usr/bin/python3
"""F3 of VALIDATION.md: the Kleefsman et al. (2005) 3D dam break with an obstacle, run to 6 s
with each model (cases/kleefsman_3d.yaml, --set model.name=...), and its probes plotted: the
water height at the four gauges and the pressure at the eight sensors on the obstacle, the
models in one figure each. Writes docs/img/f3_kleefsman_gauges.png and
docs/img/f3_kleefsman_pressure.png.

usage: /usr/bin/python3 validation/kleefsman_3d.py [--no-run] [--out DIR] [--models wcsph,mps]
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from probes_csv import read_probe
from runs import case_parser, require, run_case, save_figure

GAUGES = ["g496", "g992", "g1488", "g2638"]
SENSORS = [f"P{k}" for k in range(1, 9)]
COLOURS = {"wcsph": "tab:blue", "mps": "tab:red"}


def main():
    parser = case_parser("kleefsman_3d", __doc__.splitlines()[0])
    parser.add_argument("--models", default="wcsph,mps")
    args = parser.parse_args()
    models = args.models.split(",")
    outputs = {}
    for model in models:
        out = run_case("kleefsman_3d", args, [f"model.name={model}"], suffix=f"_{model}")
        require(os.path.join(out, "probes.csv"))
        outputs[model] = os.path.join(out, "probes.csv")

    fig, axes = plt.subplots(4, 1, figsize=(7, 8), sharex=True)
    for ax, gauge in zip(axes, GAUGES):
        for model in models:
            t, h = read_probe(outputs[model], gauge)
            ax.plot(t, h, color=COLOURS.get(model), lw=0.8, label=f"sluice {model}")
        ax.set_ylabel(f"{gauge} [m]")
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper right", fontsize=8)
    axes[0].set_title("F3: water height at the gauges (x in mm), Kleefsman et al. 2005")
    axes[-1].set_xlabel("time [s]")
    save_figure(fig, "f3_kleefsman_gauges.png")

    fig, axes = plt.subplots(4, 2, figsize=(10, 8), sharex=True)
    for ax, sensor in zip(axes.T.flat, SENSORS):
        for model in models:
            t, p = read_probe(outputs[model], sensor)
            ax.plot(t, [v / 1000 for v in p], color=COLOURS.get(model), lw=0.6,
                    label=f"sluice {model}")
        ax.set_ylabel(f"{sensor} [kPa]")
        # The impact's acoustic spikes of the weakly compressible model (tens of kPa for a
        # millisecond) would flatten every other curve: clipped, and said so in the title.
        ax.set_ylim(-5, 20 if sensor in SENSORS[:4] else 8)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(loc="upper right", fontsize=8)
    axes[0, 0].set_title("front face of the obstacle (P1-P4), spikes clipped")
    axes[0, 1].set_title("top of the obstacle (P5-P8), spikes clipped")
    for ax in axes[-1]:
        ax.set_xlabel("time [s]")
    save_figure(fig, "f3_kleefsman_pressure.png")


if __name__ == "__main__":
    main()
