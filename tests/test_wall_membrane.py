# SPDX-License-Identifier: GPL-2.0-or-later
"""Angle style cell/membrane (the wall as Neo-Hookean membrane elements) inside LAMMPS, on a
level-3 wall without fluid (642 nodes, 1280 triangles); the single element against the closed
forms is in tests/unit/test_physics.cpp (MembraneElement).

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
4. Bad input: a negative modulus, too few arguments and a wall without reference positions each
   stop with an error naming the command.
"""
import math
import os

import numpy as np

import lmptest as T

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
def reference_area(path):
    text = open(path).read().split("\n")
    ref, tri = {}, []
    sec = None
    for line in text:
        s = line.split("#")[0].strip()
        if not s:
            continue
        if s in ("Atoms", "Bonds", "Angles", "Masses", "Velocities") or s.startswith("cell"):
            sec = s.split()[0]
            continue
        if sec == "cell" and len(s.split()) >= 7:
            w = s.split()
            ref[int(w[0])] = np.array([float(w[4]), float(w[5]), float(w[6])])  # id rmass rho drho ref
        elif sec == "Angles":
            w = s.split()
            tri.append((int(w[2]), int(w[3]), int(w[4])))
    area = 0.0
    for a, b, c in tri:
        area += 0.5 * np.linalg.norm(np.cross(ref[a] - ref[b], ref[c] - ref[b]))
    return area, len(tri)


def main():
    d = T.workdir("wall_membrane")
    T.cellgen("cell", "-o", "cell.data", "--level", 3, "--nfluid", 0, cwd=d)
    A0, ntri = reference_area(os.path.join(d, "cell.data"))
    print(f"level-3 wall: {ntri} triangles, reference area {A0:.6f} um^2")
    T.check("the data file holds the 1280 triangles of a level-3 wall", ntri == 1280, ntri)

    # 1. uniform scaling: energy and virial against the closed form
    for lam in (0.95, 1.02, 1.1):
        inp = SETUP.format(G=G, t0=T0, gamma=0.0, dt=0.001) + f"""
variable        cx equal xcm(all,x)
variable        cy equal xcm(all,y)
variable        cz equal xcm(all,z)
variable        sx atom v_cx+{lam}*(x-v_cx)
variable        sy atom v_cy+{lam}*(y-v_cy)
variable        sz atom v_cz+{lam}*(z-v_cz)
set             group all x v_sx y v_sy z v_sz
compute         vir all pressure NULL virial
variable        xf equal c_vir*3*vol
thermo_style    custom step eangle v_xf
thermo_modify   format float %.17g
run             0
print           "SCALED {lam} $(eangle:%.17g) $(v_xf:%.17g)"
"""
        _, log = T.lmp(inp, cwd=d, log=f"log.scale{lam}")
        line = [l for l in log.splitlines() if l.startswith("SCALED")][-1].split()
        E, xf = float(line[2]), float(line[3])
        Eexp = 0.5 * G * T0 * A0 * (2 * lam ** 2 + lam ** -4 - 3)
        xfexp = -2.0 * G * T0 * A0 * (lam ** 2 - lam ** -4)
        eE, ex = abs(E / Eexp - 1), abs(xf / xfexp - 1)
        print(f"lam {lam}: energy {E:.10g} (closed form {Eexp:.10g}, rel. error {eE:.1e}); "
              f"sum x.f {xf:.10g} ({xfexp:.10g}, {ex:.1e})")
        T.check(f"lam {lam}: energy of the equibiaxially stretched wall", eE < 1e-10, f"{eE:.1e}")
        T.check(f"lam {lam}: virial of the equibiaxially stretched wall", ex < 1e-10, f"{ex:.1e}")

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

    # 4. bad input
    bad = {
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
    T.finish()


if __name__ == "__main__":
    main()
