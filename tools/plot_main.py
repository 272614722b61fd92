#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Turn the main job's LAMMPS outputs (inflate.dat, compress.dat) into CSV tables and PNG plots."""
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def table(path):
    return np.loadtxt(path, comments="#", ndmin=2)


def main(out):
    # inflate.dat: step t V A P M Nf lam lammax Feq leak dM
    a = table(f"{out}/inflate.dat")
    t, P, lam, Feq, leak, M = a[:, 1], a[:, 4], a[:, 7], a[:, 9], a[:, 10], a[:, 5]
    np.savetxt(f"{out}/inflation.csv", np.column_stack([t, P, lam, Feq * 1e-3, M, leak]), delimiter=",",
               header="time_us,mean_pressure_kPa,mean_stretch,equatorial_force_uN,fluid_mass_pg,leaked",
               comments="")
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.5))
    ax[0].plot(t, P)
    ax[0].set_xlabel("time (us)")
    ax[0].set_ylabel("mean fluid pressure (kPa)")
    ax[1].plot(t, lam)
    ax[1].set_xlabel("time (us)")
    ax[1].set_ylabel("mean tether stretch")
    fig.suptitle("inflation of the stiff cell by osmosis")
    fig.tight_layout()
    fig.savefig(f"{out}/inflation.png", dpi=120)

    # compress.dat: step t eps Ftop Fbot Feq P
    c = table(f"{out}/compress.dat")
    eps, Ftop, Fbot = c[:, 2], c[:, 3], c[:, 4]
    keep = eps >= 0
    np.savetxt(f"{out}/force-strain.csv", np.column_stack([eps, Ftop * 1e-3, Fbot * 1e-3])[keep],
               delimiter=",", header="strain,F_top_uN,F_bottom_uN", comments="")
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(eps[keep], Ftop[keep] * 1e-3, label="top plate (moving)")
    ax.plot(eps[keep], Fbot[keep] * 1e-3, label="bottom plate")
    ax.set_xlabel("strain DeltaX / 2R")
    ax.set_ylabel("plate force (uN)")
    ax.set_title("quasistatic compression of the inflated stiff cell")
    ax.legend()
    fig.tight_layout()
    fig.savefig(f"{out}/force-strain.png", dpi=120)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
