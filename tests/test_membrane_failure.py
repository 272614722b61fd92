# SPDX-License-Identifier: GPL-2.0-or-later
"""Failure of the membrane wall (angle_coeff N G t0 gamma lamf X, angle style cell/membrane): a
triangle fails when its largest principal in-plane stretch passes X.

1. Threshold, on a level-3 wall (642 nodes, 1280 triangles, 1920 edges) deformed by hand and
   evaluated once (run 0). The principal stretches of every triangle are computed here with numpy
   from the data file, independently of the style:
   - uniaxial stretch by 1.06 along x with X = 1.03: exactly the triangles with lam1 > X fail (the
     band around the x axis), the others stay (the smallest gap |lam1 - X| is printed);
   - equibiaxial stretch by X (1 - 1e-6) and X (1 + 1e-6): none fail, then all;
   - compression (uniaxial 0.7 in x, equibiaxial 0.9) with X = 1.0001: none fail (tension only).
   Counts, against the topology computed here: an edge is open (broken) from the step its first
   triangle fails, and leaves the bonds and the special lists when its last one has; so
   f_cell_broken = compute cell/props column 13 = edges of failed triangles, the nodes' counts
   (dump, fix cell/vtk field 'broken') are those edges at each node, the bond count drops by the
   edges with both triangles failed, the angles left are the triangles expected, the VTK file
   has those triangles, and the pairs of nodes that interact again (neighbor list after the
   failure) are exactly the released edges.
   The equatorial force of compute cell/props (column 8) on the membrane wall, scaled by 1.02,
   within 2% of T 2 pi R lam (the tethers' is printed beside it).
2. A wall thrown outward (radial velocity, nve, 8-4 contacts between wall nodes) fails
   progressively: 1 and 2 ranks give the same counts and positions; a restart written while
   it is failing continues it exactly (counts, per-node counts, positions).
3. A coarse cell (level 3, 440 fluid particles) with the membrane wall: (a) its protoplasm
   compressed to about turgor and osmosis burst it (X = 1.012): no fluid outside before the first
   failure, osmosis adds mass before it and none after; (b) the fluid pushed against one side
   (body force, the other hemisphere of the wall held) with X = 1.01 opens the wall there and
   leaves through the hole, while the same push against a wall that cannot fail (X = 10) keeps
   all fluid inside.
4. Bad input: lamf <= 1, a missing value, an unknown keyword.
"""
import os
import re

import numpy as np
import pytest

import lmptest as T
from cellmech.cellgen.datafile import read_data

G, T0 = 8.0e5, 0.126

SETUP = """
units           micro
atom_style      molecular
atom_modify     map array
boundary        f f f
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
read_data       cell.data fix cell NULL cell
group           wall type 1
bond_style      zero
bond_coeff      *
angle_style     cell/membrane
angle_coeff     1 {G} {t0} {gamma} lamf {lamf}
pair_style      {pair}
pair_coeff      {pcoeff}
special_bonds   lj 0 1 1
comm_modify     vel yes cutoff 8.0
neighbor        0.5 bin
neigh_modify    every 1 delay 0 check yes
timestep        0.0005
"""


def read_wall(path):
    """Reference positions (by atom ID), triangles and bonds of the data file."""
    data = read_data(path)
    ref = {int(w[0]): np.array([float(v) for v in w[4:7]]) for w in data.rows("cell")}
    tri = [tuple(int(v) for v in w[2:5]) for w in data.rows("Angles")]
    bonds = [tuple(sorted((int(w[2]), int(w[3])))) for w in data.rows("Bonds")]
    return ref, tri, bonds


def largest_stretch(A, C, a, c):
    """lam1 of the constant-strain triangle with reference edges A, C and current edges a, c."""
    e1 = A / np.linalg.norm(A)
    n = np.cross(A, C)
    e2 = np.cross(n / np.linalg.norm(n), e1)
    D = np.array([[A @ e1, C @ e1], [A @ e2, C @ e2]])
    F = np.column_stack([a, c]) @ np.linalg.inv(D)
    return np.sqrt(np.linalg.eigvalsh(F.T @ F).max())


def edges_of(t):
    a, b, c = sorted(t)
    return [(a, b), (a, c), (b, c)]


def data_angles(path):
    return [tuple(sorted(map(int, w[2:5]))) for w in read_data(path).rows("Angles")]


def threshold_case(d, name, ref, tri, sx, sy, sz, lamf):
    """Deform the wall about its centre by (sx, sy, sz), evaluate once, compare with numpy."""
    centre = np.mean(np.array(list(ref.values())), axis=0)
    scale = np.array([sx, sy, sz])
    lam1 = np.array([largest_stretch(ref[a] - ref[b], ref[c] - ref[b],
                                     scale * (ref[a] - ref[b]), scale * (ref[c] - ref[b]))
                     for a, b, c in tri])
    fail = {tuple(sorted(t)) for t, l in zip(tri, lam1) if l > lamf}
    keep = {tuple(sorted(t)) for t in tri} - fail
    # edges: opened = edges of failed triangles; released = edges with no triangle left
    opened = {e for t in fail for e in edges_of(t)}
    released = opened - {e for t in keep for e in edges_of(t)}
    per_node = {}
    for e in opened:
        for n in e:
            per_node[n] = per_node.get(n, 0) + 1
    gap = np.abs(lam1 - lamf).min()

    inp = SETUP.format(G=G, t0=T0, gamma=0.0, lamf=lamf, pair="zero 8.0", pcoeff="* *") + f"""
variable        sx atom ({centre[0]})+{sx}*(x-({centre[0]}))
variable        sy atom ({centre[1]})+{sy}*(y-({centre[1]}))
variable        sz atom ({centre[2]})+{sz}*(z-({centre[2]}))
set             group all x v_sx y v_sy z v_sz
compute         props all cell/props
fix             surf wall cell/vtk 1 walls
run             0
print           "COUNTS $(f_cell_broken) $(c_props[1][13]) $(bonds) $(angles)"
write_dump      all custom nodes.dump id f_cell_broken modify sort id
write_data      after.data nocoeff
unfix           surf
compute         pairs all property/local patom1 patom2
run             0
write_dump      all local pairs.dump c_pairs[1] c_pairs[2]
"""
    _, log = T.lmp(inp, cwd=d, log=f"log.{name}")
    broken, props13, nbonds, nangles = map(float, log.split("COUNTS ")[-1].split()[:4])
    nodes = np.loadtxt(os.path.join(d, "nodes.dump"), skiprows=9, ndmin=2)
    node_ok = all(int(n) == per_node.get(int(i), 0) for i, n in nodes)
    left = set(data_angles(os.path.join(d, "after.data")))
    pairs = np.loadtxt(os.path.join(d, "pairs.dump"), skiprows=9, ndmin=2)
    edges = {e for t in tri for e in edges_of(t)}
    bonded_pairs = {tuple(sorted((int(p), int(q)))) for p, q in pairs} & edges

    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkPolyDataReader()
    reader.SetFileName(os.path.join(d, "walls.0.vtk"))
    reader.ReadAllScalarsOn()
    reader.Update()
    poly = reader.GetOutput()
    vtk_broken = vtk_to_numpy(poly.GetPointData().GetArray("broken")).sum()

    print(f"{name}: stretch ({sx}, {sy}, {sz}), lamf {lamf}: lam1 in [{lam1.min():.6f}, "
          f"{lam1.max():.6f}], closest to lamf by {gap:.1e}; expected {len(fail)} failed "
          f"triangles, {len(opened)} open and {len(released)} released edges")
    print(f"  LAMMPS: {1280 - int(nangles)} failed (angles {nangles:.0f}), f_cell_broken "
          f"{broken:.0f}, cell/props broken {props13:.0f}, VTK broken sum {vtk_broken:.0f}, "
          f"triangles {poly.GetNumberOfPolys()}, bonds {nbonds:.0f} (of 1920), edge pairs in "
          f"the neighbor list {len(bonded_pairs)}")
    T.check(f"{name}: the triangles left are those with lam1 <= lamf", left == keep,
            f"{len(left)} vs {len(keep)}")
    T.check(f"{name}: angle count", nangles == len(keep), f"{nangles:.0f}")
    T.check(f"{name}: f_cell_broken = cell/props column 13 = open edges",
            broken == props13 == len(opened), f"{broken:.0f} {props13:.0f} {len(opened)}")
    T.check(f"{name}: per-node broken counts = open edges at the node", node_ok)
    T.check(f"{name}: VTK 'broken' sums to 2 x open edges, VTK triangles = triangles left",
            vtk_broken == 2 * len(opened) and poly.GetNumberOfPolys() == len(keep))
    T.check(f"{name}: bonds left = 1920 - released edges", nbonds == 1920 - len(released),
            f"{nbonds:.0f}")
    T.check(f"{name}: nodes of released edges (only) meet in the neighbor list again",
            bonded_pairs == released, f"{len(bonded_pairs)} vs {len(released)}")
    return len(fail), gap


@pytest.fixture(scope="module")
def wall(rundir):
    """The coarse wall alone (cell.data): the run folder, its reference positions, triangles and
    tethers."""
    d = rundir
    T.cellgen("cell", "-o", "cell.data", "--level", 3, "--nfluid", 0, cwd=d)
    ref, tri, bonds = read_wall(os.path.join(d, "cell.data"))
    return d, ref, tri, bonds


def test_level3_wall(wall):
    _, _, tri, bonds = wall
    T.check("level-3 wall: 1280 triangles, 1920 tethers", len(tri) == 1280 and len(bonds) == 1920)


def test_failure_threshold(wall):
    d, ref, tri, _ = wall
    # 1. threshold
    nfail, gap = threshold_case(d, "uniaxial 1.06", ref, tri, 1.06, 1.0, 1.0, 1.03)
    T.check("uniaxial 1.06, lamf 1.03: a region fails, not all", 0 < nfail < 1280, nfail)
    T.check("uniaxial: no triangle within round-off of lamf", gap > 1e-9, f"{gap:.1e}")
    lamf = 1.03
    below, _ = threshold_case(d, "equibiaxial below", ref, tri, *(3 * [lamf * (1 - 1e-6)]), lamf)
    above, _ = threshold_case(d, "equibiaxial above", ref, tri, *(3 * [lamf * (1 + 1e-6)]), lamf)
    T.check("equibiaxial lamf (1 - 1e-6): none fail", below == 0, below)
    T.check("equibiaxial lamf (1 + 1e-6): all fail", above == 1280, above)
    for name, s in (("uniaxial compression 0.7", (0.7, 1.0, 1.0)),
                    ("equibiaxial compression 0.9", (0.9, 0.9, 0.9))):
        n, _ = threshold_case(d, name, ref, tri, *s, 1.0001)
        T.check(f"{name}, lamf 1.0001: no triangle fails (tension only)", n == 0, n)


def test_equatorial_force(wall):
    d, ref, _, _ = wall
    # the equatorial force (compute cell/props column 8) of the membrane wall: the triangles the
    # plane cuts carry it. A wall scaled by lam is stretched equibiaxially, where the element and
    # the tethers have the same law (T = G t0 (1 - lam^-6) per current length), so both walls must
    # give about T times the equator's length (2 pi R lam, R the mean reference radius).
    radius = np.mean([np.linalg.norm(v - np.mean(np.array(list(ref.values())), axis=0))
                      for v in ref.values()])
    lam = 1.02
    feq = {}
    for wall, styles in (("membrane", "angle_coeff 1 {G} {t0} 0.0"),
                         ("tethers", "bond_style cell/tether\nbond_coeff 1 {G} {t0} 0.0\n"
                                     "angle_style zero nocoeff\nangle_coeff *")):
        inp = SETUP.format(G=G, t0=T0, gamma=0.0, lamf=0, pair="zero 8.0", pcoeff="* *").replace(
            "angle_coeff     1 {} {} 0.0 lamf 0".format(G, T0), styles.format(G=G, t0=T0)) + f"""
variable        sx atom {lam}*x
variable        sy atom {lam}*y
variable        sz atom {lam}*z
set             group all x v_sx y v_sy z v_sz
compute         props all cell/props normal 0 0 1
run             0
print           "FEQ $(c_props[1][8]:%.10g)"
"""
        _, log = T.lmp(inp, cwd=d, log=f"log.feq-{wall}")
        feq[wall] = float(log.split("FEQ ")[-1].split()[0])
    closed = G * T0 * (1 - lam ** -6) * 2 * np.pi * radius * lam
    print(f"equatorial force at equibiaxial stretch {lam}: membrane {feq['membrane']:.6g} nN, "
          f"tethers {feq['tethers']:.6g} nN, T 2 pi R lam = {closed:.6g} nN "
          f"(R = {radius:.4f} um); membrane / tethers - 1 = {feq['membrane'] / feq['tethers'] - 1:.2e}")
    T.check("equatorial force of the membrane wall within 2% of the closed form",
            abs(feq["membrane"] / closed - 1) < 0.02, f"{feq['membrane'] / closed - 1:.2e}")


def history(log):
    """The thermo rows (step, open edges, angles, bonds) of a log."""
    rows = re.findall(r"^\s+(\d+)\s+(\S+)\s+(\d+)\s+(\d+)\s*$", log, flags=re.M)
    return [tuple(float(v) for v in r) for r in rows]


N1, N2 = 120, 120     # steps before and after the restart of the progressive failure


@pytest.fixture(scope="module")
def thrown(wall):
    """2. progressive failure: the wall thrown outward on 1 and 2 ranks, the 2-rank run restarted
    while failing; the three logs."""
    d, ref, _, _ = wall
    f0, r0 = T.COARSE["f0"], T.COARSE["r0"]
    centre = np.mean(np.array(list(ref.values())), axis=0)
    pair = dict(pair="cell/lj84", pcoeff=f"* * {2 * f0} {0.8 * r0}")
    throw = SETUP.format(G=G, t0=T0, gamma=0.1, lamf=1.02, **pair) + f"""
displace_atoms  all random 0.03 0.03 0.03 8123 units box
variable        vx atom 0.4*(x-({centre[0]}))
variable        vy atom 0.4*(y-({centre[1]}))
variable        vz atom 0.4*(z-({centre[2]}))
velocity        all set v_vx v_vy v_vz
fix             nve all nve
thermo_style    custom step f_cell_broken angles bonds
thermo_modify   format float %.17g
thermo          20
run             {{n1}}
{{mid}}
run             {{n2}}
print           "END $(f_cell_broken) $(angles) $(bonds)"
write_dump      all custom {{out}} id x y z f_cell_broken modify sort id format float %.17g
"""
    n1, n2 = N1, N2
    T.lmp(throw.format(n1=n1, n2=n2, mid="", out="np1.dump"), cwd=d, log="log.throw1")
    T.lmp(throw.format(n1=n1, n2=n2, mid="write_restart mid.restart", out="np2.dump"), cwd=d,
          nprocs=2, log="log.throw2")
    cont = f"""
units           micro
read_restart    mid.restart
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
comm_modify     vel yes cutoff 8.0
neighbor        0.5 bin
neigh_modify    every 1 delay 0 check yes
pair_coeff      {pair['pcoeff']}
# the coefficients are in the restart file; given again (as an input that includes its model
# file does) they make the failure bookkeeping (f_cell_broken) known to thermo_style at once
angle_coeff     1 {G} {T0} 0.1 lamf 1.02
fix             nve all nve
thermo_style    custom step f_cell_broken angles bonds
thermo          20
run             {n2}
print           "END $(f_cell_broken) $(angles) $(bonds)"
write_dump      all custom cont.dump id x y z f_cell_broken modify sort id format float %.17g
"""
    T.lmp(cont, cwd=d, nprocs=2, log="log.throw-cont")
    return {k: open(os.path.join(d, f"log.throw{k}")).read() for k in ("1", "2", "-cont")}


def test_progressive_failure_counts(thrown):
    n1 = N1
    logs = thrown
    h1, h2 = history(logs["1"]), history(logs["2"])
    mid = [r for r in h2 if r[0] == n1]
    end = {k: logs[k].split("END ")[-1].split()[:3] for k in logs}
    print("progressive failure (step, open edges, angles, bonds), 1 rank:")
    for r in h1:
        print("   ", " ".join(f"{v:.0f}" for v in r))
    print(f"at the restart (step {n1}): {mid[0] if mid else None}; at the end 1 rank {end['1']}, "
          f"2 ranks {end['2']}, restarted {end['-cont']}")
    T.check("the wall fails progressively: some but not all triangles failed at the restart",
            bool(mid) and 0 < mid[0][1] and 1280 > mid[0][2] > float(end["2"][1]))
    T.check("1 and 2 ranks: the same counts at every output", h1 == h2 and end["1"] == end["2"])
    T.check("restart while failing: the same counts at the end", end["2"] == end["-cont"])


def test_progressive_failure_positions(wall, thrown):
    d = wall[0]
    dumps = {k: np.loadtxt(os.path.join(d, f"{k}.dump"), skiprows=9) for k in ("np1", "np2", "cont")}
    d12 = np.abs(dumps["np1"][:, 1:4] - dumps["np2"][:, 1:4]).max()
    drs = np.abs(dumps["np2"][:, 1:4] - dumps["cont"][:, 1:4]).max()
    dn12 = np.abs(dumps["np1"][:, 4] - dumps["np2"][:, 4]).max()
    dnrs = np.abs(dumps["np2"][:, 4] - dumps["cont"][:, 4]).max()
    print(f"positions: 1 vs 2 ranks differ by {d12:.1e} um, restart vs straight by {drs:.1e} um; "
          f"per-node broken counts by {dn12:.0f} and {dnrs:.0f}")
    T.check("1 and 2 ranks: the same wall (1e-9 um) and per-node counts", d12 < 1e-9 and dn12 == 0,
            f"{d12:.1e}")
    T.check("restart while failing continues exactly (1e-9 um, per-node counts)",
            drs < 1e-9 and dnrs == 0, f"{drs:.1e}")


@pytest.fixture(scope="module")
def fluid_cell(wall):
    """3. a loaded cell with fluid: the membrane wall around the coarse fluid (fluid.data); the
    input lines of the cell and its model lengths."""
    d = wall[0]
    r0 = T.COARSE["r0"]
    # 3. a loaded cell with fluid: (a) compressed protoplasm and osmosis burst the wall, and
    # osmosis stops with the first failure; (b) the fluid pushed against one side of the wall
    # (body force on the fluid, the other hemisphere of the wall held) opens it there and leaves
    # through the hole, where the same push against a wall that cannot fail keeps it all inside
    T.cellgen("cell", "-o", "fluid.data", "--level", 3, "--nfluid", 440, "--inset", r0, cwd=d)
    cell = T.cell_from_data("fluid.data") + f"""variable        dir index {T.INPUTS}
include         {T.INPUTS}/cell-model.lmp
bond_style      zero
bond_coeff      *
angle_style     cell/membrane
angle_coeff     1 ${{G}} ${{t0}} ${{gamma}} lamf ${{lamf}}
fix             integrate all nve
compute         props all cell/props leaks yes
variable        broken equal f_cell_broken
variable        leak equal c_props[1][9]
variable        M equal c_props[1][4]
timestep        0.001
"""
    model = {k: T.COARSE[k] for k in ("s", "r0", "f0", "reach")}
    model["mu"] = 10.0
    return cell, model


def test_osmotic_burst(wall, fluid_cell):
    d = wall[0]
    cell, model = fluid_cell
    osmosis = cell + """
# the protoplasm starts compressed to about the stiff cell's turgor (364 kPa: rho/rho0 = 1.0051
# by the Tait equation with kappa = 10 MPa), so the wall is loaded at once
variable        m atom mass*1.006
set             group fluid mass v_m
set             group fluid d_rho 1.006
fix             osmosis fluid cell/fluid Pi -364.0 Lp 100.0
fix             rec all ave/time 100 1 100 v_broken v_leak v_M file burst.dat format " %.12g"
run             1000
"""
    T.lmp(osmosis, cwd=d, variables=dict(model, lamf=1.012), log="log.burst")
    rows = T.load(os.path.join(d, "burst.dat"))    # step broken leak M
    k = np.nonzero(rows[:, 1] > 0)[0]
    print("burst (step, open edges, fluid outside, fluid mass):")
    for r in rows:
        print("   ", " ".join(f"{v:.6g}" for v in r))
    T.check("burst: the wall fails", len(k) > 0)
    if len(k):
        k = k[0]
        gained = rows[k - 1, 3] - rows[0, 3] if k > 0 else 0.0
        after = np.ptp(rows[k:, 3])
        print(f"first failure by step {rows[k, 0]:.0f}: osmosis gained {gained:.4g} pg before, "
              f"the mass varied by {after:.3g} pg after")
        T.check("burst: no fluid outside before the first failure", rows[:k, 2].max(initial=0) == 0)
        T.check("burst: osmosis works before the failure and stops with it",
                gained > 0 and after == 0, f"{gained:.4g} {after:.3g}")


def test_fluid_escapes_through_failure(wall, fluid_cell):
    d = wall[0]
    cell, model = fluid_cell
    push = cell + """
fix             dens fluid cell/fluid Pi 0 Lp 0
variable        xc equal xcm(wall,x)
group           held variable v_back
fix             hold held setforce 0.0 0.0 0.0
velocity        held set 0.0 0.0 0.0
fix             push fluid addforce 1500.0 0.0 0.0
fix             rec all ave/time 100 1 100 v_broken v_leak v_M file OUT format " %.12g"
run             1500
"""
    push = push.replace("group           held variable v_back",
                        "variable        back atom type==1&&x<v_xc\n"
                        "group           held variable back")
    leaks = {}
    for name, lamf in (("failing", 1.01), ("intact", 10.0)):
        T.lmp(push.replace("OUT", f"push-{name}.dat"), cwd=d, variables=dict(model, lamf=lamf),
              log=f"log.push-{name}")
        rows = T.load(os.path.join(d, f"push-{name}.dat"))
        k = np.nonzero(rows[:, 1] > 0)[0]
        leaks[name] = (rows, k[0] if len(k) else None)
        print(f"fluid pushed against the wall, lamf {lamf} (step, open edges, fluid outside):")
        for r in rows[::3]:
            print("   ", " ".join(f"{v:.6g}" for v in r[:3]))
    rows, k = leaks["failing"]
    T.check("push, lamf 1.01: the wall opens", k is not None)
    if k is not None:
        T.check("push, lamf 1.01: no fluid outside before the first failure",
                rows[:k, 2].max(initial=0) == 0)
        T.check("push, lamf 1.01: fluid escapes through the failed triangles", rows[-1, 2] > 0,
                f"{rows[-1, 2]:.0f} of 440")
    rows, k = leaks["intact"]
    T.check("push, lamf 10: the wall holds and keeps all fluid in",
            k is None and rows[:, 2].max() == 0, f"{rows[:, 2].max():.0f}")


def test_bad_input_refused(wall):
    d = wall[0]
    # 4. bad input
    base = SETUP.format(G=G, t0=T0, gamma=0.0, lamf=1.05, pair="zero 8.0", pcoeff="* *")
    bad = {
        "lamf 1": (base.replace("lamf 1.05", "lamf 1.0"), "critical stretch lamf must be > 1"),
        "lamf 0.9": (base.replace("lamf 1.05", "lamf 0.9"), "critical stretch lamf must be > 1"),
        "lamf without value": (base.replace("lamf 1.05", "lamf"), "expected 'angle_coeff N G t0"),
        "unknown keyword": (base.replace("lamf 1.05", "lamb 1.05"), "unknown keyword 'lamb'"),
    }
    for name, (inp, expect) in bad.items():
        rc, log = T.lmp(inp, cwd=d, log=f"log.bad-{name.replace(' ', '_')}", check=False)
        msg = [l for l in log.splitlines() if "ERROR" in l]
        print(f"{name}: rc {rc}, {msg[-1] if msg else 'no error'}")
        T.check(f"bad input ({name}) is refused with a clear error",
                rc != 0 and any(expect in l for l in msg), msg[-1] if msg else "no error")
