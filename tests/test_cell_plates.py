# SPDX-License-Identifier: GPL-2.0-or-later
"""fix cell/plates (issue 12, target 3): the plates of Eq. 21 as fix wall/harmonic, whose force
under run_style respa on an inner level is the mean over the inner steps of each outer step.

An empty coarse wall (lammps-inputs/in.plates, no fluid) moves at 1 m/s onto the bottom plate,
both plates at rest (a moving plate is a function of *time*, which respa advances once per outer
step: the inner steps would then see another plate than Verlet's steps). Asserted:
 * under Verlet, cell/plates is fix wall/harmonic: the plate forces and the wall's momentum of
   every step are the same to the last bit (and with the moving top plate of in.plates);
 * under run_style respa 2 3 with every force on the inner level (tethers, 8-4 contacts and the
   plates, fix_modify respa 1), the outer level has no force, so the wall moves as under Verlet
   with the inner step (checked: its momentum, to round-off); cell/plates then reports at each
   outer step the mean of Verlet's plate forces over the three inner steps (1e-9 of the largest
   force), and fix wall/harmonic the last of them, which differs from the mean by a printed
   fraction of the force (the reason for the fix);
 * cell/plates on the outermost level under respa reports the force of its one call per step,
   k_p times the overlaps at the outer step's positions (1e-9);
 * the work of the moving top plate it sums (f_ID[4]) is the force times the plate's speed summed
   over the steps as an input would sum it with fix ave/time (1e-9 of it: the plate moves by
   exactly vplate dt a step, so the two differ by round-off), and the fixed plate's is zero.
"""
import numpy as np
import pytest

import lmptest as T

KP, GAP, V = 1.0e6, 0.2, 1.0


def run(d, tag, style, tail):
    """in.plates (0 steps) with its plates of `style`, then the commands of `tail`; the record of
    every step: t, Ftop, Fbot, the wall's z momentum, k_p times the overlaps with the bottom plate
    at the step's positions."""
    src = open(T.INPUTS + "/in.plates").read()
    key = "fix             plates wall cell/plates"
    assert src.count(key) == 1, "in.plates no longer defines its plates in one fix cell/plates"
    text = src.replace(key, f"fix             plates wall {style}") + f"""
variable        pz atom mass*vz
compute         pz all reduce sum v_pz
variable        dbot atom (z<v_zb)*(v_zb-z)
compute         sbot wall reduce sum v_dbot
variable        KPbot equal ${{kp}}*c_sbot
fix             rec2 all ave/time 1 1 1 v_t v_Ftop v_Fbot c_pz v_KPbot file {tag}.dat format " %.17g"
{tail}
"""
    path = f"{d}/in.plates-{tag}"
    with open(path, "w") as f:
        f.write(text)
    T.lmp(path, cwd=d, log=f"log.{tag}", variables=dict(
        dir=T.INPUTS, data="wall.data", nsteps=0, kp=KP, gap=GAP, vplate=V, dt=0.001, every=100))
    return T.load(f"{d}/{tag}.dat")[:, 1:6]


@pytest.fixture(scope="module")
def wall(rundir):
    T.cellgen("cell", "-o", "wall.data", "--level", 3, "--nfluid", 0, cwd=rundir)
    return rundir


def test_verlet_plates_match_wall_harmonic(wall):
    """Verlet, the moving top plate of in.plates: the same bits as fix wall/harmonic."""
    d = wall
    moving = "run 1200"
    a = run(d, "verlet-wh", "wall/harmonic", moving)
    b = run(d, "verlet-cp", "cell/plates", moving)
    T.check("the top plate reached the wall under Verlet", np.max(a[:, 1]) > 0, f"{np.max(a[:, 1]):.4g}")
    T.check("Verlet: cell/plates = fix wall/harmonic bit for bit (forces, momentum, every step)",
            a.shape == b.shape and np.array_equal(a, b))


def test_plates_work(wall):
    """The work the plates did, summed by the fix, against the same sum made by the input."""
    d = wall
    tail = """variable        dW equal v_Ftop*v_vplate*dt
fix             work all ave/time 1 1 1 v_dW ave running
variable        Win equal f_work*(step+1)
run             1200
print           "WORK ${Win} $(f_plates[4]:%.17g) $(f_plates[3]:%.17g)"
"""
    run(d, "work", "cell/plates", tail)
    line = [ln for ln in open(f"{d}/log.work") if ln.startswith("WORK ")][-1].split()
    w_input, w_top, w_bottom = (float(x) for x in line[1:4])
    err = abs(w_top - w_input) / abs(w_input)
    print(f"work of the moving top plate: summed by the fix {w_top:.10g} nN um, by the input "
          f"{w_input:.10g} ({err:.2e}); the fixed bottom plate's {w_bottom:g}")
    T.check("the top plate did work on the wall", w_input > 0, f"{w_input:.4g}")
    T.check("cell/plates sums the moving plate's work as the input does", err < 1e-9, f"{err:.2e}")
    T.check("the fixed plate does no work", w_bottom == 0.0, f"{w_bottom:g}")


def test_respa_plates_mean_over_inner_steps(wall):
    """Plates at rest, the wall thrown onto the bottom one, under Verlet and respa."""
    d = wall
    still = "variable ztop equal v_zt0\nvelocity wall set 0.0 0.0 -1.0\n"
    verlet = run(d, "still-verlet", "cell/plates", still + "run 1200")
    respa = "run_style respa 2 3 bond 1 angle 1 pair 1\nfix_modify plates respa 1\ntimestep 0.003\n"
    mean = run(d, "still-respa-cp", "cell/plates", still + respa + "run 400")
    last = run(d, "still-respa-wh", "wall/harmonic", still + respa + "run 400")
    outer = run(d, "still-respa-outer", "cell/plates",
                still + "run_style respa 2 3 bond 1 angle 1 pair 1\ntimestep 0.003\nrun 400")

    # Verlet records steps 0..1200, respa outer steps 0..400: outer step k covers Verlet steps
    # 3k-2, 3k-1, 3k
    Fv = verlet[1:, 2].reshape(-1, 3)
    scale = np.max(np.abs(verlet[:, 2]))
    T.check("the wall hit the bottom plate", scale > 0, f"largest force {scale:.4g} nN")
    pz_err = np.max(np.abs(mean[:, 3] - verlet[::3, 3])) / np.max(np.abs(verlet[:, 3]))
    print(f"respa, every force on the inner level: the wall's momentum against Verlet's, largest "
          f"difference {pz_err:.2e} of its largest")
    T.check("respa with no outer force moves the wall as Verlet with the inner step", pz_err < 1e-9,
            f"{pz_err:.2e}")
    err_mean = np.max(np.abs(mean[1:, 2] - Fv.mean(axis=1))) / scale
    err_last = np.max(np.abs(last[1:, 2] - Fv[:, 2])) / scale
    last_vs_mean = np.max(np.abs(last[1:, 2] - Fv.mean(axis=1))) / scale
    print(f"bottom plate force under respa 3, inner level: cell/plates against the mean of the "
          f"inner steps {err_mean:.2e}, fix wall/harmonic against the last inner step "
          f"{err_last:.2e}; wall/harmonic against the mean {last_vs_mean:.2%} of the largest force")
    T.check("cell/plates on the inner level reports the mean over the inner steps", err_mean < 1e-9,
            f"{err_mean:.2e}")
    T.check("fix wall/harmonic there reports the last inner step (what cell/plates corrects)",
            err_last < 1e-9 and last_vs_mean > 1e-3, f"{err_last:.2e}, {last_vs_mean:.2%}")
    # on the outermost level the plates act once per outer step, at the outer step's positions
    err_outer = np.max(np.abs(outer[:, 2] - outer[:, 4])) / max(np.max(np.abs(outer[:, 2])), 1e-300)
    T.check("cell/plates on the outer level reports its one call per step: k_p times the overlaps "
            "at the outer step's positions", np.max(outer[:, 2]) > 0 and err_outer < 1e-9,
            f"{err_outer:.2e}")
