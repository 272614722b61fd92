#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Report of the paper's experiments (tools/experiments.sh): plots, snapshot pictures, a table that
sets each result of docs/model.md section 4 beside ours, and the wall time of every run.

  report.py --run RUNDIR --res coarse|paper --report REPORTDIR [--fallback COARSE_RUNDIR]
  report.py --membrane MEMBRANE_RUNDIR --report REPORTDIR

Writes REPORTDIR/experiments.md and REPORTDIR/experiments/*.png. A run that is missing from RUNDIR
(not finished) is taken from --fallback when given, and marked so in the table. --membrane (alone,
or with --run) writes the section "Membrane wall" (walls.py): relaxation, impact and failure of a
WALL=membrane run beside the tether numbers of REPORTDIR/experiments.md and the paper's; a report
written again without it keeps the section it had.
"""
import argparse
import math
import os
import shutil

import numpy as np

from .. import params
from .. import reporting as rp
from ..launch import stage_times
from . import analyse as A
from . import walls

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MU = [1, 10, 100, 1000]
R0 = params.CELL["R"]
G_T0 = params.stiff()["G"] * params.stiff()["t0"]   # the stiff wall's G t0 (Table I)
# the stages of tools/experiments.sh, in its order
STAGES = (["inflate", "soft"] + [f"impact-{c}-{m}" for c in ("stiff", "soft") for m in MU]
          + [f"relax-stiff-{m}" for m in MU] + ["relax-stiff-zeta", "failure-qs", "failure-impact-1",
          "failure-impact-1000", "compress-0.5", "compress-0.25"] + [f"relax-soft-{m}" for m in (1, 10, 100)]
          + [f"turgor-{P}" for P in (300, 30, 3)] + ["compress-soft"])


class Runs:
    """Files of the run folder, with the fallback folder for what is missing."""

    def __init__(self, run, fallback):
        self.run, self.fallback = run, fallback
        self.used_fallback = set()
        self.partial = set()
        self.base = {}
        self.times = stage_times(run)
        self.fb_times = stage_times(fallback) if fallback else {}

    def ok(self, stage):
        return self.times.get(stage, (0, ""))[1] == "ok"

    @staticmethod
    def _usable(times, stage, partial):
        st = times.get(stage, (0, ""))[1]
        return st == "ok" or (partial and st.startswith("failed"))

    def group(self, stages, partial=False):
        """Take an experiment's runs all from this resolution when all of them finished (partial:
        or stopped with an error after writing data), else all from the fallback run when they
        finished there, so that one plot never mixes resolutions."""
        if all(self._usable(self.times, st, partial) for st in stages) or not self.fallback:
            base = self.run
        elif all(self._usable(self.fb_times, st, partial) for st in stages):
            base = self.fallback
        else:
            base = self.run
        for st in stages:
            self.base[st] = base
        return base

    def path(self, name, stage, partial=False):
        """Path of file `name` written by `stage`, from the folder its group chose (group()), if
        that stage finished there (or, with partial, stopped with an error after writing some)."""
        base = self.base.get(stage, self.run)
        times = self.times if base == self.run else self.fb_times
        p = os.path.join(base, name)
        if not (os.path.exists(p) and self._usable(times, stage, partial)):
            return None
        if base != self.run:
            self.used_fallback.add(stage)
        if not times.get(stage, (0, ""))[1] == "ok":
            self.partial.add(stage)
        return p

    def table(self, name, stage, partial=False):
        p = self.path(name, stage, partial)
        return A.load(p) if p else None

    def mark(self, *stages):
        m = ""
        fb = [st for st in stages if st in self.used_fallback]
        if fb:
            m += " (coarse)" if len(fb) == len(stages) else " (coarse: " + ", ".join(fb) + ")"
        stopped = [st for st in stages if st in self.partial]
        if stopped:
            m += " (stopped early: " + ", ".join(stopped) + ")"
        return m


run_setting = rp.run_setting
fmt = rp.fmt
pct = rp.change


def recorded(path, stage):
    """The effective settings of the run of `stage` that wrote the file `path`, as tools/experiments.sh
    recorded them beside it (settings.json, under the stage's log name); None for a run from before
    those records."""
    return params.recorded_settings(os.path.dirname(path), f"log.{stage}")


# the impact-zone shear stress the paper gives (kPa, at eps = 4%) per (cell, viscosity mPa s)
PAPER_TAU = {("stiff", 1): 0.25, ("stiff", 10): 2.45, ("stiff", 1000): 180.0}
FAILURES = (("qs", "failure-qs"), ("impact-1", "failure-impact-1"), ("impact-1000", "failure-impact-1000"))


class Report:
    """One experiments report being written: the runs (Runs), the rows of the table "Paper
    against ours" (experiment, paper, ours, difference, why), the lines of "Details", the figures,
    and the main numbers for the summary (key). Each experiment is a section in four steps: load
    its runs, measure, draw, write its rows."""

    def __init__(self, args):
        self.args = args
        self.R = Runs(args.run, args.fallback)
        self.figdir = os.path.join(args.report, "experiments")
        os.makedirs(self.figdir, exist_ok=True)
        self.settings_line, settings = rp.run_info(args.run)
        self.r0 = float(settings.get("r0", 1.6))
        self.rows, self.md, self.figs = [], [], []
        self.key = {}

    def fig(self, name, title):
        rp.save_figure(os.path.join(self.figdir, name), bbox_tight=True)
        self.figs.append((title, name))


def full_report(args):
    rep = Report(args)
    compression(rep)
    turgor(rep)
    relaxation(rep)
    impact(rep)
    failure(rep)
    write(rep)


# ------------------------------------------------------------ 1 quasistatic compression (Fig. 4)
def compression(rep):
    R = rep.R
    R.group(["compress-0.5", "compress-0.25"])
    c05, c025 = R.table("compress-0.5.dat", "compress-0.5"), R.table("compress-0.25.dat", "compress-0.25")
    if c05 is None:
        return
    plt.figure(figsize=(5.5, 4))
    for a, lab in ((c05, "0.5 m/s"), (c025, "0.25 m/s")):
        if a is not None:
            plt.plot(a[:, A.CMP["eps"]] * 100, a[:, A.CMP["fbot"]] / 1e3, label=f"bottom plate, {lab}")
    # the wall of the run (G t0): its record, else Table I's (a run from before the records)
    s = recorded(R.path("compress-0.5.dat", "compress-0.5"), "compress-0.5")
    F_mem20, F_net20 = membrane_reference(c05, s["G"] * s["t0"] if s else G_T0)
    plt.xlabel("strain eps = DeltaX / 2R (%)")
    plt.ylabel("plate force (uN)")
    plt.legend()
    plt.title("Quasistatic compression, stiff cell")
    rep.fig("fig4-compression.png", "Fig. 4: quasistatic compression at two plate speeds")
    if c025 is not None:
        dmax, drms = A.rate_difference(c05, c025)
        rep.key["rate"] = dmax
        rep.rows.append(("compression (Fig. 4): rate independence", "quasistatic (0.002 m/s)",
                         f"0.5 vs 0.25 m/s: largest difference {100*dmax:.1f}%, rms {100*drms:.1f}% "
                         f"(4%-wide windows at 6-18%){R.mark('compress-0.25')}",
                         "target <= 2%", "mean force of both plates per window (the discrete wall meets the plates ring by ring)"))
    F20 = A.window_mean(c05[:, A.CMP["eps"]], 0.5 * (c05[:, A.CMP["ftop"]] + c05[:, A.CMP["fbot"]]), 0.19, 0.01)[0]
    rep.key["F20"] = (F20, F_mem20, F_net20)
    rep.rows.append(("compression: force at eps = 19% (Fig. 4)", "follows the analytical membrane model and the tomato "
                     "cell to 20% strain",
                     f"{F20/1e3:.0f} uN at 0.5 m/s (mean of both plates over 18-20%){R.mark('compress-0.5')}; "
                     f"membrane theory (tools/membrane.py, same turgor and wall, same window) {F_mem20/1e3:.0f} uN "
                     f"(Neo-Hookean), {F_net20/1e3:.0f} uN (tether-network law)",
                     pct(F20, F_mem20) + " vs Neo-Hookean, " + pct(F20, F_net20) + " vs network law",
                     "the tethers of Eq. 19 on a triangular net have the Neo-Hookean sheet's "
                     "equibiaxial tension (inflation matches Young-Laplace) but 1.5x its shear "
                     "modulus (docs/membrane.rst): most of the gap; the paper gives its curves as a "
                     "figure only"))


def membrane_reference(c05, GT):
    """The membrane theory's compression curves (Neo-Hookean and the tether network's law) of a
    wall of G t0 = GT drawn into the current figure, and their forces at eps = 19% as the run sees
    them (nan, nan when the optional reference fails)."""
    F_mem20 = F_net20 = float("nan")
    try:
        from .. import membrane  # the independent membrane-theory reference
        # in.compress counts the strain from the plates' contact (eps < 0 while they close
        # their 0.2 um gaps), as the membrane model does
        Pturg = float(np.mean(c05[:3, A.CMP["p"]]))
        strains = np.linspace(0.0, 0.21, 43)
        e05 = c05[:, A.CMP["eps"]]

        def seen_as_sim(F):
            # the model through the simulation's window (its value at each record's strain,
            # averaged as the plate force is): a curved force's window mean is not its
            # value at the window's centre
            return A.window_mean(e05, np.interp(e05, strains, F), 0.19, 0.01)[0]
        # contents: the Tait fluid, bulk modulus rho0 c^2 = 7 kappa = 70 MPa
        cur = membrane.compress_curve(GT, R0, Pturg, strains, bulk_modulus=7.0e4)
        F = [c["F"] for c in cur]
        plt.plot(strains * 100, np.array(F) / 1e3, "k--", label="membrane theory (tools/membrane.py)")
        F_mem20 = seen_as_sim(F)
        # the same membrane with the tether network's own law (1.5x the Neo-Hookean shear
        # modulus, the same equibiaxial tension): what the discrete wall should follow
        cur = membrane.compress_curve(GT, R0, Pturg, strains, bulk_modulus=7.0e4,
                                      material="network")
        Fn = [c["F"] for c in cur]
        plt.plot(strains * 100, np.array(Fn) / 1e3, "k:", label="membrane, tether-network law")
        F_net20 = seen_as_sim(Fn)
    except Exception as e:  # the reference is optional
        print(f"report: membrane reference left out ({e.__class__.__name__}: {e})")
    return F_mem20, F_net20


# ------------------------------------------------------------ 2 turgor series (Fig. 5)
def turgor(rep):
    R = rep.R
    R.group([f"turgor-{P}" for P in (3, 30, 300)])
    tur = {P: R.table(f"turgor-{P}.dat", f"turgor-{P}") for P in (3, 30, 300)}
    tmark = R.mark(*[f"turgor-{P}" for P in (3, 30, 300)])
    if not any(v is not None for v in tur.values()):
        return
    plt.figure(figsize=(5.5, 4))
    f3, s1 = {}, {}
    for P, a in tur.items():
        if a is None:
            continue
        # in.compress's strain is 0 where both plates have closed their 0.2 um gaps
        e = a[:, A.CMP["eps"]]
        f = 0.5 * (a[:, A.CMP["ftop"]] + a[:, A.CMP["fbot"]])
        f3[P] = A.window_mean(e, f, 0.03, 0.005)[0]
        s1[P] = A.slope(a, 0.12, 0.2)
        plt.plot(e * 100, a[:, A.CMP["fbot"]] / 1e3, label=f"P = {P} kPa")
    plt.xlabel("strain (%)")
    plt.ylabel("bottom plate force (uN)")
    plt.legend()
    plt.title("Turgor series, stiff cell, 0.5 m/s")
    rep.fig("fig5-turgor.png", "Fig. 5: compression at turgor 3, 30, 300 kPa")
    order = " > ".join(f"{P}" for P in sorted(f3, key=lambda p: -f3[p]))
    rep.key["turgor_order"] = order
    rep.rows.append(("turgor (Fig. 5): small strain", "higher turgor stiffer; low-turgor slope ~0 at first",
                     "plate force 3% after contact: " + ", ".join(f"{P} kPa {f3[P]/1e3:.1f} uN" for P in sorted(f3))
                     + f"; order {order}" + tmark, "",
                     "small strain: the wall's pre-tension P R / 2 carries the load"))
    rep.rows.append(("turgor: large strain", "curves run parallel",
                     "slopes over eps 12-20% (uN per 1%): " +
                     ", ".join(f"{P} kPa {s1[P]/1e5:.2f}" for P in sorted(s1)) + tmark, "", ""))


# ------------------------------------------------------------ 3 relaxation (Fig. 6)
def relax_set(R, cell, cases):
    """{label: (table, relaxation measures, free cell's F_eq)} of the cell's releases."""
    out = {}
    for lab, stage in cases:
        a = R.table(f"relax-{cell}-{lab}.dat", stage)
        load = R.path(f"{cell}-compressed.restart.load.dat", stage)
        if a is None:
            continue
        # the free cell's equatorial force: before the plates touched (in.compress's record)
        f_inf = float("nan")
        if load:
            L = A.load(load)
            f_inf = float(np.mean(L[:5, A.CMP["feq"]]))
        out[lab] = (a, A.relaxation(a[:, A.REL["t"]], a[:, A.REL["feq"]], f_inf), f_inf)
    return out


def relaxation(rep):
    R = rep.R
    R.group([f"relax-stiff-{m}" for m in MU] + ["relax-stiff-zeta"])
    R.group([f"relax-soft-{m}" for m in (1, 10, 100)])
    stiff = relax_set(R, "stiff", [(str(m), f"relax-stiff-{m}") for m in MU] + [("zeta", "relax-stiff-zeta")])
    soft = relax_set(R, "soft", [(str(m), f"relax-soft-{m}") for m in (1, 10, 100)])
    for cell, S in (("stiff", stiff), ("soft", soft)):
        if S:
            relax_figure(rep, cell, S)
            relax_details(rep, cell, S)
    relax_rows(rep, stiff, soft)


def relax_figure(rep, cell, S):
    plt.figure(figsize=(6, 4))
    for lab, (a, r, finf) in S.items():
        name = "zeta = 1.1, 1 mPa s" if lab == "zeta" else f"{lab} mPa s"
        plt.plot(a[:, A.REL["t"]], a[:, A.REL["feq"]] / 1e3, label=name)
    finf = next(iter(S.values()))[2]
    if math.isfinite(finf):
        plt.axhline(finf / 1e3, color="k", lw=0.6, ls=":", label="free cell")
    plt.xlabel("time after release (us)")
    plt.ylabel("equatorial force (uN)")
    plt.legend(fontsize=8)
    plt.title(f"Relaxation, {cell} cell (released from 10% strain)")
    rep.fig(f"fig6-relax-{cell}.png", f"Fig. 6: relaxation of the {cell} cell")


def relax_details(rep, cell, S):
    rep.md.append(f"\n**Relaxation, {cell} cell** (initial deviation of F_eq from the free cell d0; t_first: "
                  "first time the deviation falls below d0/e; tau_e: from then on for good (envelope); "
                  "tau_fit: exponential fit of the envelope; offset: where the cell still swings about, "
                  "relative to d0; period from the sign changes about that centre):\n")
    rep.md.append("| case | d0 (uN) | t_first (us) | tau_e (us) | tau_fit (us) | offset | period (us) | "
                  "sign changes | regime |")
    rep.md.append("|---|---|---|---|---|---|---|---|---|")
    for lab, (a, r, finf) in S.items():
        regime = "oscillating" if r["crossings"] >= 2 else "overdamped"
        rep.md.append(f"| {lab} {'' if lab == 'zeta' else 'mPa s'} | {r['d0']/1e3:.3g} | {fmt(r['t_first'])} | "
                      f"{fmt(r['tau_e'])}{' (record too short)' if not math.isfinite(r['tau_e']) else ''} | "
                      f"{fmt(r['tau_fit'])}{' (extrapolated)' if r['extrapolated'] else ''} | "
                      f"{r['centre']/r['d0']:+.2f} | {fmt(r['period'])} | {r['crossings']} | {regime} |")


def relax_rows(rep, stiff, soft):
    R, rows = rep.R, rep.rows
    smark = R.mark(*[f"relax-stiff-{m}" for m in MU], "relax-stiff-zeta")
    softmark = R.mark(*[f"relax-soft-{m}" for m in (1, 10, 100)])
    if "1" in stiff:
        r = stiff["1"][1]
        rep.key["period"] = r["period"]
        rows.append(("relaxation stiff, 1 mPa s (Fig. 6a)", "relaxes in ~1 us, then oscillates, period < 1 us",
                     f"t_first {fmt(r['t_first'])} us, period {fmt(r['period'])} us, envelope to 1/e "
                     f"(tau_e) {fmt(r['tau_e'])} us" + R.mark("relax-stiff-1"),
                     pct(r["t_first"], 1.0) + " (t_first); period " + pct(r["period"], 1.0),
                     "the oscillation is the cell's shape mode (prolate-oblate), lightly damped at 1 mPa s; why "
                     "its period is longer than the paper's is not established"))
        osc = [m for m in MU if str(m) in stiff and stiff[str(m)][1]["crossings"] >= 2]
        od = [m for m in MU if str(m) in stiff and stiff[str(m)][1]["crossings"] < 2]
        rows.append(("relaxation stiff: overdamped above", "~0.5 Pa s",
                     f"oscillating at {osc} mPa s, overdamped at {od} mPa s" + smark, "", ""))
    if "zeta" in stiff:
        r = stiff["zeta"][1]
        rows.append(("relaxation stiff, zeta = 1.1 wall", "damped, shown in Fig. 6a",
                     f"tau_e {fmt(r['tau_e'])} us, {r['crossings']} crossings" + R.mark("relax-stiff-zeta"), "", ""))
    if "1" in soft:
        r = soft["1"][1]
        rows.append(("relaxation soft, 1 mPa s (Fig. 6b)", "30 us",
                     f"t_first {fmt(r['t_first'])} us, tau_e {fmt(r['tau_e'])} us, tau_fit {fmt(r['tau_fit'])} us"
                     + R.mark("relax-soft-1"), pct(r["t_first"], 30.0) + " (t_first)", ""))
        osc = [m for m in (1, 10, 100) if str(m) in soft and soft[str(m)][1]["crossings"] >= 2]
        od = [m for m in (1, 10, 100) if str(m) in soft and soft[str(m)][1]["crossings"] < 2]
        rows.append(("relaxation soft: overdamped near", "10 mPa s",
                     f"oscillating at {osc} mPa s, overdamped at {od} mPa s" + softmark, "", ""))
        rows.append(("relaxation soft, 1 Pa s", "about 5 ms", "not run",
                     "", "5 ms is 2.5 million steps of 2 ns (the acoustic limit 0.25 s/c = 3 ns)"))


# ------------------------------------------------------------ 4 impact (Figs. 7-10)
def impact(rep):
    imp, tau = impact_load(rep.R)
    if not imp:
        return
    shear_figure(rep, tau)
    for cell, qs_name, qs_stage, figname in (("stiff", "compress-0.5.dat", "compress-0.5", "fig9"),
                                              ("soft", "compress-soft.dat", "compress-soft", "fig10")):
        transmitted(rep, imp, cell, qs_name, qs_stage, figname)
    shear_rows(rep, tau)
    impact_details(rep, imp, tau)
    snapshots(rep)


def impact_load(R):
    """The impact tables {(cell, mu): table} and the impact-zone shear stress {(cell, mu, eps %)}."""
    tau, imp = {}, {}
    for cell in ("stiff", "soft"):
        R.group([f"impact-{cell}-{m}" for m in MU], partial=True)
    R.group(["compress-soft"])
    for cell in ("stiff", "soft"):
        for m in MU:
            a = R.table(f"impact-{cell}-{m}.dat", f"impact-{cell}-{m}", partial=True)
            if a is None or len(a) < 2:
                continue
            imp[(cell, m)] = a
            tau[(cell, m, 4)] = A.impact_shear(a, 0.04)[0]
            tau[(cell, m, 10)] = A.impact_shear(a, 0.10)[0]
    return imp, tau


def shear_figure(rep, tau):
    plt.figure(figsize=(5.5, 4))
    for cell, mk in (("stiff", "o-"), ("soft", "s-")):
        for e in (4, 10):
            ms = [m for m in MU if (cell, m, e) in tau]
            if ms:
                plt.loglog(ms, [tau[(cell, m, e)] * 1e3 for m in ms], mk, mfc="none" if e == 10 else None,
                           label=f"{cell}, eps = {e}%")
    pm = [1, 10, 1000]
    plt.loglog(pm, [PAPER_TAU[("stiff", m)] * 1e3 for m in pm], "k*", ms=10, label="paper, stiff, 4%")
    mm = np.array([1, 1000.0])
    if ("stiff", 1, 4) in tau:
        plt.loglog(mm, tau[("stiff", 1, 4)] * 1e3 * mm, "k:", lw=0.8, label="linear in mu")
    plt.xlabel("viscosity (mPa s)")
    plt.ylabel("mean shear stress in the impact zone (Pa)")
    plt.legend(fontsize=8)
    plt.title("Impact at 5 m/s: protoplasm shear stress")
    rep.fig("fig8-shear.png", "Impact-zone shear stress against viscosity (Sec. III C)")


def transmitted(rep, imp, cell, qs_name, qs_stage, figname):
    """Fig. 9/10: the force the cell passes to the bottom plate under impact beside the quasistatic
    one, and its row."""
    R = rep.R
    ms = [m for m in MU if (cell, m) in imp]
    if not ms:
        return
    plt.figure(figsize=(5.5, 4))
    for m in ms:
        a = imp[(cell, m)]
        plt.plot(a[:, A.IMP["eps"]] * 100, a[:, A.IMP["fbot"]] / 1e3, label=f"{m} mPa s")
    q = R.table(qs_name, qs_stage)
    if q is not None:
        plt.plot(q[:, A.CMP["eps"]] * 100, q[:, A.CMP["fbot"]] / 1e3, "k--", label="quasistatic")
    plt.xlabel("strain (%)")
    plt.ylabel("transmitted force, bottom plate (uN)")
    plt.xlim(0, 25)
    plt.legend(fontsize=8)
    plt.title(f"Impact at 5 m/s, {cell} cell")
    rep.fig(f"{figname}-transmitted-{cell}.png", f"{'Fig. 9' if cell == 'stiff' else 'Fig. 10'}: "
            f"transmitted force, {cell} cell, beside the quasistatic curve")
    if q is None or (cell, 1) not in imp:
        return
    tr = A.transmitted(imp[(cell, 1)], q)
    level, lg, e_hi, fi, fq = tr["level"], tr["lag"], tr["eps"], tr["f_imp"], tr["f_qs"]
    rep.rows.append((f"impact {cell}: transmitted force (Fig. {9 if cell == 'stiff' else 10})",
                     "lags, then exceeds the quasistatic force",
                     f"1 mPa s: reaches {level:.3g} nN (20% of the largest quasistatic force) "
                     f"{100*lg:+.1f}% strain later than quasistatic; mean over eps = {100*e_hi:.0f}+-1%: "
                     f"impact {fi:.3g} nN, quasistatic {fq:.3g} nN"
                     + R.mark(f"impact-{cell}-1", qs_stage), "",
                     "" if cell == "stiff" else "the soft cell spreads sideways under the impacting plate "
                     "and hardly loads the bottom plate (Fig. 7 pictures)"))


def shear_rows(rep, tau):
    R, rows = rep.R, rep.rows
    for (cell, m), pv in PAPER_TAU.items():
        if (cell, m, 4) in tau:
            rows.append((f"impact {cell}, {m} mPa s: shear stress at eps = 4%", f"{pv*1e3:.0f} Pa",
                         f"{tau[(cell, m, 4)]*1e3:.0f} Pa (10%: {tau[(cell, m, 10)]*1e3:.0f} Pa)"
                         + R.mark(f"impact-{cell}-{m}"), pct(tau[(cell, m, 4)], pv),
                         "zone: the fluid within 12 um of the plate (the paper: 'about one fifth of the cell "
                         "area'); Eq. 25 without kernel correction at the wall" +
                         ("; below linear in mu, as in the paper" if m == 1000 else "")))
    if ("stiff", 1, 4) in tau:
        rep.key["tau1"] = tau[("stiff", 1, 4)]
    if ("stiff", 1, 4) in tau and ("stiff", 10, 4) in tau:
        rows.append(("impact stiff: linear at low viscosity", "tau(10)/tau(1) = 9.8",
                     f"{tau[('stiff', 10, 4)]/tau[('stiff', 1, 4)]:.1f}", "", ""))
    for cell in ("soft",):
        if (cell, 1, 4) in tau:
            rows.append(("impact soft: shear stresses at eps = 4%", "same range as the stiff cell",
                         ", ".join(f"{m} mPa s {tau[(cell, m, 4)]*1e3:.0f} Pa" for m in MU if (cell, m, 4) in tau)
                         + R.mark(*[f"impact-soft-{m}" for m in MU]), "", ""))


def impact_details(rep, imp, tau):
    stopped = [f"{c} {m} mPa s (at eps = {100*imp[(c, m)][-1, A.IMP['eps']]:.0f}%)" for (c, m) in imp
               if f"impact-{c}-{m}" in rep.R.partial]
    md = rep.md
    md.append("\n**Impact-zone shear stress (Pa)** at eps = 4% and 10% (mean over eps +- 0.5%)"
              + (f"; runs that stopped with an error before eps = 25%: {', '.join(stopped)} "
                 "(see the notes)" if stopped else "") + ":\n")
    md.append("| cell | " + " | ".join(f"{m} mPa s 4% / 10%" for m in MU) + " |")
    md.append("|---|" + "---|" * len(MU))
    for cell in ("stiff", "soft"):
        md.append(f"| {cell} | " + " | ".join(
            f"{tau[(cell, m, 4)]*1e3:.0f} / {tau[(cell, m, 10)]*1e3:.0f}" if (cell, m, 4) in tau else "n/a"
            for m in MU) + " |")


def snapshots(rep):
    """Fig. 7: the runs' own pictures at eps = 25%, copied."""
    for cell in ("stiff", "soft"):
        for m in MU:
            p = rep.R.path(f"impact-{cell}-{m}.png", f"impact-{cell}-{m}")
            if p:
                shutil.copy(p, os.path.join(rep.figdir, f"fig7-{cell}-{m}.png"))
    rep.figs.append(("Fig. 7: snapshots at eps = 25% (half cell cut at y = centre, fluid coloured by shear "
                     "stress from blue (0) to red (the variable taumax of in.impact, in kPa: 0.04 mu v by default, 0.1 mu v in "
                     "runs made before that default); wall nodes grey; stiff then soft, 1, 10, 100, 1000 mPa s; a run "
                     "that stopped early has no picture)",
                     [f"fig7-{c}-{m}.png" for c in ("stiff", "soft") for m in MU
                      if os.path.exists(os.path.join(rep.figdir, f"fig7-{c}-{m}.png"))]))


# ------------------------------------------------------------ 5 failure (Fig. 11)
def failure(rep):
    R = rep.R
    fres = {}
    R.group(["failure-qs"])
    R.group(["failure-impact-1", "failure-impact-1000"])
    for lab, stage in FAILURES:
        p = R.path(f"failure-{lab}.dat", stage)
        if p:
            fres[lab] = failure_measure(R, lab, stage, p, rep.r0)
            failure_pictures(rep, lab, p)
    if fres:
        crack_figure(rep, fres)
        failure_details(rep, fres)
        failure_rows(rep, fres)


def failure_measure(R, lab, stage, p, r0, dt=0.001):
    """What analyse.failure measures, with the pressure before the break, the Bernoulli speed at
    it, and the fluid outside the wall before the break and at the end."""
    # the time step and the escape margin (the fluid-wall contact distance r0) of the run the file
    # comes from: its record (tools/experiments.sh, settings.json); a run from before the records
    # has run-info.txt's r0 (else the report's) and dt, in.failure's time step then
    s = recorded(p, stage) or dict(r0=run_setting(os.path.dirname(p), "r0", r0), dt=dt)
    f = A.failure(p, p[:-4] + ".dump", float(s["dt"]), float(s["r0"]))
    a = A.load(p)
    i = np.nonzero(a[:, A.IMP["nbroken"]] > 0)[0]
    # Bernoulli speed of the fluid leaving through an opening at the pressure before the break
    f["p_f"] = float(a[max(i[0] - 1, 0), A.IMP["p"]]) if len(i) else float("nan")
    f["v_bernoulli"] = math.sqrt(2.0 * f["p_f"] * 1e3 / 1e3) if f["p_f"] > 0 else float("nan")
    lk = R.path(f"failure-{lab}.dat.leaks", stage)
    if lk:
        L = A.load(lk)
        before = L[L[:, 3] == 0]
        f["leak_before"] = int(before[:, 4].max()) if len(before) else 0
        f["leak_end"] = int(L[-1, 4])
    return f


def failure_pictures(rep, lab, p):
    """The run's pictures: the last one before the first break, the first two after it, and the end."""
    a = A.load(p)
    i = np.nonzero(a[:, A.IMP["nbroken"]] > 0)[0]
    step_f = int(a[i[0], 0]) if len(i) else None
    imgs = sorted((int(k.split(".")[-2]), k) for k in os.listdir(os.path.dirname(p))
                  if k.startswith(f"failure-{lab}.") and k.endswith(".png") and k.split(".")[-2].isdigit())
    if step_f is None or not imgs:
        return
    before = [k for st, k in imgs if st < step_f][-1:]
    after = [k for st, k in imgs if st >= step_f][:2]
    pick = before + after + [f"failure-{lab}-end.png"]
    for k in pick:
        if os.path.exists(os.path.join(os.path.dirname(p), k)):
            shutil.copy(os.path.join(os.path.dirname(p), k), os.path.join(rep.figdir, k))


def crack_figure(rep, fres):
    plt.figure(figsize=(6, 4))
    for lab, f in fres.items():
        if f.get("course"):
            c = np.array(f["course"])
            plt.plot(c[:, 0], c[:, 2], "-", label=f"{lab}: lowest latitude")
            plt.plot(c[:, 0], c[:, 3], "--", label=f"{lab}: highest latitude")
    plt.xlim(0, 1.0)     # the crack runs within a few tenths of a microsecond
    plt.xlabel("time after the first broken tether (us)")
    plt.ylabel("latitude of broken-tether nodes (deg)")
    plt.legend(fontsize=7)
    plt.title("Crack course (0 = equator, +90 = impacting/top plate)")
    rep.fig("fig11-crack.png", "Fig. 11: how the crack runs")


def failure_details(rep, fres):
    md = rep.md
    md.append("\n**Failure** (lamf = 1.04):\n")
    md.append("| run | eps_f | first broken nodes: mean latitude (range) | span after 0.2 us, "
              "speed of its ends | broken tethers at end | 90% of them after | fluid outside before / at end | "
              "escaping fluid median / 90th pct speed |")
    md.append("|---|---|---|---|---|---|---|---|")
    for lab, f in fres.items():
        lr = f.get("lat_first_range")
        md.append(f"| {lab} | {100*f['eps_f']:.1f}% | {fmt(f.get('lat_first_mean'))} deg "
                  f"({fmt(lr[0]) if lr else 'n/a'} to {fmt(lr[1]) if lr else 'n/a'}) | "
                  + (f"{f['span_02'][0]:.0f} to {f['span_02'][1]:.0f} deg, {f['crack_speed']:.0f} m/s | "
                     if "span_02" in f else "n/a | ")
                  + f"{f.get('n_final', 'n/a')} | "
                  f"{fmt(f.get('t_90'))} us | {f.get('leak_before', 'n/a')} / {f.get('leak_end', 'n/a')} | "
                  f"{fmt(f.get('jet_median'))} / {fmt(f.get('jet_p90'))} m/s |")


def failure_rows(rep, fres):
    R, rows = rep.R, rep.rows
    if "qs" in fres:
        f = fres["qs"]
        rep.key["eps_f"] = f["eps_f"]
        rows.append(("failure, quasistatic: strain", "eps_f ~ 14%", f"{100*f['eps_f']:.1f}%" + R.mark("failure-qs"),
                     pct(100 * f["eps_f"], 14.0), "the strain at which the largest tether stretch reaches "
                     "lamf: a local quantity, set by how the discrete wall meets the plate edge"))
        rows.append(("failure, quasistatic: origin", "near the equator, runs to the poles in < 0.5 us",
                     f"first broken nodes at latitude {fmt(f.get('lat_first_mean'))} deg; "
                     # a run without its dump (a short test run) has no crack to follow
                     + (f"after 0.2 us the crack spans {f['span_02'][0]:.0f} to {f['span_02'][1]:.0f} deg "
                        f"({f['crack_speed']:.0f} m/s); " if "span_02" in f else "crack not followed (no dump); ")
                     + f"90% of the final breaks within {fmt(f.get('t_90'))} us" + R.mark("failure-qs"), "",
                     ("starts near the equator, as in the paper" if abs(f.get("lat_first_mean", 90)) < 20 else
                      "starts between the equator and a plate's contact edge, where the discrete wall bends "
                      "over the plate edge (likely: the largest tether stretch there); it then runs along a "
                      "meridian (hoop tension, as the paper explains)")))
        rows.append(("failure, quasistatic: fluid jet", "~3 m/s",
                     f"median {fmt(f.get('jet_median'))} m/s, 90th percentile {fmt(f.get('jet_p90'))} m/s"
                     + R.mark("failure-qs"),
                     pct(f.get("jet_median", float("nan")), 3.0),
                     f"the fluid outside the wall (see notes); the paper does not say how it measured; the "
                     f"Bernoulli speed sqrt(2 P / rho) at the {fmt(f['p_f'])} kPa before the break, "
                     f"{fmt(f['v_bernoulli'])} m/s, bounds it"))
    for m, pv in ((1, 7.0), (1000, 10.0)):
        if f"impact-{m}" in fres:
            f = fres[f"impact-{m}"]
            rows.append((f"failure, impact {m} mPa s", f"eps_f ~ {pv:.0f}%, near the plate",
                         f"{100*f['eps_f']:.1f}%, first broken nodes at latitude {fmt(f.get('lat_first_mean'))} deg"
                         + R.mark(f"failure-impact-{m}"), pct(100 * f["eps_f"], pv), ""))


# ------------------------------------------------------------ write
def write(rep):
    args, R = rep.args, rep.R
    times, total = wall_times(R)
    L = [f"# The paper's experiments ({args.res} resolution)\n", summary(rep, total) + "\n"]
    L.append(rp.generated_by("RES=" + args.res + " bash tools/experiments.sh",
                             "tools/cellmech/experiments/report.py") + ". "
             "Run settings: `" + rep.settings_line + "`.\n")
    if R.used_fallback:
        L.append("Runs that had not finished at this resolution when the report was written are taken from "
                 "the coarse run and marked *(coarse)*: " + ", ".join(sorted(R.used_fallback)) + ".\n")
    L.append("## Paper against ours\n")
    L += rp.table(["experiment", "paper (docs/model.md sec. 4)", "ours", "difference", "why / note"], rep.rows)
    L.append("\n## Details\n")
    L += rep.md
    L.append("\n## Plots and pictures\n")
    L += figure_lines(rep)
    L.append("\n## Wall time of each run\n")
    L += times
    L.append(rp.read_text(os.path.join(os.path.dirname(os.path.abspath(__file__)), "notes.md")))
    path = os.path.join(args.report, "experiments.md")
    # the other wall's section is made from other runs: keep it
    kept = {w: walls.section_of(path, walls.title_of(w)) for w in walls.WALLS}
    rp.write_lines(path, L)
    for w, lines in kept.items():
        if lines:
            walls.splice(path, lines, title=walls.title_of(w))
    print(f"report: {os.path.join(args.report, 'experiments.md')}")


def figure_lines(rep):
    L = []
    for title, name in rep.figs:
        if isinstance(name, list):
            L.append(f"**{title}**\n")
            L.append(" ".join(f"![{n}](experiments/{n})" for n in name) + "\n")
        else:
            L.append(f"**{title}**\n\n![{title}](experiments/{name})\n")
    for lab, _ in FAILURES:
        imgs = sorted(k for k in os.listdir(rep.figdir) if k.startswith(f"failure-{lab}.") and k.endswith(".png"))
        imgs = sorted(imgs, key=lambda k: int(k.split(".")[-2])) + (
            [f"failure-{lab}-end.png"] if os.path.exists(os.path.join(rep.figdir, f"failure-{lab}-end.png")) else [])
        if imgs:
            L.append(f"**Fig. 11: failure, {lab}** (whole cell seen from -y; fluid coloured by speed, blue 0 to "
                     "red 5 m/s; the last picture before the first broken tether, the next two, and the end of "
                     "the run; file names give the step): " + " ".join(
                         f"![{k}](experiments/{k})" for k in imgs) + "\n")
    return L


def wall_times(R):
    """The lines of the wall-time table (every stage of tools/experiments.sh in its order, then any
    other) and the total of the runs made here (s)."""
    L = rp.table(["run", "wall time (s)", "status"])
    total = 0
    for k in STAGES + [k for k in R.times if k not in STAGES]:
        if k in R.times:
            sec, st = R.times[k]
            total += sec
            fb = " (report uses the coarse run)" if k in R.used_fallback else ""
            L.append(f"| {k} | {sec} | {st}{fb} |")
        else:
            fb = R.fb_times.get(k)
            L.append(f"| {k} | not finished | " + (f"report uses the coarse run ({fb[0]} s there)" if fb else "") + " |")
    L.append(f"| total | {total} | |\n")
    return L, total


def summary(rep, total):
    """The report's opening paragraph in plain words: what ran, the main numbers beside the
    paper's, and the one stated criterion (rate independence) met or not."""
    R, key = rep.R, rep.key
    done = sum(1 for st in STAGES if R.ok(st))
    said = [f"The paper's experiments (Secs. III A-D: quasistatic compression, turgor series, relaxation, "
            f"impact, failure) on one cell at {rep.args.res} resolution: {done} of the {len(STAGES)} runs of "
            f"tools/experiments.sh finished here ({total} s of wall time)"
            + (f", {len(R.used_fallback)} more are taken from the coarse run" if R.used_fallback else "") + "."]
    said.append(f"The table below sets {len(rep.rows)} of our results beside the paper's.")
    if "F20" in key:
        F20, Fm, Fn = key["F20"]
        said.append(f"Compressed to 19% strain the cell pushes back with {F20 / 1e3:.0f} uN, {pct(F20, Fn)} "
                    f"against a continuous membrane of the tether network's law ({pct(F20, Fm)} against the "
                    "Neo-Hookean one).")
    if "period" in key:
        said.append(f"Released, the stiff cell at 1 mPa s swings with a period of {fmt(key['period'])} us "
                    "(the paper: under 1 us).")
    if "tau1" in key:
        said.append(f"Under a 5 m/s impact at 1 mPa s the fluid near the plate carries a shear stress of "
                    f"{key['tau1'] * 1e3:.0f} Pa at 4% strain (the paper: 250 Pa).")
    if "eps_f" in key:
        said.append(f"Compressed slowly, the wall breaks at {100 * key['eps_f']:.1f}% strain (the paper: about 14%).")
    if "rate" in key:
        said.append("The paper states one criterion, that the compression is quasistatic (the force at 0.5 and "
                    f"0.25 m/s within 2%): the largest difference is {100 * key['rate']:.1f}%, "
                    + ("met." if key["rate"] <= 0.02 else "not met."))
    return rp.summary(*said)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--run")
    ap.add_argument("--res", default="coarse")
    ap.add_argument("--report", required=True)
    ap.add_argument("--fallback")
    ap.add_argument("--membrane", help="run folder of WALL=membrane tools/experiments.sh: write its "
                    "section beside the tether numbers of REPORT/experiments.md")
    ap.add_argument("--wall", default="membrane", choices=walls.WALLS,
                    help="the wall of the --membrane run (the section's name)")
    args = ap.parse_args()
    if not args.run and not args.membrane:
        ap.error("give --run, --membrane or both")
    if args.run:
        full_report(args)
    if args.membrane:
        lines = walls.section(args.membrane, args.report, label=args.wall)[0]
        walls.splice(os.path.join(args.report, "experiments.md"), lines, title=walls.title_of(args.wall))
        print(f"report: section '{walls.title_of(args.wall)[3:]}' of "
              f"{os.path.join(args.report, 'experiments.md')}")


if __name__ == "__main__":
    main()
