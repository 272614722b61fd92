# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 5, case 5: the membrane compression reference (tools/membrane.py) on its own limits.

The reference is an axisymmetric Neo-Hookean membrane of fixed contents squeezed between two
frictionless plates, solved by collocation with a slack (tension-field) centre of the contact disc
where the classical solution would compress it (docs/membrane.rst). Stiff cell: G t0 = 8e5 kPa *
0.126 um, R0 = 30 um (cellgen's unstressed radius). Checked, each error printed:
 (a) first contact: as eps -> 0 the solution tends to the Young-Laplace sphere (r_eq, p);
 (b) the enclosed volume, integrated from the shape, holds V0 (K = None) or follows
     V0 (1 - (p - P)/K);
 (c) the plate force F = p pi a^2 (the plate carries p over the whole contact disc, slack centre
     included) equals the force from virtual work, F = (dU - p dV)/dDeltaX with U the wall's
     strain energy: this holds only if every part of the solution, the free boundary of the slack
     disc included, is an equilibrium (Richardson-extrapolated central differences);
 (d) vertical balance of the upper half at the equator: F = p pi r_eq^2 - 2 pi r_eq T1(eq);
 (e) convergence of F at eps = 0.1 and 0.2 with the collocation tolerance;
 (f) F(0) = 0, F increasing, and the small-strain limit of a tensioned membrane pulled off a
     flat disc: eps = (a/R)^2 (ln(R/a) + C), i.e. d(eps R^2/a^2)/d ln(R/a) -> 1;
 (g) no compressive tension anywhere (admissible tension field), and where the slack centre starts.
Tolerances: the solver's (1e-7 residual) times the quantities' condition, stated at each check.
"""
import math
import sys
import time

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

import lmptest as T  # the check helper only: no LAMMPS run here
from cellmech import membrane as M

G_T0, R0 = T.STIFF["G"] * T.STIFF["t0"], T.CELL["R"]
K_FLUID = 7.0e4          # rho0 c^2 of the model's fluid (kPa)
VW_H = 1e-3              # strain step of the virtual-work differences (c)


def volume_by_quadrature(curve):
    """Enclosed volume from the converged shape: 2 * integral pi r^2 dz over the free meridian."""
    from scipy.integrate import simpson
    eps, slack, sol = curve.state
    thc = sol.p[1]
    tau = np.linspace(0.0, 1.0, 20001)
    l2, l1, psi = sol.sol(tau)[2:5]
    th = thc + (M.HALF_PI - thc) * tau
    r = np.sin(th) * l2
    return 2.0 * simpson(math.pi * r * r * l1 * np.sin(psi), x=th) * R0 ** 3


STRAINS = [0.0, 0.05, 0.1, 0.15, 0.2]
# the turgor series and the strains of each curve that the virtual-work check (c) differentiates at
VW_CASES = {364.0: (0.05, 0.15), 300.0: (), 30.0: (0.1,), 3.0: (0.1,)}
T_START = time.process_time()     # the module's CPU time, from its import (the last test)


def bond(lam):          # Eq. 19 bond energy per G t0 l0^2 / sqrt3 (physics/tether.h)
    return 0.5 * lam * lam - 0.75 + 0.25 * lam ** -4


def test_first_contact_is_young_laplace():
    print(f"stiff cell: G t0 = {G_T0:g} nN/um, R0 = {R0:g} um")
    # ---- (a) first contact -> Young-Laplace
    print("\n(a) eps -> 0: r_eq and p against the Young-Laplace sphere")
    for P in (364.0, 3.0):
        lam = M.young_laplace_stretch(P * R0 / G_T0)
        R_yl = lam * R0
        law = P * R_yl / 2.0 / (-G_T0 * math.expm1(-6.0 * math.log(lam))) - 1.0
        for e in (1e-6, 1e-5):
            d = M.compress_curve(G_T0, R0, P, [e])[0]
            er, ep = d["r_eq"] / R_yl - 1.0, d["p"] / P - 1.0
            print(f"  P {P:5g}  eps {e:.0e}  R_YL {R_yl:.6f}  r_eq {d['r_eq']:.6f} ({er:+.2e})  "
                  f"p {d['p']:.6f} ({ep:+.2e})  law residual {law:.1e}")
        # the perturbation of a point-like contact scales with eps (a^2 ~ eps R^2 / ln)
        # the law's residual is round-off: lam is stored to 1e-16 absolute, and the tension
        # 1 - lam^-6 ~ 6 (lam - 1) amplifies that by 1 / (lam - 1) (1.3e4 at 3 kPa)
        T.check(f"P {P:g}: eps = 1e-5 is the Young-Laplace sphere within 10 eps",
                abs(er) < 1e-4 and abs(ep) < 1e-4
                and abs(law) < 10 * sys.float_info.epsilon / (lam - 1.0),
                f"r_eq {er:+.1e}, p {ep:+.1e}, law {law:.1e}")


@pytest.fixture(scope="module")
def curves():
    """The curves of the turgor series: P -> (the curve, its states by strain)."""
    strains = STRAINS
    vw_cases = VW_CASES
    # ---- curves of the turgor series, with the checks along them; each continuation also
    # passes the strains e +- h, e +- h/2 that the virtual-work check (c) differentiates over
    curves = {}
    for P, vw in vw_cases.items():
        c = M.Curve(G_T0, R0, P)
        todo = sorted(set(strains) | {e + s * VW_H for e in vw for s in (-1, -0.5, 0.5, 1)})
        rows = {}
        for e in todo:
            d = c.zero_load() if e == 0.0 else c.dimensional(e, c.advance(e))
            if e > 0.0:
                d["V_quad"] = volume_by_quadrature(c)
            rows[e] = d
        curves[P] = (c, rows)
    return curves


def test_turgor_series_balances(curves):
    """(b) volume, (d) equatorial balance, (g) no compressive tension, (f) F increasing."""
    strains = STRAINS
    print("\nturgor series (stiff cell), F in nN (= 1e-3 uN)")
    print(f"{'P kPa':>6s} {'eps':>5s} {'F nN':>11s} {'p kPa':>9s} {'a um':>8s} {'a_slack':>8s} "
          f"{'r_eq um':>9s} {'(b) V err':>9s} {'(d) F_eq err':>12s} {'min T':>9s}")
    for P, (c, rows) in curves.items():
        rows = [rows[e] for e in strains]
        for d in rows:
            if d["eps"] == 0.0:
                continue
            ev = d["V_quad"] / d["V_target"] - 1.0
            ed = d["F_eq"] / d["F"] - 1.0
            mt = min(d["min_T_disc"], d["min_T_free"])
            print(f"{P:6g} {d['eps']:5.2f} {d['F']:11.5g} {d['p']:9.3f} {d['a']:8.4f} "
                  f"{d['a_slack']:8.4f} {d['r_eq']:9.4f} {ev:+9.1e} {ed:+12.1e} {mt:9.2e}")
            # collocation residual 1e-7 on O(1) states: the volume integral and the equatorial
            # balance inherit errors of that order
            T.check(f"(b) P {P:g} eps {d['eps']:.2f}: volume conserved", abs(ev) < 1e-6,
                    f"{ev:+.1e}")
            T.check(f"(d) P {P:g} eps {d['eps']:.2f}: equatorial balance", abs(ed) < 1e-6,
                    f"{ed:+.1e}")
            # (g) tensions >= 0 up to the tolerance times the tension scale G t0
            T.check(f"(g) P {P:g} eps {d['eps']:.2f}: no compressive tension",
                    mt > -1e-6 * G_T0, f"min {mt:.1e} nN/um")
        F = [d["F"] for d in rows]
        T.check(f"(f) P {P:g}: F(0) = 0 and F increasing", F[0] == 0.0 and np.all(np.diff(F) > 0),
                " ".join(f"{f:.4g}" for f in F))
        print(f"(g) P {P:g} kPa: slack centre from eps = {c.eps_slack:.5f}" if c.eps_slack else
              f"(g) P {P:g} kPa: no slack centre up to eps 0.2")


def test_slack_onset_decreases_with_turgor(curves):
    # slack onset falls with turgor: the prestretch that the flattening must undo shrinks
    onsets = [curves[P][0].eps_slack for P in (364.0, 300.0, 30.0, 3.0)]
    T.check("(g) slack onset decreases with turgor", all(o is not None for o in onsets)
            and np.all(np.diff(onsets) < 0), " ".join(f"{o:.5f}" for o in onsets))


def test_slack_centre_lowers_energy(curves):
    # the tension field relaxes the energy: at the same strain and volume the slack-centre state
    # stores less strain energy than the classical one, whose pole carries compression
    print("\n(g) strain energy: slack centre against the classical (compressed pole) branch, 364 kPa")
    cc = M.Curve(G_T0, R0, 364.0, tension_field=False)
    for e in (0.1, 0.15):
        dc = cc.dimensional(e, cc.advance(e))
        ds = curves[364.0][1][e]
        du = ds["U"] / dc["U"] - 1.0
        print(f"  eps {e:.2f}: classical pole stretch {dc['lam_inner']:.5f}, pole tension "
              f"{dc['min_T_disc']:.4g} nN/um, U {dc['U']:.8g}, F {dc['F']:.6g};  slack U "
              f"{ds['U']:.8g} ({du:+.2e}), F {ds['F']:.6g} ({ds['F'] / dc['F'] - 1:+.2%})")
        # energies are converged to ~1e-9 relative (e): the difference is far above that
        T.check(f"(g) eps {e:.2f}: slack centre has the lower energy", du < -1e-6, f"{du:+.1e}")


@pytest.fixture(scope="module")
def compressible():
    """(b) the 364 kPa curve with contents of bulk modulus K_FLUID: the curve and its states."""
    ck = M.Curve(G_T0, R0, 364.0, bulk_modulus=K_FLUID)
    krows = {}
    for e in sorted({0.1, 0.2} | {0.15 + s * VW_H for s in (-1, -0.5, 0, 0.5, 1)}):
        d = ck.dimensional(e, ck.advance(e))
        if e in (0.1, 0.2):
            d["V_quad"] = volume_by_quadrature(ck)
        krows[e] = d
    return ck, krows


def test_compressible_contents(curves, compressible):
    ck, krows = compressible
    print("\n(b) contents of bulk modulus K = 7e4 kPa: V against V0 (1 - (p - P)/K)")
    V0 = 4.0 / 3.0 * math.pi * ck.R_infl ** 3
    for e in (0.1, 0.2):
        d = krows[e]
        Vq = d["V_quad"]
        law = V0 * (1.0 - (d["p"] - 364.0) / K_FLUID)
        err = Vq / law - 1.0
        F_inc = curves[364.0][1][e]["F"]
        print(f"  eps {e:.1f}  p {d['p']:.3f}  V {Vq:.6g}  law {law:.6g} ({err:+.1e})  "
              f"V/V0 - 1 {Vq / V0 - 1:+.2e}  F {d['F']:.5g} (incompressible {F_inc:.5g})")
        T.check(f"(b) K: eps {e:.1f} volume follows the bulk modulus", abs(err) < 1e-6, f"{err:+.1e}")
        T.check(f"(b) K: eps {e:.1f} compressible contents are softer", d["F"] < F_inc,
                f"{d['F'] / F_inc - 1:+.2%}")


def test_virtual_work(curves, compressible):
    """(c) F = (dU - p dV) / dDeltaX, on the incompressible curves and the compressible one."""
    # ---- (c) virtual work: F = (dU - p dV) / dDeltaX
    print("\n(c) F = p pi a^2 against virtual work (dU - p dV)/dDeltaX, Richardson on h, h/2")
    _, krows = compressible
    cases = [(P, None, e, curves[P][1]) for P, vw in VW_CASES.items() for e in vw]
    for P, K, e, rows in cases + [(364.0, K_FLUID, 0.15, krows)]:
        est = []
        for h in (VW_H, 0.5 * VW_H):
            lo, hi = rows[e - h], rows[e + h]
            dX = 2.0 * lo["R_inflated"] * 2.0 * h
            est.append((hi["U"] - lo["U"] - rows[e]["p"] * (hi["V"] - lo["V"])) / dX)
        F = rows[e]["F"]
        Fw = (4.0 * est[1] - est[0]) / 3.0
        err = Fw / F - 1.0
        print(f"  P {P:5g} K {K}  eps {e:.2f} ({'slack' if rows[e]['slack'] else 'taut'})  "
              f"p pi a^2 {F:.8g}  work {Fw:.8g} ({err:+.1e}; central h, h/2: "
              f"{est[0] / F - 1:+.1e}, {est[1] / F - 1:+.1e})")
        # the central differences themselves shrink 4x per halving (O(h^2)); after Richardson
        # what is left is the energy's quadrature and solver error over dDeltaX ~ 1e-3 R
        T.check(f"(c) P {P:g} K {K} eps {e:.2f}: virtual work", abs(err) < 2e-5, f"{err:+.1e}")


def test_convergence_with_tolerance():
    # ---- (e) convergence with the collocation tolerance
    print("\n(e) F against the collocation tolerance: each state re-solved from a coarse guess")
    for P in (364.0, 3.0):
        c = M.Curve(G_T0, R0, P, tol=1e-5)
        for e in (0.1, 0.2):
            c.advance(e)
            prob = c.problem(e, c.state[1])
            sol0 = c.state[2]
            tau = np.linspace(0.0, 1.0, 101)
            res = {}
            for tol in (1e-5, 1e-6, 1e-7, 1e-9):
                s = M.solve(prob, tau, sol0.sol(tau), sol0.p, tol=tol)
                res[tol] = (M.describe(prob, s)["F"], len(s.x))
            ref = res[1e-9][0]
            errs = {tol: res[tol][0] / ref - 1.0 for tol in res}
            print(f"  P {P:5g} eps {e:.1f}: F(tol 1e-9) {ref * G_T0 * R0:.10g} nN; " + ", ".join(
                f"tol {tol:.0e}: {errs[tol]:+.1e} ({res[tol][1]} nodes)" for tol in (1e-5, 1e-6, 1e-7)))
            T.check(f"(e) P {P:g} eps {e:.1f}: F within 10 tol of the tol-1e-9 result",
                    all(abs(errs[tol]) < 10 * tol for tol in (1e-5, 1e-6, 1e-7)),
                    f"{max(abs(errs[tol]) for tol in (1e-5, 1e-6, 1e-7)):.1e}")


def test_pole_offset_negligible():
    # the classical branch's pole condition sits at POLE * theta_c
    keep = M.POLE
    f = []
    for pole in (1e-3, 1e-4):
        M.POLE = pole
        f.append(M.compress_curve(G_T0, R0, 364.0, [0.05])[0]["F"])
    M.POLE = keep
    err = f[0] / f[1] - 1.0
    print(f"  classical branch, P 364 eps 0.05: F with pole offset 1e-3 / 1e-4 theta_c: {err:+.1e}")
    T.check("(e) pole offset negligible", abs(err) < 1e-6, f"{err:+.1e}")


def test_small_strain_log_slope():
    # ---- (f) small-strain limit: outside a contact disc of radius a the wall is a membrane of
    # tension T0 = P R / 2 pulled by F = p pi a^2, slope F/(2 pi T0 r): the pole sinks by
    # (F/(2 pi T0)) ln(R/a) + O(a^2), so eps R^2/a^2 = ln(R/a) + C: unit slope in ln(R/a)
    print("\n(f) small strain: eps (R/a)^2 against ln(R/a)")
    for P in (364.0, 30.0):
        rows = M.compress_curve(G_T0, R0, P, [1e-6, 1e-5, 1e-4])
        R = rows[0]["R_inflated"]
        q = [(r["eps"] * (R / r["a"]) ** 2, math.log(R / r["a"])) for r in rows]
        slopes = [(q[i + 1][0] - q[i][0]) / (q[i + 1][1] - q[i][1]) for i in range(2)]
        print(f"  P {P:5g}: eps (R/a)^2 - ln(R/a) = " + ", ".join(f"{a - b:.5f}" for a, b in q)
              + f";  slopes {slopes[1]:.5f} (1e-4..1e-5), {slopes[0]:.5f} (1e-5..1e-6)")
        T.check(f"(f) P {P:g}: log slope -> 1", abs(slopes[0] - 1.0) < 1e-2
                and abs(slopes[0] - 1.0) < abs(slopes[1] - 1.0), f"{slopes[0]:.5f}")


def test_network_law():
    """(h) the network law: W the orientation average of the bond energy, its tensions W's
    derivatives, equibiaxially the Neo-Hookean law."""
    # ---- (h) material="network": the orientation-averaged tether network (Eq. 19 bonds)
    print("\n(h) network law: W against direct quadrature over bond directions, tensions, moduli")
    werr, terr = 0.0, 0.0
    for l1, l2 in ((1.1, 0.95), (1.3, 1.05), (0.9, 1.2)):
        Wq = 2.0 * quad(lambda ph: bond(math.hypot(l1 * math.cos(ph), l2 * math.sin(ph))),
                        0.0, 2.0 * math.pi, epsabs=1e-15, epsrel=1e-13)[0] / (2.0 * math.pi)
        werr = max(werr, abs(M.network_energy_density(l1, l2) - Wq))
        # T_i = (dW/dl_i) / l_j by central differences: O(h^2) ~ 1e-12, round-off 1e-16/h
        h = 1e-5
        W = M.network_energy_density
        T1 = (W(l1 + h, l2) - W(l1 - h, l2)) / (2 * h) / l2
        T2 = (W(l1, l2 + h) - W(l1, l2 - h)) / (2 * h) / l1
        d11 = (M.network_tensions(l1 + h, l2)[0] - M.network_tensions(l1 - h, l2)[0]) / (2 * h)
        d12 = (M.network_tensions(l1, l2 + h)[0] - M.network_tensions(l1, l2 - h)[0]) / (2 * h)
        Tn, dn = M.network_tensions(l1, l2), M.network_dtension1(l1, l2)
        terr = max(terr, abs(T1 - Tn[0]), abs(T2 - Tn[1]), abs(d11 - dn[0]), abs(d12 - dn[1]))
    print(f"  closed-form W vs quadrature: {werr:.1e};  T, dT1 vs differences of W, T: {terr:.1e}")
    T.check("(h) network W is the orientation average of the bond energy", werr < 1e-12,
            f"{werr:.1e}")
    T.check("(h) network tensions are W's derivatives", terr < 1e-8, f"{terr:.1e}")
    eq = max(abs(M.network_tensions(l, l)[0] / M.tensions(l, l)[0] - 1.0)
             for l in (1.0001, 1.01, 1.0303, 1.1, 1.25))
    l = 1.01
    print(f"  equibiaxial lam {l}: T/(G t0) Neo-Hookean {M.tensions(l, l)[0]:.15g}, network "
          f"{M.network_tensions(l, l)[0]:.15g}; max relative difference lam 1.0001..1.25 {eq:.1e}")
    # the two laws are the same function equibiaxially: round-off only (1 - lam^-6 cancels
    # ~ 1/(lam - 1) = 1e4 at lam 1.0001)
    T.check("(h) equibiaxial tension: network = Neo-Hookean", eq < 1e4 * 4 * sys.float_info.epsilon,
            f"{eq:.1e}")


def test_network_small_strain_moduli():
    e = 1e-4
    mu = {m: (law[0](1 + e, 1 - e)[0] - law[0](1 + e, 1 - e)[1]) / (4 * e)
          for m, law in M.MATERIALS.items()}
    # uniaxial: T2 = 0 sets the lateral stretch; E = T1 / e
    E = {}
    for m, law in M.MATERIALS.items():
        l2 = brentq(lambda x: law[0](1 + e, x)[1], 0.99, 1.0, xtol=1e-15)
        E[m] = law[0](1 + e, l2)[0] / e
    print(f"  small strain (e = 1e-4): shear modulus NH {mu['neohookean']:.8f}, network "
          f"{mu['network']:.8f} G t0; uniaxial modulus NH {E['neohookean']:.6f}, network "
          f"{E['network']:.6f} G t0 (triangular net: mu = sqrt3 k / 4, E = 2 k / sqrt3)")
    # pure shear is even in e: the deviation is O(e^2) = 1e-8; uniaxial is O(e) ~ 1e-3 relative
    T.check("(h) shear modulus 1.5 G t0 (network), G t0 (NH)",
            abs(mu["network"] - 1.5) < 1e-7 and abs(mu["neohookean"] - 1.0) < 1e-7,
            f"{mu['network'] - 1.5:+.1e}, {mu['neohookean'] - 1.0:+.1e}")
    T.check("(h) uniaxial modulus 4 G t0 (network), 3 G t0 (NH)",
            abs(E["network"] / 4.0 - 1.0) < 2e-3 and abs(E["neohookean"] / 3.0 - 1.0) < 2e-3,
            f"{E['network']:.5f}, {E['neohookean']:.5f}")


def test_network_compression(curves):
    print("\n(h) network compression, 364 kPa, incompressible: balances, tension field, virtual work")
    cn = M.Curve(G_T0, R0, 364.0, material="network")
    nrows = {}
    for e in sorted({0.1, 0.2} | {0.15 + s * VW_H for s in (-1, -0.5, 0, 0.5, 1)}):
        d = cn.dimensional(e, cn.advance(e))
        d["V_quad"] = volume_by_quadrature(cn)
        nrows[e] = d
    for e in (0.1, 0.15, 0.2):
        d = nrows[e]
        ev, ed = d["V_quad"] / d["V_target"] - 1.0, d["F_eq"] / d["F"] - 1.0
        mt = min(d["min_T_disc"], d["min_T_free"])
        Fnh = curves[364.0][1][e]["F"]
        print(f"  eps {e:.2f}: F {d['F']:.6g} nN (NH {Fnh:.6g}, {d['F'] / Fnh - 1:+.2%}), "
              f"V err {ev:+.1e}, F_eq err {ed:+.1e}, min T {mt:.2e}, a_slack {d['a_slack']:.3f}")
        T.check(f"(h) network eps {e:.2f}: volume, equatorial balance, no compression",
                abs(ev) < 1e-6 and abs(ed) < 1e-6 and mt > -1e-6 * G_T0,
                f"{ev:+.1e} {ed:+.1e} {mt:.1e}")
        # same equibiaxial law, stiffer in shear: the flattened wall needs more force
        T.check(f"(h) network eps {e:.2f}: stiffer than Neo-Hookean", d["F"] > Fnh,
                f"{d['F'] / Fnh - 1:+.2%}")
    print(f"  slack centre from eps {cn.eps_slack:.5f} (NH {curves[364.0][0].eps_slack:.5f})")
    e = 0.15
    est = []
    for h in (VW_H, 0.5 * VW_H):
        lo, hi = nrows[e - h], nrows[e + h]
        est.append((hi["U"] - lo["U"] - nrows[e]["p"] * (hi["V"] - lo["V"]))
                   / (2.0 * lo["R_inflated"] * 2.0 * h))
    Fw = (4.0 * est[1] - est[0]) / 3.0
    err = Fw / nrows[e]["F"] - 1.0
    print(f"  eps 0.15 (slack): p pi a^2 {nrows[e]['F']:.8g}, virtual work {Fw:.8g} ({err:+.1e}): "
          f"the slack edge lam1 = lam2 = 1 is the network energy's stationarity condition too")
    T.check("(h) network eps 0.15: virtual work", abs(err) < 2e-5, f"{err:+.1e}")


def test_cpu_time():
    """The module's checks run in under 60 s of CPU (the last test: T_START is its import)."""
    cpu = time.process_time() - T_START
    print(f"\nCPU time {cpu:.1f} s")
    T.check("runs in under 60 s of CPU", cpu < 60.0, f"{cpu:.1f} s")
