# SPDX-License-Identifier: GPL-2.0-or-later
"""LAMMPS data files: read any of them (cellgen's, LAMMPS's write_data) into header counts, box and
sections, and write them back.

The layout is LAMMPS's (read_data): the first line is a title; header lines ("N keyword", "lo hi
xlo xhi", "xy xz yz") until the first section; a section is a line that starts with a letter (its
name, "Atoms", "Pair Coeffs", or a fix's ID such as cellgen's per-atom "cell" section), a comment
after '#' on that line (the atom style, or the names of a fix's columns), then its rows. Comments
('#' to the end of a line) and blank lines are not data anywhere."""
import os
from dataclasses import dataclass, field

import numpy as np

from .. import params
from .mesh import hinges

AXES = ("xlo xhi", "ylo yhi", "zlo zhi")
TILT = "xy xz yz"


@dataclass
class DataFile:
    """title: the first line as it stands; counts: header number of each keyword ("atoms",
    "atom types", "bonds", ...) in file order; box: xlo xhi ylo yhi zlo zhi; tilt: xy xz yz or None;
    sections: name -> rows, each row its words (strings, as written), in file order; comments:
    name -> the text after '#' on the section's line ('' when none)."""
    title: str = ""
    counts: dict = field(default_factory=dict)
    box: list = field(default_factory=list)
    tilt: list = None
    sections: dict = field(default_factory=dict)
    comments: dict = field(default_factory=dict)

    def rows(self, name):
        """The rows of a section, [] when the file has none."""
        return self.sections.get(name, [])

    def array(self, name, dtype=float, width=0):
        """A section as a 2-d array (rows x columns) of dtype; shape (0, width) when absent or
        empty."""
        rows = self.rows(name)
        return np.array(rows, dtype=dtype) if rows else np.zeros((0, width), dtype)


def _header_line(data, words):
    if len(words) == 4 and " ".join(words[2:]) in AXES:
        axis = AXES.index(" ".join(words[2:]))
        data.box[2 * axis:2 * axis + 2] = [float(words[0]), float(words[1])]
    elif words[3:] == TILT.split() and len(words) == 6:
        data.tilt = [float(w) for w in words[:3]]
    else:
        key = " ".join(words[1:])
        data.counts[key] = int(words[0]) if words[0].lstrip("+-").isdigit() else float(words[0])


def read_data(path):
    """Read a LAMMPS data file into a DataFile."""
    data, section = DataFile(box=[-0.5, 0.5] * 3), None    # LAMMPS's box when the file gives none
    with open(path) as f:
        data.title = f.readline().rstrip("\n")
        for line in f:
            text, _, comment = line.partition("#")
            words = text.split()
            if not words:
                continue
            if words[0][0].isalpha():
                section = " ".join(words)
                data.sections[section] = []
                data.comments[section] = comment.strip()
            elif section is None:
                _header_line(data, words)
            else:
                data.sections[section].append(words)
    return data


def _lines(data, box_format):
    yield data.title + "\n\n"
    yield from (f"{n} {k}\n" for k, n in data.counts.items())
    yield "\n"
    for k, axis in enumerate(AXES):
        yield f"{box_format.format(data.box[2 * k])} {box_format.format(data.box[2 * k + 1])} {axis}\n"
    if data.tilt is not None:
        yield " ".join(box_format.format(v) for v in data.tilt) + f" {TILT}\n"
    for name, rows in data.sections.items():
        comment = data.comments.get(name, "")
        yield "\n" + name + (f" # {comment}" if comment else "") + "\n\n"
        yield from ((r if isinstance(r, str) else " ".join(map(str, r))) + "\n" for r in rows)


def format_data(data, box_format="{:.10g}"):
    """The text of a DataFile in cellgen's layout: the title, a blank line, the counts, a blank
    line, the box (and tilt), then each section after a blank line: its line, a blank line, its
    rows. A row is its words (joined by one space) or a whole line; rows may be any iterable (a
    generator is written as it is consumed, not held)."""
    return "".join(_lines(data, box_format))


def write(path, data, box_format="{:.10g}"):
    """Write a DataFile (format_data's layout) to path."""
    with open(path, "w") as f:
        f.writelines(_lines(data, box_format))


def write_data(path, title, box, atoms, bonds, angles, masses, refs, rho, bond_types=None,
               rmass=None, alam=None, bending=False):
    """cellgen's data file. atoms: list of (mol, type, x, y, z); bonds/angles 0-based atom indices;
    rho per atom.

    The `cell` section (named like the fix, as write_data names it) holds, per atom, the values of
      fix ID all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
    in that order: mass, density, density rate (0), reference position.
    Tissues: bond_types = (number of bond types, type of each bond), rmass = per-atom masses
    (default: the type's mass), alam = per-atom lamella area, written as a last column d_alam.
    bending: also the hinges of the triangles as dihedrals of type 1 (hinges())."""
    nbt, btype = bond_types if bond_types is not None else (1, [1] * len(bonds))
    dihedrals = hinges(angles) if bending else []
    data = DataFile(title=f"# {title}", box=box)
    data.counts = {"atoms": len(atoms), "bonds": len(bonds), "angles": len(angles)}
    if bending:
        data.counts["dihedrals"] = len(dihedrals)
    data.counts.update({"atom types": len(masses), "bond types": nbt, "angle types": 1})
    if bending:
        data.counts["dihedral types"] = 1
    data.sections["Masses"] = (f"{i} {m:.15g}" for i, m in enumerate(masses, 1))
    data.sections["Atoms"] = (f"{i} {mol} {typ} {x:.15g} {y:.15g} {z:.15g}"
                              for i, (mol, typ, x, y, z) in enumerate(atoms, 1))
    data.comments["Atoms"] = "molecular"
    if len(bonds):
        data.sections["Bonds"] = (f"{k} {t} {a + 1} {b + 1}"
                                  for k, ((a, b), t) in enumerate(zip(bonds, btype), 1))
    if len(angles):
        data.sections["Angles"] = (f"{k} 1 {a + 1} {b + 1} {c + 1}"
                                   for k, (a, b, c) in enumerate(angles, 1))
    if len(dihedrals):
        data.sections["Dihedrals"] = (f"{k} 1 {i + 1} {j + 1} {kk + 1} {l + 1}"
                                      for k, (i, j, kk, l) in enumerate(dihedrals, 1))

    def cell_row(i, typ, x, y, z, r):
        m = masses[typ - 1] if rmass is None else rmass[i - 1]
        extra = "" if alam is None else f" {alam[i - 1]:.15g}"
        return f"{i} {m:.15g} {r:.15g} 0 {x:.15g} {y:.15g} {z:.15g}{extra}"
    data.sections["cell"] = (cell_row(i, typ, x, y, z, r)
                             for i, ((mol, typ, *_), (x, y, z), r) in enumerate(zip(atoms, refs, rho), 1))
    data.comments["cell"] = ("rmass d_rho d_drho d2_cellref[1] d2_cellref[2] d2_cellref[3]"
                             + (" d_alam" if alam is not None else ""))
    write(path, data)


def write_lengths(path, what, level, reach, special):
    """The model lengths of the data file's level, as the LAMMPS include the inputs read before
    their own defaults (in.tissue-inflate: include ${data}.lmp): a coarse tissue run with the
    paper's lengths holds neither its fluid nor its turgor. A -var on the command line still wins."""
    lines = [f"# written by cellgen.py {what} with {os.path.basename(path)[:-4]}: the model lengths of "
             f"its wall level {level}"]
    if level in params.LEVELS:
        row = params.LEVELS[level]
        lines.append("# from the level table (tools/cellmech/params.py LEVELS)")
        for k, note in (("s", "smoothing length, um"), ("r0", "fluid-wall contact distance, um"),
                        ("f0", "fluid-wall 8-4 strength, nN um"), ("dt", "time step, us"),
                        ("delta", "adhesion range beyond r0, um (with -var Fa)"),
                        ("dp", "fluid spacing, um (artificial stress, -var sphstress)")):
            lines.append(f"variable {k:8s} index {row[k]:<10g} # {note}")
        reach = max(reach, row["reach"])
    else:
        lines.append(f"# level {level} has no row in the level table (levels {', '.join(map(str, params.LEVELS))}):"
                     " give -var s r0 f0 dt")
    lines.append(f"variable {'reach':8s} index {reach:<10g} # cell/virtual reach, um (>= the mesh's)")
    lines.append(f"variable {'special':8s} index {special:<10d} # read_data extra/special/per/atom")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
