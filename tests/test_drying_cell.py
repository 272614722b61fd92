# SPDX-License-Identifier: GPL-2.0-or-later
"""A cell dried below zero turgor (docs/studies/drying-cell.md): the coarse cell (level 3) inflated
at Pi0 = -364 kPa by in.inflate, then in.water-potential with the solutes kept (Pi W = Pi0 W0) from
psi_ext = 0 to 2 Pi0 in steps of Pi0 / 2: (a) as the inputs run by default; (b) with the fluid's
adhesion to its own wall (-var Fa, its strength from the suction it must hold, the study) and the
artificial stress (-var sphstress 0.2). Asserted, per run:
1. the mass balance: the fluid mass at the end is W0 plus what fix cell/fluid took up (to round-off);
   no fluid particle outside its wall (compute cell/props leaks yes).
2. (a) below zero turgor the fluid does not pull on its wall (mean pressure ~0) and the wall stays
   put while the water leaves: the fault the features address; (b) the protoplasm holds its wall:
   the fluid goes into tension, in osmotic equilibrium P = psi_ext - Pi0 W0 / W, and the wall moves
   in with it.
3. Known gap, marked xfail (strict): (b) should follow Boyle-van 't Hoff with a slack wall (enclosed
   volume proportional to the water within 5%); the tether wall keeps its area and resists.
4. The slack wall: the membrane wall in tension-field theory (-var wall membrane, wrinkle yes: a
   compressed direction carries nothing) follows the water with the adhesion (m): at psi_ext =
   1.5 Pi0 (a third of the water gone) the enclosed volume within 5% of Boyle-van 't Hoff's (the
   issue's criterion; the study reads +2.8% there, the fluid's r0 contact layer) and the mean
   pressure near zero (the wrinkled wall takes the shrinking without a suction); without the
   adhesion (n) the same wall stays at its rest shape, far from it (more than 20% above).
5. Rehydration: (m) returned to pure water (in.water-potential -var psistart) takes back its water
   and turgor, the mass balance holding through the restart.
6. To 20% of the water (w): the same wall with the residual stiffness that keeps its triangles
   open (angle_coeff ... residual, Eq. M4) and the fluid's cohesion (pair_style cell/sph cohesion),
   at the level table's values, dried to 5 Pi0 in levels of Pi0/2: the run reaches the end (no
   triangle crushed; without the residual one is, on the way from 25% to 22% of the water, in the
   study's run of these levels) with the enclosed volume within 5% of Boyle-van 't Hoff's (the
   study reads -1.9%), the mass balance to round-off and no fluid outside the wall.
7. Continuous drying (in.water-potential at psi_ext -3000 kPa throughout, Lp 2e-4, to about 60% of
   the water) with the same wall and fluid: with an even share of the cell's flux (cp, share
   particle, Eq. 10 as written) the light particles of the contact layer dry first and the fluid
   reads a tension of hundreds of kPa that no slack wall can hold (the fault); with the flux
   shared by volume (cv, share volume, Eq. W5) that tension is at most a fifth of it and the
   enclosed volume stays within 5% of Boyle-van 't Hoff's at every record.
"""
import os

import numpy as np
import pytest

import lmptest as T
from cellmech import params

PI0 = -364.0
LEVEL = params.model_vars(3)
FA = params.LEVELS[3]["fa"]   # nN: Fa >= |P| A_c with margin 5 (docs/studies/drying-cell.md)
DRIVER = """include         ${dir}/in.water-potential
compute         leak all cell/props leaks yes
run             0
print           "BALANCE $(c_props[1][4]:%.17g) $(f_water[1]:%.17g) $(f_water[1][7]:%.17g) $(c_leak[1][9])"
"""


def dry(d, tag, **extra):
    """in.water-potential from 0 to 2 Pi0 (4 levels; extra -var settings may change them); the
    CSV's levels and the balance line."""
    base = dict(T.COARSE, delta=LEVEL["delta"], dp=LEVEL["dp"], dir=T.INPUTS, restart="inflated.restart",
                solute="yes", psiend=2 * PI0, nlevels=4, nsteps=4000, nave=1000, out=f"{tag}.csv")
    T.lmp(DRIVER, cwd=d, log=f"log.{tag}", variables=dict(base, **extra))
    a = np.genfromtxt(os.path.join(d, f"{tag}.csv"), delimiter=",", names=True)
    line = [ln for ln in open(os.path.join(d, f"log.{tag}")) if ln.startswith("BALANCE")][-1]
    M, U, W0, leaked = map(float, line.split()[1:])
    print(f"run {tag}: psi_ext  W/W0    P (kPa)  P_osm   V/V0    A/A0")
    for k in range(len(a)):
        w = a["water_pg"][k] / a["water_pg"][0]
        print(f"        {a['psi_ext_kPa'][k]:7.1f} {w:.4f} {a['turgor_kPa'][k]:8.2f} "
              f"{a['psi_ext_kPa'][k] - PI0 / w:8.2f} {a['volume_um3'][k] / a['volume_um3'][0]:.4f} "
              f"{a['area_um2'][k] / a['area_um2'][0]:.4f}")
    print(f"        balance: M - W0 - U = {M - W0 - U:.3g} pg of {W0:.6g}; leaked {leaked:g}")
    return a, (M, U, W0, leaked)


@pytest.fixture(scope="module")
def runs(rundir):
    T.inflate_coarse(rundir, nsteps=25000, every=5000)
    return {"a": dry(rundir, "a"), "b": dry(rundir, "b", Fa=FA, sphstress=0.2)}


def test_balance_and_no_leak(runs):
    for tag, (_, (M, U, W0, leaked)) in runs.items():
        # m += dm on 461 particles over 20000 steps: round-off a random walk of 1e-16 steps
        T.check(f"run {tag}: fluid mass = W0 + uptake (1e-12 of W0)", abs(M - W0 - U) < 1e-12 * W0,
                f"{M - W0 - U:.3g} pg")
        T.check(f"run {tag}: no fluid particle outside the wall", leaked == 0, f"{leaked:g}")


def below_zero_turgor(a):
    """The levels below zero turgor: where the osmotic equilibrium's P would be < 0 with the
    water of the first level at or below zero turgor (psi_ext = Pi0 has P > 0 at any W < W0)."""
    return a["psi_ext_kPa"] < PI0 - 1.0


def test_protoplasm_holds_its_wall(runs):
    a, _ = runs["a"]
    b, _ = runs["b"]
    below = below_zero_turgor(a)
    zt = np.argmax(a["psi_ext_kPa"] <= PI0)       # the level psi_ext = Pi0, just above zero turgor
    # (a) the fluid lets go: its mean pressure reads 0 (the noise of a level's mean, well under
    # 2 kPa) and the wall stays within 0.5% of its volume at zero turgor while 1/3 of the water goes
    Va = a["volume_um3"][below] / a["volume_um3"][zt]
    T.check("(a) below zero turgor the fluid pulls nothing (|P| < 2 kPa)",
            np.all(np.abs(a["turgor_kPa"][below]) < 2.0), f"{a['turgor_kPa'][below]}")
    T.check("(a) the wall stays put (V within 0.5% of zero turgor's)", np.all(np.abs(Va - 1) < 0.005),
            f"{Va}")
    # (b) the last level: tension in the fluid, in osmotic equilibrium (within 2% of Pi0: the
    # levels settle), and the wall pulled in by more than (a)'s band, 4x over
    wb = b["water_pg"][-1] / b["water_pg"][0]
    Pb, Posm = b["turgor_kPa"][-1], b["psi_ext_kPa"][-1] - PI0 / wb
    Vb = b["volume_um3"][-1] / b["volume_um3"][zt]
    T.check("(b) the fluid is in tension at 2 Pi0 (P < -10 kPa)", Pb < -10.0, f"P {Pb:.1f} kPa")
    T.check("(b) osmotic equilibrium P = psi - Pi0 W0/W (2% of Pi0)", abs(Pb - Posm) < 0.02 * abs(PI0),
            f"P {Pb:.1f} vs {Posm:.1f} kPa")
    T.check("(b) the wall moves in below zero turgor (V < 0.98 of zero turgor's)", Vb < 0.98,
            f"V/Vzt {Vb:.4f}")


@pytest.mark.xfail(strict=True, reason="the tether wall keeps its area and resists the suction "
                   "(docs/studies/drying-cell.md): the enclosed volume does not follow the water")
def test_volume_follows_water(runs):
    b, _ = runs["b"]
    below = below_zero_turgor(b)
    w = b["water_pg"][below] / b["water_pg"][0]
    v = b["volume_um3"][below] / b["volume_um3"][0]
    # Boyle-van 't Hoff with a slack wall: the enclosed volume follows the fluid's, V/V0 = W/W0
    assert np.all(np.abs(v / w - 1) < 0.05), f"V/V0 {v} vs W/W0 {w}"


@pytest.fixture(scope="module")
def membrane_runs(rundir):
    """A coarse cell with the membrane wall, inflated, then dried to 1.5 Pi0 with the wall in
    tension-field theory: with the adhesion (m) and without (n)."""
    d = os.path.join(rundir, "membrane")
    os.makedirs(d, exist_ok=True)
    T.coarse_cell(d)
    T.lmp(T.INPUTS + "/in.inflate", cwd=d, log="log.inflate", variables=dict(
        T.COARSE, dir=T.INPUTS, data="cell.data", nsteps=25000, every=5000, out="inflate.dat",
        restart_out="inflated.restart", wall="membrane"))
    wall = dict(wall="membrane", wrinkle="yes", psiend=1.5 * PI0, nlevels=3)
    m = dry(d, "m", Fa=FA, save=1, **wall)
    # (r) back to pure water from m's last state (in.water-potential -var psistart)
    back = dict(wall, restart="water-potential.restart", psistart=1.5 * PI0, psiend=0.0)
    lv = params.LEVELS[3]
    far = dict(wall, psiend=5 * PI0, nlevels=10, sphstress=0.2, sphcoh=lv["coh"], residual=lv["residual"])
    # continuous: psi_ext -3000 kPa from the start, ten records of 1000 steps
    cont = dict(wall, psistart=-3000.0, psiend=-3000.0, nlevels=9, nsteps=1000, nave=200, Lp=2e-4,
                sphstress=0.2, sphcoh=lv["coh"], residual=lv["residual"])
    return {"m": m, "r": dry(d, "r", Fa=FA, **back), "n": dry(d, "n", **wall), "w": dry(d, "w", Fa=FA, **far),
            "cp": dry(d, "cp", Fa=FA, share="particle", **cont), "cv": dry(d, "cv", Fa=FA, share="volume", **cont)}


def slack_reference(a):
    """A run's last W/W0 and V/V0, and Boyle-van 't Hoff's V/V0 with a slack wall: the fluid at
    P = 0 fills V = W / rho(0); V0 held it at the turgor's density, rho(P0) / rho(0) = (1 + P0 /
    B)^(1/7) (Tait, B = rho0 c^2 / 7)."""
    B = params.table()["rho0"] * params.table()["c"] ** 2 / 7.0
    w = a["water_pg"][-1] / a["water_pg"][0]
    return w, a["volume_um3"][-1] / a["volume_um3"][0], w * (1.0 + a["turgor_kPa"][0] / B) ** (1.0 / 7.0)


def test_slack_wall_follows_the_water(membrane_runs):
    m, (M, U, W0, leaked) = membrane_runs["m"]
    n, _ = membrane_runs["n"]
    T.check("(m) fluid mass = W0 + uptake (1e-12 of W0); nothing outside the wall",
            abs(M - W0 - U) < 1e-12 * W0 and leaked == 0, f"{M - W0 - U:.3g} pg, leaked {leaked:g}")
    w, v, ref = slack_reference(m)
    T.check("(m) at 1.5 Pi0 the enclosed volume follows Boyle-van 't Hoff (5%)", abs(v / ref - 1) < 0.05,
            f"V/V0 {v:.4f} vs {ref:.4f} ({v / ref - 1:+.2%}), W/W0 {w:.4f}")
    T.check("(m) the wrinkled wall needs no suction (|P| < 2 kPa)", abs(m["turgor_kPa"][-1]) < 2.0,
            f"P {m['turgor_kPa'][-1]:.2f} kPa")
    # without the adhesion the wall relaxes to its rest shape and stays there: far outside the 5%
    # (a third of the water gone leaves it about 45% above Boyle-van 't Hoff's volume)
    _, vn, refn = slack_reference(n)
    T.check("(n) without the adhesion the wall does not follow (V > 1.2 x Boyle-van 't Hoff's)",
            vn / refn > 1.2, f"V/V0 {vn:.4f} vs {refn:.4f} ({vn / refn - 1:+.1%})")


def test_dried_to_a_fifth_of_its_water(membrane_runs):
    w, (M, U, W0, leaked) = membrane_runs["w"]
    T.check("(w) fluid mass = W0 + uptake (1e-12 of W0); nothing outside the wall",
            abs(M - W0 - U) < 1e-12 * W0 and leaked == 0, f"{M - W0 - U:.3g} pg, leaked {leaked:g}")
    x, v, ref = slack_reference(w)
    T.check("(w) dried to 5 Pi0: the run reaches the last level", abs(w["psi_ext_kPa"][-1] - 5 * PI0) < 1e-6,
            f"last psi_ext {w['psi_ext_kPa'][-1]:.1f} kPa")
    T.check("(w) at 5 Pi0 (20% of the water) the enclosed volume follows Boyle-van 't Hoff (5%)",
            abs(v / ref - 1) < 0.05, f"V/V0 {v:.4f} vs {ref:.4f} ({v / ref - 1:+.2%}), W/W0 {x:.4f}, "
            f"P {w['turgor_kPa'][-1]:.1f} kPa, A/A0 {w['area_um2'][-1] / w['area_um2'][0]:.4f}")


def test_continuous_drying_shares_by_volume(membrane_runs):
    P = {}
    for tag in ("cp", "cv"):
        a, (M, U, W0, leaked) = membrane_runs[tag]
        T.check(f"({tag}) fluid mass = W0 + uptake (1e-12 of W0); nothing outside the wall",
                abs(M - W0 - U) < 1e-12 * W0 and leaked == 0, f"{M - W0 - U:.3g} pg, leaked {leaked:g}")
        gaps = [slack_reference(a[: k + 1]) for k in range(1, len(a))]
        worst = max((v / ref - 1 for _, v, ref in gaps), key=abs)
        P[tag] = a["turgor_kPa"][-1]
        print(f"({tag}) W/W0 {gaps[-1][0]:.4f}: P {P[tag]:.1f} kPa, V vs Boyle-van 't Hoff at the end "
              f"{gaps[-1][1] / gaps[-1][2] - 1:+.2%}, worst {worst:+.2%}")
        if tag == "cv":
            T.check("(cv) the enclosed volume within 5% of Boyle-van 't Hoff's at every record",
                    abs(worst) < 0.05, f"worst {worst:+.2%}")
    T.check("(cp) the even share holds a tension in the fluid (< -150 kPa): the fault", P["cp"] < -150.0,
            f"{P['cp']:.1f} kPa")
    T.check("(cv) shared by volume, the tension at most a fifth of (cp)'s", abs(P["cv"]) < 0.2 * abs(P["cp"]),
            f"{P['cv']:.1f} vs {P['cp']:.1f} kPa")


def test_rehydrated_cell_takes_back_water_and_turgor(membrane_runs):
    """Solutes kept and the wall elastic, pure water again is the turgid state again: the cell
    takes its water and turgor back (the levels settle to within about 1 kPa of the osmotic
    equilibrium: 1% of the turgor), the mass balance holds through the restart (fix cell/fluid's
    W0 and uptake come back with it). The wall's shape keeps some memory of the drying (the
    study: -1.9% of the volume at the same area), printed, not asserted."""
    m, _ = membrane_runs["m"]
    r, (M, U, W0, leaked) = membrane_runs["r"]
    T.check("(r) fluid mass = W0 + uptake through drying and rehydration (1e-12 of W0); nothing "
            "outside the wall", abs(M - W0 - U) < 1e-12 * W0 and leaked == 0,
            f"{M - W0 - U:.3g} pg, leaked {leaked:g}")
    w = r["water_pg"][-1] / m["water_pg"][0]
    P, P0 = r["turgor_kPa"][-1], m["turgor_kPa"][0]
    T.check("(r) in pure water again: turgor back within 1% and on the osmotic equilibrium "
            "-Pi0 W0 / W (1 kPa)", abs(P / P0 - 1) < 0.01 and abs(P + PI0 / w) < 1.0,
            f"P {P:.2f} vs {P0:.2f} kPa, -Pi0 W0/W {-PI0 / w:.2f}, W/W0 {w:.4f}")
    print(f"(r) shape: V/V0 {r['volume_um3'][-1] / m['volume_um3'][0]:.4f}, "
          f"A/A0 {r['area_um2'][-1] / m['area_um2'][0]:.4f}")


if __name__ == "__main__":
    import sys
    sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", __file__]))
