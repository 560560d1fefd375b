#!/usr/bin/python3
"""C2 of VALIDATION.md: an elastic sphere hitting the floor at v0 = 1 m/s (cases/hertz_impact.yaml).
Compares the contact time and the peak overlap with Hertz's formulas, and plots the contact
force against the Hertz force from integrating m* delta'' = -4/3 E* sqrt(R*) delta^(3/2).
Writes docs/img/hertz_impact.png.

usage: /usr/bin/python3 validation/hertz_impact.py [--out DIR] [--no-run] [--sluice PATH]
"""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from runs import case_parser, read_body, run_case, save_figure

# cases/hertz_impact.yaml: the sphere; the floor is the tank wall, whose default material is
# steel (E = 200 GPa, nu = 0.3) with infinite mass and radius.
R, RHO, E1, NU1, V0 = 0.1, 1000.0, 1.0e8, 0.3, 1.0
E2, NU2 = 200.0e9, 0.3
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
E_STAR = 1.0 / ((1 - NU1 ** 2) / E1 + (1 - NU2 ** 2) / E2)
K_N = 4.0 / 3.0 * E_STAR * math.sqrt(R)
T_CONTACT = 2.868 * (MASS ** 2 / (R * E_STAR ** 2 * V0)) ** 0.2
DELTA_MAX = (15.0 * MASS * V0 ** 2 / (16.0 * E_STAR * math.sqrt(R))) ** 0.4


def hertz_overlap(steps=20000):
    """delta(t) through the contact, by RK4 on m* delta'' = -K_n delta^(3/2), delta(0) = 0,
    delta'(0) = v0, until the sphere leaves the floor."""
    def accel(d):
        return -K_N * max(d, 0.0) ** 1.5 / MASS

    dt = 1.2 * T_CONTACT / steps
    t, d, v = 0.0, 0.0, V0
    times, overlaps = [t], [d]
    while d >= 0.0:
        k1d, k1v = v, accel(d)
        k2d, k2v = v + 0.5 * dt * k1v, accel(d + 0.5 * dt * k1d)
        k3d, k3v = v + 0.5 * dt * k2v, accel(d + 0.5 * dt * k2d)
        k4d, k4v = v + dt * k3v, accel(d + dt * k3d)
        d += dt / 6.0 * (k1d + 2 * k2d + 2 * k3d + k4d)
        v += dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v)
        t += dt
        times.append(t)
        overlaps.append(d)
    return np.array(times), np.clip(np.array(overlaps), 0.0, None)


def main():
    args = case_parser("hertz_impact", __doc__.splitlines()[0]).parse_args()
    data = read_body(run_case("hertz_impact", args), "sphere")
    t, z, fz = data["time"], data["z"], data["contact_fz"]

    interval = t[1] - t[0]
    touching = np.nonzero(fz > 0)[0]
    first, last = touching[0], touching[-1]
    duration = t[last] - t[first] + interval
    overlap = -(z - R).min()
    print(f"contact time {duration * 1e3:.4f} ms against Hertz {T_CONTACT * 1e3:.4f} ms "
          f"({100 * (duration / T_CONTACT - 1):+.2f} %)")
    print(f"peak overlap {overlap * 1e3:.4f} mm against Hertz {DELTA_MAX * 1e3:.4f} mm "
          f"({100 * (overlap / DELTA_MAX - 1):+.2f} %); peak force {fz.max():.1f} N against "
          f"{K_N * DELTA_MAX ** 1.5:.1f} N")

    # the sphere starts (z0 - R) above the floor at speed |vz0|: that is when contact begins
    t0 = (z[0] - R) / abs(data["vz"][0])
    tau, delta = hertz_overlap()
    window = slice(first, last + 1)
    fig = plt.figure(figsize=(6.4, 4.4))
    plt.plot(1e3 * t[window], fz[window], "-", lw=2.5, color="tab:blue",
             label=f"sluice, contact_fz every {interval * 1e3:g} ms")
    plt.plot(1e3 * (t0 + tau), K_N * delta ** 1.5, "k--", lw=1.2,
             label="Hertz, F = 4/3 E* sqrt(R*) delta^(3/2)")
    plt.axvline(1e3 * (t0 + T_CONTACT), color="0.6", lw=0.8, label="end of contact, Hertz t_c")
    plt.xlabel("time [ms]")
    plt.ylabel("contact force on the sphere, z [N]")
    plt.title("C2 Hertz impact")
    plt.text(0.03, 0.97,
             f"R = {R} m, E = {E1:.0e} Pa, v0 = {V0} m/s\n"
             f"t_c: {duration * 1e3:.3f} ms ({100 * (duration / T_CONTACT - 1):+.2f} %)\n"
             f"peak overlap: {overlap * 1e3:.4f} mm ({100 * (overlap / DELTA_MAX - 1):+.2f} %)",
             transform=plt.gca().transAxes, va="top", fontsize=8)
    plt.legend(loc="upper right", fontsize=8)
    plt.grid(alpha=0.3)
    save_figure(fig, "hertz_impact.png")


if __name__ == "__main__":
    main()
