# SPDX-License-Identifier: GPL-2.0-or-later
"""The Poiseuille channel of test_poiseuille.py and test_shear.py (a fixture, not a test): SPH
fluid between lattice walls driven by a body force, units micro.
Fluid: rho0 = 1, mu = 1000 mPa s (nu = mu/rho0 = 1000 um^2/us), c = 10 um/us, P0 = 10 kPa,
s = 1.2 um on a dx = 1 um lattice; G = 2 um/us^2 along x; L = 20 um; dt 1e-4 us, 6000 steps."""
import lmptest as T

RHO0, MU, C, P0, S, DX = 1.0, 1000.0, 10.0, 10.0, 1.2, 1.0
NL, NW, NXZ = 20, 3, 6
G = 2.0
DT, NSTEPS, NBLOCK = 1e-4, 6000, 1000
L = NL * DX
NU = MU / RHO0


def channel_input(wall, extra=""):
    """LAMMPS input of the channel; `extra` goes in before the run (outputs of other tests)"""
    mirror = ""
    if wall == "mirror":
        for j in range(NW):
            lo = f"""
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
            mirror += lo
        mirror = "variable        zero equal 0.0\n" + mirror
    inp = T.SPH_BOX_HEAD + f"""
region          box block 0 {NXZ} {-NW * DX} {L + NW * DX} 0 {NXZ} units box
create_box      2 box
lattice         sc {DX} origin 0.5 0.5 0.5
region          fl block INF INF 0 {L} INF INF units box
region          wall block INF INF 0 {L} INF INF side out units box
create_atoms    1 region fl
create_atoms    2 region wall
""" + T.sph_box_fluid(RHO0, C, P0, MU, S, DX) + f"""
{mirror}
variable        fx atom mass*{G}
fix             push fluid addforce v_fx 0.0 0.0
timestep        {DT}
compute         ch fluid chunk/atom bin/1d y 0.0 {DX} units box
fix             prof fluid ave/chunk 10 {NBLOCK // 10} {NBLOCK} ch vx vy density/number &
                file prof.dat format " %.12g"
variable        drho atom abs(d_rho-{RHO0})
compute         rmax fluid reduce max v_drho
compute         vymax fluid reduce max vy
thermo_style    custom step time ke c_rmax c_vymax
thermo          1000
{extra}
run             {NSTEPS}
"""
    return inp
