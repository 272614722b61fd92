# SPDX-License-Identifier: GPL-2.0-or-later
"""Dihedral style cell/bending (the wall's bending stiffness, Eqs. B1-B3) inside LAMMPS; one hinge
against its closed form and the forces against the energy's finite-difference gradient are in
tests/unit/physics/test_bending.cpp (BendingHinge).

1. Walls at rest store no bending energy, whatever their curvature: a level-3 cell and a two-cell
   tissue from cellgen --bending give zero energy and force (the hinges bend against their rest
   angles from d2_cellref), also after a uniform scaling (dihedral angles do not change).
2. Cylinder (analytic plate result): a flat sheet (rest shape flat) bent onto a cylinder of radius
   R, arc lengths kept, stores D / (2 R^2) per area, D = G t0^3 / 3 (E = 3G, nu = 1/2). Every node
   away from the sheet's edges is equivalent (the lattice's translations are the cylinder's
   rotations and axial shifts), so the energy of the central node (compute pe/atom: a quarter of
   each hinge it belongs to) over its area sqrt3/2 a^2 is the mesh's energy per area. Edge length a
   = R/4, R/8, R/16, bent across and along the bond rows: the error must fall with the observed
   order p = log2(e(a) / e(a/2)) near 2 (asserted 1.8..2.2, the hinge being a second-order
   difference of the normals), and the finest error must be within 1.5 times what that order
   predicts from the coarser ones (no stagnation, no offset the refinement does not remove).
   The virial: the hinge energy does not change when the wall is scaled, so sum x.f = 0 (to
   round-off of sum |x.f|), and the per-atom virials (compute stress/atom) sum to the global one.
3. nve with hinges alone (a perturbed level-2 wall): energy conserved to O(dt^2), the error ratio
   for dt halved 3..5; a force that is not the energy's gradient would not converge.
4. 1 vs 2 ranks give the same wall, and a restart in the middle continues it exactly.
5. Bad input: negative modulus, too few arguments, no reference positions and a collapsed hinge
   each stop with an error naming the command.
6. Failure: a level-3 wall stretched by 1.06 in x, tethers (bond_coeff ... lamf 1.03) or membrane
   triangles (angle_coeff ... lamf 1.03) failing in run 0: the hinges left (count, data file) are
   exactly those whose two wings survive (computed here with numpy); in the step of the failure
   every hinge still bends (the topology around a failure changes at the neighbour build of the
   next step, on any number of ranks), from that build on the energy is that of a wall holding
   only those hinges, on 1 and 2 ranks and after a restart.
"""
import math
import os
from types import SimpleNamespace

import numpy as np
import pytest

import lmptest as T
from cellmech.cellgen.datafile import read_data, write

G, T0 = 8.0e5, 0.126
D = G * T0 ** 3 / 3.0

SETUP = """
units           micro
atom_style      molecular
atom_modify     map array
boundary        f f f
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3{alam} ghost yes
read_data       {data} fix cell NULL cell{extra}
bond_style      zero
bond_coeff      *
angle_style     zero
angle_coeff     *
dihedral_style  cell/bending
dihedral_coeff  1 {G} {t0}
pair_style      zero 1.0
pair_coeff      * *
special_bonds   lj 0 1 1
comm_modify     vel yes cutoff {cut}
neighbor        0.5 nsq
neigh_modify    every 1 delay 0 check yes
timestep        {dt}
variable        fa atom sqrt(fx*fx+fy*fy+fz*fz)
compute         fmax all reduce max v_fa
variable        fmax equal c_fmax
"""


def wall_input(data, G=G, t0=T0, cut=20.0, dt=0.001):
    # a tissue's data file also holds the lamella areas and needs room for more special neighbours
    tissue = data.startswith("tissue")
    return SETUP.format(data=data, G=G, t0=t0, cut=cut, dt=dt, alam=" d_alam" if tissue else "",
                        extra=" extra/special/per/atom 50" if tissue else "")


def last(log, tag):
    return [l for l in log.splitlines() if l.startswith(tag)][-1].split()


def test_walls_at_rest_store_no_energy(rundir):
    d = rundir
    T.cellgen("cell", "-o", "cell3.data", "--level", 3, "--nfluid", 0, "--bending", cwd=d)
    T.cellgen("tissue", "-o", "tissue.data", "--lattice", "sc", "--n", 2, 1, 1, "--level", 2,
              "--nfluid", 4, "--bending", cwd=d)
    for data, cut in (("cell3.data", 20.0), ("tissue.data", 40.0)):
        for lam in (1.0, 0.9):
            inp = wall_input(data, cut=cut) + f"""
variable        sx atom {lam}*x
variable        sy atom {lam}*y
variable        sz atom {lam}*z
set             group all x v_sx y v_sy z v_sz
thermo_style    custom step edihed v_fmax
run             0
print           "REST $(edihed:%.17g) $(v_fmax:%.17g) $(dihedrals)"
"""
            _, log = T.lmp(inp, cwd=d, log=f"log.rest-{data}-{lam}")
            w = last(log, "REST")
            E, fmax, nh = float(w[1]), float(w[2]), int(w[3])
            # the scale of the forces a unit bend of every hinge would give: D / edge
            print(f"{data} scaled by {lam}: {nh} hinges, bending energy {E:.3g}, largest force "
                  f"{fmax:.3g} (D = {D:.6g} pg um^2/us^2)")
            T.check(f"{data} x {lam}: no bending energy at rest", abs(E) < 1e-20 * D * nh, f"{E:.3g}")
            T.check(f"{data} x {lam}: no force at rest", fmax < 1e-9 * D, f"{fmax:.3g}")


def test_cylinder_bending_energy(rundir):
    d = rundir
    R, n = 20.0, 9
    centre = (n // 2) * (n + 1)    # node (4, 4) of the 9x9 sheet, 1-based id below
    err = {}
    for axis in ("x", "y"):
        for k, a in enumerate((R / 4, R / 8, R / 16)):
            data = f"sheet{k}.data"
            T.cellgen("sheet", "-o", data, "--nx", n, "--ny", n, "--bond", a, "--bending", cwd=d)
            node = (n // 2) * n + n // 2 + 1
            # bend the coordinate u (x or y) onto the cylinder of radius R about an axis through
            # the centre node, keeping arc lengths: u -> uc + R sin(s/R), z -> R (1 - cos(s/R))
            u = "x" if axis == "y" else "y"
            inp = wall_input(data, cut=4.0 * a) + f"""
variable        uc equal {u}[{node}]
variable        su atom v_uc+{R}*sin(({u}-v_uc)/{R})
variable        sz atom {R}*(1-cos(({u}-v_uc)/{R}))
set             group all {u} v_su z v_sz
compute         pe all pe/atom dihedral
compute         st all stress/atom NULL dihedral
compute         sst all reduce sum c_st[1] c_st[2] c_st[3] c_st[4] c_st[5] c_st[6]
compute         vir all pressure NULL dihedral
variable        e1 equal C_pe[{node}]
variable        xf equal (c_vir[1]+c_vir[2]+c_vir[3])*vol
variable        sxf equal -(c_sst[1]+c_sst[2]+c_sst[3])
variable        dvir equal abs(c_vir[1]*vol+c_sst[1])+abs(c_vir[2]*vol+c_sst[2])+abs(c_vir[3]*vol+c_sst[3])+abs(c_vir[4]*vol+c_sst[4])+abs(c_vir[5]*vol+c_sst[5])+abs(c_vir[6]*vol+c_sst[6])
variable        vabs equal abs(c_vir[1]*vol)+abs(c_vir[2]*vol)+abs(c_vir[3]*vol)
thermo_style    custom step edihed v_e1 v_xf
run             0
print           "CYL $(edihed:%.17g) $(v_e1:%.17g) $(v_xf:%.17g) $(v_dvir:%.17g) $(v_vabs:%.17g)"
"""
            _, log = T.lmp(inp, cwd=d, log=f"log.cyl-{axis}{k}")
            w = last(log, "CYL")
            E, e1, xf, dvir, vabs = (float(v) for v in w[1:6])
            dens = e1 / (math.sqrt(3.0) / 2.0 * a * a)
            exact = D / (2.0 * R * R)
            err[(axis, k)] = dens / exact - 1.0
            print(f"axis {axis}, a = R/{R / a:g}: energy per area at the centre {dens:.10g} "
                  f"(D/(2R^2) = {exact:.10g}, rel. error {err[(axis, k)]:+.4e}); whole sheet "
                  f"{E:.6g}; trace of the virial {xf:.3g} of sum |W_aa| {vabs:.3g}, "
                  f"per-atom vs global virial {dvir:.3g}")
            T.check(f"axis {axis}, a = R/{R / a:g}: the bent sheet's virial trace vanishes",
                    abs(xf) < 1e-10 * vabs, f"{xf:.3g} of {vabs:.3g}")
            T.check(f"axis {axis}, a = R/{R / a:g}: per-atom virials sum to the global one",
                    dvir < 1e-10 * vabs, f"{dvir:.3g}")
        e = [abs(err[(axis, k)]) for k in range(3)]
        p1, p2 = math.log2(e[0] / e[1]), math.log2(e[1] / e[2])
        predicted = e[1] * 2.0 ** -p1
        print(f"axis {axis}: errors {e[0]:.3e}, {e[1]:.3e}, {e[2]:.3e}; observed order "
              f"{p1:.3f}, {p2:.3f}; finest error {e[2]:.3e} vs {predicted:.3e} predicted")
        T.check(f"axis {axis}: second-order convergence to D/(2R^2)", 1.8 < p1 < 2.2 and 1.8 < p2 < 2.2,
                f"orders {p1:.3f} {p2:.3f}")
        T.check(f"axis {axis}: the finest error is what the order predicts", e[2] < 1.5 * predicted,
                f"{e[2]:.3e} vs {predicted:.3e}")


@pytest.fixture(scope="module")
def cell2(rundir):
    """The level-2 wall with hinges (cell2.data)."""
    T.cellgen("cell", "-o", "cell2.data", "--level", 2, "--nfluid", 0, "--bending", cwd=rundir)
    return rundir


def test_nve_restart_and_ranks(cell2):
    d = cell2
    # a stiff plate (t0 = 1 um) so that the hinges alone oscillate within the run
    drift, swing = {}, {}
    for dt, nsteps in ((0.004, 1000), (0.002, 2000)):
        inp = wall_input("cell2.data", t0=1.0, dt=dt) + f"""
displace_atoms  all random 0.3 0.3 0.3 8123 units box
fix             nve all nve
variable        etot equal ke+edihed
variable        eb equal edihed
thermo_style    custom step ke edihed v_etot
thermo          {nsteps // 10}
fix             rec all ave/time {nsteps // 100} 1 {nsteps // 100} v_etot v_eb file energy{dt}.dat &
                format " %.17g"
run             {nsteps}
"""
        T.lmp(inp, cwd=d, log=f"log.nve{dt}")
        e = T.load(os.path.join(d, f"energy{dt}.dat"))
        drift[dt] = np.abs(e[:, 1] - e[0, 1]).max() / e[0, 2]
        swing[dt] = e[:, 2].min() / e[0, 2]
        print(f"dt {dt} us, {nsteps} steps: largest |E - E0| / E_bend(0) = {drift[dt]:.3e} "
              f"(E_bend(0) = {e[0, 2]:.6g}, smallest E_bend {e[:, 2].min():.6g})")
    ratio = drift[0.004] / drift[0.002]
    print(f"error ratio for dt halved: {ratio:.2f} (second order: 4)")
    # conservation means something only if the hinges trade their energy with the motion
    T.check("the hinges give up most of their energy to the motion", swing[0.004] < 0.5,
            f"smallest E_bend / E_bend(0) {swing[0.004]:.3f}")
    T.check("nve conserves the bent wall's energy", drift[0.004] < 1e-2, f"{drift[0.004]:.1e}")
    T.check("the energy error is second order in dt", 3.0 < ratio < 5.0, f"{ratio:.2f}")

    run = wall_input("cell2.data", t0=1.0, dt=0.004) + """
displace_atoms  all random 0.3 0.3 0.3 8123 units box
fix             nve all nve
run             300
write_restart   mid.restart
run             300
write_dump      all custom {out} id x y z vx vy vz modify sort id format float %.17g
"""
    T.lmp(run.format(out="np1.dump"), cwd=d, log="log.np1")
    T.lmp(run.format(out="np2.dump"), cwd=d, log="log.np2", nprocs=2)
    cont = """
units           micro
read_restart    mid.restart
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
comm_modify     vel yes cutoff 20.0
neighbor        0.5 nsq
neigh_modify    every 1 delay 0 check yes
pair_coeff      * *
fix             nve all nve
run             300
write_dump      all custom restart.dump id x y z vx vy vz modify sort id format float %.17g
"""
    T.lmp(cont, cwd=d, log="log.restart")
    dumps = {k: np.loadtxt(os.path.join(d, f"{k}.dump"), skiprows=9) for k in ("np1", "np2", "restart")}
    size = np.ptp(dumps["np1"][:, 1:4], axis=0).max()
    moved = np.abs(dumps["np1"][:, 1:4]).max()
    d12 = np.abs(dumps["np1"][:, 1:4] - dumps["np2"][:, 1:4]).max() / size
    dre = np.abs(dumps["np1"][:, 1:4] - dumps["restart"][:, 1:4]).max() / size
    print(f"after 600 steps: 1 vs 2 ranks differ by {d12:.1e}, restart vs straight by {dre:.1e} "
          f"(of the wall size {size:.2f} um)")
    T.check("1 and 2 ranks give the same wall", d12 < 1e-9, f"{d12:.1e}")
    T.check("a restart continues the run", dre < 1e-9, f"{dre:.1e}")


def test_bad_input_refused(cell2):
    d = cell2
    base = wall_input("cell2.data")
    # the first hinge i-j-k-l of the data file, its node i moved onto the middle of its edge j-k
    i, j, k = [int(v) for v in read_data(os.path.join(d, "cell2.data")).rows("Dihedrals")[0][2:5]]
    collapse = (f"set atom {i} x $((x[{j}]+x[{k}])/2) y $((y[{j}]+y[{k}])/2) "
                f"z $((z[{j}]+z[{k}])/2)\nrun 0\n")
    bad = {
        "negative modulus": (base.replace(f"dihedral_coeff  1 {G} {T0}", "dihedral_coeff  1 -1 0.126"),
                             "shear modulus G must be > 0"),
        "too few arguments": (base.replace(f"dihedral_coeff  1 {G} {T0}", "dihedral_coeff  1 8e5"),
                              "expected 'dihedral_coeff N G t0'"),
        "no reference positions": (base.replace("d2_cellref 3", "d2_elsewhere 3") + "run 0\n",
                                   "requires the wall reference positions"),
        "collapsed hinge": (base + collapse, "has collapsed"),
    }
    for name, (inp, expect) in bad.items():
        rc, log = T.lmp(inp, cwd=d, log=f"log.bad-{name.replace(' ', '_')}", check=False)
        msg = [l for l in log.splitlines() if "ERROR" in l]
        print(f"{name}: rc {rc}, {msg[-1] if msg else 'no error'}")
        T.check(f"bad input ({name}) is refused with a clear error",
                rc != 0 and any(expect in l for l in msg), msg[-1] if msg else "no error")


def read_topology(path):
    """Reference positions by ID, and the triangles, tethers and hinges of a data file."""
    data = read_data(path)
    ref = {int(w[0]): np.array([float(v) for v in w[4:7]]) for w in data.rows("cell")}
    return ref, *([tuple(int(v) for v in w[2:]) for w in data.rows(k)]
                  for k in ("Angles", "Bonds", "Dihedrals"))


@pytest.fixture(scope="module")
def hinged(rundir):
    """The coarse wall with hinges (cellb.data) stretched 1.06 in x against lamf 1.03: its hinges,
    the triangles each wall model loses, the input with the wall's styles left open ({styles}) and
    the stretch."""
    d = rundir
    T.cellgen("cell", "-o", "cellb.data", "--level", 3, "--nfluid", 0, "--bending", cwd=d)
    ref, tri, bonds, hinges = read_topology(os.path.join(d, "cellb.data"))
    centre = np.mean(np.array(list(ref.values())), axis=0)
    scale, lamf = np.array([1.06, 1.0, 1.0]), 1.03
    key = lambda *t: tuple(sorted(t))

    def lam1(a, b, c):
        A, C = ref[a] - ref[b], ref[c] - ref[b]
        e1 = A / np.linalg.norm(A)
        n = np.cross(A, C)
        e2 = np.cross(n / np.linalg.norm(n), e1)
        F = np.column_stack([scale * A, scale * C]) @ np.linalg.inv(
            np.array([[A @ e1, C @ e1], [A @ e2, C @ e2]]))
        return np.sqrt(np.linalg.eigvalsh(F.T @ F).max())

    stretch = lambda a, b: np.linalg.norm(scale * (ref[a] - ref[b])) / np.linalg.norm(ref[a] - ref[b])
    broken = {key(a, b) for a, b in bonds if stretch(a, b) > lamf}
    gone = {"membrane": {key(*t) for t in tri if lam1(*t) > lamf},
            "tether": {key(*t) for t in tri
                       if {key(t[0], t[1]), key(t[0], t[2]), key(t[1], t[2])} & broken}}
    styles = {"membrane": (f"bond_style      zero\nbond_coeff      *\nangle_style     cell/membrane\n"
                           f"angle_coeff     1 {G} {T0} 0.0 {{lamf}}"),
              "tether": (f"bond_style      cell/tether\nbond_coeff      1 {G} {T0} 0.0 {{lamf}}\n"
                         f"angle_style     zero nocoeff\nangle_coeff     *")}
    base = wall_input("{data}").replace("bond_style      zero\nbond_coeff      *\nangle_style     zero\n"
                                   "angle_coeff     *", "{styles}")
    deform = "".join(f"variable s{x} atom ({c})+{f}*({x}-({c}))\n"
                     for x, c, f in zip("xyz", centre, scale)) + "set group all x v_sx y v_sy z v_sz\n"
    return SimpleNamespace(hinges=hinges, gone=gone, styles=styles, base=base, deform=deform, lamf=lamf,
                           key=key)


def hinge_energies(d, hg, wall):
    """The hinges that should be left (both wings intact); the bending energy of exactly those at
    the stretched positions (a data file with only them, keep.data, and no failure), and of all."""
    hinges, gone, key, base, styles, deform = hg.hinges, hg.gone, hg.key, hg.base, hg.styles, hg.deform
    keep = [h for h in hinges if key(*h[:3]) not in gone[wall] and key(*h[1:]) not in gone[wall]]
    # the energy of exactly the hinges that should be left, at the same positions: a data file
    # with only those, and no failure
    data = read_data(os.path.join(d, "cellb.data"))
    data.counts["dihedrals"] = len(keep)
    data.sections["Dihedrals"] = [[n + 1, 1, *h] for n, h in enumerate(keep)]
    write(os.path.join(d, "keep.data"), data)
    _, log = T.lmp(base.format(data="keep.data", styles=styles[wall].format(lamf="")) + deform +
                   'run 0\nprint "EB $(edihed:%.17g) $(dihedrals)"\n', cwd=d, log=f"log.keep-{wall}")
    eb_expect = float(last(log, "EB")[1])
    _, log = T.lmp(base.format(data="cellb.data", styles=styles[wall].format(lamf="")) + deform +
                   'run 0\nprint "EB $(edihed:%.17g) $(dihedrals)"\n', cwd=d, log=f"log.all-{wall}")
    eb_all = float(last(log, "EB")[1])
    return keep, eb_expect, eb_all


def fail_and_restart(d, hg, wall, np_):
    """The stretched wall with failure on np_ ranks, run 0 twice (the step of the failure and the
    next build), written to a data file and a restart and continued: the energies and counts."""
    base, styles, deform, lamf = hg.base, hg.styles, hg.deform, hg.lamf
    inp = base.format(data="cellb.data", styles=styles[wall].format(lamf=f"lamf {lamf}")) + deform + f"""
thermo_style    custom step edihed dihedrals angles bonds
thermo_modify   format float %.17g
run             0
print           "FAIL $(edihed:%.17g) $(dihedrals) $(angles) $(bonds)"
run             0
print           "NEXT $(edihed:%.17g)"
write_data      after{np_}.data nocoeff
write_restart   after{np_}.restart
"""
    _, log = T.lmp(inp, cwd=d, nprocs=np_, log=f"log.hinges-{wall}{np_}")
    eb_fail, nd, na, nb = (float(v) for v in last(log, "FAIL")[1:5])
    eb = float(last(log, "NEXT")[1])
    left = sorted(read_topology(os.path.join(d, f"after{np_}.data"))[3])
    cont = f"""
units           micro
read_restart    after{np_}.restart
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
comm_modify     vel yes cutoff 20.0
pair_coeff      * *
run             0
print           "CONT $(edihed:%.17g) $(dihedrals)"
"""
    _, log = T.lmp(cont, cwd=d, nprocs=np_, log=f"log.hinges-{wall}{np_}-cont")
    ebc, ndc = (float(v) for v in last(log, "CONT")[1:3])
    return eb_fail, nd, na, nb, eb, left, ebc, ndc


@pytest.mark.parametrize("wall", ("membrane", "tether"))
def test_hinges_follow_failure(rundir, hinged, wall):
    """A hinge whose wing triangle leaves the wall (broken tether, failed membrane triangle) leaves
    with it: arrays, count, and the neighbour lists from the build of the next step (its energy is
    gone from then on; in the step of the failure it still bends), on 1 and 2 ranks and through a
    restart."""
    d, hinges, gone, lamf = rundir, hinged.hinges, hinged.gone, hinged.lamf
    keep, eb_expect, eb_all = hinge_energies(d, hinged, wall)
    counts = {}
    for np_ in (1, 2):
        eb_fail, nd, na, nb, eb, left, ebc, ndc = fail_and_restart(d, hinged, wall, np_)
        counts[np_] = (nd, na, nb, eb)
        print(f"{wall} wall, {np_} rank(s), lamf {lamf}, stretch 1.06 in x: {len(gone[wall])} "
              f"triangles gone, hinges {len(hinges)} -> {nd:.0f} (expected {len(keep)}), "
              f"after restart {ndc:.0f}; E_bend in the step of the failure {eb_fail:.10g} (all "
              f"hinges {eb_all:.10g}), from the next build {eb:.10g}, restarted {ebc:.10g}, of "
              f"the expected hinges alone {eb_expect:.10g} (rel. diff {abs(eb / eb_expect - 1):.1e})")
        T.check(f"{wall}/{np_}: some hinges leave, not all", 0 < len(keep) < len(hinges))
        T.check(f"{wall}/{np_}: hinge count and the data file's hinges are those with both "
                f"wings intact", nd == len(keep) and left == sorted(keep), f"{nd:.0f}")
        T.check(f"{wall}/{np_}: in the step of the failure every hinge still bends (1e-12)",
                abs(eb_fail / eb_all - 1) < 1e-12, f"{abs(eb_fail / eb_all - 1):.1e}")
        T.check(f"{wall}/{np_}: the hinges of torn triangles bend nothing from the next "
                f"neighbour build on (1e-12)", abs(eb / eb_expect - 1) < 1e-12,
                f"{abs(eb / eb_expect - 1):.1e}")
        T.check(f"{wall}/{np_}: the restart keeps them out", ndc == len(keep) and
                abs(ebc / eb_expect - 1) < 1e-12, f"{ndc:.0f}")
    T.check(f"{wall}: 1 and 2 ranks agree", counts[1][:3] == counts[2][:3], str(counts))
