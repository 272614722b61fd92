#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The main job's tissue part: stress-strain of a tissue block compressed to failure
(in.tissue-compress output) as CSV and PNG, with the failure events marked: wall rupture (a cell
loses a tether) and cells coming apart (a lamella bond lets go).

  plot_tissue.py DIR [PREFIX]      reads DIR/PREFIX.dat (default tissue-compress), writes
                                   DIR/tissue-stress-strain.csv and .png
  plot_tissue.py DIR tissue-tension  the pull of in.tissue-tension (a PREFIX with "tension"):
                                   DIR/tissue-tension.csv and .png, failure stress (the peak of
                                   the smoothed stress), strain at the peak, failure mode

It also says whether the compression was quasi-static (cellmech.quasistatic) from 2% strain
(TISSUE_FROM) to the first wall rupture or the end: the table and verdict are printed and written
to DIR/tissue-stress-strain-quasistatic.txt; a dynamic run says so in its summary and plot title.
"""
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# the columns of in.tissue-compress's file and the smoothing are the tissue report's
from cellmech.tissue.tissuedata import COMPRESS as COLS, TENSION, failure, smooth  # noqa: E402
from cellmech import quasistatic as Q  # noqa: E402

# issue 29's range for the tissue: from 2% strain (the first contacts of a block's uneven faces
# are behind) to its first rupture (quasistatic.check cuts there) or the end of the record
TISSUE_FROM = 0.02


def load(path, cols=COLS):
    a = np.loadtxt(path, comments="#", ndmin=2)
    return {name: a[:, k + 1] for k, name in enumerate(cols)}


def events(strain, count):
    """Strains at which a cumulative count rises, and by how much."""
    d = np.diff(count, prepend=count[0])
    k = np.nonzero(d > 0)[0]
    return strain[k], d[k]


def main(out, prefix="tissue-compress"):
    c = load(f"{out}/{prefix}.dat")
    keep = c["strain"] >= 0
    d = {k: v[keep] for k, v in c.items()}
    # window of 1% strain: longer than the ringing of the plates, shorter than the failure
    ds = np.median(np.diff(d["strain"])) if len(d["strain"]) > 1 else 1.0
    n = max(1, int(round(0.01 / ds)))
    s = smooth(d["stress_kPa"], n)
    np.savetxt(f"{out}/tissue-stress-strain.csv",
               np.column_stack([d[k] for k in COLS] + [s]), delimiter=",",
               header=",".join(COLS + ["stress_smoothed_kPa"]), comments="")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(d["strain"], d["stress_kPa"], color="0.75", lw=0.8, label="stress (raw)")
    ax.plot(d["strain"], s, color="k", lw=1.8, label="stress (1% strain window)")
    er, nr = events(d["strain"], d["broken_tethers"])
    ed, nd = events(d["strain"], d["debonded_bonds"])
    top = max(s.max(), 1e-9)
    if len(er):
        ax.scatter(er, np.interp(er, d["strain"], s), s=12 + 4 * np.sqrt(nr), color="red", zorder=3,
                   label=f"wall rupture ({int(d['broken_tethers'][-1])} tethers)")
        ax.axvline(er[0], color="red", ls="--", lw=0.8)
    if len(ed):
        ax.scatter(ed, np.interp(ed, d["strain"], s), s=12 + 4 * np.sqrt(nd), marker="s",
                   color="tab:green", zorder=3,
                   label=f"lamella debonding ({int(d['debonded_bonds'][-1])} bonds)")
        ax.axvline(ed[0], color="tab:green", ls="--", lw=0.8)
    ax.set_ylim(min(0.0, s.min()), 1.15 * top)
    ax.set_xlabel("strain (plate travel / initial height)")
    ax.set_ylabel("stress (top plate force / initial cross-section, kPa)")
    bal, en, _, v = Q.check(d, TISSUE_FROM, float(d["strain"].max()))
    text = Q.report(bal, en, None, v, "tissue compression")
    with open(f"{out}/tissue-stress-strain-quasistatic.txt", "w") as f:
        f.write(text + "\n")
    # a dynamic run is labelled so: its stress holds the block's inertia as well as its stiffness
    ax.set_title(f"tissue block compressed to failure ({v.label})")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{out}/tissue-stress-strain.png", dpi=120)
    k = int(np.argmax(s))
    first = [f"first rupture at strain {er[0]:.4f}" if len(er) else "no rupture",
             f"first debond at strain {ed[0]:.4f}" if len(ed) else "no debonding"]
    print(text)
    print(f"tissue ({v.label}): peak stress {s[k]:.4g} kPa at strain {d['strain'][k]:.4f}; "
          + "; ".join(first))


def tension(out, prefix="tissue-tension"):
    """in.tissue-tension's record: stress-strain CSV and PNG with the events marked, failure stress
    and strain, failure mode, and the quasi-static verdict (the two grips' forces over strain windows,
    KE against the top grip's work) from the start to the peak. Returns (failure(), Verdict)."""
    d = load(f"{out}/{prefix}.dat", TENSION)
    f = failure(d)
    s = f["smoothed"]
    np.savetxt(f"{out}/{prefix}.csv", np.column_stack([d[k] for k in TENSION] + [s]), delimiter=",",
               header=",".join(TENSION + ["stress_smoothed_kPa"]), comments="")
    # judged up to the peak: beyond it the block comes apart at a speed no grip sets
    bal, en, _, v = Q.check(d, float(d["strain"][0]), max(f["strain_at_peak"], Q.WINDOW))
    text = Q.report(bal, en, None, v, "tissue tension")
    with open(f"{out}/{prefix}-quasistatic.txt", "w") as fh:
        fh.write(text + "\n")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(d["strain"], d["stress_kPa"], color="0.75", lw=0.8, label="stress (raw)")
    ax.plot(d["strain"], s, color="k", lw=1.8, label="stress (1% strain window)")
    for col, kw, name in (("broken_tethers", dict(color="red"), "wall rupture"),
                          ("debonded_bonds", dict(color="tab:green", marker="s"), "lamella debonding")):
        e, n = events(d["strain"], d[col])
        if len(e):
            ax.scatter(e, np.interp(e, d["strain"], s), s=12 + 4 * np.sqrt(n), zorder=3, **kw,
                       label=f"{name} ({f[col]} {'tethers' if col == 'broken_tethers' else 'bonds'})")
            ax.axvline(e[0], color=kw["color"], ls="--", lw=0.8)
    ax.plot([f["strain_at_peak"]], [f["peak_kPa"]], "kv", ms=8, label=f"failure stress {f['peak_kPa']:.3g} kPa")
    ax.axhline(0, color="0.5", lw=0.5)
    ax.set_xlabel("strain (top grip travel / initial height)")
    ax.set_ylabel("stress (top grip force / initial cross-section, kPa)")
    ax.set_title(f"tissue block pulled apart ({v.label}); failure mode: {f['mode']}")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{out}/{prefix}.png", dpi=120)
    print(text)
    print(f"tension ({v.label}): failure stress {f['peak_kPa']:.4g} kPa at strain {f['strain_at_peak']:.4f}; "
          f"failure mode {f['mode']} (to the peak: {f['broken_tethers_to_peak']} broken tethers, "
          f"{f['debonded_bonds_to_peak']} debonded bonds; to the end: {f['broken_tethers']} and "
          f"{f['debonded_bonds']}); final stress {f['final_kPa']:.4g} kPa")
    return f, v


if __name__ == "__main__":
    args = sys.argv[1:3]
    if len(args) > 1 and "tension" in args[1]:
        tension(*args)
    else:
        main(args[0] if args else ".", *args[1:2])
