# SPDX-License-Identifier: GPL-2.0-or-later
"""Angle style cell/membrane (the wall as Neo-Hookean membrane elements) inside LAMMPS, on a
level-3 wall without fluid (642 nodes, 1280 triangles); the single element against the closed
forms is in tests/unit/physics/test_membrane.cpp (MembraneElement).

1. Uniform scaling of the wall by lam about its centre stretches every triangle equibiaxially, so
   the wall's energy is exactly (G t0 A0 / 2)(2 lam^2 + lam^-4 - 3) with A0 the reference area,
   and the virial sum x.f = -lam dE/dlam = -2 G t0 A0 (lam^2 - lam^-4) (homogeneous scaling):
   both to round-off (1e-10 relative) at lam = 0.95, 1.02, 1.1.
2. A randomly perturbed, stretched wall run with nve and no damping conserves its energy up to
   the error of velocity Verlet, which is O(dt^2) when the forces are the exact gradient of the
   energy: halving dt must divide the largest deviation by 4 (asserted 3..5). A force that is
   not the gradient would leave an error that does not converge. The perturbation (0.05 um at
   random on every node) excites the wall's fastest modes, so the deviation is 4e-4 of the
   potential energy at dt = 0.5 ns; asserted below 1e-3 as a guard against a gross error.
3. The same run on 1 and 2 ranks gives the same positions (to 1e-9 of the wall size), and a
   restart in the middle continues it exactly.
4. Bad input: a negative modulus, too few arguments, a wall without reference positions and a
   wrinkle value other than yes/no each stop with an error naming the command.
5. Tension-field theory (angle_coeff ... wrinkle yes, Eq. M3): the wall scaled by (1.08, 1.0, 0.93)
   along x, y, z has triangles taut, wrinkled and slack; its energy equals Eq. M3 summed over the
   triangles by this script from numpy's principal stretches (1e-10 relative), and is below the
   full sheet's. Scaled uniformly by 0.95 every triangle is slack: no energy and no virial. The
   setting survives write_data and a restart (the same energy after reading either back).
"""
import math
import os

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
angle_coeff     1 {G} {t0} {gamma}
pair_style      zero 1.0
pair_coeff      * *
special_bonds   lj 0 1 1
comm_modify     vel yes cutoff 8.0
neighbor        0.5 bin
neigh_modify    every 1 delay 0 check yes
timestep        {dt}
"""

# reference area of the wall (sum of the triangles' areas at the reference positions): from
# the data file, independently of the style
def wall_triangles(path):
    """(reference positions by atom id, triangles a-b-c) of a data file."""
    data = read_data(path)
    ref = {int(w[0]): np.array([float(v) for v in w[4:7]])    # id rmass rho drho ref
           for w in data.rows("cell")}
    return ref, [tuple(int(v) for v in w[2:5]) for w in data.rows("Angles")]


def reference_area(path):
    ref, tri = wall_triangles(path)
    area = 0.0
    for a, b, c in tri:
        area += 0.5 * np.linalg.norm(np.cross(ref[a] - ref[b], ref[c] - ref[b]))
    return area, len(tri)


def tension_field_energy(ref, tri, x):
    """Eq. M3 summed over the triangles, computed here from the principal stretches (numpy's
    eigenvalues of C2), independently of the style: taut W(l1, l2), wrinkled W(l1, l1^-1/2),
    slack 0; also the number of triangles in each state."""
    E, states = 0.0, [0, 0, 0]
    for a, b, c in tri:
        A, C = ref[a] - ref[b], ref[c] - ref[b]
        e1 = A / np.linalg.norm(A)
        n = np.cross(A, C)
        e2 = np.cross(n / np.linalg.norm(n), e1)
        D = np.array([[A @ e1, C @ e1], [A @ e2, C @ e2]])
        F = np.column_stack([x[a] - x[b], x[c] - x[b]]) @ np.linalg.inv(D)
        ev = np.linalg.eigvalsh(F.T @ F)
        l1, l2 = math.sqrt(ev[1]), math.sqrt(ev[0])
        A0 = 0.5 * np.linalg.norm(n)
        if l1 <= 1.0:
            states[2] += 1
        elif l2 < l1 ** -0.5:
            E += 0.5 * G * T0 * A0 * (l1 * l1 + 2.0 / l1 - 3.0)
            states[1] += 1
        else:
            E += 0.5 * G * T0 * A0 * (l1 * l1 + l2 * l2 + 1.0 / (l1 * l1 * l2 * l2) - 3.0)
            states[0] += 1
    return E, states


def scaled(setup, a, b, c, d, tag, after=""):
    """The wall of `setup` scaled by (a, b, c) about its centre of mass along x, y, z: (angle
    energy, virial sum x.f) after run 0, then the commands `after`."""
    inp = setup + f"""
variable        cx equal xcm(all,x)
variable        cy equal xcm(all,y)
variable        cz equal xcm(all,z)
variable        sx atom v_cx+{a}*(x-v_cx)
variable        sy atom v_cy+{b}*(y-v_cy)
variable        sz atom v_cz+{c}*(z-v_cz)
set             group all x v_sx y v_sy z v_sz
compute         vir all pressure NULL virial
variable        xf equal c_vir*3*vol
thermo_style    custom step eangle v_xf
thermo_modify   format float %.17g
run             0
print           "SCALED $(eangle:%.17g) $(v_xf:%.17g)"
""" + after
    _, log = T.lmp(inp, cwd=d, log=f"log.{tag}")
    line = [l for l in log.splitlines() if l.startswith("SCALED")][-1].split()
    return float(line[1]), float(line[2])


@pytest.fixture(scope="module")
def wall(rundir):
    """The coarse wall alone (cell.data) and its reference area."""
    d = rundir
    T.cellgen("cell", "-o", "cell.data", "--level", 3, "--nfluid", 0, cwd=d)
    A0, ntri = reference_area(os.path.join(d, "cell.data"))
    print(f"level-3 wall: {ntri} triangles, reference area {A0:.6f} um^2")
    return d, A0, ntri


def test_level3_wall(wall):
    ntri = wall[2]
    T.check("the data file holds the 1280 triangles of a level-3 wall", ntri == 1280, ntri)


def test_uniform_scaling(wall):
    d, A0, _ = wall
    # 1. uniform scaling: energy and virial against the closed form
    for lam in (0.95, 1.02, 1.1):
        E, xf = scaled(SETUP.format(G=G, t0=T0, gamma=0.0, dt=0.001), lam, lam, lam, d,
                       f"scale{lam}")
        Eexp = 0.5 * G * T0 * A0 * (2 * lam ** 2 + lam ** -4 - 3)
        xfexp = -2.0 * G * T0 * A0 * (lam ** 2 - lam ** -4)
        eE, ex = abs(E / Eexp - 1), abs(xf / xfexp - 1)
        print(f"lam {lam}: energy {E:.10g} (closed form {Eexp:.10g}, rel. error {eE:.1e}); "
              f"sum x.f {xf:.10g} ({xfexp:.10g}, {ex:.1e})")
        T.check(f"lam {lam}: energy of the equibiaxially stretched wall", eE < 1e-10, f"{eE:.1e}")
        T.check(f"lam {lam}: virial of the equibiaxially stretched wall", ex < 1e-10, f"{ex:.1e}")


def test_nve_energy_second_order(wall):
    d = wall[0]
    # 2. energy conservation with nve, at dt and dt/2
    drift = {}
    for dt, nsteps in ((0.0005, 2000), (0.00025, 4000)):
        inp = SETUP.format(G=G, t0=T0, gamma=0.0, dt=dt) + f"""
displace_atoms  all random 0.05 0.05 0.05 8123 units box
variable        sx atom 1.02*x
variable        sy atom 1.02*y
variable        sz atom 1.02*z
set             group all x v_sx y v_sy z v_sz
fix             nve all nve
variable        etot equal ke+eangle
variable        ea equal eangle
thermo_style    custom step ke eangle v_etot
thermo          {nsteps // 20}
fix             rec all ave/time {nsteps // 100} 1 {nsteps // 100} v_etot v_ea file energy{dt}.dat &
                format " %.17g"
run             {nsteps}
"""
        T.lmp(inp, cwd=d, log=f"log.nve{dt}")
        e = T.load(os.path.join(d, f"energy{dt}.dat"))
        drift[dt] = np.abs(e[:, 1] - e[0, 1]).max() / e[0, 2]
        print(f"dt {dt} us, {nsteps} steps: largest |E - E0| / E_pot(0) = {drift[dt]:.3e} "
              f"(E_pot(0) = {e[0, 2]:.6g}, E_pot at the end {e[-1, 2]:.6g})")
    ratio = drift[0.0005] / drift[0.00025]
    print(f"error ratio for dt halved: {ratio:.2f} (second order: 4)")
    T.check("nve conserves the membrane wall's energy", drift[0.0005] < 1e-3, f"{drift[0.0005]:.1e}")
    T.check("the energy error is second order in dt", 3.0 < ratio < 5.0, f"{ratio:.2f}")


def test_ranks_and_restart(wall):
    d = wall[0]
    # 3. one rank against two, and a restart in the middle
    run = SETUP.format(G=G, t0=T0, gamma=0.1, dt=0.0005) + """
displace_atoms  all random 0.05 0.05 0.05 8123 units box
fix             nve all nve
run             300
write_restart   mid.restart
run             300
write_dump      all custom {out} id x y z vx vy vz modify sort id format float %.17g
"""
    T.lmp(run.format(out="np1.dump"), cwd=d, log="log.np1")
    T.lmp(run.format(out="np2.dump"), cwd=d, log="log.np2", nprocs=2)
    cont = f"""
units           micro
read_restart    mid.restart
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
comm_modify     vel yes cutoff 8.0
neighbor        0.5 bin
neigh_modify    every 1 delay 0 check yes
pair_coeff      * *
fix             nve all nve
run             300
write_dump      all custom restart.dump id x y z vx vy vz modify sort id format float %.17g
"""
    T.lmp(cont, cwd=d, log="log.restart")
    dumps = {k: np.loadtxt(os.path.join(d, f"{k}.dump"), skiprows=9) for k in ("np1", "np2", "restart")}
    size = np.ptp(dumps["np1"][:, 1:4], axis=0).max()
    d12 = np.abs(dumps["np1"][:, 1:4] - dumps["np2"][:, 1:4]).max() / size
    dre = np.abs(dumps["np1"][:, 1:4] - dumps["restart"][:, 1:4]).max() / size
    print(f"after 600 steps: 1 vs 2 ranks differ by {d12:.1e}, restart vs straight by {dre:.1e} "
          f"(of the wall size {size:.2f} um)")
    T.check("1 and 2 ranks give the same wall", d12 < 1e-9, f"{d12:.1e}")
    T.check("a restart continues the run", dre < 1e-9, f"{dre:.1e}")


def test_bad_input_refused(wall):
    d = wall[0]
    # 4. bad input
    bad = {
        "wrinkle not yes or no": (SETUP.format(G=G, t0=T0, gamma=0.0, dt=0.001).replace(
            f"angle_coeff     1 {G} {T0} 0.0", f"angle_coeff     1 {G} {T0} 0.0 wrinkle maybe"),
            "wrinkle must be 'yes'"),
        "residual out of range": (SETUP.format(G=G, t0=T0, gamma=0.0, dt=0.001).replace(
            f"angle_coeff     1 {G} {T0} 0.0", f"angle_coeff     1 {G} {T0} 0.0 wrinkle yes residual 0"),
            "residual must be > 0 and < 1"),
        "residual without wrinkle": (SETUP.format(G=G, t0=T0, gamma=0.0, dt=0.001).replace(
            f"angle_coeff     1 {G} {T0} 0.0", f"angle_coeff     1 {G} {T0} 0.0 residual 1e-4"),
            "residual 0.0001 needs wrinkle yes"),
        "negative modulus": (SETUP.format(G=-1.0, t0=T0, gamma=0.0, dt=0.001),
                             "shear modulus G must be > 0"),
        "too few arguments": (SETUP.format(G=G, t0=T0, gamma=0.0, dt=0.001).replace(
            f"angle_coeff     1 {G} {T0} 0.0", "angle_coeff     1 8e5"), "expected 'angle_coeff N G t0"),
        "no reference positions": (SETUP.format(G=G, t0=T0, gamma=0.0, dt=0.001).replace(
            "d2_cellref 3", "d2_elsewhere 3")
            + "run 0\n", "requires the wall reference positions"),
    }
    for name, (inp, expect) in bad.items():
        rc, log = T.lmp(inp, cwd=d, log=f"log.bad-{name.replace(' ', '_')}", check=False)
        msg = [l for l in log.splitlines() if "ERROR" in l]
        print(f"{name}: rc {rc}, {msg[-1] if msg else 'no error'}")
        T.check(f"bad input ({name}) is refused with a clear error",
                rc != 0 and any(expect in l for l in msg), msg[-1] if msg else "no error")


@pytest.fixture(scope="module")
def wrinkled(wall):
    """5. tension-field theory: the wall scaled (1.08, 1, 0.93) with wrinkle yes, written to a dump,
    a data file and a restart; its energy."""
    d = wall[0]
    wr = SETUP.format(G=G, t0=T0, gamma=0.0, dt=0.001).replace(
        f"angle_coeff     1 {G} {T0} 0.0", f"angle_coeff     1 {G} {T0} 0.0 wrinkle yes")
    E, _ = scaled(wr, 1.08, 1.0, 0.93, d, "wrinkle-aniso", """
write_dump      all custom wrinkled.dump id x y z modify sort id format float %.17g
write_data      wrinkled.data
write_restart   wrinkled.restart
""")
    return wr, E


def test_tension_field_energy(wall, wrinkled):
    d = wall[0]
    wr, E = wrinkled
    ref, tri = wall_triangles(os.path.join(d, "cell.data"))
    Efull, _ = scaled(SETUP.format(G=G, t0=T0, gamma=0.0, dt=0.001), 1.08, 1.0, 0.93, d,
                      "full-aniso")
    dmp = np.loadtxt(os.path.join(d, "wrinkled.dump"), skiprows=9)
    x = {int(r[0]): r[1:4] for r in dmp}
    Eexp, states = tension_field_energy(ref, tri, x)
    eE = abs(E / Eexp - 1)
    print(f"wrinkle yes, wall scaled (1.08, 1, 0.93): {states[0]} taut, {states[1]} wrinkled, "
          f"{states[2]} slack triangles; energy {E:.10g}, Eq. M3 here {Eexp:.10g} (rel. error "
          f"{eE:.1e}); the full sheet {Efull:.10g}")
    T.check("the scaled wall has taut, wrinkled and slack triangles", min(states) > 0, states)
    T.check("tension-field energy of the wall equals Eq. M3 summed independently", eE < 1e-10,
            f"{eE:.1e}")
    T.check("the tension-field wall stores less than the full sheet", E < Efull, f"{E:.6g} {Efull:.6g}")
    E95, xf95 = scaled(wr, 0.95, 0.95, 0.95, d, "wrinkle-0.95")
    print(f"wrinkle yes, wall scaled by 0.95: energy {E95:g}, sum x.f {xf95:g}")
    T.check("a wall shrunk in every direction is slack: no energy, no virial",
            E95 == 0.0 and xf95 == 0.0, f"{E95:g} {xf95:g}")
    coeffs = " ".join(read_data(os.path.join(d, "wrinkled.data")).rows("Angle Coeffs")[0])
    print(f"write_data Angle Coeffs: {coeffs}")
    T.check("write_data keeps wrinkle yes", coeffs.endswith("wrinkle yes"), coeffs)


def test_tension_field_wall_read_back(wall, wrinkled):
    d = wall[0]
    _, E = wrinkled
    back = {}
    for how, head in (("data", """
units           micro
atom_style      molecular
atom_modify     map array
boundary        f f f
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
bond_style      zero
angle_style     cell/membrane
pair_style      zero 1.0
read_data       wrinkled.data fix cell NULL cell
pair_coeff      * *
"""), ("restart", """
units           micro
read_restart    wrinkled.restart
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
pair_coeff      * *
""")):
        _, log = T.lmp(head + """
special_bonds   lj 0 1 1
comm_modify     cutoff 8.0
thermo_style    custom step eangle
run             0
print           "BACK $(eangle:%.17g)"
""", cwd=d, log=f"log.wrinkle-{how}")
        back[how] = float([l for l in log.splitlines() if l.startswith("BACK")][-1].split()[1])
        print(f"read back from the {how} file: energy {back[how]:.10g}")
        T.check(f"the {how} file keeps the tension-field wall", abs(back[how] / E - 1) < 1e-12,
                f"{back[how]:.10g} vs {E:.10g}")


def test_residual_stiffness_of_a_slack_wall(wall):
    """Eq. M4 on the wall: shrunk by 0.95 in every direction every triangle is slack, so with
    wrinkle yes residual r the wall stores r times the full sheet's energy (Eq. M1) and pushes back
    with r times its virial; write_data and a restart keep the residual (the same energy read
    back)."""
    d = wall[0]
    r = 1e-3
    full = SETUP.format(G=G, t0=T0, gamma=0.0, dt=0.001)
    res = full.replace(f"angle_coeff     1 {G} {T0} 0.0", f"angle_coeff     1 {G} {T0} 0.0 wrinkle yes residual {r}")
    Ef, xff = scaled(full, 0.95, 0.95, 0.95, d, "full-0.95")
    E, xf = scaled(res, 0.95, 0.95, 0.95, d, "residual-0.95", """
write_data      residual.data
write_restart   residual.restart
""")
    print(f"wall scaled by 0.95: residual {r}: energy {E:.10g}, sum x.f {xf:.10g}; the full sheet "
          f"{Ef:.10g}, {xff:.10g}")
    T.check("a slack wall with a residual stores r x the full sheet's energy", abs(E / (r * Ef) - 1) < 1e-12,
            f"{E:.10g} vs {r * Ef:.10g}")
    T.check("and pushes back with r x its virial", abs(xf / (r * xff) - 1) < 1e-10, f"{xf:.10g} vs {r * xff:.10g}")
    coeffs = " ".join(read_data(os.path.join(d, "residual.data")).rows("Angle Coeffs")[0])
    T.check("write_data keeps the residual", coeffs.endswith(f"wrinkle yes residual {r:g}"), coeffs)
    _, log = T.lmp(f"""
units           micro
read_restart    residual.restart
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
pair_coeff      * *
special_bonds   lj 0 1 1
comm_modify     cutoff 8.0
thermo_style    custom step eangle
run             0
print           "BACK $(eangle:%.17g)"
""", cwd=d, log="log.residual-restart")
    back = float([l for l in log.splitlines() if l.startswith("BACK")][-1].split()[1])
    T.check("a restart keeps the residual", abs(back / E - 1) < 1e-12, f"{back:.10g} vs {E:.10g}")
