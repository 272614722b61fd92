# SPDX-License-Identifier: GPL-2.0-or-later
"""The model's parameters, one source for the generator, the inputs, the scripts and the tests.

Where each number lives (and nowhere else):
  * Table I of the paper (wall, fluid, contacts) in lammps-inputs/cell-model.lmp, as the
    `variable NAME index VALUE` lines LAMMPS reads; `table()` parses them. A script or -var that
    sets one of them first wins in LAMMPS, and `table(overrides)` does the same here.
  * The cell that is not in the force field (radius, wall mass, turgor, the soft wall) and the
    per-resolution lengths and time steps (the level table, LEVELS) here, in this module.
Shell scripts read both through the command line:
  python3 -m cellmech.params level 4 nfluid s r0 f0 reach dt    -> 3500 3.2 1.6 10000.0 2.0 0.001
  python3 -m cellmech.params table G t0 c                       -> 800000.0 0.126 264.6
  python3 -m cellmech.params cell R M_wall P                    -> 30.0 13000.0 364.0
  python3 -m cellmech.params lamella weak sigl Gl               -> 30.0 100.0
  python3 -m cellmech.params settings -- -in FILE -var Pi -100 ...   (before a LAMMPS run: writes
      ./settings.json, the run's effective settings; `run_settings()` reads them back; with
      --key log.NAME before the --, under that key: runs of one input sharing a folder)
(tools/common.sh sets PYTHONPATH for them). Units micro: um, pg, us, kPa, nN, mPa s.
"""
import argparse
import json
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
INPUTS = os.path.join(ROOT, "lammps-inputs")
MODEL_FILE = os.path.join(INPUTS, "cell-model.lmp")
TISSUE_FILE = os.path.join(INPUTS, "tissue-model.lmp")
SETTINGS = "settings.json"

# Model lengths per level of the wall's icosphere (10 4^level + 2 nodes). A level coarser doubles
# the wall spacing, the contact distance r0 and the barycentre reach, and the contact strength f0
# (force x length, acting at r0) grows 2^3. Level 4 is the paper's (2562 + 3500) and the values of
# cell-model.lmp. The smoothing length s belongs to the fluid and follows the fluid spacing dx: the
# paper's fluid counts (440, 3500, 14000) refine dx by 1.9 from level 3 to 4 (5.71 -> 3.01 um)
# but only by 1.55 from 4 to 5 (-> 1.95 um), so level 5 keeps level 4's s/dx = 1.063 with
# s = 2.07 um (halving s to 1.6 would leave s/dx = 0.82, fewer kernel neighbours than at the
# other levels; the formula 3.2 2^(4-level) gives 1.6 there and is not the table). Level 5 has a
# wall node a quarter as heavy: its fastest tether mode (about 4 ns period) needs dt = 0.5 ns.
# Five entries serve the drying cell's features, off by default (cell-model.lmp's Fa, sphstress
# and sphcoh, cell-wall.lmp's residual; docs/studies/drying-cell.md): delta, the range of the fluid's adhesion to its own wall
# beyond r0, r0/16 (a wider well pulls the wall in above zero turgor: r0/4 costs 7% of the volume
# at low turgor, r0/16 nothing); fa, the adhesion strength that holds the suction of a cell dried
# to 2.5 Pi0 (Fa >= |P| A_c, margin 5, the contact area A_c ~ r0^2: a level finer, a quarter); dp,
# the artificial stress's nearest-neighbour distance (docs/studies/pair_cell_sph-tension.rst): the
# median nearest-neighbour distance of the inflated cell's fluid, measured (docs/studies/
# drying-cell.py ac: 4.57 um at level 3, 3.05 at level 4), not cellgen's lattice spacing (5.714,
# 3.010, 1.947 um): at level 3 the inflated fluid is packed closer than its lattice, and with
# dp = 5.71 a turgid 2x2x2 block (Pi -100, strong lamella) blew up once its fluid went into
# tension (mean pressure 98 -> 313 kPa, 179 tethers broken within 9 us), with 4.57 it did not.
# Level 5's value is the lattice spacing, not measured. coh, the surface tension of the fluid's
# cohesion (pair_style cell/sph cohesion, mN/m): a void of radius l opens under a tension |P| only
# if l > 3 coh / |P|; 10 mN/m keeps voids under 10 um at the 3 kPa a slack wall leaves the fluid
# (level 4), and its bias on the turgor stays small (8 kPa near zero turgor at level 3; water's 72
# mN/m reads 41 kPa there). The same at every level, measured at levels 3 and 4. residual, the
# stiffness a wrinkled membrane triangle keeps (angle_coeff ... wrinkle yes residual, Eq. M4): the
# smallest tried that keeps every triangle open while the coarse cell dries to 20% of its water
# (without it one is crushed at 21%; 1e-3 holds too but reads a suction of 48 kPa there, 1e-4 15
# kPa); a fraction of the stiffness, the same at every level.
LEVELS = {
    3: dict(nfluid=440, s=6.4, r0=3.2, f0=8.0e4, reach=4.0, dt=0.001, delta=0.2, dp=4.57, fa=2.0e4, coh=10.0, residual=1.0e-4),
    4: dict(nfluid=3500, s=3.2, r0=1.6, f0=1.0e4, reach=2.0, dt=0.001, delta=0.1, dp=3.05, fa=5.0e3, coh=10.0, residual=1.0e-4),
    5: dict(nfluid=14000, s=2.07, r0=0.8, f0=1.25e3, reach=1.0, dt=0.0005, delta=0.05, dp=1.95, fa=1.25e3, coh=10.0, residual=1.0e-4),
}
# the resolutions the experiment and validation scripts name
RES_LEVEL = {"coarse": 3, "paper": 4, "study": 4, "fine": 5}
# the walls of lammps-inputs/cell-wall.lmp (-var wall), the paper's tethers first (the default)
WALLS = ("tether", "membrane", "bending")

# The cell around the force field (paper Table I and Sec. III): unstressed radius R, wall mass,
# turgor P of the stiff cell; the soft wall (E = 20 MPa, t0 = 5 nm) at its turgor of 0.1 kPa.
CELL = dict(R=30.0, M_wall=1.3e4, P=364.0)
SOFT = dict(G=20.0e3 / 3.0, t0=0.005, P=0.1)

# The named middle lamellae of the tissue experiments (strength sigl, kPa; fracture energy Gl,
# pg/us^2 = mJ/m^2, LAMMPS's -var Gl). The strong one is tissue-model.lmp's default lamella, read
# from there; the weak one has a tenth of its strength and a tenth of its fracture energy.
WEAK_LAMELLA = dict(sigl=30.0, Gl=100.0)

_VARIABLE = re.compile(r"^\s*variable\s+(\w+)\s+index\s+(\S+)")
_INCLUDE = re.compile(r"^\s*include\s+\$\{dir\}/(\S+)")
_COMPANION = re.compile(r"\binclude\s+\$\{(data|restart)\}\.lmp\b")


def table(path=MODEL_FILE, overrides=None):
    """Table I as cell-model.lmp sets it: {name: value} of its `variable NAME index VALUE` lines
    (numbers as floats, others as strings); overrides (like -var) win."""
    out = {}
    with open(path) as f:
        for line in f:
            m = _VARIABLE.match(line)
            if m and m.group(1) not in out:
                try:
                    out[m.group(1)] = float(m.group(2))
                except ValueError:
                    out[m.group(1)] = m.group(2)
    out.update(overrides or {})
    return out


def number(text):
    """A -var or index value as table() reads it: a float where it is a number, else the text."""
    try:
        return float(text)
    except ValueError:
        return text


def lamellae():
    """{name: {sigl, Gl}} of the named lamellae: strong (tissue-model.lmp's default) and weak."""
    t = table(TISSUE_FILE)
    return {"strong": dict(sigl=t["sigl"], Gl=t["Gl"]), "weak": dict(WEAK_LAMELLA)}


def defaults(path, inputs=INPUTS, var=None):
    """The `variable NAME index VALUE` settings of an input script and of the files it includes
    (`include ${dir}/NAME`, in order, from the folder inputs), the first definition of each: what
    LAMMPS uses where no -var sets it. Of the conditional includes (`if ... then "include ..."`)
    only the companion of a data or restart file is followed, `include ${data}.lmp` or
    `include ${restart}.lmp` where var (the -var settings) names a file that has one, as LAMMPS
    does: it holds the model lengths of the data's wall level (s, r0, f0, reach, dt), which the
    input's own defaults (the paper's level 4) would misstate for the coarse cells."""
    out = {}
    var = var or {}

    def walk(p):
        with open(p) as f:
            for line in f:
                m = _VARIABLE.match(line)
                if m:
                    out.setdefault(m.group(1), number(m.group(2)))
                m = _INCLUDE.match(line)
                if m and os.path.exists(os.path.join(inputs, m.group(1))):
                    walk(os.path.join(inputs, m.group(1)))
                m = _COMPANION.search(line)
                name = var.get(m.group(1), out.get(m.group(1))) if m else None
                if name is not None and os.path.exists(f"{name}.lmp"):
                    walk(f"{name}.lmp")
    walk(path)
    return out


def lammps_vars(argv):
    """(input file, {name: value}) of a LAMMPS command line's -in and -var NAME VALUE arguments.
    A name given twice keeps its first value, as LAMMPS does (an index variable that exists is
    not redefined)."""
    inp, var = None, {}
    k = 0
    while k < len(argv):
        a = argv[k]
        if a in ("-in", "-i") and k + 1 < len(argv):
            inp, k = argv[k + 1], k + 2
        elif a in ("-var", "-v") and k + 2 < len(argv):
            var.setdefault(argv[k + 1], number(argv[k + 2]))
            k += 3
        else:
            k += 1
    return inp, var


def write_settings(argv, folder=".", key=None):
    """Record a LAMMPS run's effective settings in FOLDER/settings.json, under its input's name:
    the -var values passed (var) and every index setting with the defaults that applied (settings).
    A folder of several runs keeps one entry per input; one where an input runs more than once
    (tools/experiments.sh) gives each run its own key (its log name), the entry naming its input."""
    inp, var = lammps_vars(argv)
    if inp is None:
        raise ValueError("settings: no -in FILE in the LAMMPS command line")
    inputs = var.get("dir", os.path.dirname(os.path.abspath(inp)))
    eff = dict(defaults(inp, str(inputs), var))
    eff.update(var)
    path = os.path.join(folder, SETTINGS)
    data = json.load(open(path)) if os.path.exists(path) else {}
    entry = {"var": var, "settings": eff}
    if key is not None:
        entry = {"input": os.path.basename(inp), **entry}
    data[os.path.basename(inp) if key is None else key] = entry
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    return eff


def recorded_settings(folder, key):
    """The effective settings FOLDER/settings.json holds under key (an input's name, or the key
    of a run write_settings was given); None where there is no such record (a run from before)."""
    path = os.path.join(folder, SETTINGS)
    if os.path.exists(path):
        data = json.load(open(path))
        if key in data:
            return data[key]["settings"]
    return None


def run_settings(folder, inp, var=None, key=None):
    """A run's effective settings, read back from FOLDER/settings.json (its entry for input inp,
    or under key where the run was recorded under one). A run older than settings.json has none:
    then the input's defaults here, with var (what its driver is known to have passed) over them,
    and a note on stderr."""
    eff = recorded_settings(folder, inp if key is None else key)
    if eff is not None:
        return eff
    name = inp if key is None else key
    print(f"params: no {name} entry in {os.path.join(folder, SETTINGS)}: {inp}'s defaults assumed",
          file=sys.stderr)
    eff = defaults(os.path.join(INPUTS, inp))
    eff.update(var or {})
    return eff


def stiff():
    """The stiff cell of Table I: G, t0 from cell-model.lmp, turgor P."""
    t = table()
    return dict(G=t["G"], t0=t["t0"], P=CELL["P"])


def wall_nodes(level):
    return 10 * 4 ** level + 2


def level(lvl):
    """The level table's row, with the wall node count; a clear error for a level not in it."""
    if lvl not in LEVELS:
        raise ValueError(f"level must be one of {', '.join(map(str, LEVELS))}, got {lvl!r}")
    return dict(LEVELS[lvl], nodes=wall_nodes(lvl))


def model_vars(lvl):
    """The -var settings of cell-model.lmp that depend on the level."""
    p = level(lvl)
    return dict(s=p["s"], r0=p["r0"], f0=p["f0"], reach=p["reach"], dt=p["dt"], delta=p["delta"],
                dp=p["dp"])


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m cellmech.params",
                                description="print model parameters, space-separated, for scripts")
    sub = p.add_subparsers(dest="what", required=True)
    lv = sub.add_parser("level", help="a row of the level table")
    lv.add_argument("level", type=int)
    lv.add_argument("keys", nargs="*", help=f"of {', '.join(list(LEVELS[4]) + ['nodes'])} (default all)")
    tb = sub.add_parser("table", help="Table I from lammps-inputs/cell-model.lmp")
    tb.add_argument("keys", nargs="*")
    ce = sub.add_parser("cell", help="the cell around the force field")
    ce.add_argument("keys", nargs="*", help=f"of {', '.join(CELL)}")
    la = sub.add_parser("lamella", help="a named middle lamella (strong: tissue-model.lmp's default)")
    la.add_argument("name", choices=sorted(lamellae()))
    la.add_argument("keys", nargs="*", help="of sigl, Gl")
    se = sub.add_parser("settings", help="write ./settings.json for a LAMMPS command line")
    se.add_argument("--key", help="record the run under this key (default: its input's name)")
    se.add_argument("lammps", nargs=argparse.REMAINDER, help="-- -in FILE -var NAME VALUE ...")
    a = p.parse_args(argv)
    if a.what == "settings":
        try:
            write_settings([x for x in a.lammps if x != "--"], key=a.key)
        except (ValueError, OSError) as e:
            p.exit(2, f"{p.prog} settings: error: {e}\n")
        return
    if a.what == "level":
        try:
            row = level(a.level)
        except ValueError as e:
            p.exit(2, f"{p.prog} level: error: {e}\n")
    else:
        row = {"table": table, "cell": lambda: CELL, "lamella": lambda: lamellae()[a.name]}[a.what]()
    keys = a.keys or list(row)
    bad = [k for k in keys if k not in row]
    if bad:
        p.exit(2, f"{p.prog} {a.what}: error: unknown {', '.join(bad)}; expected one of {', '.join(row)}\n")
    print(" ".join(f"{row[k]}" for k in keys) if a.keys else
          "\n".join(f"{k} {v}" for k, v in row.items()))


if __name__ == "__main__":
    sys.exit(main())
