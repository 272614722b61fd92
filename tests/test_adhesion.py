# SPDX-License-Identifier: GPL-2.0-or-later
"""pair_style cell/virtual with adhere Fa delta: the protoplasm holds on to its own wall (Eq. A1 of
docs/pair_cell_virtual.rst, src/physics/adhesion.h), another cell's fluid is only kept out.

A system written here: twelve lone wall triangles (cell 1), each with one fluid particle of cell 1
or of cell 2 at a chosen distance from its barycentre (inside r0, in the adhesion range, beyond
it), and a fan of six triangles around one node with fluid of both cells above it, on the border
of two ranks. Everything moves (random velocities, contact damping gamma on). Checked:
 (i)   the force on each lone cell-1 particle against the law (8-4 repulsion + damping within r0,
       adhesion to r0 + delta), relative 1e-10; each atom's force, the energy and the virial of
       the whole system against the same law summed here, and the per-atom energies and virials
       summed;
 (ii)  the cell-2 particles: the repulsion within r0, nothing in (r0, r0 + delta);
 (iii) total force and torque zero to round-off;
 (iv)  a cell-1 particle released in the well bounces off the wall and back, energy conserved in
       a velocity-Verlet (NVE) run to the bound of its time step;
 (v)   1 and 2 ranks give the same forces to round-off;
 (vi)  bad adhere arguments are refused with messages that name them;
 (vii) a restart file keeps Fa and delta (the forces after read_restart are those before).
"""
import re

import numpy as np

import lmptest as T

EPS = np.finfo(float).eps
F0, R0, GAMMA, FA, DELTA, REACH = 1.0e4, 1.6, 50.0, 500.0, 0.8, 2.0
EDGE = 2.0    # triangle edge: r0 >= half the edge (check_contact_distance of the style)


def rotation():
    """A general rotation, so that no triangle lies in a coordinate plane."""
    k = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0)
    th = 0.7
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(th) * K + (1 - np.cos(th)) * K @ K


ROT = rotation()
# distances of the lone fluid particles from their barycentres (r0 = 1.6, r0 + delta = 2.4)
LONE_R = [0.85 * R0, 0.97 * R0, R0 + 0.1 * DELTA, R0 + 0.5 * DELTA, R0 + 0.9 * DELTA,
          R0 + 1.2 * DELTA]


def lone_triangle(centre):
    """Three nodes of an equilateral triangle (edge EDGE) around centre, turned by ROT."""
    a = EDGE / np.sqrt(3.0)
    return [centre + ROT @ (a * np.array([np.cos(t), np.sin(t), 0.0]))
            for t in np.radians([90.0, 210.0, 330.0])]


def build_system():
    """Atoms (id, mol, type, x), velocities and triangles (a, b, c: b the central node)."""
    atoms, tris, lone = [], [], []
    slots = [x for x in range(0, 130, 10) if x != 60]    # x = 60: the fan, on the rank border
    normal = ROT @ (np.array([0.3, 0.2, 0.933]) / np.linalg.norm([0.3, 0.2, 0.933]))
    cases = [(mol, r) for mol in (1, 2) for r in LONE_R]
    for (mol, r), x in zip(cases, slots):
        c = np.array([x, 0.0, 0.0])
        ids = []
        for p in lone_triangle(c):
            atoms.append((len(atoms) + 1, 1, 1, p))
            ids.append(len(atoms))
        tris.append(tuple(ids))
        atoms.append((len(atoms) + 1, mol, 2, c + r * normal))
        lone.append((len(atoms), mol, r))
    # the fan: a hexagon of triangles around a node at x = 60, the border of 2 ranks
    hub = np.array([60.0, 0.0, 0.0])
    atoms.append((len(atoms) + 1, 1, 1, hub))
    h = len(atoms)
    ring = []
    for t in np.radians(np.arange(0, 360, 60) + 15.0):
        atoms.append((len(atoms) + 1, 1, 1, hub + EDGE * np.array([np.cos(t), np.sin(t), 0.1])))
        ring.append(len(atoms))
    tris += [(ring[i], h, ring[(i + 1) % 6]) for i in range(6)]
    for mol, off in ((1, (0.3, 0.2, 1.2)), (1, (-0.5, -0.6, 1.9)), (2, (1.0, 0.8, 2.1)),
                     (2, (-0.8, 0.9, 1.0)), (1, (0.8, -1.0, 2.6)), (2, (0.0, 0.0, 3.0))):
        atoms.append((len(atoms) + 1, mol, 2, hub + np.array(off)))
    vel = np.random.default_rng(7).normal(0.0, 0.5, (len(atoms), 3))
    return atoms, vel, tris, lone


def write_data(path, atoms, vel, tris, masses=(1.0, 1.0), box=((-10, 130), (-10, 10), (-10, 10))):
    with open(path, "w") as f:
        f.write(f"test_adhesion.py\n\n{len(atoms)} atoms\n{len(tris)} angles\n2 atom types\n"
                "1 angle types\n\n")
        for (lo, hi), d in zip(box, "xyz"):
            f.write(f"{lo} {hi} {d}lo {d}hi\n")
        f.write(f"\nMasses\n\n1 {masses[0]}\n2 {masses[1]}\n\nAtoms # molecular\n\n")
        for i, mol, t, x in atoms:
            f.write(f"{i} {mol} {t} {x[0]!r} {x[1]!r} {x[2]!r}\n")
        f.write("\nVelocities\n\n")
        for (i, *_), v in zip(atoms, vel):
            f.write(f"{i} {v[0]!r} {v[1]!r} {v[2]!r}\n")
        f.write("\nAngles\n\n")
        for n, (a, b, c) in enumerate(tris):
            f.write(f"{n + 1} 1 {a} {b} {c}\n")


def head(data, px=1, coeff=f"{F0} {R0} {GAMMA} adhere {FA} {DELTA}"):
    return f"""
units           micro
atom_style      molecular
atom_modify     map array
boundary        f f f
processors      {px} 1 1
angle_style     zero nocoeff
read_data       {data}
angle_coeff     *
pair_style      cell/virtual {REACH}
pair_coeff      1 1 0.0 1.0
pair_coeff      2 2 0.0 1.0
pair_coeff      1 2 {coeff}
comm_modify     vel yes
neighbor        0.3 bin
"""


FORCES = """
compute         vir all pressure NULL virial
# per atom: energy and virial (compute stress/atom is minus the virial), summed
compute         pea all pe/atom
compute         sa all stress/atom NULL virial
compute         sums all reduce sum c_pea c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6]
thermo_style    custom step pe vol c_vir[1] c_vir[2] c_vir[3] c_vir[4] c_vir[5] c_vir[6] c_sums[*]
thermo_modify   format float %.17g
dump            d all custom 1 {dump} id x y z fx fy fz
dump_modify     d format float %.17g sort id
run             0
"""


# the law, written out here (not from the plugin's headers)
def law(rsq, own, rate):
    """fpair and energy of one virtual particle - fluid pair; rate = (x_k - B).(v_k - V_B)."""
    r = np.sqrt(rsq)
    fpair = e = 0.0
    if r < R0:
        s4 = (R0 * R0 / rsq) ** 2
        fpair = F0 * (s4 * s4 - s4) / rsq - GAMMA * rate / rsq
        e = F0 * (s4 * s4 / 8 - s4 / 4 + 1 / 8)
    if own:
        depth = 2.0 / 3.0 * FA * DELTA
        if r < R0:
            e -= depth
        elif r < R0 + DELTA:
            xi = (r - R0) / DELTA
            fpair += -4.0 * FA * xi * (1 - xi) / r
            e -= depth * (1 - 3 * xi ** 2 + 2 * xi ** 3)
    return fpair, e


def reference(x, v, mol, tris, fluid):
    """Forces, energy and virial of the system by the law; x, v, mol indexed by atom id."""
    f = np.zeros_like(x)
    energy, virial = 0.0, np.zeros(6)
    for a, b, c in tris:
        B = (x[a] + x[b] + x[c]) / 3.0
        VB = (v[a] + v[b] + v[c]) / 3.0
        for k in fluid:
            d = x[k] - B
            fpair, e = law(d @ d, mol[k] == mol[b], d @ (v[k] - VB))
            fk = fpair * d
            f[k] += fk
            for n in (a, b, c):
                f[n] -= fk / 3.0
            energy += e
            virial += [d[0] * fk[0], d[1] * fk[1], d[2] * fk[2], d[0] * fk[1], d[0] * fk[2],
                       d[1] * fk[2]]
    return f, energy, virial


def read_dump(path):
    """id x y z fx fy fz of the dump's single frame, as arrays indexed by atom id."""
    lines = open(path).read().splitlines()
    i = lines.index("ITEM: ATOMS id x y z fx fy fz") + 1
    a = np.array([[float(w) for w in l.split()] for l in lines[i:]])
    n = int(a[:, 0].max())
    x, f = np.zeros((n + 1, 3)), np.zeros((n + 1, 3))
    x[a[:, 0].astype(int)] = a[:, 1:4]
    f[a[:, 0].astype(int)] = a[:, 4:7]
    return x, f


def thermo_row(log):
    """The values of the thermo line of step 0 after the header 'Step PotEng Volume ...'."""
    lines = log.splitlines()
    i = [n for n, l in enumerate(lines) if l.split()[:3] == ["Step", "PotEng", "Volume"]][-1]
    return [float(w) for w in lines[i + 1].split()]


def test_forces_energy_virial_and_ranks(rundir):
    d = rundir
    atoms, vel, tris, lone = build_system()
    write_data(f"{d}/adh.data", atoms, vel, tris)
    runs = {}
    for px in (1, 2):
        _, log = T.lmp(head("adh.data", px) + FORCES.format(dump=f"forces.{px}")
                       + f"write_restart   adh.{px}.restart\n", cwd=d, nprocs=px, log=f"log.{px}")
        runs[px] = (read_dump(f"{d}/forces.{px}"), thermo_row(log))
    (x, f), row = runs[1]
    ids = [a[0] for a in atoms]
    v = np.zeros_like(x)
    v[ids] = vel
    mol = {a[0]: a[1] for a in atoms}
    fluid = [a[0] for a in atoms if a[2] == 2]
    fref, eref, vref = reference(x, v, mol, tris, fluid)

    # (i), (ii): the lone particles one by one
    for k, m, r in lone:
        fr, fl = fref[k], f[k]
        where = ("within r0" if r < R0 else "adhesion range" if r < R0 + DELTA
                 else "beyond r0 + delta")
        if np.linalg.norm(fr) == 0.0:
            T.check(f"cell {m}, r = {r:.3f} ({where}): no force", np.all(fl == 0.0), f"{fl}")
            continue
        err = np.linalg.norm(fl - fr) / np.linalg.norm(fr)
        radial = fl @ (x[k] - np.mean([x[n] for n in tris[lone.index((k, m, r))]], axis=0)) / r
        print(f"cell {m}, r = {r:.3f} ({where}): radial force {radial:+.10g}, "
              f"relative error {err:.1e}")
        T.check(f"cell {m}, r = {r:.3f}: force of the law", err < 1e-10, f"{err:.1e}")
    pulled = [f[k] for k, m, r in lone if m == 1 and R0 < r < R0 + DELTA]
    T.check("the own cell's fluid in the adhesion range is pulled",
            len(pulled) == 3 and all(np.linalg.norm(p) > 0.3 * FA for p in pulled))
    free = [f[k] for k, m, r in lone if m == 2 and r > R0]
    T.check("the other cell's fluid beyond r0 feels nothing",
            len(free) == 4 and all(np.all(p == 0.0) for p in free))

    # the whole system: every atom, the energy and the virial (LAMMPS: sum x f over all atoms,
    # round-off eps |x| |f| per term)
    scale = np.abs(fref).max()
    ferr = np.abs(f[ids] - fref[ids]).max() / scale
    pe, vol, vir = row[1], row[2], np.array(row[3:9]) * row[2]
    eerr = abs(pe - eref) / abs(eref)
    xf = np.sum(np.linalg.norm(x[ids], axis=1) * np.linalg.norm(f[ids], axis=1))
    verr = np.abs(vir - vref).max()
    print(f"all {len(ids)} atoms: largest force error {ferr:.1e} of the largest force; energy "
          f"{pe:.12g} against {eref:.12g} ({eerr:.1e}); virial error {verr:.2e} "
          f"(sum |x| |f| = {xf:.4g})")
    T.check("every atom's force of the law", ferr < 1e-10, f"{ferr:.1e}")
    T.check("energy of the law", eerr < 1e-12, f"{eerr:.1e}")
    T.check("virial of the law to round-off", verr < 16 * EPS * xf, f"{verr:.1e}")
    # per atom: half of each contact to its particle, a sixth to each node; the sums are those of
    # the contacts, in another order
    peatom, vatom = row[9], -np.array(row[10:16])
    aerr = abs(peatom - eref) / abs(eref)
    vaerr = np.abs(vatom - vref).max() / np.abs(vref).max()
    print(f"per-atom energies sum to {aerr:.1e} of the energy, per-atom virials to {vaerr:.1e}")
    T.check("per-atom energies sum to the energy", aerr < len(ids) * EPS, f"{aerr:.1e}")
    T.check("per-atom virials sum to the virial", vaerr < len(ids) * EPS, f"{vaerr:.1e}")

    # (iii) momentum: N atoms, each sum to round-off
    n = len(ids)
    fsum = np.abs(f[ids].sum(axis=0)).max() / np.abs(f[ids]).sum()
    tsum = np.abs(np.cross(x[ids], f[ids]).sum(axis=0)).max() / xf
    print(f"total force {fsum:.1e} of sum |f|, total torque {tsum:.1e} of sum |x| |f|")
    T.check("total force zero", fsum < n * EPS, f"{fsum:.1e}")
    T.check("total torque zero", tsum < n * EPS, f"{tsum:.1e}")

    # (v) two ranks: each force a sum of at most as many terms as the contacts, in another order
    (x2, f2), row2 = runs[2]
    ncontact = sum(1 for a, b, c in tris for k in fluid
                   if np.linalg.norm(x[k] - (x[a] + x[b] + x[c]) / 3) < R0 + DELTA)
    dmax = np.abs(f2[ids] - f[ids]).max() / scale
    de = abs(row2[1] - pe) / abs(pe)
    print(f"2 ranks against 1: forces {dmax:.1e} of the largest, energy {de:.1e} "
          f"({ncontact} contacts)")
    T.check("2 ranks: same positions", np.array_equal(x2[ids], x[ids]))
    T.check("2 ranks: same forces to round-off", dmax <= ncontact * EPS, f"{dmax:.1e}")
    T.check("2 ranks: same energy to round-off", de <= ncontact * EPS, f"{de:.1e}")

    # (vii) the restart file keeps the adhesion: the same forces and energy after read_restart
    _, log = T.lmp(f"""
read_restart    adh.1.restart
comm_modify     vel yes
""" + FORCES.format(dump="forces.restart"), cwd=d, log="log.restart")
    xr, fr = read_dump(f"{d}/forces.restart")
    dr = np.abs(fr[ids] - f[ids]).max() / scale
    der = abs(thermo_row(log)[1] - pe) / abs(pe)
    print(f"after read_restart: forces {dr:.1e} of the largest, energy {der:.1e}")
    T.check("restart: same positions", np.array_equal(xr[ids], x[ids]))
    T.check("restart: the same forces and energy (Fa, delta kept)",
            dr <= ncontact * EPS and der <= ncontact * EPS, f"{dr:.1e}, {der:.1e}")


def test_energy_conserved_in_the_well(rundir):
    """(iv) One triangle and one particle of its cell released at rest at r0 + delta/2, where the
    pull is Fa: it falls onto the wall, bounces off the repulsion and climbs back, again and
    again; nodes and particle move (NVE), gamma = 0. Velocity Verlet's energy error oscillates
    with amplitude about (omega dt)^2 / 4 of the oscillation's energy for a harmonic oscillator;
    omega here is that of the stiffest curvature on the path (the repulsion at the turning point,
    reduced mass mu of the particle against the triangle). Asserted: deviation below (omega
    dt)^2 of the largest kinetic energy, secular drift (linear fit over the run) below a tenth
    of it."""
    d = rundir
    m = 1.0
    c = np.array([0.0, 0.0, 0.0])
    nodes = lone_triangle(c)
    normal = ROT @ np.array([0.0, 0.0, 1.0])
    r_start = R0 + 0.5 * DELTA
    atoms = [(i + 1, 1, 1, p) for i, p in enumerate(nodes)] + [(4, 1, 2, c + r_start * normal)]
    write_data(f"{d}/well.data", atoms, np.zeros((4, 3)), [(1, 2, 3)], masses=(m, m),
               box=((-6, 6), (-6, 6), (-6, 6)))
    # the path: from r_start in to the turning point where the repulsion holds the energy
    # released, E(r_t) = E(r_start)
    def pot(r):
        return law(r * r, True, 0.0)[1]

    rs = np.linspace(0.8 * R0, r_start, 200001)
    es = np.array([pot(r) for r in rs])
    r_turn = rs[np.argmax(es <= pot(r_start))]
    path = np.linspace(r_turn, r_start, 20001)
    fr = np.array([law(r * r, True, 0.0)[0] * r for r in path])
    k_max = np.abs(np.gradient(fr, path)).max()
    mu = 1.0 / (1.0 / m + 1.0 / (3.0 * m))
    omega = np.sqrt(k_max / mu)
    dt = 2.5e-4
    nsteps = 20000
    bound = (omega * dt) ** 2
    print(f"turning point r = {r_turn:.4f} (r0 = {R0}); stiffest curvature {k_max:.4g} nN/um, "
          f"omega {omega:.4g} /us, dt {dt} us: (omega dt)^2 = {bound:.2e}")
    T.lmp(head("well.data", coeff=f"{F0} {R0} 0.0 adhere {FA} {DELTA}") + f"""
timestep        {dt}
fix             nve all nve
variable        r equal sqrt((x[4]-(x[1]+x[2]+x[3])/3)^2+(y[4]-(y[1]+y[2]+y[3])/3)^2+(z[4]-(z[1]+z[2]+z[3])/3)^2)
variable        t equal time
variable        k equal ke
variable        e equal ke+pe
fix             rec all ave/time 5 1 5 v_t v_r v_k v_e file well.dat format " %.15g"
run             {nsteps}
""", cwd=d, log="log.well")
    a = T.load(f"{d}/well.dat")
    t, r, ke, e = a[:, 1], a[:, 2], a[:, 3], a[:, 4]
    dev = np.abs(e - e[0]).max() / ke.max()
    drift = abs(np.polyfit(t, e, 1)[0]) * (t[-1] - t[0]) / ke.max()
    bounces = int(np.sum((r[1:-1] < r[:-2]) & (r[1:-1] <= r[2:])))
    print(f"{nsteps} steps: r between {r.min():.4f} and {r.max():.4f}, {bounces} bounces; max KE "
          f"{ke.max():.6g}, energy {e[0]:.10g} -> {e[-1]:.10g}: deviation {dev:.2e}, drift "
          f"{drift:.2e} of max KE")
    T.check("the particle reaches the repulsion and stays in the well",
            r.min() < R0 and r.max() < R0 + DELTA and bounces >= 10, f"{bounces} bounces")
    T.check("energy deviation within (omega dt)^2", dev < bound, f"{dev:.1e} < {bound:.1e}")
    T.check("no secular drift (a tenth of it)", drift < 0.1 * bound, f"{drift:.1e}")


BAD = [
    ("adhere -1.0 0.8", r"pair_coeff cell/virtual: adhesion strength Fa must be >= 0, got -1"),
    ("adhere 500.0 0.0", r"pair_coeff cell/virtual: adhesion range delta must be > 0, got 0"),
    ("adhere 500.0 -0.5", r"pair_coeff cell/virtual: adhesion range delta must be > 0, got -0\.5"),
    ("adhere 500.0", r"pair_coeff cell/virtual: keyword adhere needs two values, Fa delta; got 1"),
    ("adhesion 500.0 0.8", r"pair_coeff cell/virtual: unknown keyword 'adhesion' \(expected "
     r"'pair_coeff I J f0 r0 \[gamma\] \[adhere Fa delta\]'\)"),
    ("adhere 500.0 0.8 0.1", r"pair_coeff cell/virtual: unknown keyword '0\.1'"),
]


def test_bad_input_refused(rundir):
    """(vi) Each bad adhere argument stops LAMMPS at its pair_coeff with a message naming it; and
    adhesion without molecule IDs (atom_style atomic)."""
    d = rundir
    for args, msg in BAD:
        rc, log = T.lmp(head("adh.data", coeff=f"{F0} {R0} {GAMMA} {args}") + "run 0\n", cwd=d,
                        check=False, log="log.bad")
        ok = rc != 0 and re.search(r"ERROR: " + msg, log) is not None
        T.check(f"'pair_coeff 1 2 cell/virtual {F0} {R0} {GAMMA} {args}' refused", ok,
                (re.findall(r"ERROR.*", log) or ["no error"])[0])
    rc, log = T.lmp(f"""
units           micro
atom_style      atomic
region          box block 0 10 0 10 0 10
create_box      2 box
pair_style      cell/virtual {REACH}
pair_coeff      1 2 {F0} {R0} adhere {FA} {DELTA}
""", cwd=d, check=False, log="log.bad")
    T.check("adhesion without molecule IDs refused", rc != 0 and re.search(
        r"ERROR: pair_coeff cell/virtual: adhere Fa = 500 needs molecule IDs", log) is not None,
        (re.findall(r"ERROR.*", log) or ["no error"])[0])
