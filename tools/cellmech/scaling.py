# SPDX-License-Identifier: GPL-2.0-or-later
"""Parallel cost of a tissue run: what a LAMMPS log says about each rank, and the expected parallel
efficiency on many ranks from the measured compute and communication (tools/benchmark-tissue.sh,
docs/tissue-benchmark.md).

The projection is a model on paper, not a measurement: every step a rank computes its cells and the
ghost atoms around its subdomain, swaps the halo of those ghosts with its neighbours (the exchanges
of the force field, HALO_DOUBLES per ghost atom) and joins the global reductions of one step
(`reductions`). The network enters as a latency alpha and a bandwidth beta, stated by the caller."""
import math
import re

from . import reporting as rp

SECTIONS = ("Pair", "Bond", "Neigh", "Comm", "Output", "Modify")

# Halo exchanges of one step of the tissue force field, doubles per ghost atom: positions and
# velocities (comm_modify vel yes, 6), pair cell/sph's density and mass (forward, 2), its density
# rate (reverse, 1), the forces (reverse, newton on, 3)
HALO_EXCHANGES = 4
HALO_DOUBLES = 6 + 2 + 1 + 3


def reductions(ncells):
    """Global reductions of one tissue step: (count, doubles) each. The neighbour-list check
    (neigh_modify check yes, one int) and fix cell/fluid's per-cell sums while osmosis is on (8 per
    cell slot, ncells + 1). The failure bookkeeping of the lamella and the walls reduces two ints
    once per neighbour build, not per step (FixCellFailure), and is left out."""
    return [(1, 1), (1, 8 * (ncells + 1))]


def parse_log(text):
    """The last run of a LAMMPS log: loop time, steps, atoms, ranks, neighbour-list builds, each
    timing section as (min, avg, max) seconds over the ranks, and Nlocal / Nghost as
    (ave, max, min) over the ranks."""
    runs = re.findall(r"Loop time of ([\d.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    if not runs:
        raise ValueError("no 'Loop time of' line: the run did not finish")
    t, np_, steps, atoms = runs[-1]
    tail = text[text.rfind("MPI task timing breakdown"):]
    sec = {}
    for name in SECTIONS:
        m = re.search(rf"^{name}\s*\|\s*([\d.eE+-]+)\s*\|\s*([\d.eE+-]+)\s*\|\s*([\d.eE+-]+)\s*\|", tail, re.M)
        if m:
            sec[name] = tuple(float(v) for v in m.groups())
    hist = {}
    for name in ("Nlocal", "Nghost"):
        m = re.search(rf"^{name}:\s*([\d.eE+-]+) ave\s+([\d.eE+-]+) max\s+([\d.eE+-]+) min", tail, re.M)
        hist[name] = tuple(float(v) for v in m.groups()) if m else (0.0, 0.0, 0.0)
    builds = re.findall(r"Neighbor list builds = (\d+)", tail)
    return dict(loop=float(t), ranks=int(np_), steps=int(steps), atoms=int(atoms),
                builds=int(builds[-1]) if builds else 0, sections=sec, nlocal=hist["Nlocal"],
                nghost=hist["Nghost"])


def imbalance(run):
    """Most particles on a rank over the mean: the time lost to an uneven split when every
    particle costs the same (1: even)."""
    ave, mx, _ = run["nlocal"]
    return mx / ave if ave > 0 else 1.0


def work_imbalance(run):
    """The larger of the particle imbalance and the spread of the pair forces' time over the ranks
    (max / avg of LAMMPS's Pair, a section with no collective call in it, so no waiting): wall nodes
    and fluid particles cost differently, which Nlocal alone does not see."""
    pair = run["sections"].get("Pair", (0.0, 0.0, 0.0))
    return max(imbalance(run), pair[2] / pair[1] if pair[1] > 0 else 1.0)


def ghost_atoms(cells_per_rank, cell_volume, atoms_per_cell, cutoff):
    """Ghost atoms of a cubic subdomain holding cells_per_rank cells of volume cell_volume at
    atoms_per_cell each: the atom density times the shell of thickness cutoff (LAMMPS's ghost
    cutoff) around it, (L + 2 c)^3 - L^3."""
    edge = (cells_per_rank * cell_volume) ** (1.0 / 3.0)
    return atoms_per_cell / cell_volume * ((edge + 2.0 * cutoff) ** 3 - edge ** 3)


def allreduce_time(nranks, doubles, alpha, beta):
    """Seconds of one MPI_Allreduce of `doubles` on nranks: a tree of ceil(log2 P) latencies and,
    for the data, a reduce-scatter plus allgather (2 (P-1)/P of the message over the bandwidth
    beta, bytes/s)."""
    if nranks <= 1:
        return 0.0
    return math.ceil(math.log2(nranks)) * alpha + 2.0 * (nranks - 1) / nranks * 8.0 * doubles / beta


def halo_time(nghost, alpha, beta, swaps=6):
    """Seconds of one step's halo exchanges: HALO_EXCHANGES exchanges of `swaps` messages (a 3-d
    brick: two per dimension), each a latency, and HALO_DOUBLES doubles per ghost atom over beta."""
    return HALO_EXCHANGES * swaps * alpha + 8.0 * HALO_DOUBLES * nghost / beta


def project(nranks, ncells, t_cell, cell_volume, atoms_per_cell, cutoff, ghost_cost, imbalance,
            alpha, beta):
    """Expected parallel efficiency of a tissue of ncells cells on nranks ranks.

    t_cell: seconds per cell-step on one rank (compute only); ghost_cost: seconds per ghost atom
    per step (the work a ghost adds: binning, pairs across the boundary); imbalance: most work on a
    rank over the mean after balancing. Returns dict(efficiency, compute, ghost, halo, reduce,
    nghost, cells_per_rank), times in seconds per step."""
    per_rank = ncells / nranks
    compute = per_rank * t_cell * imbalance
    nghost = ghost_atoms(per_rank, cell_volume, atoms_per_cell, cutoff) if nranks > 1 else 0.0
    ghost = ghost_cost * nghost
    halo = halo_time(nghost, alpha, beta) if nranks > 1 else 0.0
    reduce = sum(k * allreduce_time(nranks, d, alpha, beta) for k, d in reductions(ncells))
    total = compute + ghost + halo + reduce
    return dict(efficiency=ncells * t_cell / nranks / total, compute=compute, ghost=ghost, halo=halo,
                reduce=reduce, nghost=nghost, cells_per_rank=per_rank)


# ---- the report of tools/benchmark-tissue.sh

NETWORKS = ((2e-6, 5e9), (5e-6, 1e9), (1e-6, 10e9))   # (alpha s, beta bytes/s): InfiniBand, slow, fast


def _pct(run, name):
    return 100.0 * run["sections"].get(name, (0.0, 0.0, 0.0))[1] / run["loop"]


def report(work, steps, warm, settle, load_before, lammps, load_after=None):
    """The markdown report of a benchmark-tissue.sh work folder: runs log.CASE.NP.BALANCE, data
    statistics CASE.json (cellgen.py tissue --stats)."""
    runs, stats = load_work(work)
    if load_after is None:
        with open("/proc/loadavg") as f:
            load_after = " ".join(f.read().split()[:3])
    blocks = sorted((c for c in stats if c.startswith("block")), key=lambda c: stats[c]["cells"])
    order = blocks + sorted(c for c in stats if not c.startswith("block"))
    out = measured_table(runs, stats, order, steps, warm, settle, load_before, load_after, lammps)
    out += per_rank_table(runs, order)
    # ---- the projection
    fit = [(stats[c]["neighbours_mean"], runs[(c, 1, "0")]["loop"] / runs[(c, 1, "0")]["steps"] / stats[c]["cells"])
           for c in blocks if stats[c]["cells"] > 1 and (c, 1, "0") in runs]
    pair = [c for c in blocks if stats[c]["cells"] > 1 and (c, 1, "0") in runs and (c, 2, "0") in runs]
    projected = {}
    if len(fit) < 2 or not pair:
        out += ["", "(no projection: it needs two blocks of more than one cell on 1 rank and one on 2 ranks)"]
    else:
        lines, projected = projection(work, runs, stats, fit, pair)
        out += lines
        out += ["", "Reproduce with `bash tools/benchmark-tissue.sh -r 3 -o docs/tissue-benchmark.md` (about 8 "
                "minutes on 2 cores). What the figures say: docs/performance.md, section \"Tissues on MPI\"."]
    out[2:2] = [summary(runs, stats, order, steps, projected), ""]
    return "\n".join(out) + "\n"


def summary(runs, stats, order, steps, projected):
    """The report's opening paragraph in plain words: what ran, the measured 2-rank efficiencies,
    the projection's efficiencies on the InfiniBand network."""
    cases = sorted(stats, key=order.index)
    ranks = sorted({k[1] for k in runs})
    sizes = ", ".join(f"{c}: {stats[c]['cells']} cell{'' if stats[c]['cells'] == 1 else 's'}" for c in cases)
    said = [f"Each of {len(cases)} tissues ({sizes}) ran "
            f"{steps} timed steps on {' and '.join(str(r) for r in ranks)} MPI rank(s)."]
    eff = {k: runs[(k[0], 1, "0")]["loop"] / r["loop"] / k[1] for k, r in runs.items()
           if k[1] > 1 and (k[0], 1, "0") in runs}
    if eff:
        lo, hi = min(eff, key=eff.get), max(eff, key=eff.get)
        said.append(f"On more ranks than one, the parallel efficiency measured here runs from {100 * eff[lo]:.0f}% "
                    f"({lo[0]}, {lo[1]} ranks, balance {_bal_name(lo[2])}) to {100 * eff[hi]:.0f}% "
                    f"({hi[0]}, {hi[1]} ranks, balance {_bal_name(hi[2])}).")
    if projected:
        said.append("The model projects a 1000-cell tissue to " + " and ".join(
            f"{100 * e:.0f}% on {P} ranks" for P, e in sorted(projected.items()))
            + " on an InfiniBand-like network (a projection, not a measurement; its assumptions below).")
    said.append("A benchmark has no pass or fail: the numbers are measurements of this machine under the load "
                "stated below.")
    return rp.summary(*said)


def load_work(work):
    """{(case, ranks, balance): parse_log} of the folder's logs and {case: statistics}."""
    import glob
    import json
    import os
    runs, stats = {}, {}
    for path in glob.glob(os.path.join(work, "log.*")):
        _, case, np_, bal = os.path.basename(path).split(".", 3)
        runs[(case, int(np_), bal)] = parse_log(open(path).read())
        stats[case] = json.load(open(os.path.join(work, case + ".json")))
    return runs, stats


def cpu_name():
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    return "?"


def _bal_name(b):
    return "off" if b == "0" else b


def measured_table(runs, stats, order, steps, warm, settle, load_before, load_after, lammps):
    """The report's head and the table of every run measured."""
    import os
    out = ["# Tissue benchmark", "",
           f"machine: {os.cpu_count()} cores, {cpu_name()}; load before the runs {load_before}, after {load_after}; "
           f"LAMMPS {lammps}",
           f"each case: in.tissue-inflate's {warm} steps of inflation (Lp 10, Pi -364 kPa) and {settle} of its "
           f"settle, then {steps} timed steps (dt 0.001 us). neighbours/cell: glued neighbour cells (6 inside a "
           "large block); speed-up and efficiency: against the same case on one rank; imbalance: most "
           "particles on a rank over the mean (LAMMPS's Nlocal); builds: neighbour-list builds in the timed "
           "steps; the sections: % of the loop time, averaged over the ranks", ""]
    out += rp.table(["case", "cells", "neighbours/cell", "atoms", "ranks", "balance", "particle-steps/s",
                     "cell-steps/s", "speed-up", "efficiency", "imbalance", "builds", "Pair %", "Bond %",
                     "Neigh %", "Comm %", "Modify %"])
    for (case, np_, bal) in sorted(runs, key=lambda k: (order.index(k[0]), k[1], k[2])):
        r, st = runs[(case, np_, bal)], stats[case]
        cells = st["cells"]
        one = runs.get((case, 1, "0"))
        su = one["loop"] / r["loop"] if one else float("nan")
        out.append(f"| {case} | {cells} | {st['neighbours_mean'] if cells > 1 else 0:.2g} | {r['atoms']} | "
                   f"{np_} | {_bal_name(bal)} | {r['atoms'] * r['steps'] / r['loop']:.3g} | "
                   f"{cells * r['steps'] / r['loop']:.4g} | {su:.2f} | {100 * su / np_:.0f}% | "
                   f"{imbalance(r):.3f} | {r['builds']} | "
                   + " | ".join(f"{_pct(r, k):.1f}" for k in ("Pair", "Bond", "Neigh", "Comm", "Modify")) + " |")
    return out


def per_rank_table(runs, order):
    """The timing sections of every run on more than one rank, min / avg / max over the ranks."""
    multi = sorted((k for k in runs if k[1] > 1), key=lambda k: (order.index(k[0]), k[1], k[2]))
    if not multi:
        return []
    out = ["", "## Per rank", "",
           "LAMMPS's timing sections in seconds, min / avg / max over the ranks, with the particles "
           "(Nlocal) and ghost atoms (Nghost) of the least and the most loaded rank. A rank that waits "
           "for another at a collective step books the wait in the section it waits in.", ""]
    out += rp.table(["case", "ranks", "balance", "Nlocal min-max", "Nghost min-max", "Pair", "Bond", "Neigh",
                     "Comm", "Modify"])
    for k in multi:
        r = runs[k]
        sec = " | ".join("{:.3g} / {:.3g} / {:.3g}".format(*r["sections"][s])
                         for s in ("Pair", "Bond", "Neigh", "Comm", "Modify"))
        out.append(f"| {k[0]} | {k[1]} | {_bal_name(k[2])} | {r['nlocal'][2]:.0f}-{r['nlocal'][1]:.0f} | "
                   f"{r['nghost'][2]:.0f}-{r['nghost'][1]:.0f} | {sec} |")
    return out


def ghost_charge(runs, stats, pair):
    """What 2 ranks cost beyond half the 1-rank time, less the uneven split and the communication,
    per ghost atom: a fit through zero over the blocks (one block alone is at the mercy of noise).
    Returns the charge (s per ghost atom and step) and a line of words per block."""
    import numpy as np
    xs, ys, lines = [], [], []
    for c in pair:
        one, two = runs[(c, 1, "0")], runs[(c, 2, "0")]
        comm, imb = two["sections"]["Comm"][1], imbalance(two)
        rest = two["loop"] - one["loop"] / 2.0 * imb - comm
        xs.append(two["nghost"][0])
        ys.append(rest / two["steps"])
        lines.append(f"{stats[c]['cells']} cells: {two['loop']:.3f} s on 2 ranks against {one['loop'] / 2:.3f} s "
                     f"(half of 1 rank), of the {two['loop'] - one['loop'] / 2:.3f} s more the uneven split "
                     f"(imbalance {imb:.4f}) takes {one['loop'] / 2 * (imb - 1):.3f} s, communication (Comm, "
                     f"average over the ranks) {comm:.3f} s, the rest {rest:.3f} s on {two['nghost'][0]:.0f} "
                     f"ghost atoms a rank ({1e9 * ys[-1] / xs[-1]:.0f} ns per ghost atom and step)")
    xs, ys = np.array(xs), np.array(ys)
    return max(float(xs @ ys / (xs @ xs)), 0.0), lines


def projection(work, runs, stats, fit, pair):
    """The section on a 1000-cell tissue on 64 and 256 ranks: the measured inputs and the model's
    table, and the efficiencies it projects on the first network, {ranks: efficiency}."""
    import os
    import numpy as np
    f, t = np.array(fit).T
    b, a = np.polyfit(f, t, 1)
    t_cell = a + 6.0 * b
    ghost_cost, lines = ghost_charge(runs, stats, pair)
    big = pair[-1]
    st = stats[big]
    text = open(os.path.join(work, f"log.{big}.2.0")).read()
    cutoff = float(re.search(r"ghost atom cutoff = ([\d.eE+-]+)", text).group(1))
    vcell = st.get("block_volume", st["box_volume"]) / st["cells"]
    apc = runs[(big, 1, "0")]["atoms"] / st["cells"]
    # blocks split evenly are balanced by symmetry; the notch only with balancing on
    even = [work_imbalance(r) for (c, np_, bl), r in runs.items()
            if np_ > 1 and (bl != "0" or (c in pair))]
    imb_p = max(even)
    out = ["", "## A 1000-cell tissue on 64 and 256 ranks: a projection, not a measurement", "",
           f"Measured here: the time per cell-step on one rank is t = {1e6 * a:.1f} + {1e6 * b:.2f} f us over "
           f"the blocks (f: glued neighbours per cell), {1e6 * t_cell:.0f} us for a cell inside a tissue "
           f"(f = 6). On 2 ranks:", ""] + [f"- {ln}" for ln in lines] + [
           "", f"The fit through zero over these blocks charges {1e9 * ghost_cost:.0f} ns per ghost atom and "
           f"step (a particle of the tissue costs {1e9 * t_cell / (runs[(big, 1, '0')]['atoms'] / st['cells']):.0f} "
           "ns a step on one rank). It holds whatever 2 ranks lose besides the split and Comm: the ghosts' "
           "binning and the pairs across the cut, and also an uneven work per particle that Nlocal does not "
           "see, so the projection is pessimistic." + (" (None measurable: ghosts are charged nothing.)"
                                                       if ghost_cost == 0 else ""), "",
           f"Model (tools/cellmech/scaling.py, `project`): P cubic subdomains of 1000/P cells of "
           f"{vcell:.4g} um^3 and {apc:.0f} particles each; the ghost shell of LAMMPS's ghost cutoff "
           f"{cutoff:g} um around each; the most loaded rank at the largest imbalance measured here on "
           f"2 ranks in a balanced run, in particles or in the pair forces' time ({imb_p:.3f}); {HALO_EXCHANGES} halo exchanges per step ({HALO_DOUBLES} doubles per ghost "
           "atom, 6 messages each); the step's global reductions (the neighbour check's single integer and fix cell/fluid's "
           f"{8 * 1001} per-cell sums while osmosis is on). Network: latency alpha and bandwidth beta, "
           "about 2 us and 5 GB/s on an InfiniBand cluster; the other rows show a slower and a faster one. "
           "Efficiency: 1000 t / P over the time of the step on P ranks.", ""]
    out += projection_table(t_cell, vcell, apc, cutoff, ghost_cost, imb_p)
    alpha, beta = NETWORKS[0]
    return out, {P: project(P, 1000, t_cell, vcell, apc, cutoff, ghost_cost, imb_p, alpha, beta)["efficiency"]
                 for P in (64, 256)}


def projection_table(t_cell, vcell, apc, cutoff, ghost_cost, imb_p):
    out = rp.table(["ranks", "cells/rank", "ghost atoms/rank", "ns per ghost", "compute ms", "ghosts ms",
                    "halo ms", "reductions ms", "alpha us", "beta GB/s", "efficiency"])
    # the ghost charge is a small difference of two measured times; the last rows bound it by half
    # the whole cost of a particle (a ghost has no forces or integration of its own)
    half = 0.5 * t_cell / apc
    rows = [(P, net, ghost_cost) for P in (2, 64, 256) for net in NETWORKS[:1]]
    rows += [(P, net, ghost_cost) for P in (64, 256) for net in NETWORKS[1:]]
    rows += [(P, NETWORKS[0], half) for P in (64, 256)]
    for P, (alpha, beta), g in rows:
        pr = project(P, 1000, t_cell, vcell, apc, cutoff, g, imb_p, alpha, beta)
        out.append(f"| {P} | {pr['cells_per_rank']:.3g} | {pr['nghost']:.0f} | {1e9 * g:.0f} | "
                   f"{1e3 * pr['compute']:.3f} | {1e3 * pr['ghost']:.3f} | {1e3 * pr['halo']:.4f} | "
                   f"{1e3 * pr['reduce']:.4f} | {1e6 * alpha:g} | {beta / 1e9:g} | {100 * pr['efficiency']:.0f}% |")
    out.append("\nThe 2-rank row is the model's, for 1000 cells; the measured 2-rank efficiencies are in the "
               "first table. The last two rows charge each ghost atom half of what a particle costs on one "
               "rank: a bound on the ghost charge, which the blocks above cannot resolve from noise and "
               "cache effects (a block whose particles no longer fit the cache of one core runs faster "
               "than twice as fast on two).")
    return out


def main(argv=None):
    import argparse
    p = argparse.ArgumentParser(description="report of a tools/benchmark-tissue.sh work folder")
    p.add_argument("work")
    p.add_argument("--steps", type=int, required=True)
    p.add_argument("--warm", type=int, required=True)
    p.add_argument("--settle", type=int, required=True)
    p.add_argument("--load-before", default="?")
    p.add_argument("--load-after", help="load average after the runs (default: now)")
    p.add_argument("--lammps", default="?")
    a = p.parse_args(argv)
    print(report(a.work, a.steps, a.warm, a.settle, a.load_before, a.lammps, a.load_after), end="")


if __name__ == "__main__":
    main()
