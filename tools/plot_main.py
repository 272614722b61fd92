#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Turn the main job's LAMMPS outputs (inflate.dat, compress.dat) into CSV tables and PNG plots,
and say whether the compression was quasi-static (cellmech.quasistatic, over CELL_RANGE): the
table and verdict are printed and written to force-strain-quasistatic.txt beside the CSV; a
dynamic run says so in its plot's title. The force-strain plot carries the membrane reference
(tools/cellmech/membrane.py: the inflated Neo-Hookean membrane and the same membrane with the
tether network's law, at the run's turgor), and the summary the model against it at 19% strain."""
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from cellmech import membrane, params  # noqa: E402
from cellmech import quasistatic as Q  # noqa: E402
from cellmech.tissue.tissuedata import load  # noqa: E402

# issue 29's range for the single cell: from 5% strain (past the first contact's transient, where
# the cell is brought from rest to the plate's speed) to the end of the compression, 20%
CELL_RANGE = (0.05, 0.20)


def table(path):
    return np.loadtxt(path, comments="#", ndmin=2)


def reference(turgor, strains):
    """The membrane model's plate force (nN) at the strains, for the Neo-Hookean sheet and for the
    tether network's law: Table I's stiff wall (cell-model.lmp), the main job's radius, the
    contents the model's Tait fluid of bulk modulus rho0 c^2 (docs/membrane.rst)."""
    t = params.table()
    args = (t["G"] * t["t0"], params.CELL["R"], turgor, strains)
    kw = dict(bulk_modulus=t["rho0"] * t["c"] ** 2)
    return {law: np.array([c["F"] for c in membrane.compress_curve(*args, **kw, material=law)])
            for law in ("neohookean", "network")}


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

    # compress.dat: in.compress's record, named by cellmech.quasistatic.CELL_COMPRESS
    c = load(f"{out}/compress.dat", Q.CELL_COMPRESS)
    eps, Ftop, Fbot = c["strain"], c["F_top_nN"], c["F_bottom_nN"]
    keep = eps >= 0
    np.savetxt(f"{out}/force-strain.csv", np.column_stack([eps, Ftop * 1e-3, Fbot * 1e-3])[keep],
               delimiter=",", header="strain,F_top_uN,F_bottom_uN", comments="")
    bal, en, _, v = Q.check(c, *CELL_RANGE)
    text = Q.report(bal, en, None, v, "single cell compression")
    print(text)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(eps[keep], Ftop[keep] * 1e-3, label="top plate")
    ax.plot(eps[keep], Fbot[keep] * 1e-3, label="bottom plate")
    # the reference at the run's turgor (the mean pressure before contact); compared at 19% strain,
    # both plates' mean over the 18-20% window against the model's mean over the same records
    turgor = float(np.mean(c["P_mean_kPa"][eps < 0])) if np.any(eps < 0) else float(c["P_mean_kPa"][0])
    strains = np.linspace(0.0, max(0.21, float(eps.max())), 43)
    try:
        ref = reference(turgor, strains)
    except Exception as e:  # an unconverged reference leaves the plot without it, said so
        ref = {}
        print(f"membrane reference left out ({e.__class__.__name__}: {e})")
    win = (eps >= CELL_RANGE[1] - 0.02) & (eps <= CELL_RANGE[1])
    for law, style, name in (("neohookean", "k--", "membrane theory, Neo-Hookean"),
                             ("network", "k:", "membrane theory, tether-network law")):
        if law not in ref:
            continue
        ax.plot(strains, ref[law] * 1e-3, style, label=name)
        if win.any():
            model = float(np.mean(0.5 * (Ftop + Fbot)[win]))
            theory = float(np.mean(np.interp(eps[win], strains, ref[law])))
            line = (f"at {CELL_RANGE[1] - 0.02:.0%}-{CELL_RANGE[1]:.0%} strain: model {model * 1e-3:.1f} uN, "
                    f"{name} {theory * 1e-3:.1f} uN ({model / theory - 1:+.1%}; turgor {turgor:.0f} kPa)")
            print(line)
            text += "\n" + line
    ax.set_xlabel("strain DeltaX / 2R")
    ax.set_ylabel("plate force (uN)")
    # a dynamic run is labelled so: its curve holds the cell's inertia as well as its stiffness
    ax.set_title(f"{v.label} compression of the inflated stiff cell"
                 + ("" if v.quasistatic else "\n(not quasi-static: force-strain-quasistatic.txt says why)"),
                 fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{out}/force-strain.png", dpi=120)
    with open(f"{out}/force-strain-quasistatic.txt", "w") as f:
        f.write(text + "\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
