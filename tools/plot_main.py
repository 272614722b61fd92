#!/usr/bin/python3
"""Turn the main job's LAMMPS outputs into CSV tables and PNG plots (Debian's matplotlib)."""
import math
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def table(path):
    return np.loadtxt(path, comments="#", ndmin=2)


def main(out):
    b = table(f"{out}/breathing.dat")
    t, r = b[:, 1], b[:, 2]
    np.savetxt(f"{out}/breathing.csv", np.column_stack([t, r]), delimiter=",",
               header="time_us,mean_radius_um", comments="")
    R, M, G, t0 = 30.0, 1.3e4, 8.0e5, 0.126
    omega = math.sqrt(4 * 3 * G / (M / (4 * math.pi * R * R * t0))) / R
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(t, r, label="simulation")
    ax.plot(t, R + (r[0] - R) * np.cos(omega * t), "--", label="Eq. A5, linear")
    ax.set_xlabel("time (us)")
    ax.set_ylabel("mean wall radius (um)")
    ax.set_title("in-vacuo breathing, stiff wall")
    ax.legend()
    fig.tight_layout()
    fig.savefig(f"{out}/breathing.png", dpi=120)

    p = table(f"{out}/plates.dat")
    eps, Ftop, Fbot = p[:, 3], p[:, 4], p[:, 5]
    np.savetxt(f"{out}/force-strain.csv", np.column_stack([eps, Ftop * 1e-3, Fbot * 1e-3]),
               delimiter=",", header="strain,F_top_uN,F_bottom_uN", comments="")
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(eps, Ftop * 1e-3, label="top plate (moving)")
    ax.plot(eps, Fbot * 1e-3, label="bottom plate")
    ax.set_xlabel("strain DeltaX / 2R")
    ax.set_ylabel("plate force (uN)")
    ax.set_title("empty stiff wall between plates")
    ax.legend()
    fig.tight_layout()
    fig.savefig(f"{out}/force-strain.png", dpi=120)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
