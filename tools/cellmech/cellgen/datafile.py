# SPDX-License-Identifier: GPL-2.0-or-later
"""LAMMPS data files: read any of them (cellgen's, LAMMPS's write_data) into header counts, box and
sections, and write them back.

The layout is LAMMPS's (read_data): the first line is a title; header lines ("N keyword", "lo hi
xlo xhi", "xy xz yz") until the first section; a section is a line that starts with a letter (its
name, "Atoms", "Pair Coeffs", or a fix's ID such as cellgen's per-atom "cell" section), a comment
after '#' on that line (the atom style, or the names of a fix's columns), then its rows. Comments
('#' to the end of a line) and blank lines are not data anywhere."""
from dataclasses import dataclass, field

import numpy as np

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
    data, section = DataFile(box=[0.0] * 6), None
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


def format_data(data, box_format="{:.10g}"):
    """The text of a DataFile in cellgen's layout: title, blank, counts, blank, box (and tilt),
    then each section as its line, blank, rows, each section after a blank line. Rows are words
    (joined by one space) or whole lines."""
    out = [data.title, ""] + [f"{n} {k}" for k, n in data.counts.items()] + [""]
    out += [f"{box_format.format(data.box[2 * k])} {box_format.format(data.box[2 * k + 1])} {a}"
            for k, a in enumerate(AXES)]
    if data.tilt is not None:
        out.append(" ".join(box_format.format(v) for v in data.tilt) + " " + TILT)
    for name, rows in data.sections.items():
        comment = data.comments.get(name, "")
        out += ["", name + (f" # {comment}" if comment else ""), ""]
        out += [r if isinstance(r, str) else " ".join(map(str, r)) for r in rows]
    return "\n".join(out) + "\n"


def write(path, data, box_format="{:.10g}"):
    with open(path, "w") as f:
        f.write(format_data(data, box_format))
