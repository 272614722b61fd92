#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Report of the tissue experiments (tools/tissue.sh): a glued pair pressed and pulled apart, a
block compressed to failure at two turgors and two lamella strengths, impacts at three speeds.

  report.py --run RUNDIR --res coarse|small --report REPORTDIR [--figs FIGDIR]

Writes REPORTDIR/tissue.md, REPORTDIR/tissue-summary.json, and the plots, pictures and CSV files of
the raw curves to FIGDIR (default REPORTDIR). Every number of the report is in the summary.
"""
import argparse
import json
import math
import os
import sys

import numpy as np

from .. import params  # noqa: E402
from . import tissuedata as T  # noqa: E402
from . import water  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PIS = (-364, -100)
LAMS = tuple(params.lamellae())   # the named lamellae: strong, weak
SPEEDS = (5, 10, 20)
WINDOW_US = 1.0        # moving-average window of the plate force, us of plate travel time
EPS_FIT = (0.01, 0.03)  # strain range of the apparent modulus


def fmt(x, nd=3):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    if x == 0:
        return "0"
    return f"{x:.{nd}g}"


def pct(x, nd=3):
    return "-" if x is None else f"{100 * x:.{nd}g}%"


class Report:
    def __init__(self, run, res, report, figs):
        self.run, self.res, self.report, self.figs = run, res, report, figs
        os.makedirs(report, exist_ok=True)
        os.makedirs(figs, exist_ok=True)
        self.rel = os.path.relpath(figs, report)
        self.times = T.times(run)
        self.S = {"res": res, "run": os.path.relpath(run, os.getcwd()) if run.startswith(os.getcwd()) else run}
        self.md = []
        self.block = T.gen_stats(os.path.join(run, "gen", "block.json"))
        self.info = open(os.path.join(run, "run-info.txt")).read() if os.path.exists(
            os.path.join(run, "run-info.txt")) else ""

    def p(self, path):
        return os.path.join(self.run, path)

    def fig(self, name):
        return os.path.join(self.figs, name)

    def link(self, name):
        return name if self.rel == "." else f"{self.rel}/{name}"

    def settings(self, name, inp, lamella="strong"):
        """The effective settings of the run in folder name (its settings.json); for a run older
        than settings.json, the input's defaults with the named lamella tools/tissue.sh gave it."""
        return params.run_settings(self.p(name), inp, params.lamellae()[lamella])

    def ok(self, stage):
        return self.times.get(stage, (0, ""))[1] == "ok"

    def tethers_total(self):
        """All wall tethers of the block: 3 n - 6 edges on each closed triangulated wall of n nodes."""
        return self.block["cells"] * (3 * self.block["wall_nodes_per_cell"] - 6)

    def w(self, *lines):
        self.md.extend(lines)

    # ------------------------------------------------------------------ 1. pair
    def pair(self):
        S = {}
        have_pair = os.path.exists(self.p("pair/pair-press.dat"))
        have_single = os.path.exists(self.p("single/pair-press.dat"))
        if not (have_pair and have_single):
            self.w("## 1. Two glued cells: press and pull", "", "Not run or failed (see times.txt).", "")
            self.S["pair"] = None
            return
        pr = T.load(self.p("pair/pair-press.dat"), T.PRESS)
        sg = T.load(self.p("single/pair-press.dat"), T.PRESS)
        pl = T.load(self.p("pair/pair-pull.dat"), T.PULL) if os.path.exists(self.p("pair/pair-pull.dat")) else None
        ps = self.settings("pair", "in.tissue-pair")
        vplate, gap, vpull, Gl, sigl = ps["vplate"], ps["gap"], ps["vpull"], ps["Gl"], ps["sigl"]
        for d in (pr, sg):
            d["approach_um"] = vplate * d["time_us"] - 2 * gap
        T.write_csv(self.fig("pair-press.csv"), pr, ["time_us", "strain", "approach_um"] + T.PRESS[2:],
                    "in.tissue-pair, two glued cells stacked along z: press (P1, P2 the two cells)")
        T.write_csv(self.fig("single-press.csv"), sg, ["time_us", "strain", "approach_um", "F_top_nN",
                    "F_bottom_nN", "P1_kPa"], "in.tissue-pair -var ncell 1: the single cell pressed")
        n = max(1, int(round(WINDOW_US / np.median(np.diff(pr["time_us"])))))
        fp, fs = T.smooth(pr["F_top_nN"], n), T.smooth(sg["F_top_nN"], n)
        # forces at the end of the press (mean of the last window)
        S["press_end_strain_pair"] = float(pr["strain"][-1])
        S["press_end_force_pair_nN"] = float(fp[-1])
        S["press_end_strain_single"] = float(sg["strain"][-1])
        S["press_end_force_single_nN"] = float(fs[-1])
        # force at the same strain: 5% (both reach it)
        e5 = 0.05
        S["force_at_5pct_pair_nN"] = float(np.interp(e5, pr["strain"], fp))
        S["force_at_5pct_single_nN"] = float(np.interp(e5, sg["strain"], fs))
        S["glued_area_start_um2"] = float(pr["glued_area_um2"][0])
        S["contact_area_start_um2"] = float(pr["contact_area_um2"][0])
        S["glued_area_end_press_um2"] = float(pr["glued_area_um2"][-1])
        S["contact_area_end_press_um2"] = float(pr["contact_area_um2"][-1])
        S["P_start_kPa"] = [float(pr["P1_kPa"][0]), float(pr["P2_kPa"][0])]
        S["P_end_press_kPa"] = [float(np.mean(pr["P1_kPa"][-n:])), float(np.mean(pr["P2_kPa"][-n:]))]
        S["P_single_start_kPa"] = float(sg["P1_kPa"][0])
        S["P_single_end_press_kPa"] = float(np.mean(sg["P1_kPa"][-n:]))
        S["press_work_pair_nNum"] = T.integral(pr["F_top_nN"][pr["approach_um"] > 0],
                                               pr["approach_um"][pr["approach_um"] > 0])
        S["window_samples"] = n

        fig, ax = plt.subplots(1, 4, figsize=(20, 4.6))
        ax[3].plot(pr["approach_um"], fp / 1e3, color="C0", label="glued pair")
        ax[3].plot(sg["approach_um"], fs / 1e3, color="C1", label="single cell")
        ax[3].set_xlabel("approach = plate travel from first contact (um)")
        ax[3].set_ylabel("top plate force (uN, smoothed)")
        ax[3].set_xlim(left=-0.5)
        ax[3].legend(fontsize=8)
        ax[3].set_title("press: force vs approach", fontsize=9)
        ax[0].plot(pr["strain"], pr["F_top_nN"] / 1e3, color="C0", alpha=0.25, lw=0.7)
        ax[0].plot(sg["strain"], sg["F_top_nN"] / 1e3, color="C1", alpha=0.25, lw=0.7)
        ax[0].plot(pr["strain"], fp / 1e3, color="C0", label="glued pair (two cells in series)")
        ax[0].plot(sg["strain"], fs / 1e3, color="C1", label="single cell")
        ax[0].set_xlabel("strain (plate travel / initial height)")
        ax[0].set_ylabel("top plate force (uN)")
        ax[0].set_xlim(left=-0.01)
        ax0b = ax[0].secondary_xaxis("top")
        ax0b.set_xlabel("(pair height ~ 2x single: same strain = twice the approach)", fontsize=8)
        ax0b.set_xticks([])
        ax[0].legend(fontsize=8)
        ax[0].set_title(f"press (smoothed: {WINDOW_US:g} us window; faint: raw)", fontsize=9)
        ax[1].plot(pr["strain"], pr["contact_area_um2"], label="contact area (glued or touching)")
        ax[1].plot(pr["strain"], pr["glued_area_um2"], label="glued area (intact lamella)")
        ax[1].set_xlabel("strain")
        ax[1].set_ylabel("area (um^2)")
        ax[1].set_xlim(left=-0.01)
        ax[1].legend(fontsize=8)
        ax[1].set_title("cell-cell interface of the pair", fontsize=9)
        ax[2].plot(pr["strain"], T.smooth(pr["P1_kPa"], n), label="pair: cell 1 (bottom)")
        ax[2].plot(pr["strain"], T.smooth(pr["P2_kPa"], n), label="pair: cell 2 (top)")
        ax[2].plot(sg["strain"], T.smooth(sg["P1_kPa"], n), label="single cell", ls="--")
        if pl is not None:
            ax[2].plot([], [])
        ax[2].set_xlabel("strain")
        ax[2].set_ylabel("mean fluid pressure (kPa)")
        ax[2].set_xlim(left=-0.01)
        ax[2].legend(fontsize=8)
        ax[2].set_title("pressures during the press", fontsize=9)
        fig.tight_layout()
        fig.savefig(self.fig("pair-press.png"), dpi=110)
        plt.close(fig)

        if pl is not None:
            sep, Fraw = pl["separation_um"], pl["F_pull_nN"]
            # the grip force rings (the pair's shape oscillation against the rigidly moved grips): smoothed
            # over one period of that ringing (its strongest Fourier component) before the F > 0 cut,
            # which would otherwise keep half of every oscillation
            dsep = float(np.median(np.diff(sep)))
            per = T.dominant_period(Fraw, dsep)
            npl = max(1, int(round((per if per else WINDOW_US * 0.5) / dsep)))
            S["pull_ringing_period_um"] = per
            F = T.smooth(Fraw, npl)
            pl["F_pull_smoothed_nN"] = F
            deb = pl["debonded_bonds"]
            kd = np.nonzero(np.diff(deb) > 0)[0]
            k_last = int(kd[-1] + 1) if len(kd) else len(sep) - 1
            separated = bool(pl["glued_area_um2"][-1] <= 0 or pl["lamella_bonds"][-1] <= 0)
            sl = slice(0, k_last + 1)
            Fp = np.where(F[sl] > 0, F[sl], 0.0)
            W = T.integral(Fp, sep[sl])
            A0 = float(pl["glued_area_um2"][0])
            kmax = int(np.argmax(F))
            T.write_csv(self.fig("pair-pull.csv"), pl, T.PULL[:2] + ["F_pull_smoothed_nN"] + T.PULL[2:],
                        f"in.tissue-pair, pull: top grip moves up at {vpull:g} m/s; F_pull > 0 in tension; smoothed: "
                        f"centred moving average over {npl} samples ({npl * dsep:.3g} um of separation)")
            S["pull_window_samples"] = npl
            S["pull_force_max_raw_nN"] = float(np.max(Fraw))
            S["work_signed_raw_nNum"] = T.integral(Fraw[sl], sep[sl])
            S["interface_adhesion_max_nN"] = float(-np.min(pl["F_interface_nN"]))
            S.update(pull_force_max_nN=float(F[kmax]), pull_force_max_sep_um=float(sep[kmax]),
                     pull_glued_area_start_um2=A0, pull_last_debond_sep_um=float(sep[k_last]),
                     pull_separated=separated, pull_glued_area_end_um2=float(pl["glued_area_um2"][-1]),
                     pull_debonded_bonds_end=int(deb[-1]), pull_lamella_bonds_end=int(pl["lamella_bonds"][-1]),
                     work_separation_nNum=W, Gc=Gl, sigl_kPa=sigl,
                     GcA_nNum=Gl * A0, W_over_GcA=W / (Gl * A0) if A0 > 0 else None,
                     sigmaA_nN=sigl * A0,
                     pull_P_end_kPa=[float(pl["P1_kPa"][-1]), float(pl["P2_kPa"][-1])],
                     pull_F_end_nN=float(F[-1]))
            # the first positive pull force: where the cells start to pull on the grip
            fig, ax = plt.subplots(1, 2, figsize=(12, 4.4))
            ax[0].plot(sep, Fraw / 1e3, lw=0.5, color="C0", alpha=0.25, label="raw")
            ax[0].plot(sep, F / 1e3, lw=1.2, color="C0", label=f"pull force on the top grip (window {npl * dsep:.3g} um)")
            ax[0].plot(sep, -pl["F_interface_nN"] / 1e3, lw=0.8, color="C4",
                       label="adhesion across the interface (-lamella - contact force)")
            ax[0].fill_between(sep[sl], 0, Fp / 1e3, color="C0", alpha=0.2,
                               label=f"W = {W / 1e3:.3g} pJ (F > 0, to the last debond)")
            ax[0].axvline(sep[k_last], color="k", ls=":", lw=0.8, label="last debond")
            ax[0].plot(sep[kmax], F[kmax] / 1e3, "rv", label=f"pull-off force {F[kmax] / 1e3:.3g} uN")
            ax[0].axhline(0, color="grey", lw=0.5)
            ax[0].set_xlabel("grip separation (um)")
            ax[0].set_ylabel("pull force (uN)")
            ax[0].legend(fontsize=8)
            ax[0].set_title(f"pull at {vpull:g} m/s; Gc A0 = {Gl * A0 / 1e3:.3g} pJ", fontsize=9)
            ax[1].plot(sep, pl["glued_area_um2"], label="glued area")
            ax[1].plot(sep, pl["contact_area_um2"], label="contact area")
            ax[1].set_xlabel("grip separation (um)")
            ax[1].set_ylabel("area (um^2)")
            a2 = ax[1].twinx()
            a2.plot(sep, pl["P1_kPa"], "C2--", lw=0.8, label="P cell 1")
            a2.plot(sep, pl["P2_kPa"], "C3--", lw=0.8, label="P cell 2")
            a2.set_ylabel("pressure (kPa)")
            h1, l1 = ax[1].get_legend_handles_labels()
            h2, l2 = a2.get_legend_handles_labels()
            ax[1].legend(h1 + h2, l1 + l2, fontsize=8)
            fig.tight_layout()
            fig.savefig(self.fig("pair-pull.png"), dpi=110)
            plt.close(fig)
        self.S["pair"] = S

        w = self.w
        w("## 1. Two glued cells: press and pull", "",
          "`cellgen.py tissue --lattice sc --n 1 1 2` (two cells stacked along z, glued across one face) and "
          "`--n 1 1 1` (one cell of the same equivalent radius, 30 um), each inflated with `in.tissue-inflate` "
          f"(Pi {ps['Pi']:g} kPa, Lp 10, the steps of run-info.txt), then `in.tissue-pair`: the plates press at "
          f"{vplate:g} m/s to {ps['press']:.0%} "
          "strain (strain = plate travel from first contact / initial height; the pair is twice as high, so at one "
          f"strain it is pressed twice as far); the pair is then gripped (wall nodes within {ps['grip']:g} um of a "
          f"plate) and the top grip pulled up at {vpull:g} m/s. Walls do not rupture (lamf {ps['lamf']:g}); lamella: "
          f"strength sigl {sigl:g} kPa, fracture energy Gc {Gl:g} pg/us^2 = {Gl / 1000:g} J/m^2 "
          "(tissue-model.lmp defaults). Force curves are smoothed by a centred moving average over "
          f"{WINDOW_US:g} us ({n} samples) of plate time; the raw force rings at the walls' frequencies.", "",
          f"![press]({self.link('pair-press.png')})", "",
          "| quantity | definition | value |", "|---|---|---|",
          f"| force at 5% strain, pair | smoothed top-plate force | {fmt(S['force_at_5pct_pair_nN'] / 1e3)} uN |",
          f"| force at 5% strain, single cell | same | {fmt(S['force_at_5pct_single_nN'] / 1e3)} uN |",
          f"| force at the end of the press, pair | smoothed, at strain {pct(S['press_end_strain_pair'])} | "
          f"{fmt(S['press_end_force_pair_nN'] / 1e3)} uN |",
          f"| force at the end of the press, single | smoothed, at strain {pct(S['press_end_strain_single'])} | "
          f"{fmt(S['press_end_force_single_nN'] / 1e3)} uN |",
          f"| glued area, start / end of press | intact lamella bonds' area (cell/contacts col. 4) | "
          f"{fmt(S['glued_area_start_um2'])} / {fmt(S['glued_area_end_press_um2'])} um^2 |",
          f"| contact area, start / end of press | wall area touching the other cell (col. 10) | "
          f"{fmt(S['contact_area_start_um2'])} / {fmt(S['contact_area_end_press_um2'])} um^2 |",
          f"| pressures before the press | cells 1, 2 of the pair; single | {fmt(S['P_start_kPa'][0])}, "
          f"{fmt(S['P_start_kPa'][1])}; {fmt(S['P_single_start_kPa'])} kPa |",
          f"| pressures at the end of the press | mean of the last window | {fmt(S['P_end_press_kPa'][0])}, "
          f"{fmt(S['P_end_press_kPa'][1])}; {fmt(S['P_single_end_press_kPa'])} kPa |", "")
        if pl is not None:
            w(f"![pull]({self.link('pair-pull.png')})", "",
              "| quantity | definition | value |", "|---|---|---|",
              f"| pull-off force | largest smoothed force on the top grip (tension > 0; centred moving average over "
              f"{npl * dsep:.3g} um of separation = {npl * dsep / vpull:.3g} us, one period of the ringing) | "
              f"{fmt(S['pull_force_max_nN'] / 1e3)} uN at {fmt(S['pull_force_max_sep_um'])} um (raw largest: "
              f"{fmt(S['pull_force_max_raw_nN'] / 1e3)} uN) |",
              f"| largest adhesion across the interface | -(lamella + contact force), cell/contacts col. 7 + 8 | "
              f"{fmt(S['interface_adhesion_max_nN'] / 1e3)} uN |",
              f"| glued area at the start of the pull, A0 | intact lamella area | {fmt(A0)} um^2 |",
              f"| strength x area | sigl A0 (the force the whole interface could carry at once) | "
              f"{fmt(S['sigmaA_nN'] / 1e3)} uN |",
              f"| work of separation W | integral of F_pull d(sep) where F_pull > 0, up to the last debond "
              f"(at {fmt(S['pull_last_debond_sep_um'])} um), of the smoothed force | {fmt(W / 1e3)} pJ |",
              f"| signed work to the last debond | integral of the raw F_pull d(sep), negative parts included | "
              f"{fmt(S['work_signed_raw_nNum'] / 1e3)} pJ |",
              f"| Gc A0 | fracture energy x glued area | {fmt(S['GcA_nNum'] / 1e3)} pJ |",
              f"| W / (Gc A0) | | **{fmt(S['W_over_GcA'])}** |",
              f"| separated at the end? | glued area 0 | {'yes' if separated else 'no'} "
              f"({fmt(S['pull_glued_area_end_um2'])} um^2 left, {S['pull_debonded_bonds_end']} bonds debonded, "
              f"{S['pull_lamella_bonds_end']} intact) |",
              f"| work of the press | integral of F_top d(approach) | {fmt(S['press_work_pair_nNum'] / 1e3)} pJ |", "")
            r = S["W_over_GcA"]
            if r is None:
                verdict = ""
            elif abs(r - 1) <= 0.15:
                verdict = (f"Here W / (Gc A0) = {r:.2f}: within 15% of 1, the cohesive law's energy balance holds "
                           "at this pull speed, but it is a balance of the terms above, not a direct measure of "
                           "Gc (the signed work, which lets the negative half-cycles of the ringing cancel, is "
                           f"{S['work_signed_raw_nNum'] / 1e3:.3g} pJ).")
            elif r > 1:
                verdict = (f"Here W / (Gc A0) = {r:.2f} > 1: the grip does more work than the glue absorbs; the "
                           "rest goes into viscous and contact damping and into the cells' elastic energy that "
                           "is still stored when the last bond lets go (then released as oscillation).")
            else:
                verdict = (f"Here W / (Gc A0) = {r:.2f} < 1: the stored elastic energy of the cells (and of the "
                           "compressed interface after the press) drives part of the debonding, so the grip "
                           "does less than Gc A0 of work.")
            w("Why W need not equal Gc A0: the grips pull on the walls, not on the interface. (i) The grip force "
              "works on the cells' walls and fluid too: elastic energy stored in the stretched cells is released "
              "when the last bonds go (and can drive debonding the grip does not pay for); (ii) the fluid viscosity "
              f"and the contact damping dissipate work at {vpull:g} m/s; the pair rings at its shape mode (period "
              f"{fmt(S.get('pull_ringing_period_um'))} um of separation here), and clipping F > 0 on that signal "
              "counts half-cycles that give energy back, so the force is smoothed over one period first; "
              "(iii) the interface peels from its rim: only part of the bonds carries load at a time, so the "
              "pull-off force stays below sigl A0 and the bonds opened last may let go elastically; (iv) the press "
              "before the pull leaves the interface in compression, and the pull first unloads it (F_pull <= 0, "
              "not counted). " + verdict, "")
        w("CSV of the raw curves: "
          f"[pair-press.csv]({self.link('pair-press.csv')}), [single-press.csv]({self.link('single-press.csv')})"
          + (f", [pair-pull.csv]({self.link('pair-pull.csv')})" if pl is not None else "") + ".", "")

    # ------------------------------------------------------------------ 2. block
    def compress_run(self, name, Pi, lam):
        d = T.load(self.p(f"{name}/tissue-compress.dat"), T.COMPRESS)
        cs = self.settings(name, "in.tissue-compress", lam)
        ncell = int(self.block["cells"])
        dt = float(np.median(np.diff(d["time_us"])))
        n = max(1, int(round(WINDOW_US / dt)))
        sm = T.smooth(d["stress_kPa"], n)
        eps = d["strain"]
        R = {"name": name, "Pi_kPa": Pi, "lamella": lam, "sigl_kPa": cs["sigl"], "Gl": cs["Gl"],
             "window_samples": n, "strain_end": float(eps[-1])}
        m = (eps >= EPS_FIT[0]) & (eps <= EPS_FIT[1])
        R["modulus_kPa"] = float(np.polyfit(eps[m], sm[m], 1)[0]) if m.sum() >= 3 else None
        kpk = int(np.argmax(sm))
        R["peak_stress_kPa"], R["strain_at_peak"] = float(sm[kpk]), float(eps[kpk])
        R["peak_is_end"] = bool(eps[kpk] >= eps[-1] - 0.01)
        R["first_rupture_strain"], kr = T.first_rise(eps, d["broken_tethers"])
        R["first_debond_strain"], kb = T.first_rise(eps, d["debonded_bonds"])
        ev = [x for x in (R["first_rupture_strain"], R["first_debond_strain"]) if x is not None]
        R["first_event_strain"] = min(ev) if ev else None
        R["P_start_kPa"] = float(d["P_mean_kPa"][0])
        R["glued_start_um2"] = float(d["glued_area_um2"][0])
        R["debarea_start_um2"] = float(d["debonded_area_um2"][0])
        A0 = R["glued_start_um2"] + R["debarea_start_um2"]
        R["glued_initial_um2"] = A0
        tab = T.load_table(self.p(f"{name}/tissue-compress-cells.dat"))
        tab = [(s, a) for s, a in tab if len(a) == ncell]
        if tab:
            step, a = tab[-1]
            R["table_step"] = step
            R["table_strain"] = float(np.interp(step, d["step"], eps))
            R["ruptured_cells"] = int(np.sum(a[:, 12] >= 1))
            R["broken_tethers_table"] = int(np.sum(a[:, 12]))
            R["debonded_area_um2"] = float(np.sum(a[:, 16]) / 2)
        else:
            R["table_step"], R["table_strain"], R["ruptured_cells"] = None, None, None
            R["debonded_area_um2"] = float(d["debonded_area_um2"][-1])
        R["debonded_area_dat_end_um2"] = float(d["debonded_area_um2"][-1])
        R["broken_tethers_end"] = int(d["broken_tethers"][-1])
        R["debonded_bonds_end"] = int(d["debonded_bonds"][-1])
        R["debonded_fraction"] = R["debonded_area_um2"] / A0 if A0 > 0 else None
        # like with like: the share of each failing material that has failed (a cell with one broken
        # tether of 1920 is not a burst cell)
        fr = R.get("broken_tethers_table", R["broken_tethers_end"]) / self.tethers_total()
        fd = R["debonded_fraction"] or 0.0
        R["ruptured_fraction"] = fr
        R["mode"] = "none" if fr == 0 and fd == 0 else ("rupture" if fr >= fd else "debonding")
        lk = self.p(f"{name}/tissue-compress.dat.leaks")
        if os.path.exists(lk):
            L = T.load(lk, T.LEAKS)
            R["leaked_particles_end"] = int(L["leaked_particles"][-1])
        T.write_csv(self.fig(f"{name}.csv"), {**d, "stress_smoothed_kPa": sm},
                    ["time_us", "strain", "stress_kPa", "stress_smoothed_kPa"] + T.COMPRESS[3:],
                    f"in.tissue-compress Pi {Pi} kPa, lamella {lam} (sigl {cs['sigl']:g} kPa, Gl {cs['Gl']:g}); "
                    f"smoothed: centred moving average over {n} samples ({WINDOW_US:g} us)")
        return R, d, sm

    def block_settings(self):
        """{lamella: the settings of its first block compression} (where none ran: the input's
        defaults with the named lamella)."""
        out = {}
        for lam in LAMS:
            names = [f"compress{Pi}-{lam}" for Pi in PIS if os.path.exists(self.p(f"compress{Pi}-{lam}/tissue-compress.dat"))]
            out[lam] = (self.settings(names[0], "in.tissue-compress", lam) if names else
                        dict(params.defaults(os.path.join(params.INPUTS, "in.tissue-compress")), **params.lamellae()[lam]))
        return out

    def blocks(self):
        w = self.w
        ncell = int(self.block["cells"])
        st, wk = (self.block_settings()[lam] for lam in ("strong", "weak"))
        runs = {}
        for Pi in PIS:
            for lam in LAMS:
                name = f"compress{Pi}-{lam}"
                if os.path.exists(self.p(f"{name}/tissue-compress.dat")):
                    try:
                        runs[(Pi, lam)] = self.compress_run(name, Pi, lam)
                    except Exception as e:  # a broken run should not stop the report
                        print(f"report: {name}: {e}", file=sys.stderr)
        nx = "x".join(str(int(round((self.block['tissue_box'][2 * k + 1] - self.block['tissue_box'][2 * k])
                                   / 48.3598))) for k in range(3))
        w(f"## 2. Block of {ncell} cells compressed to failure", "",
          f"`cellgen.py tissue --lattice sc` ({ncell} cells, {self.block['lamella_bonds']} lamella bonds, glued "
          f"area {sum(p['glued_area'] for p in self.block['pairs']):.6g} um^2 over {len(self.block['pairs'])} "
          f"cell pairs), inflated twice with `in.tissue-inflate` (Pi {' and '.join(map(str, PIS))} kPa), each "
          f"compressed with `in.tissue-compress -var lamf {st['lamf']:g}` (tethers break at {st['lamf'] - 1:.0%} "
          f"stretch, the paper's) with a strong (sigl {st['sigl']:g} kPa, Gl {st['Gl']:g} pg/us^2 = "
          f"{st['Gl'] / 1000:g} J/m^2) and a weak lamella ({wk['sigl']:g} kPa, {wk['Gl']:g} pg/us^2). "
          "Stress = top-plate force / initial cross-section of the block; strain = plate travel from first "
          f"contact / initial height. Stress smoothed by a centred moving average over {WINDOW_US:g} us of plate "
          "time (faint: raw); the plate force rings with the walls.", "",
          "Definitions: **apparent modulus** = slope of a straight-line fit of the smoothed stress over strain "
          f"{EPS_FIT[0]:.0%}-{EPS_FIT[1]:.0%}; **strain at peak** = strain of the largest smoothed stress (if that "
          "is at the end of the run, the block has not softened yet: marked 'end'); **first rupture** = strain "
          "of the first record with a broken tether; **first debond** = first record with a debonded lamella "
          "bond (beyond those at the start); **ruptured cells** = cells with >= 1 broken tether (compute "
          "cell/props column 13) in the last per-cell table; **ruptured fraction** = broken tethers in that table "
          "over all the block's tethers (3 n - 6 per closed wall of n nodes); **debonded fraction** = column 17 summed / 2 (each "
          "bond counts in both cells) in that table, over the glued area at the start of the compression plus "
          "any debonded during inflation (= the area glued by the generator); **failure mode**: *rupture* if "
          "the ruptured fraction of the walls >= the debonded fraction of the glued area, *debonding* otherwise, "
          "*none* if both are 0: the share of each failing material that has failed.", "")
        if not runs:
            w("No block compression finished.", "")
            self.S["block"] = None
            return
        fig, ax = plt.subplots(1, 2, figsize=(14, 5))
        cols = {(-364, "strong"): "C3", (-364, "weak"): "C1", (-100, "strong"): "C0", (-100, "weak"): "C9"}
        for key, (R, d, sm) in runs.items():
            c = cols[key]
            lab = f"Pi {key[0]}, {key[1]}"
            ax[0].plot(d["strain"], d["stress_kPa"], color=c, alpha=0.15, lw=0.6)
            ax[0].plot(d["strain"], sm, color=c, label=lab, ls="-" if key[1] == "strong" else "--")
            for x, mk in ((R["first_rupture_strain"], "x"), (R["first_debond_strain"], "o")):
                if x is not None:
                    ax[0].plot(x, np.interp(x, d["strain"], sm), mk, color=c, ms=9, mfc="none", mew=2)
            ax[1].plot(d["strain"], d["broken_tethers"], color=c, label=f"{lab}: broken tethers")
            ax[1].plot(d["strain"], d["debonded_bonds"], color=c, ls=":", label=f"{lab}: debonded bonds")
        ax[0].plot([], [], "kx", label="first broken tether")
        ax[0].plot([], [], "ko", mfc="none", label="first debond")
        ax[0].set_xlabel("strain")
        ax[0].set_ylabel("stress = F_top / A0 (kPa)")
        ax[0].set_xlim(left=-0.005)
        ax[0].set_ylim(bottom=min(0, min(np.min(r[2]) for r in runs.values())))
        ax[0].legend(fontsize=8, loc="upper right")
        ax[0].set_title(f"block compression at the plate speed of run-info.txt; smoothed {WINDOW_US:g} us", fontsize=9)
        ax[1].set_xlabel("strain")
        ax[1].set_ylabel("count")
        ax[1].set_yscale("symlog", linthresh=10)
        ax[1].legend(fontsize=7)
        ax[1].set_title("failure events: wall rupture (solid) and debonding (dotted)", fontsize=9)
        fig.tight_layout()
        fig.savefig(self.fig("block-stress-strain.png"), dpi=110)
        plt.close(fig)

        fig, ax = plt.subplots(figsize=(6, 4.6))
        for key, (R, d, sm) in runs.items():
            ax.plot(100 * (R["debonded_fraction"] or 0), 100 * R["ruptured_fraction"],
                    "o" if key[1] == "strong" else "s", color=cols[key], ms=10,
                    label=f"Pi {key[0]}, {key[1]}: {R['mode']}")
        xm = 100 * max([max(R["debonded_fraction"] or 0, R["ruptured_fraction"]) for R, _, _ in runs.values()]
                       + [0.05]) * 1.15
        ax.plot([0, xm], [0, xm], "k:", lw=0.8, label="ruptured fraction = debonded fraction")
        ax.set_xlim(-0.02 * xm, xm)
        ax.set_ylim(-0.02 * xm, xm)
        ax.set_xlabel("debonded fraction of the glued area (%)")
        ax.set_ylabel("ruptured fraction of the wall tethers (%)")
        ax.legend(fontsize=8)
        ax.set_title("failure mode at the end of the compression", fontsize=9)
        fig.tight_layout()
        fig.savefig(self.fig("block-failure-mode.png"), dpi=110)
        plt.close(fig)

        w(f"![stress-strain]({self.link('block-stress-strain.png')})", "",
          f"![failure mode]({self.link('block-failure-mode.png')})", "",
          "| Pi (kPa) | lamella | P at start (kPa) | modulus (kPa) | peak stress (kPa) | strain at peak | first rupture | "
          "first debond | ruptured cells | broken tethers | ruptured fraction | debonded area (um^2) | debonded "
          "fraction | leaked fluid particles | mode |", "|" + "---|" * 15)
        for key, (R, d, sm) in sorted(runs.items(), key=lambda kv: (kv[0][0], kv[0][1])):
            w(f"| {key[0]} | {key[1]} | {fmt(R['P_start_kPa'])} | {fmt(R['modulus_kPa'])} | {fmt(R['peak_stress_kPa'])} | "
              f"{pct(R['strain_at_peak'])}{' (end)' if R['peak_is_end'] else ''} | {pct(R['first_rupture_strain'])} | "
              f"{pct(R['first_debond_strain'])} | {fmt(R['ruptured_cells'])} / {ncell} | {R['broken_tethers_end']} | "
              f"{pct(R['ruptured_fraction'])} | {fmt(R['debonded_area_um2'])} | {pct(R['debonded_fraction'])} | {R.get('leaked_particles_end', '-')} | "
              f"{R['mode']} |")
        some = next(iter(runs.values()))[0]
        w("", f"Per-cell table: the last one written, at strain {pct(some['table_strain'])} (step {some['table_step']}; "
          "tables every `tabevery` steps, see run-info.txt). Glued area at the start of the compression: "
          + ", ".join(f"Pi {k[0]} {k[1]} {fmt(R['glued_start_um2'])} um^2 (debonded in inflation "
                      f"{fmt(R['debarea_start_um2'])})" for k, (R, _, _) in sorted(runs.items())) + ".", "")
        # trends
        T_ = {}
        lines = []
        for lam in LAMS:
            a, b = runs.get((-364, lam)), runs.get((-100, lam))
            if a and b:
                Ea, Eb = a[0]["modulus_kPa"], b[0]["modulus_kPa"]
                stiffer = Ea is not None and Eb is not None and Ea > Eb
                fa, fb = a[0]["first_event_strain"], b[0]["first_event_strain"]
                pa, pb = a[0]["strain_at_peak"], b[0]["strain_at_peak"]
                earlier = fa is not None and (fb is None or fa < fb)
                earlier_pk = pa < pb
                T_[f"turgor_stiffer_{lam}"] = stiffer
                T_[f"turgor_fails_earlier_{lam}"] = earlier
                T_[f"turgor_peak_earlier_{lam}"] = earlier_pk
                lines.append(f"* {lam} lamella: modulus {fmt(Ea)} kPa at Pi -364 vs {fmt(Eb)} kPa at -100 -> "
                             f"higher turgor stiffer: **{'yes' if stiffer else 'no'}**; first failure event at "
                             f"{pct(fa)} vs {pct(fb)} -> fails earlier: **{'yes' if earlier else 'no'}** "
                             f"(strain at peak stress {pct(pa)} vs {pct(pb)}: "
                             f"{'earlier' if earlier_pk else 'not earlier'}).")
        for Pi in PIS:
            a, b = runs.get((Pi, "strong")), runs.get((Pi, "weak"))
            if a and b:
                ra, rb = a[0], b[0]
                turns = ra["mode"] == "rupture" and rb["mode"] == "debonding"
                more_deb = (rb["debonded_fraction"] or 0) > (ra["debonded_fraction"] or 0)
                fewer_rup = rb["ruptured_fraction"] < ra["ruptured_fraction"]
                T_[f"weak_turns_rupture_into_debonding_Pi{Pi}"] = turns
                T_[f"weak_more_debonding_Pi{Pi}"] = more_deb
                T_[f"weak_fewer_ruptured_Pi{Pi}"] = fewer_rup
                lines.append(f"* Pi {Pi}: strong lamella {ra['mode']} ({pct(ra['ruptured_fraction'])} of the tethers "
                             f"broken in {ra['ruptured_cells']} cells, {pct(ra['debonded_fraction'])} of the glued area "
                             f"debonded), weak {rb['mode']} ({pct(rb['ruptured_fraction'])} broken in "
                             f"{rb['ruptured_cells']} cells, {pct(rb['debonded_fraction'])} debonded) -> weak adhesion "
                             f"turns rupture into debonding: **{'yes' if turns else 'no'}** (more debonding: "
                             f"{'yes' if more_deb else 'no'}, fewer broken tethers: {'yes' if fewer_rup else 'no'}).")
        w("### Do the published trends hold here?", "", *lines, "")
        self.block_trend_lines = lines
        self.S["block"] = {f"{k[0]}_{k[1]}": R for k, (R, _, _) in runs.items()}
        self.S["block_trends"] = T_
        self.S["block_definitions"] = {"window_us": WINDOW_US, "modulus_strain_range": list(EPS_FIT),
                                       "mode_rule": "rupture if broken tethers / all tethers >= debonded area / glued area, "
                                       "debonding otherwise, none if both 0"}
        self.runs = runs
        self.pair_table(runs)

    def pair_table(self, runs):
        w = self.w
        for key in ((-364, "weak"), (-364, "strong")):
            name = f"compress{key[0]}-{key[1]}"
            path = self.p(f"{name}/tissue-compress-pairs.dat")
            if not os.path.exists(path):
                continue
            tab = T.load_table(path)
            if not tab or not len(tab[-1][1]):
                continue
            step, a = tab[-1]
            order = np.argsort(-a[:, 5], kind="stable")
            k = order[:8]
            w(f"Per cell pair (`compute cell/contacts`, {name}/tissue-compress-pairs.dat, last table, step {step}): "
              f"the {len(k)} pairs with the most debonded area of {len(a)} rows "
              f"(glued {fmt(np.sum(a[:, 3]))} um^2, debonded {fmt(np.sum(a[:, 5]))} um^2 in all).", "",
              "| cells i, j | lamella bonds | glued area (um^2) | debonded bonds | debonded area (um^2) | "
              "lamella force (nN) | contact force (nN) | contact area (um^2) | distance (um) |", "|" + "---|" * 9)
            for r in a[k]:
                w(f"| {int(r[0])}, {int(r[1])} | {int(r[2])} | {fmt(r[3])} | {int(r[4])} | {fmt(r[5])} | {fmt(r[6])} | "
                  f"{fmt(r[7])} | {fmt(r[9])} | {fmt(r[10])} |")
            w("")

    # ------------------------------------------------------------------ pictures
    def montage(self, name, prefix, title, d):
        import glob
        files = sorted(glob.glob(self.p(f"{name}/{prefix}.*.png")), key=lambda f: int(f.split(".")[-2]))
        if not files:
            return None
        files = files[-4:] if len(files) > 4 else files
        fig, ax = plt.subplots(1, len(files), figsize=(4.2 * len(files), 3.6))
        ax = np.atleast_1d(ax)
        for a, f in zip(ax, files):
            step = int(f.split(".")[-2])
            a.imshow(plt.imread(f))
            a.axis("off")
            e = float(np.interp(step, d["step"], d["strain"]))
            t = float(np.interp(step, d["step"], d["time_us"]))
            a.set_title(f"strain {e:.1%}, t = {t:.3g} us", fontsize=9)
        fig.suptitle(title, fontsize=10)
        fig.tight_layout()
        out = f"pictures-{name}.png"
        fig.savefig(self.fig(out), dpi=90)
        plt.close(fig)
        return out

    def pictures(self):
        w = self.w
        pics = []
        for (Pi, lam), (R, d, sm) in sorted(getattr(self, "runs", {}).items()):
            name = f"compress{Pi}-{lam}"
            m = self.montage(name, name, f"{name}: cells coloured by cell; red = ruptured wall, green = debonded", d)
            if m:
                pics.append(m)
        for v in SPEEDS:
            name = f"impact-{v}"
            if os.path.exists(self.p(f"{name}/tissue-impact.dat")):
                d = T.load(self.p(f"{name}/tissue-impact.dat"), T.COMPRESS)
                m = self.montage(name, name, f"impact at {v} m/s", d)
                if m:
                    pics.append(m)
        if pics:
            w("## Pictures", "", "`dump image` of the wall nodes (in.tissue-compress `-var img N`), about four frames per "
              "run (the last four written): nodes coloured by cell (blue to yellow), red where the wall has "
              "ruptured (broken tethers), green where the lamella has debonded; the fluid is not drawn. The VTK "
              "surfaces (`walls.STEP.vtk`, fields *broken* and *debonded*) are in each compression's run folder.", "")
            for m in pics:
                w(f"![{m}]({self.link(m)})", "")
        self.S["pictures"] = pics

    # ------------------------------------------------------------------ 3. impact
    def impacts(self):
        w = self.w
        ncell = int(self.block["cells"])
        m_fluid = float(self.block["fluid_mass"])
        rows = []
        fig, ax = plt.subplots(1, 2, figsize=(13, 4.6))
        for v in SPEEDS:
            name = f"impact-{v}"
            path = self.p(f"{name}/tissue-impact.dat")
            if not os.path.exists(path):
                continue
            d = T.load(path, T.COMPRESS)
            t, eps = d["time_us"], d["strain"]
            # the plate moves at v until tpress: the strain stops growing there
            kp = int(np.nonzero(eps >= eps.max() - 1e-9)[0][0])
            W = T.integral(d["F_top_nN"][:kp + 1] * v, t[:kp + 1])
            R = {"vplate_m_s": v, "tpress_us": float(t[kp]), "strain_max": float(eps.max()),
                 "energy_nNum": W, "energy_pJ": W / 1e3, "t_end_us": float(t[-1])}
            tab = [(s, a) for s, a in T.load_table(self.p(f"{name}/tissue-impact-cells.dat")) if len(a) == ncell]
            if tab:
                step, a = tab[-1]
                R["table_time_us"] = float(np.interp(step, d["step"], t))
                R["ruptured_cells"] = int(np.sum(a[:, 12] >= 1))
                R["debonded_area_um2"] = float(np.sum(a[:, 16]) / 2)
            else:
                R["ruptured_cells"], R["debonded_area_um2"] = None, float(d["debonded_area_um2"][-1])
            A0 = float(d["glued_area_um2"][0] + d["debonded_area_um2"][0])
            R["debonded_fraction"] = R["debonded_area_um2"] / A0 if A0 > 0 else None
            R["broken_tethers_end"] = int(d["broken_tethers"][-1])
            lk = self.p(f"{name}/tissue-impact.dat.leaks")
            if os.path.exists(lk):
                L = T.load(lk, T.LEAKS)
                R["leaked_particles"] = int(L["leaked_particles"][-1])
                R["fluid_lost_pg"] = R["leaked_particles"] * m_fluid
                R["fluid_lost_fraction"] = R["fluid_lost_pg"] / float(d["fluid_mass_pg"][0])
            R["fluid_mass_change_pg"] = float(d["fluid_mass_pg"][-1] - d["fluid_mass_pg"][0])
            T.write_csv(self.fig(f"{name}.csv"), d, T.COMPRESS, f"in.tissue-impact at {v} m/s")
            rows.append(R)
            ax[0].plot(t, d["F_top_nN"] / 1e3, lw=0.7, label=f"{v} m/s")
            ax[0].axvline(t[kp], color=ax[0].lines[-1].get_color(), ls=":", lw=0.7)
        ax[0].set_xlabel("time (us)")
        ax[0].set_ylabel("top plate force (uN)")
        ax[0].legend(fontsize=8)
        ax[0].set_title("impact: plate force (dotted: plate stops)", fontsize=9)
        if rows:
            E = [r["energy_pJ"] for r in rows]
            ax[1].plot(E, [r["ruptured_cells"] or 0 for r in rows], "o-", label="ruptured cells")
            ax[1].set_xlabel("impact energy = plate work (pJ)")
            ax[1].set_ylabel(f"ruptured cells (of {ncell})")
            a2 = ax[1].twinx()
            a2.plot(E, [100 * (r["debonded_fraction"] or 0) for r in rows], "s--", color="C1",
                    label="debonded area (% of glued)")
            a2.plot(E, [100 * r.get("fluid_lost_fraction", 0) for r in rows], "^:", color="C2",
                    label="fluid lost (% of fluid mass)")
            a2.set_ylabel("%")
            for r in rows:
                ax[1].annotate(f"{r['vplate_m_s']} m/s\n{r['broken_tethers_end']} broken tethers",
                               (r["energy_pJ"], r["ruptured_cells"] or 0), fontsize=7,
                               textcoords="offset points", xytext=(-20, -28))
            ax[1].set_ylim(-0.5, ncell + 1.5)
            h1, l1 = ax[1].get_legend_handles_labels()
            h2, l2 = a2.get_legend_handles_labels()
            ax[1].legend(h1 + h2, l1 + l2, fontsize=8)
            ax[1].set_title("bruise against impact energy", fontsize=9)
        fig.tight_layout()
        fig.savefig(self.fig("impact-bruise.png"), dpi=110)
        plt.close(fig)
        ran = [v for v in SPEEDS if os.path.exists(self.p(f"impact-{v}/tissue-impact.dat"))]
        im = self.settings(f"impact-{ran[0] if ran else SPEEDS[0]}", "in.tissue-impact")
        w(f"## 3. Impact on the turgid block (Pi {im['Pi']:g} kPa, strong lamella)", "",
          f"`in.tissue-impact -var vplate V` (lamf {im['lamf']:g}, sigl {im['sigl']:g} kPa, Gl {im['Gl'] / 1000:g} J/m^2): "
          "the top plate hits at V and drives "
          "in at that constant speed to the strain of run-info.txt, then holds (run-info.txt) while the block settles. "
          "**Impact energy** = the plate's work, the integral of F_top x V dt over the pressing time (until the "
          "strain stops growing), from the force time series (every 50 steps, trapezoids; 1 pJ = 1000 nN um). "
          "**Bruise** at the end of the hold: **ruptured cells** (>= 1 broken tether, per-cell table), **debonded "
          "area** (column 17 summed / 2; fraction of the glued area at the impact), **fluid lost** = fluid "
          "particles outside their own wall (in.tissue-compress's .leaks file, last value) x the fluid particle "
          f"mass {fmt(m_fluid)} pg, and as a fraction of the fluid mass. (The cells' fluid mass itself does not "
          "change: escaped particles still belong to their cell; its change, osmosis at Lp 1e-9, is in the "
          "summary.)", "",
          f"![impact]({self.link('impact-bruise.png')})", "",
          "| V (m/s) | energy (pJ) | plate stops at strain | ruptured cells | broken tethers | debonded area (um^2) | "
          "debonded fraction | fluid lost (particles) | fluid lost (pg) | fluid lost (% of mass) |", "|" + "---|" * 10)
        for r in rows:
            w(f"| {r['vplate_m_s']} | {fmt(r['energy_pJ'])} | {pct(r['strain_max'])} | {fmt(r['ruptured_cells'])} / {ncell} | "
              f"{r['broken_tethers_end']} | {fmt(r['debonded_area_um2'])} | {pct(r['debonded_fraction'])} | "
              f"{r.get('leaked_particles', '-')} | {fmt(r.get('fluid_lost_pg'))} | {pct(r.get('fluid_lost_fraction'))} |")
        w("")
        self.S["impact"] = rows

    # ------------------------------------------------------------------ inflations
    def inflations(self):
        rows = []
        for name, what in (("inflate-364", "block, Pi -364"), ("inflate-100", "block, Pi -100"),
                           ("inflate-pair", "pair, Pi -364"), ("inflate-single", "single cell, Pi -364")):
            path = self.p(f"{name}/tissue-inflate.dat")
            if not os.path.exists(path):
                continue
            d = T.load(path, T.INFLATE)
            M = d["fluid_mass_pg"]
            dM = (M[-1] - M[-2]) / M[-1] if len(M) > 1 else None
            rows.append({"run": name, "what": what, "time_us": float(d["time_us"][-1]),
                         "P_mean_kPa": float(d["P_mean_kPa"][-1]), "P_min_kPa": float(d["P_min_kPa"][-1]),
                         "P_max_kPa": float(d["P_max_kPa"][-1]), "stretch_mean": float(d["stretch_mean"][-1]),
                         "mass_change_last_interval": dM, "glued_area_um2": float(d["glued_area_um2"][-1]),
                         "debonded_bonds": int(d["debonded_bonds"][-1]), "broken_tethers": int(d["broken_tethers"][-1])})
        self.S["inflation"] = rows
        if not rows:
            return
        s = self.settings(rows[0]["run"], "in.tissue-inflate")
        self.w("## Inflation", "", f"`in.tissue-inflate` (Lp {s['Lp']:g} um/(kPa us), mu {s['mu']:g} mPa s, then a "
               f"{s['nsettle']:.0f}-step settle under "
               "a drag with osmosis on, so that the tissue is at rest): the state at its end, which "
               "every experiment continues from (Lp 1e-9 then: the cells keep their water). Mass change: relative "
               f"growth of the fluid mass over the last {s['every']:.0f} steps (how far from osmotic equilibrium).", "",
               f"| run | cells | time (us) | P mean / min / max (kPa) | mean tether stretch | mass change, last {s['every']:.0f} steps | "
               "glued area (um^2) | debonded bonds | broken tethers |", "|" + "---|" * 9)
        for r in rows:
            self.w(f"| {r['run']} | {r['what']} | {fmt(r['time_us'])} | {fmt(r['P_mean_kPa'])} / {fmt(r['P_min_kPa'])} / "
                   f"{fmt(r['P_max_kPa'])} | {r['stretch_mean']:.4f} | {pct(r['mass_change_last_interval'], 2)} | "
                   f"{fmt(r['glued_area_um2'])} | {r['debonded_bonds']} | {r['broken_tethers']} |")
        self.w("")

    # ------------------------------------------------------------------ wall times
    def walltimes(self):
        w = self.w
        total = sum(v[0] for v in self.times.values())
        w("## Wall times", "", "Runs two at a time on the machine's cores, one MPI rank each (tools/tissue.sh "
          "`JOBS`, `NP`); the elapsed time of the whole script is about half the sum.", "",
          "| stage | wall time (s) | status |", "|---|---|---|")
        for k, (s, st) in self.times.items():
            w(f"| {k} | {s} | {st} |")
        w(f"| sum | {total} | |", "")
        el = None
        lines = self.info.splitlines()
        import datetime as dt
        try:
            st = [ln for ln in lines if ln.startswith("# started")][0].split()[2:4]
            fi = [ln for ln in lines if ln.startswith("# finished")][0].split()[2:4]
            f = "%Y-%m-%d %H:%M:%S"
            el = (dt.datetime.strptime(" ".join(fi), f) - dt.datetime.strptime(" ".join(st), f)).total_seconds()
            w(f"Elapsed (first run to last): {el:.0f} s.", "")
        except (IndexError, ValueError):
            pass
        self.S["wall_times_s"] = {k: {"s": s, "status": st} for k, (s, st) in self.times.items()}
        self.S["wall_time_sum_s"] = total
        self.S["elapsed_s"] = el

    def write(self):
        ncell = int(self.block["cells"])
        head = [f"# Tissue experiments ({self.res})", "",
                f"Generated by `RES={self.res} bash tools/tissue.sh` (tools/cellmech/tissue/report.py). Coarse level-3 walls "
                f"(642 nodes per cell, ~440 fluid particles), `-var s 6.4 -var r0 3.2 -var f0 8e4`, reach and "
                f"extra/special/per/atom from the generator's statistics (max(4.0, recommended_reach)). Block: "
                f"{ncell} cells. Units: um, us, pg; force nN (uN = 1000 nN), stress kPa, energy pJ = 1000 nN um.", "",
                "Run settings:", "", "```", self.info.strip(), "```", ""]
        self.md = head + self.md
        with open(os.path.join(self.report, "tissue.md"), "w") as f:
            f.write("\n".join(self.md) + "\n")
        self.S["cells"] = ncell
        self.S["run_info"] = self.info.strip().splitlines()

        def clean(o):
            if isinstance(o, dict):
                return {k: clean(v) for k, v in o.items()}
            if isinstance(o, (list, tuple)):
                return [clean(v) for v in o]
            if isinstance(o, (np.floating,)):
                return float(o)
            if isinstance(o, (np.integer,)):
                return int(o)
            if isinstance(o, (np.bool_,)):
                return bool(o)
            return o
        with open(os.path.join(self.report, "tissue-summary.json"), "w") as f:
            json.dump(clean(self.S), f, indent=1)


def splice_water(rep):
    """The Water section alone, in place of the one in REPORT/tissue.md (before "## Pictures" if it
    has none), and its key in tissue-summary.json; the rest of both files stays as it is."""
    water.section(rep)
    path = os.path.join(rep.report, "tissue.md")
    lines = open(path).read().split("\n") if os.path.exists(path) else []
    heads = [k for k, ln in enumerate(lines) if ln.startswith("## ")]
    start = next((k for k in heads if lines[k] == "## Water"), None)
    if start is None:
        end = start = next((k for k in heads if lines[k] in ("## Pictures", "## Wall times")), len(lines))
    else:
        end = next((k for k in heads if k > start), len(lines))
    lines[start:end] = rep.md
    with open(path, "w") as f:
        f.write("\n".join(lines).rstrip("\n") + "\n")
    jp = os.path.join(rep.report, "tissue-summary.json")
    summary = json.load(open(jp)) if os.path.exists(jp) else {}
    summary["water"] = json.loads(json.dumps(rep.S["water"], default=float))
    with open(jp, "w") as f:
        json.dump(summary, f, indent=1)
    print(f"report: the Water section of {path}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--run", required=True)
    ap.add_argument("--res", default="coarse")
    ap.add_argument("--report", required=True)
    ap.add_argument("--figs")
    ap.add_argument("--only", choices=["water"],
                    help="write only this section into the existing tissue.md and summary (the other "
                    "sections stay as they are)")
    a = ap.parse_args()
    run = os.path.abspath(a.run)
    rep = Report(run, a.res, os.path.abspath(a.report), os.path.abspath(a.figs or a.report))
    if a.only:
        splice_water(rep)
        return
    for part in (rep.inflations, rep.pair, rep.blocks, rep.impacts, lambda: water.section(rep), rep.pictures,
                 rep.walltimes):
        try:
            part()
        except Exception as e:  # report what is there
            import traceback
            traceback.print_exc()
            rep.w(f"({part.__name__}: failed in the report: {e})", "")
    rep.write()
    print(f"report: {os.path.join(rep.report, 'tissue.md')}")


if __name__ == "__main__":
    main()
