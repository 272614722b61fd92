# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 29 item 3, the short form of lammps-inputs/in.tissue-tension: the coarse 2x2x2 block
(cellgen.py tissue --lattice sc --n 2 2 2 --level 3 --nfluid 440), inflated briefly (in.tissue-
inflate, 1500 steps at Lp 10 and a 2000-step settle), clamped in its grips for 2 us under drag,
then pulled at 1 m/s to 12% strain with a weak lamella (sigl 30 kPa, Gl 100 pg/us^2 = 0.1 J/m^2:
delta_c 1.23 um, a bond lets go at 12 um of opening) and walls that cannot rupture (lamf 0).

The run is dynamic, and the test says so: the grips clamp only the caps of the domed free faces,
and the block rings between them in its axial mode (period about 5 us, 4.5% strain at 1 m/s) with
an amplitude of +-20 kPa, more than the lamella can carry (a quasi-static pull of this block needs
a speed well below 0.25 m/s, tens of us of pull: not a short test). Asserted, each with its reason:

1. the quasi-static check (cellmech.quasistatic) calls the run dynamic, on the grips' balance;
2. failure mode: the lamella debonds (bonds let go), no wall ruptures (lamf 0), and plot_tissue's
   failure() names debonding;
3. the debonded area is the same in the record (compute cell/props, halved), in compute
   cell/contacts (column 6, summed over the pairs) at every record, to the table's printed digits
   (fix ave/time writes 6 significant digits: 1e-5 of the total over 12 pairs);
4. the strength bound: the load across the mid-plane, the lamella's adhesion less the walls'
   contact push of the cell pairs that straddle it (cell/contacts columns 7 and 8, on their line of
   centres), never exceeds sigl times those pairs' glued area (the strength law caps every bond's
   traction at sigl; contacts only push). The grip stress rings about it; averaged over the
   ringing period (the change of the half-block's momentum over a period is small) its peak stays
   under the bound divided by A0 as well;
5. the mid-plane load rises to its peak and drops (the lamella softens past delta_c and lets go).
About 60 s on one core.
"""
import json
import os
import sys

import numpy as np

import lmptest as T
from cellmech import quasistatic as Q
from cellmech.tissue.tissuedata import TENSION, PAIRS, PROPS, dominant_period, load, load_table, smooth

sys.path.insert(0, os.path.join(T.ROOT, "tools"))
from plot_tissue import failure  # noqa: E402

SIGL, GL = 30.0, 100.0          # kPa, pg/us^2
PULL = dict(lamf=0, sigl=SIGL, Gl=GL, mu=10.0, hold=2.0, vpull=1.0, strain=0.12, every=100, tabevery=100)


def midplane_pairs(cells, zmid):
    """The cell pairs (1-based ids) whose centres lie on either side of z = zmid."""
    cz = cells[:, PROPS.index("cz")]
    return lambda i, j: (cz[int(i) - 1] - zmid) * (cz[int(j) - 1] - zmid) < 0


def main():
    d = T.workdir("tension")
    for old in ("debond.log",):
        if os.path.exists(os.path.join(d, old)):
            os.remove(os.path.join(d, old))
    T.cellgen("tissue", "-o", "block.data", "--lattice", "sc", "--n", 2, 2, 2, "--level", 3, "--nfluid", 440,
              cwd=d)
    special = json.load(open(os.path.join(d, "block.json")))["extra_special_per_atom"]
    common = dict(T.COARSE, dir=T.INPUTS, special=special)
    T.lmp(f"{T.INPUTS}/in.tissue-inflate", cwd=d, log="log.inflate",
          variables=dict(common, data="block.data", nsteps=1500, nsettle=2000, every=500,
                         restart_out="block.restart"))
    _, log = T.lmp(f"{T.INPUTS}/in.tissue-tension", cwd=d, log="log.tension",
                   variables=dict(common, restart="block.restart", **PULL))
    analyse(d, "tissue-tension", log)
    T.finish()


def analyse(d, prefix, log):
    rec = load(f"{d}/{prefix}.dat", TENSION)
    cells = load_table(f"{d}/{prefix}-cells.dat")
    pairs = load_table(f"{d}/{prefix}-pairs.dat")
    A0 = float(log.split("um^2\n")[0].split("A0 ")[-1])     # the print line of in.tissue-tension

    # 1. dynamic, and said so
    f = failure(rec)
    bal, en, _, v = Q.check(rec, float(rec["strain"][0]), float(rec["strain"].max()))
    print(Q.report(bal, en, None, v, "tension, 1 m/s"))
    period = dominant_period(rec["stress_kPa"], float(np.median(np.diff(rec["time_us"]))))
    print(f"ringing period of the grip stress {period:.3g} us")
    T.check("the 1 m/s pull is called dynamic on the grips' balance", not v.quasistatic and "balance" in v.failed,
            f"worst imbalance {v.numbers['balance']:.0%}")

    # 2. failure mode
    T.check("failure mode: the lamella debonds, no wall ruptures (lamf 0)",
            f["mode"] == "lamella debonding" and f["debonded_bonds"] > 0 and f["broken_tethers"] == 0,
            f"{f['mode']}: {f['debonded_bonds']} bonds, {f['broken_tethers']} tethers")

    # 3. debonded area: the record (cell/props) and cell/contacts, at every record
    byrow = {int(s): r for s, r in pairs}
    worst = max(abs(rec["debonded_area_um2"][k] - byrow[int(s)][:, PAIRS.index("debonded_area")].sum())
                for k, s in enumerate(rec["step"]))
    scale = max(rec["debonded_area_um2"].max(), 1.0)
    # the per-pair table is written with fix ave/time's 6 significant digits: 12 pairs round to 1e-5
    T.check("debonded area: record (cell/props) = cell/contacts at every record (1e-5, the table's digits)",
            worst < 1e-5 * scale,
            f"{rec['debonded_area_um2'][-1]:.6g} um^2, largest difference {worst:.1e}")

    # 4. the strength bound across the mid-plane
    zmid = float(np.mean(cells[0][1][:, PROPS.index("cz")]))
    cross = midplane_pairs(cells[0][1], zmid)
    step0, p0 = pairs[0]
    m0 = np.array([cross(i, j) for i, j in p0[:, :2]])
    Across = float(p0[m0, PAIRS.index("glued_area")].sum())
    bound = SIGL * Across / A0
    load_mid, cap = [], []
    for s, p in pairs:
        m = np.array([cross(i, j) for i, j in p[:, :2]])
        lam, con = p[m, PAIRS.index("F_lamella")], p[m, PAIRS.index("F_contact")]
        load_mid.append(float(-(lam + con).sum()))
        cap.append(SIGL * float(p[m, PAIRS.index("glued_area")].sum()))
    load_mid, cap = np.array(load_mid), np.array(cap)
    over = float(np.max(load_mid - cap))
    print(f"mid-plane: {int(m0.sum())} straddling pairs, glued area {Across:.6g} um^2 of A0 {A0:.6g} um^2: "
          f"bound sigl x area / A0 = {bound:.4g} kPa; mid-plane load peaks at {load_mid.max() / A0:.4g} kPa")
    T.check("the load across the mid-plane never exceeds sigl x its glued area",
            over <= 1e-9 * cap.max(), f"peak {load_mid.max():.5g} nN against {cap[np.argmax(load_mid)]:.5g} nN")
    sp = smooth(rec["stress_kPa"], max(2, int(round(period / float(np.median(np.diff(rec["time_us"])))))))
    T.check("grip stress averaged over the ringing period stays under the bound", sp.max() <= bound,
            f"peak {sp.max():.4g} kPa at strain {rec['strain'][np.argmax(sp)]:.4f}, bound {bound:.4g} kPa")

    # 5. the mid-plane load rises then drops
    k = int(np.argmax(load_mid))
    T.check("the mid-plane load rises to a peak and drops after it (below half the peak by the end)",
            0 < k < len(load_mid) - 1 and load_mid[k] > 0 and load_mid[-1] < 0.5 * load_mid[k],
            f"{load_mid[0] / A0:.3g} -> {load_mid[k] / A0:.3g} kPa at record {k} -> {load_mid[-1] / A0:.3g} kPa")
    print(f"failure stress (grip, 1% strain window) {f['peak_kPa']:.4g} kPa at strain {f['strain_at_peak']:.4f}")


if __name__ == "__main__":
    main()
