# SPDX-License-Identifier: GPL-2.0-or-later
"""pair cell/virtual's near list (src/cell_near_list.h): each triangle's contacts are looked for
only among the fluid that lay within r0 + skin of its barycentre at the last neighbour-list
build. The guarantee is LAMMPS's own (no atom moves more than half the skin between builds), so
after any number of steps the contacts must be those of a fresh search at the same positions. The
coarse cell with a fast fluid (thermal velocities of about 10 m/s, so that particles cross the
contact range between builds) runs 300 steps at two skins; the virtual particles' contact energy
(compute pair cell/virtual: the 8-4 energy of every contact, a function of the positions alone)
at its last step is then compared with that of `run 0` at the same positions, whose setup builds
every list anew and searches every triangle's whole list. A missed contact is missing its energy
(up to f0 r0 / 4 each, hundreds of nN um); a new build only reorders the sum, a round-off of about
1e-15 of it (asserted: 1e-9). A near list found without the skin's margin fails this (the test
was run so)."""
import lmptest as T

COARSE = dict(T.COARSE)
EXTRA = """
velocity        fluid create 1.0e12 4242 dist gaussian mom yes rot yes
compute         evirt all pair cell/virtual
thermo_style    custom step c_evirt
thermo_modify   format float %.17g
thermo          100
run             300
run             0
"""


def energy_at(log, step):
    """c_evirt of each thermo line of STEP in the log, in order."""
    return [float(ln.split()[1]) for ln in log.splitlines()
            if ln.split()[:1] == [str(step)] and len(ln.split()) == 2]


def test_near_list_keeps_every_contact(rundir):
    d = rundir
    T.coarse_cell(d)
    for skin in (0.3, 1.0):
        _, log = T.lmp(f"include {T.INPUTS}/in.inflate\n" + EXTRA, cwd=d, log=f"log.skin{skin}",
                       variables=dict(COARSE, dir=T.INPUTS, data="cell.data", nsteps=0, Lp=0.0,
                                      Pi=-364.0, skin=skin))
        builds = [int(ln.split()[-1]) for ln in log.splitlines() if ln.startswith("Neighbor list builds")]
        e_run, e_fresh = energy_at(log, 300)
        diff = abs(e_run - e_fresh) / abs(e_fresh)
        print(f"skin {skin}: {builds[-2]} builds in 300 steps; contact energy at step 300 {e_run:.17g} "
              f"nN um, after a fresh search {e_fresh:.17g}: {diff:.2e} of it")
        T.check(f"skin {skin}: the lists were rebuilt during the run (the fluid moves)", builds[-2] >= 3,
                f"{builds[-2]} builds")
        T.check(f"skin {skin}: the fluid touches the virtual particles", e_fresh > 0.0, f"{e_fresh:.4g}")
        T.check(f"skin {skin}: the contacts after 300 steps are a fresh search's", diff < 1e-9, f"{diff:.2e}")
