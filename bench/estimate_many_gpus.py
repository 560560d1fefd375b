#!/usr/bin/python3
"""An estimate on paper (docs/performance.md#a-billion-particles-on-64-gpus-an-estimate) of a
10^9-particle wcsph run of the benchmark case's geometry on 64 GPUs, from figures measured on
this project's machines and an assumed network. Prints a Markdown table; every input is named
below with where it was measured.

usage: bench/estimate_many_gpus.py [PARTICLES] [GPUS]
"""
import sys

particles = float(sys.argv[1]) if len(sys.argv) > 1 else 1e9
gpus = int(sys.argv[2]) if len(sys.argv) > 2 else 64

# Measured (docs/performance.md).
bench_particles = 261_950      # the bench case at its 0.0085 m
bench_spacing = 0.0085         # m
gpu_rate = 2.56e8              # particle-steps/s on one H100 ("WCSPH on a GPU"; 2.6e8 at 33.9 M)
steps_per_second = 10_700      # steps a simulated second at the bench spacing (ibid.)
device_bytes = 372             # bytes a particle on the device (ibid., "Memory")
ghosts_per_cut = 19_600        # ghosts a rank takes across one cut, 2 ranks ("Several ranks")
ghost_bytes_today = 4e6 / 19_600  # every field of the host's set: 4 MB for 19,600 (ibid.)
# The fields a neighbour stage reads, packed as the device packs them (position, velocity,
# density, pressure in single precision, and the kind): 33 bytes, rounded up.
ghost_bytes_lean = 36
migration_share = 0.05 / 0.94  # migration's seconds against the ghosts' on 2 ranks (ibid.)

# Assumed: InfiniBand NDR, 400 Gb/s a GPU each way, and Debian's OpenMPI, which is not
# CUDA-aware: a halo goes device -> pinned host buffer -> network -> host -> device, over PCIe
# 5.0 x16 at about 50 GB/s each way, one hop after the other.
network = 400e9 / 8            # bytes/s
pcie = 50e9                    # bytes/s
reduction = 6 * 10e-6          # the time step's allreduce: log2(64) hops of 10 us

# The tank, 1.6 x 0.67 x 0.4 m: the cut of the 2-rank run is a y-z section (0.268 m^2). A cut's
# ghosts scale with its area over the spacing squared (the halo is two supports deep, and a
# support is a fixed number of spacings). Particles are taken as dense across every cut as
# across that one (the water column's full section at the start): for water spread along the
# floor, fewer.
lx, ly, lz = 1.6, 0.67, 0.4
section = ly * lz
spacing = bench_spacing * (bench_particles / particles) ** (1 / 3)
per_gpu = particles / gpus
ghosts_full_section = ghosts_per_cut * (bench_spacing / spacing) ** 2


def ghosts(nx, ny, nz):
    """Ghosts an interior subdomain takes: two faces along each axis that is cut."""
    faces = 0.0
    for n, area in ((nx, (ly / ny) * (lz / nz)), (ny, (lx / nx) * (lz / nz)),
                    (nz, (lx / nx) * (ly / ny))):
        if n > 1:
            faces += 2 * area / section
    return faces * ghosts_full_section


compute = per_gpu / gpu_rate
steps = steps_per_second * bench_spacing / spacing
print(f"{particles:.3g} particles on {gpus} GPUs: spacing {spacing * 1e3:.3g} mm, "
      f"{per_gpu / 1e6:.3g} M a GPU ({per_gpu * device_bytes / 2**30:.1f} GiB of its memory), "
      f"compute {compute * 1e3:.0f} ms a step, {steps:,.0f} steps a simulated second\n")
print("| decomposition | ghosts a GPU | bytes a ghost | halo a step | step | efficiency | "
      "wall hours a simulated second |")
print("|---|---|---|---|---|---|---|")
for name, cuts in (("64 slabs along x (today)", (64, 1, 1)), ("8 x 8 columns (x, y)", (8, 8, 1)),
                   ("4 x 4 x 4 bricks", (4, 4, 4))):
    g = ghosts(*cuts)
    for label, size in (("every field (today)", ghost_bytes_today),
                        ("the fields read, packed", ghost_bytes_lean)):
        data = g * size
        halo = data / pcie + data / network + data / pcie
        step = compute + halo * (1 + migration_share) + reduction
        print(f"| {name} | {g / 1e6:.2f} M | {size:.0f} ({label}) | {halo * 1e3:.0f} ms | "
              f"{step * 1e3:.0f} ms | {compute / step:.2f} | {step * steps / 3600:.1f} |")
