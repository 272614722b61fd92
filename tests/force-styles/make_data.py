#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Make data.cell, the system of the force-style harness tests, from a two-cell tissue of cellgen.

    python3 tools/cellgen.py tissue -o two.data --centres centres.txt --level 1 --nfluid 4 \
        --tissue-box -8 19 -8 8 -8 8 --bending   # centres.txt: "0 0 0 6" and "11 0 0 6"
    python3 tests/force-styles/make_data.py two.data tests/force-styles

cellgen's walls are at rest (every force zero) and its box is wide. The harness compares forces,
so the system is made to exert them everywhere, and made to cross a periodic boundary so that
newton on and off differ in how forces on ghost atoms reach their owners:
- the box is periodic and tight along x (cell 2 touches the periodic image of cell 1), and the
  two cells are shifted so that cell 1 straddles the x boundary;
- every atom is displaced off its reference position d2_cellref (tethers and lamella bonds are
  stretched or compressed, contacts form) and given a velocity (the damping terms act);
- the fluid densities d_rho scatter around rho0 (pressure gradients), and every wall node has a
  lamella area d_alam (cellgen's + 0.5), so that bond_style cell/lamella acts on every bond.
The per-atom fields of fix property/atom (cellgen's "cell" section) go to cell-fields.lmp as set
commands that in.cell runs after read_data: the harness's bond tests write their data file with
'nofix', and the round trip must restore them.
The random numbers are seeded, so the file is reproducible: the committed data.cell from the
cellgen of commit 7ae7c66 (README.md: today's cellgen fills this tissue with 94 atoms, not 92).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from cellmech.cellgen.datafile import read_data, write  # noqa: E402

BOX = ((-10.0, 21.0), (-13.5, 13.5), (-13.5, 13.5))
SHIFT = -5.0    # along x: cell 1 (centre 0) straddles xlo = -10
FIELDS = ["mass", "d_rho", "d_drho", "d2_cellref[1]", "d2_cellref[2]", "d2_cellref[3]", "d_alam"]


def main(src, folder):
    rng = np.random.default_rng(20260704)
    data = read_data(src)
    lo = np.array([b[0] for b in BOX])
    length = np.array([b[1] - b[0] for b in BOX])
    data.title = "# cellmech force-style tests (tests/force-styles/make_data.py) from:\n" + data.title
    data.box = [v for b in BOX for v in b]
    atoms, velocities = [], []
    for words in data.rows("Atoms"):
        x = np.array([float(w) for w in words[3:6]])
        x[0] += SHIFT
        x += rng.uniform(-0.3, 0.3, 3)
        image = np.floor((x - lo) / length).astype(int)
        x -= image * length
        atoms.append(words[:3] + [f"{v:.16g}" for v in x] + [str(i) for i in image])
        v = rng.uniform(-0.5, 0.5, 3)
        velocities.append([words[0]] + [f"{c:.16g}" for c in v])
    fields = ["# SPDX-License-Identifier: GPL-2.0-or-later",
              "# per-atom fields of fix cell (tests/force-styles/make_data.py)"]
    for words in data.rows("cell"):    # rmass d_rho d_drho d2_cellref[1-3] d_alam
        vals = [float(w) for w in words[1:]]
        if vals[1] > 0.0:    # fluid: density around rho0 = 1
            vals[1] = 1.0 + rng.uniform(-0.03, 0.03)
        else:
            vals[6] += 0.5
        vals[3] += SHIFT    # reference positions move with the cells, unwrapped
        fields.append(f"set atom {words[0]} " + " ".join(f"{n} {v:.16g}" for n, v in zip(FIELDS, vals)))
    sections, comments = {}, {}
    for name, rows in data.sections.items():
        if name == "Bonds":
            sections["Velocities"] = velocities
            # coefficients of in.cell's placeholder bond style, until the harness sets its own
            sections["Bond Coeffs"], comments["Bond Coeffs"] = [["1"], ["2"]], "zero"
        if name != "cell":
            sections[name] = atoms if name == "Atoms" else rows
            comments[name] = data.comments[name]
    data.sections, data.comments = sections, comments
    write(f"{folder}/data.cell", data, box_format="{}")
    with open(f"{folder}/cell-fields.lmp", "w") as f:
        f.write("\n".join(fields) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: make_data.py CELLGEN_TISSUE.data OUTPUT_FOLDER")
    main(sys.argv[1], sys.argv[2])
