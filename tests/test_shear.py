"""Protoplasm shear stress (compute cell/shear/atom, paper Eqs. 24-26) in steady Poiseuille flow,
where it is known exactly: tau_xy(y) = mu du/dy = rho0 G (L/2 - y), linear across the channel,
zero on the centre line, rho0 G L/2 at the walls, whatever the viscosity.

Setup as tests/test_poiseuille.py (mirror walls, which put the no-slip planes half a spacing out):
20 fluid layers, dx = 1 um, s = 1.2 um, mu = 1000 mPa s, G = 2 um/us^2, 0.6 us to steady state;
tau_xy averaged per layer over the last 0.2 us.
Tolerance 1% (relative L2 over the layers): the SPH gradient of Eq. 25 on this lattice carries the
factor K = -sum_j V_j dy_j^2 (dW/dr)/r_j = 0.98 (test_poiseuille.py), but so does the Morris
viscous force, so in steady state the flow settles at the gradient that makes K mu du/dy balance
the body force and K cancels; what remains is the transient (2e-4), compressibility (Ma^2 = 1e-4)
and the layers next to the mirror walls.
Also asserted: tau_xz and tau_yz vanish (below 2% of the wall stress) and |tau| = |tau_xy|.
"""
import numpy as np

import lmptest as T

RHO0, MU, C, P0, S, DX = 1.0, 1000.0, 10.0, 10.0, 1.2, 1.0
NL, NW, NXZ, G = 20, 3, 6, 2.0
L = NL * DX


def main():
    d = T.workdir("shear")
    mirror = "variable        zero equal 0.0\n"
    for j in range(NW):
        mirror += f"""
region          fm{j} block INF INF {j * DX} {(j + 1) * DX} INF INF units box
region          wm{j} block INF INF {-(j + 1) * DX} {-j * DX} INF INF units box
region          fp{j} block INF INF {L - (j + 1) * DX} {L - j * DX} INF INF units box
region          wp{j} block INF INF {L + j * DX} {L + (j + 1) * DX} INF INF units box
group           fm{j} region fm{j}
group           wm{j} region wm{j}
group           fp{j} region fp{j}
group           wp{j} region wp{j}
compute         um{j} fm{j} reduce ave vx
compute         up{j} fp{j} reduce ave vx
variable        vm{j} equal -c_um{j}
variable        vp{j} equal -c_up{j}
fix             mvm{j} wm{j} move variable v_zero v_zero v_zero v_vm{j} v_zero v_zero
fix             mvp{j} wp{j} move variable v_zero v_zero v_zero v_vp{j} v_zero v_zero
"""
    inp = f"""
units           micro
atom_style      molecular
atom_modify     map array
boundary        p p p
fix             cell all property/atom rmass d_rho d_drho d2_cellref 3 ghost yes
region          box block 0 {NXZ} {-NW * DX} {L + NW * DX} 0 {NXZ} units box
create_box      2 box
lattice         sc {DX} origin 0.5 0.5 0.5
region          fl block INF INF 0 {L} INF INF units box
region          wall block INF INF 0 {L} INF INF side out units box
create_atoms    1 region fl
create_atoms    2 region wall
set             type 1*2 mol 1
set             type 1*2 mass {RHO0 * DX ** 3}
set             type 1*2 d_rho {RHO0}
group           fluid type 1
pair_style      cell/sph
pair_coeff      1 1 {RHO0} {C} {P0} {MU} {S}
pair_coeff      2 2 {RHO0} {C} {P0} {MU} {S}
comm_modify     vel yes
neighbor        0.3 bin
fix             nve fluid nve
fix             dens fluid cell/fluid Pi 0 Lp 0
{mirror}
variable        fx atom mass*{G}
fix             push fluid addforce v_fx 0.0 0.0
timestep        1e-4
compute         shear fluid cell/shear/atom
compute         ch fluid chunk/atom bin/1d y 0.0 {DX} units box
fix             prof fluid ave/chunk 100 20 4000 ch c_shear[1] c_shear[2] c_shear[3] c_shear[4] &
                file shear.dat format " %.12g"
run             6000
"""
    T.lmp(inp, cwd=d, nprocs=2)
    lines = [l for l in open(f"{d}/shear.dat") if not l.startswith("#")]
    n = int(lines[0].split()[1])
    tab = np.array([list(map(float, l.split())) for l in lines[-n:]])   # the last block
    tab = tab[(tab[:, 1] > 0) & (tab[:, 1] < L)]    # the fluid layers (the wall bins are empty)
    y, tau, txy, txz, tyz = tab[:, 1], tab[:, 3], tab[:, 4], tab[:, 5], tab[:, 6]
    exact = RHO0 * G * (L / 2 - y)
    wall = RHO0 * G * L / 2
    err = np.sqrt(np.mean((txy - exact) ** 2)) / np.sqrt(np.mean(exact ** 2))
    print(f"{'y':>6} {'tau_xy':>9} {'exact':>9}")
    for yy, t, e in zip(y, txy, exact):
        print(f"{yy:6.2f} {t:9.4f} {e:9.4f}")
    print(f"relative L2 {err:.4f}; max |tau_xz|, |tau_yz| {max(abs(txz).max(), abs(tyz).max()):.2e} "
          f"kPa; wall stress rho0 G L/2 = {wall:g} kPa")
    T.check("tau_xy = rho0 G (L/2 - y) within 1%", err < 0.01, f"{err:.2%}")
    T.check("tau_xz and tau_yz vanish", max(abs(txz).max(), abs(tyz).max()) < 0.02 * wall)
    T.check("|tau| = |tau_xy| (the only shear component)",
            np.allclose(tau, np.abs(txy), atol=0.02 * wall))
    T.finish()


if __name__ == "__main__":
    main()
