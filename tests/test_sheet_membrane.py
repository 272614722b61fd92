# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 11: the sheet of tests/test_sheet.py with the membrane wall (lammps-inputs/in.sheet
-var wall membrane, angle style cell/membrane) against the exact incompressible Neo-Hookean sheet,
sides free (uniaxial stress, lam - lam^-2) and sides fixed (plane strain, lam - lam^-3), up to
stretch 1.5, bonds along X and along Y (cellgen.py sheet --orient). The tether sheet stays in
test_sheet.py: it is 30% stiffer than this, the finding that motivated the membrane element.

A constant-strain element reproduces a homogeneous stretch exactly, and a homogeneous state is
in equilibrium with the sheet's boundaries (a zigzag border's segments at one node have opposite
normals, so their tractions cancel node by node), so the force must be P W to the minimiser's
tolerance, with the nominal stress P = G t0 (lam - lam^-2) or G t0 (lam - lam^-3) and W the
sheet's reference width from its geometry, not fitted (cellmech.validation.analysis.
sheet_membrane_width, which says why: y span with bonds along X, A0 / x span along Y).
Asserted: at every stretch from 1.01 to 1.5 in all four cases within 1e-6 (the issue asks for 1%;
an exact element leaves only the minimiser's tolerance, 1e-12 here, so anything near 1e-6 would
be an error of the element or of the boundaries), and the forces on the pulled and held edges
balance.
The bending wall on a flat sheet with hinges gives the membrane's forces (the hinges stay flat),
and an unknown -var wall or the bending wall without hinges stop with a message.
A 10 x 10 node sheet (the element is exact on any mesh; tools/validate.sh runs the paper's 20 x
20 beside the tethers) keeps the test to seconds.
"""
import os
import re

import numpy as np

import lmptest as T

from cellmech.validation import references as ref
from cellmech.validation.analysis import sheet_membrane_width  # W, shared with tools/validate.sh

G, T0, A, N = T.STIFF["G"], T.STIFF["t0"], 2.5, 10
LAMS = (1.01, 1.05, 1.1, 1.2, 1.3, 1.4, 1.5)


def test_membrane_sheet_neo_hookean(rundir):
    d = rundir
    print(f"{'bonds':5s} {'sides':5s} {'lam':>5s} {'F/(G t0 W)':>11s} {'NeoH':>8s} {'err':>9s}")
    worst = {}
    for orient in ("x", "y"):
        data = f"sheet-{orient}.data"
        T.cellgen("sheet", "-o", data, "--nx", N, "--ny", N, "--bond", A, "--orient", orient, cwd=d)
        W = sheet_membrane_width(os.path.join(d, data), orient)
        for sides in ("free", "fixed"):
            out = f"{orient}-{sides}.dat"
            inp = f"variable lam index {' '.join(map(str, LAMS))}\ninclude {T.INPUTS}/in.sheet\n"
            T.lmp(inp, cwd=d, log=f"log.{orient}-{sides}", variables=dict(
                dir=T.INPUTS, wall="membrane", data=data, sides=sides, a=A, out=out))
            a = T.load(os.path.join(d, out))
            lam, f, fh = a[:, 0], a[:, 1] / (G * T0 * W), a[:, 2] / (G * T0 * W)
            nh = ref.sheet_neo_hookean(lam, sides)
            err = f / nh - 1
            for i in range(len(lam)):
                print(f"{orient:5s} {sides:5s} {lam[i]:5.2f} {f[i]:11.6f} {nh[i]:8.5f} {err[i]:+9.2e}")
            worst[(orient, sides)] = np.abs(err).max()
            T.check(f"{orient}/{sides}: the stretches 1.01 .. 1.5 were all reached",
                    len(lam) == len(LAMS) and np.allclose(lam, LAMS))
            T.check(f"{orient}/{sides}: pulled and held edge forces balance (1e-5)",
                    np.allclose(f, fh, rtol=1e-5), f"max rel diff {np.max(abs(f / fh - 1)):.1e}")
            T.check(f"{orient}/{sides}: the exact Neo-Hookean sheet within 1e-6 up to stretch 1.5",
                    worst[(orient, sides)] < 1e-6, f"{worst[(orient, sides)]:.2e}")
        print(f"bonds along {orient}: W = {W:.6f} um")
    print("largest |error| per case: " + ", ".join(f"{k[0]}/{k[1]} {v:.1e}" for k, v in worst.items()))

    # -var wall bending on a sheet with hinges (cellgen --bending): stretched in its plane, the
    # hinges stay flat and store nothing, so the forces are the membrane's
    T.cellgen("sheet", "-o", "sheet-xb.data", "--nx", N, "--ny", N, "--bond", A, "--orient", "x",
              "--bending", cwd=d)
    inp = f"variable lam index {' '.join(map(str, LAMS))}\ninclude {T.INPUTS}/in.sheet\n"
    _, log = T.lmp(inp, cwd=d, log="log.x-free-bending", variables=dict(
        dir=T.INPUTS, wall="bending", data="sheet-xb.data", sides="free", a=A, out="xb-free.dat"))
    fb, fm = T.load(os.path.join(d, "xb-free.dat"))[:, 1], T.load(os.path.join(d, "x-free.dat"))[:, 1]
    diff = np.abs(fb / fm - 1).max()
    hinges = re.search(r"^\s*(\d+) dihedrals", log, flags=re.M)
    styled = re.search(r"^dihedral_style\s+cell/bending", log, flags=re.M) is not None
    print(f"bending wall, bonds x, free sides: {hinges.group(1) if hinges else 0} hinges, "
          f"dihedral_style cell/bending {'set' if styled else 'not set'}; forces differ from the "
          f"membrane's by {diff:.1e}")
    T.check("bending wall on a flat sheet: hinges in use, the membrane's forces (1e-9)",
            diff < 1e-9 and styled and hinges is not None and int(hinges.group(1)) > 0, f"{diff:.1e}")

    # bad input: an unknown wall, and the bending wall without hinges in the data file
    for name, wall, data, expect in (
            ("unknown wall", "shell", "sheet-x.data", "-var wall shell: expected tether, membrane or bending"),
            ("bending without hinges", "bending", "sheet-x.data", "no dihedrals: write it with cellgen.py")):
        rc, log = T.lmp(inp, cwd=d, check=False, log=f"log.bad-{wall}", variables=dict(
            dir=T.INPUTS, wall=wall, data=data, sides="free", a=A, out="bad.dat"))
        msg = [l for l in log.splitlines() if l.startswith("ERROR")]
        print(f"{name}: rc {rc}, {msg[-1] if msg else 'no error'}")
        T.check(f"bad input ({name}) stops with a message naming -var wall",
                rc != 0 and any(expect in l for l in msg), msg[-1] if msg else "no error")
