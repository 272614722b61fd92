# SPDX-License-Identifier: GPL-2.0-or-later
"""The "Water" section of the tissue report (tools/tissue.sh stages water-*): one cell against
external water potentials (in.water-potential), two cells of different Pi (in.water-pair) and a
2x2x2 block dried to 20% of its water (in.tissue-dry), with CSV files, plots and wall pictures."""
import glob
import math
import os

import numpy as np

from .. import params
from . import tissuedata as T

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FRACTIONS = (1.0, 0.8, 0.6, 0.4, 0.2)   # water contents of the pictures (nearest VTK frame)


def read_csv(path):
    a = np.genfromtxt(path, delimiter=",", names=True)
    return {k: np.atleast_1d(a[k]) for k in a.dtype.names}


def read_vtk(path):
    """Points and triangles of a legacy ASCII VTK file of fix cell/vtk."""
    with open(path) as f:
        lines = f.read().split("\n")
    i = next(k for k, ln in enumerate(lines) if ln.startswith("POINTS"))
    n = int(lines[i].split()[1])
    pts = np.array([list(map(float, ln.split())) for ln in lines[i + 1:i + 1 + n]])
    j = next(k for k, ln in enumerate(lines) if ln.startswith("POLYGONS"))
    m = int(lines[j].split()[1])
    tri = np.array([list(map(int, ln.split()[1:4])) for ln in lines[j + 1:j + 1 + m]])
    return pts, tri


def read_dump(path):
    """id mol x y z mass d_rho of a dump custom snapshot."""
    with open(path) as f:
        lines = f.read().split("\n")
    i = next(k for k, ln in enumerate(lines) if ln.startswith("ITEM: ATOMS"))
    return np.array([list(map(float, ln.split())) for ln in lines[i + 1:] if ln.strip()])


def shape(cells, gyr):
    """Per cell: sphericity pi^(1/3) (6V)^(2/3) / A (1 for a sphere, 0.806 for a cube) and
    elongation sqrt(g1/g3) of the wall nodes' gyration tensor (1 for a sphere or a cube)."""
    V, A = cells[:, 0], cells[:, 1]
    sph = math.pi ** (1 / 3) * (6 * V) ** (2 / 3) / A
    el = []
    for g in gyr:
        G = np.array([[g[0], g[3], g[4]], [g[3], g[1], g[5]], [g[4], g[5], g[2]]])
        ev = np.linalg.eigvalsh(G)
        el.append(math.sqrt(ev[-1] / ev[0]))
    return sph, np.array(el)


def plane_section(pts, tri, centre, axis):
    """The section of a closed, outward-oriented triangulated wall by the plane through centre
    normal to the unit vector axis, as a microscope slice sees it: (area, perimeter, Feret
    diameter, elongation). Each triangle that crosses the plane gives one segment, oriented along
    axis x n_triangle (counter-clockwise seen from +axis), so that the enclosed area is the sum of
    the segments' signed triangles about centre, with no need to join them into a loop. Feret: the
    largest distance between two points of the section; elongation: sqrt of the ratio of the
    principal second moments of the section line (1 for a circle, a/b for an ellipse's outline
    only approximately, as for any closed curve)."""
    d = (pts - centre) @ axis
    segs = []
    for t in tri:
        p, dt = pts[t], d[t]
        # a node on the plane counts as below it, so that an edge in the plane is cut once, by the
        # triangle above it
        up = dt > 0.0
        if up.all() or not up.any():
            continue
        cut = []
        for a, b in ((0, 1), (1, 2), (2, 0)):
            if up[a] != up[b]:
                cut.append(p[a] + dt[a] / (dt[a] - dt[b]) * (p[b] - p[a]))
        n = np.cross(p[1] - p[0], p[2] - p[0])
        a_, b_ = cut
        if np.dot(b_ - a_, np.cross(axis, n)) < 0.0:
            a_, b_ = b_, a_
        segs.append((a_, b_))
    if not segs:
        return None
    a_ = np.array([s[0] for s in segs]) - centre
    b_ = np.array([s[1] for s in segs]) - centre
    area = 0.5 * float(np.sum(np.cross(a_, b_) @ axis))
    length = np.linalg.norm(b_ - a_, axis=1)
    ends = np.concatenate([a_, b_])
    feret = float(np.max(np.linalg.norm(ends[:, None] - ends[None], axis=2)))
    mid = 0.5 * (a_ + b_)
    mid = mid - (length[:, None] * mid).sum(0) / length.sum()
    ev = np.linalg.eigvalsh((length[:, None, None] * mid[:, :, None] * mid[:, None, :]).sum(0))
    # the two in-plane principal values (the third, along axis, is ~0)
    ev = np.sort(ev)[1:]
    return area, float(length.sum()), feret, math.sqrt(ev[1] / ev[0])


def cell_sections(pts, tri, cell):
    """Mean over the cells and over the three planes through each cell's node centroid normal to x,
    y and z of the section's area, perimeter, Feret diameter, elongation and perimeter /
    sqrt(area), in that order."""
    tcell = cell[tri[:, 0]]
    out = []
    for c in np.unique(cell):
        own = tri[tcell == c]
        centre = pts[cell == c].mean(axis=0)
        for axis in np.eye(3):
            s = plane_section(pts, own, centre, axis)
            if s is not None:
                out.append(s + (s[1] / math.sqrt(s[0]),))
    return np.mean(np.array(out), axis=0)


# Hot-air-dried Gala apple parenchyma, SEM, mean cell of the sections (Drying Technology 32(4),
# 455-468 (2014), doi:10.1080/07373937.2013.837479, its abstract): fresh cell area 20000 um^2,
# Feret diameter 160 um, perimeter 600 um, elongation 1.45; at the end of drying about -60%, -40%,
# -30% and +5%.
PUBLISHED_SECTIONS = dict(fresh=dict(area=20000.0, perimeter=600.0, feret=160.0, elongation=1.45),
                          dried=dict(area=-0.60, perimeter=-0.30, feret=-0.40, elongation=0.05))
SECTION_KEYS = ("area", "perimeter", "feret", "elongation", "p_sqrt_a")


def section_rows(rep, name, d):
    """The wall's mid-plane sections at each VTK frame of stage NAME: {water fraction: {key: mean}}
    (SECTION_KEYS), the frames' water from the run's CSV by step."""
    frames = sorted(glob.glob(rep.p(f"{name}/dry-walls.*.vtk")), key=lambda f: int(f.split(".")[-2]))
    dt = params.run_settings(rep.p(name), "in.tissue-dry")["dt"]
    wsteps = np.rint(d["time_us"] / dt).astype(int)
    rows = {}
    for f in frames:
        pts, tri = read_vtk(f)
        w = float(np.interp(int(f.split(".")[-2]), wsteps, d["water_fraction"]))
        rows[w] = dict(zip(SECTION_KEYS, map(float, cell_sections(pts, tri, read_vtk_cells(f)))))
    return rows


def section_text(rows):
    """The sections against the published apple cells (lines for rep.w)."""
    if not rows:
        return []
    # the frames nearest the pictures' water contents, the first and the last
    allw = sorted(rows, reverse=True)
    ws = sorted({allw[0], allw[-1], *(min(allw, key=lambda w: abs(w - f)) for f in FRACTIONS)}, reverse=True)
    first, last = rows[ws[0]], rows[ws[-1]]
    pub, fresh = PUBLISHED_SECTIONS["dried"], PUBLISHED_SECTIONS["fresh"]
    head = "| water | " + " | ".join(f"{w:.0%}" for w in ws) + " | apple, end of hot-air drying |"
    lines = [head, "|---|" + "---|" * len(ws) + "---|"]
    names = dict(area="section area", perimeter="perimeter", feret="Feret diameter", elongation="elongation")
    for k in ("area", "perimeter", "feret", "elongation"):
        lines.append(f"| {names[k]} | " + " | ".join(f"{rows[w][k] / first[k] - 1:+.1%}" for w in ws)
                     + f" | {pub[k]:+.0%} |")
    p_fresh = fresh["perimeter"] / math.sqrt(fresh["area"])
    p_dried = p_fresh * (1 + pub["perimeter"]) / math.sqrt(1 + pub["area"])
    iso = dict(area=2.0 / 3.0, perimeter=1.0 / 3.0, feret=1.0 / 3.0)
    lines.append("| isotropic: area, lengths | " + " | ".join(f"{w ** iso['area'] - 1:+.1%}, {w ** iso['feret'] - 1:+.1%}"
                                                          for w in ws) + " | |")
    lines.append("| perimeter / sqrt(area) | " + " | ".join(f"{rows[w]['p_sqrt_a']:.3f}" for w in ws)
                 + f" | {p_fresh:.2f} -> {p_dried:.2f} |")
    ratio = (1 + pub["perimeter"]) / (1 + pub["feret"])
    return ["*The cells as a microscope sees them.* Sections of each cell's wall through its centre, normal "
            "to x, y and z (24 sections), their mean against that at full turgor, beside hot-air-dried Gala "
            "apple parenchyma measured on SEM sections (Drying Technology 32(4), 455-468 (2014), "
            "doi:10.1080/07373937.2013.837479: fresh cells of 20000 um^2, Feret diameter 160 um; the changes "
            "at the end of drying as its abstract gives them, at a moisture content given in the paper, not "
            "here), and beside a cell that shrinks with its water in all directions alike (section area ~ "
            "W^(2/3), lengths ~ W^(1/3), the reference of a slack wall):", "",
            *lines, "",
            f"At {ws[-1]:.0%} water the model's sections have lost {-(last['area'] / first['area'] - 1):.0%} of "
            f"their area ({1 - ws[-1] ** iso['area']:.0%} if the cells shrank alike in all directions), the apple "
            f"cells about {-pub['area']:.0%} by the end of drying. In both the perimeter "
            f"falls less than the Feret diameter (apple: perimeter / Feret {ratio:.2f} of the fresh ratio; "
            f"model: {(last['perimeter'] / first['perimeter']) / (last['feret'] / first['feret']):.2f}): the wall "
            "keeps more length than a convex outline of the same size would, warped in the apple, crumpled here. "
            "A matched comparison needs the published curves against moisture (only the paper's abstract was "
            "read here).", ""]


def potential(rep, S):
    p = rep.p("water-potential/water-potential.csv")
    if not os.path.exists(p):
        rep.w("### 1. One cell against external water potentials", "", "Not run or failed.", "")
        return
    d = read_csv(p)
    T.write_csv(rep.fig("water-potential.csv"), d, list(d),
                "in.water-potential: one coarse cell (Pi -364 kPa, Lp 10) per external water potential")
    fig, ax = plt.subplots(1, 3, figsize=(12, 3.4))
    ax[0].plot(d["psi_ext_kPa"], d["turgor_kPa"], "o-", label="turgor")
    ax[0].plot(d["psi_ext_kPa"], d["psi_ext_kPa"] + 364, "k:", label="psi_ext - Pi")
    ax[0].set_ylabel("kPa")
    ax[0].legend()
    ax[1].plot(d["psi_ext_kPa"], d["volume_um3"] / d["volume_um3"][0], "o-", label="volume")
    ax[1].plot(d["psi_ext_kPa"], d["water_pg"] / d["water_pg"][0], "s--", label="water")
    ax[1].set_ylabel("/ value at psi_ext = 0")
    ax[1].legend()
    ax[2].plot(d["psi_ext_kPa"], d["mean_stretch"], "o-", label="mean")
    ax[2].plot(d["psi_ext_kPa"], d["max_stretch"], "s--", label="max")
    ax[2].set_ylabel("tether stretch")
    ax[2].legend()
    for a in ax:
        a.set_xlabel("external water potential (kPa)")
    fig.tight_layout()
    fig.savefig(rep.fig("water-potential.png"), dpi=90)
    plt.close(fig)
    err = float(np.max(np.abs(d["turgor_kPa"] - (d["psi_ext_kPa"] + 364.0))))
    S["potential"] = dict(levels=len(d["psi_ext_kPa"]), max_turgor_error_kPa=err,
                          volume_change=float(d["volume_um3"][-1] / d["volume_um3"][0] - 1),
                          stretch_full=float(d["mean_stretch"][0]), stretch_zero=float(d["mean_stretch"][-1]))
    rep.w("### 1. One cell against external water potentials", "",
          "`in.water-potential` after `in.inflate` (one coarse stiff cell, Pi -364 kPa, Lp 10 um/(kPa us), "
          "a drag brings each level to rest): psi_ext from 0 to Pi in 8 steps. At equilibrium Eq. 10 gives "
          "P = psi_ext - Pi, which the cell reaches at every level to "
          f"{err:.2g} kPa. Volume {100 * S['potential']['volume_change']:.3g}% from full to zero turgor, "
          f"mean tether stretch {S['potential']['stretch_full']:.4f} -> {S['potential']['stretch_zero']:.4f}: "
          "the stiff wall (E = 2.4 GPa) carries turgor at less than 1% stretch, so the cell hardly shrinks "
          "while it loses its turgor.", "",
          f"![one cell]({rep.link('water-potential.png')})", "",
          f"Data: [water-potential.csv]({rep.link('water-potential.csv')}).", "")


def pair(rep, S):
    p = rep.p("water-pair/water-pair.csv")
    if not os.path.exists(p):
        rep.w("### 2. Two cells of different osmotic potentials", "", "Not run or failed.", "")
        return
    d = read_csv(p)
    T.write_csv(rep.fig("water-pair.csv"), d, list(d),
                "in.water-pair: glued pair, cell 1 Pi -364 kPa, cell 2 Pi0 -200 kPa, solute yes, Lp 1, outside shut")
    fig, ax = plt.subplots(1, 3, figsize=(12, 3.4))
    t = d["time_us"]
    ax[0].plot(t, d["water1_pg"], label="cell 1")
    ax[0].plot(t, d["water2_pg"], label="cell 2")
    ax[0].set_ylabel("water (pg)")
    ax[1].plot(t, d["turgor1_kPa"], label="cell 1")
    ax[1].plot(t, d["turgor2_kPa"], label="cell 2")
    ax[1].set_ylabel("turgor (kPa)")
    ax[2].plot(t, d["psi1_kPa"], label="cell 1")
    ax[2].plot(t, d["psi2_kPa"], label="cell 2")
    ax[2].set_ylabel("water potential P + Pi (kPa)")
    for a in ax:
        a.set_xlabel("time (us)")
        a.legend()
    fig.tight_layout()
    fig.savefig(rep.fig("water-pair.png"), dpi=90)
    plt.close(fig)
    tot = d["water1_pg"] + d["water2_pg"]
    S["pair"] = dict(moved_pg=float(d["uptake1_pg"][-1]), psi_gap_start_kPa=float(d["psi1_kPa"][0] - d["psi2_kPa"][0]),
                     psi_gap_end_kPa=float(d["psi1_kPa"][-1] - d["psi2_kPa"][-1]),
                     total_drift_rel=float(np.max(np.abs(tot - tot[0])) / tot[0]),
                     turgor_end_kPa=[float(d["turgor1_kPa"][-1]), float(d["turgor2_kPa"][-1])])
    q = S["pair"]
    rep.w("### 2. Two cells of different osmotic potentials", "",
          "`in.water-pair`: the inflated glued pair; cell 2 gets Pi0 -200 kPa (solutes kept, Eq. W1), the outside "
          "is shut (`external flux 0`) and water crosses the glued face only (Eqs. W2-W3, Lp 1 um/(kPa us)). "
          f"Cell 1 took up {q['moved_pg']:.4g} pg from cell 2; the gap of the water potentials went from "
          f"{q['psi_gap_start_kPa']:.4g} to {q['psi_gap_end_kPa']:.3g} kPa, turgors at the end "
          f"{q['turgor_end_kPa'][0]:.4g} and {q['turgor_end_kPa'][1]:.4g} kPa; the pair's total water stayed "
          f"within {q['total_drift_rel']:.2g} of its start.", "",
          f"![pair]({rep.link('water-pair.png')})", "",
          f"Data: [water-pair.csv]({rep.link('water-pair.csv')}).", "")


def dry_run(rep, name):
    """Tissue-wide CSV plus per-cell shape, for the rows at which both tables have a record."""
    d = read_csv(rep.p(f"{name}/tissue-dry.csv"))
    cells = dict(T.load_table(rep.p(f"{name}/tissue-dry-cells.dat")))
    gyr = dict(T.load_table(rep.p(f"{name}/tissue-dry-gyration.dat")))
    steps = np.rint(d["time_us"] / 0.001).astype(int)
    sph, el = [], []
    for k, s in enumerate(steps):
        if s in cells and s in gyr:
            a, b = shape(cells[s], gyr[s])
            sph.append(a.mean())
            el.append(b.mean())
        else:
            sph.append(np.nan)
            el.append(np.nan)
    d["sphericity"] = np.array(sph)
    d["elongation"] = np.array(el)
    # the share of the wall-enclosed volume the protoplasm fills at the rest density (rho0 = 1)
    d["fluid_fill"] = d["water_pg"] / d["volume_um3"]
    return d


def fluid_state(pts, cell, fl):
    """Where the protoplasm is: the share of fluid particles within 2 r0 (6.4 um) of a wall node of
    their own cell, and the median distance of a fluid particle to its nearest fluid neighbour."""
    from scipy.spatial import cKDTree
    near, nn = [], []
    for c in np.unique(fl[:, 1]):
        f = fl[fl[:, 1] == c][:, 2:5]
        w = pts[cell == c]
        near.append(cKDTree(w).query(f)[0] < 6.4)
        nn.append(cKDTree(f).query(f, k=2)[0][:, 1])
    return float(np.mean(np.concatenate(near))), float(np.median(np.concatenate(nn)))


def read_vtk_cells(path):
    """The point field 'cell' of a fix cell/vtk file."""
    with open(path) as f:
        lines = f.read().split("\n")
    i = next(k for k, ln in enumerate(lines) if ln.startswith("SCALARS cell int"))
    n = int(next(ln for ln in lines if ln.startswith("POINT_DATA")).split()[1])
    return np.array([int(v) for v in " ".join(lines[i + 2:i + 2 + n]).split()[:n]])


def render(rep, d, S, name="water-dry", what="the 2x2x2 block"):
    """Walls (VTK, the lower layer's cells cut at mid-height of the block) and the fluid particles
    in a slice, at a few water contents: NAME-walls.png of stage NAME."""
    frames = sorted(glob.glob(rep.p(f"{name}/dry-walls.*.vtk")), key=lambda f: int(f.split(".")[-2]))
    if not frames:
        return None
    steps = np.array([int(f.split(".")[-2]) for f in frames])
    wsteps = np.rint(d["time_us"] / params.run_settings(rep.p(name), "in.tissue-dry")["dt"]).astype(int)
    frac = np.interp(steps, wsteps, d["water_fraction"])
    pick = []
    for f in FRACTIONS:
        k = int(np.argmin(np.abs(frac - f)))
        if k not in pick:
            pick.append(k)
    fig = plt.figure(figsize=(3.3 * len(pick), 6.6))
    S["fluid"] = []
    for c, k in enumerate(pick):
        pts, tri = read_vtk(frames[k])
        ax = fig.add_subplot(2, len(pick), c + 1, projection="3d")
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection
        ax.add_collection3d(Poly3DCollection(pts[tri], facecolor="0.75", edgecolor="0.35", linewidth=0.05))
        lo, hi = pts.min(0), pts.max(0)
        ax.set_xlim(lo[0], hi[0]); ax.set_ylim(lo[1], hi[1]); ax.set_zlim(lo[2], hi[2])
        ax.set_box_aspect(hi - lo)
        ax.view_init(20, 35)
        ax.set_axis_off()
        ax.set_title(f"water {frac[k]:.0%}", fontsize=9)
        # the slice |y - y_mid of the first cell layer| < 3 um: wall nodes and fluid
        dump = rep.p(f"{name}/dry-fluid.{steps[k]}.dump")
        ax2 = fig.add_subplot(2, len(pick), len(pick) + c + 1)
        yc = lo[1] + 0.25 * (hi[1] - lo[1])
        sw = np.abs(pts[:, 1] - yc) < 2.0
        ax2.plot(pts[sw, 0], pts[sw, 2], ".", ms=1.5, color="k")
        if os.path.exists(dump):
            fl = read_dump(dump)
            sf = np.abs(fl[:, 3] - yc) < 8.0
            ax2.scatter(fl[sf, 2], fl[sf, 4], s=4, c=fl[sf, 1], cmap="tab10", vmin=1, vmax=10)
            near, nn = fluid_state(pts, read_vtk_cells(frames[k]), fl)
            S["fluid"].append(dict(water=float(frac[k]), near_wall=near, nn_median_um=nn))
        ax2.set_aspect("equal")
        ax2.set_xticks([]); ax2.set_yticks([])
        ax2.set_title("slice: wall nodes (2 um), fluid by cell (8 um)", fontsize=8)
    fig.suptitle(f"in.tissue-dry: {what} (top) and a slice through its first cell layer (bottom)", fontsize=10)
    fig.tight_layout()
    fig.savefig(rep.fig(f"{name}-walls.png"), dpi=90)
    plt.close(fig)
    S["picture_water_fractions"] = [float(frac[k]) for k in pick]
    return f"{name}-walls.png"


def fluid_text(S):
    f = S.get("fluid")
    if not f:
        return ""
    a, b = f[0], f[-1]
    return (f"The share of fluid particles within 6.4 um (2 r0) of their own wall goes from {a['near_wall']:.0%} at "
            f"{a['water']:.0%} water to {b['near_wall']:.0%} at {b['water']:.0%}, the median distance to the nearest "
            f"fluid neighbour from {a['nn_median_um']:.3g} to {b['nn_median_um']:.2g} um.")


def spread(rows):
    """(largest volume difference, largest turgor difference) of the rows of rate_rows."""
    return (max(abs(v["volume_fast"] - v["volume_slow"]) for v in rows.values()),
            max(abs(v["turgor_fast"] - v["turgor_slow"]) for v in rows.values()))


def lp_text(q):
    c = q.get("lp_check")
    if not c:
        return "(not run)"
    dv, dp = spread(c)
    q["lp_check_max_volume_diff"], q["lp_check_max_turgor_diff_kPa"] = dv, dp
    return (f"gives the same enclosed volume to {100 * dv:.2g}% of full turgor's and the same mean pressure to "
            f"{dp:.2g} kPa at equal water content; the pressure, in the fluid's tension below zero turgor, is "
            "what the rate changes most")


def dry_load(rep):
    """(the drying record, the half-conductivity check's or None); the CSVs written."""
    d = dry_run(rep, "water-dry")
    T.write_csv(rep.fig("water-dry.csv"), d, list(d),
                "in.tissue-dry: 2x2x2 coarse block, Pi0 -364 kPa, solute yes, exchange yes, air at -3000 kPa, Lp 2e-4")
    slow = dry_run(rep, "water-dry-slow") if os.path.exists(rep.p("water-dry-slow/tissue-dry.csv")) else None
    return d, slow


def mean_edge(d):
    """The block's size: the mean of its three edges, um."""
    return (d["Lx_um"] + d["Ly_um"] + d["Lz_um"]) / 3


def dry_figure(rep, d, slow, png="water-dry.png"):
    """PNG: volume, area, size, turgor, stretch and cell shape against the water content."""
    x = d["water_fraction"]
    L = mean_edge(d)
    fig, ax = plt.subplots(2, 3, figsize=(13, 7))
    a = ax[0, 0]
    a.plot(x, d["volume_um3"] / d["volume_um3"][0], label="wall-enclosed volume")
    a.plot(x, d["wall_area_um2"] / d["wall_area_um2"][0], label="wall area")
    a.plot(x, L / L[0], label="block size (mean edge)")
    a.plot(x, d["fluid_fill"] / d["fluid_fill"][0], "--", label="protoplasm / enclosed volume")
    a.set_ylabel("/ value at full turgor")
    a.legend(fontsize=7)
    a = ax[0, 1]
    a.plot(x, d["turgor_mean_kPa"], label="mean")
    a.fill_between(x, d["turgor_min_kPa"], d["turgor_max_kPa"], alpha=0.3, label="min-max of the cells")
    a.axhline(0, color="k", lw=0.5)
    a.set_ylabel("turgor (kPa)")
    a.legend(fontsize=7)
    ax[0, 2].plot(x, d["mean_stretch"])
    ax[0, 2].set_ylabel("mean tether stretch")
    a = ax[1, 0]
    a.plot(x, d["sphericity"], label="sphericity")
    a.plot(x, d["elongation"], label="elongation sqrt(g1/g3)")
    a.set_ylabel("cell shape (mean of the cells)")
    a.legend(fontsize=7)
    a = ax[1, 1]
    for k, lab in (("Lx_um", "x"), ("Ly_um", "y"), ("Lz_um", "z")):
        a.plot(x, d[k], label=lab)
    a.set_ylabel("block size (um)")
    a.legend(fontsize=7)
    a = ax[1, 2]
    a.plot(x, d["turgor_mean_kPa"], label="Lp 2e-4")
    if slow is not None:
        a.plot(slow["water_fraction"], slow["turgor_mean_kPa"], "--", label="Lp 1e-4")
    a.set_ylabel("mean turgor (kPa)")
    a.legend(fontsize=7)
    for a in ax.flat:
        a.set_xlabel("water content (fraction of full turgor)")
        a.invert_xaxis()
    fig.tight_layout()
    fig.savefig(rep.fig(png), dpi=90)
    plt.close(fig)


def at(src, f, key):
    """src[key] at water content f (linear between records)."""
    o = np.argsort(src["water_fraction"])
    return float(np.interp(f, src["water_fraction"][o], src[key][o]))


def dry_measure(d, slow):
    """The drying's numbers (rep.S["water"]["dry"]): volume, area and size at a few water contents,
    their spread below 90%, turgor, fill, cell shape, damage, and the half-conductivity check."""
    x = d["water_fraction"]
    V0, A0 = d["volume_um3"][0], d["wall_area_um2"][0]
    L = mean_edge(d)
    L0 = L[0]
    FS = (0.9, 0.8, 0.6, 0.4, 0.2)
    zero = float(x[np.argmax(d["turgor_mean_kPa"] <= 0)]) if np.any(d["turgor_mean_kPa"] <= 0) else None
    q = dict(
        end_fraction=float(x[-1]), time_us=float(d["time_us"][-1]), water0_pg=float(d["water_pg"][0]),
        turgor_zero_at_fraction=zero,
        volume_at={str(f): at(d, f, "volume_um3") / V0 for f in FS if f >= x[-1] - 1e-3},
        area_at={str(f): at(d, f, "wall_area_um2") / A0 for f in FS if f >= x[-1] - 1e-3},
        size_at={str(f): float(np.interp(f, x[::-1], (L / L0)[::-1])) for f in FS if f >= x[-1] - 1e-3},
        below=dict(volume=float(np.ptp(d["volume_um3"][x <= 0.9]) / V0),
                   size=float(np.ptp(L[x <= 0.9]) / L0), area=float(np.ptp(d["wall_area_um2"][x <= 0.9]) / A0),
                   stretch=[float(d["mean_stretch"][x <= 0.9].min()), float(d["mean_stretch"][x <= 0.9].max())]),
        turgor_min_kPa=float(np.min(d["turgor_mean_kPa"])), turgor_end_kPa=float(d["turgor_mean_kPa"][-1]),
        fill_end=float(d["fluid_fill"][-1]), sphericity=[float(d["sphericity"][0]), float(np.nanmin(d["sphericity"])),
                                                         float(d["sphericity"][-1])],
        elongation=[float(d["elongation"][0]), float(np.nanmax(d["elongation"])), float(d["elongation"][-1])],
        broken=int(d["broken"][-1]), debonded=int(d["debonded"][-1]))
    if slow is not None:
        q["lp_check"] = rate_rows(d, slow)
    return q


def rate_rows(fast, slow, fractions=(0.95, 0.9, 0.85, 0.8, 0.75, 0.7)):
    """Two runs of one drying at two conductivities, at the water contents both reach (of
    fractions): mean turgor and enclosed volume (/ the faster run's first) of each."""
    end = max(float(slow["water_fraction"][-1]), float(fast["water_fraction"][-1])) - 1e-3
    V0 = fast["volume_um3"][0]
    return {str(round(f, 3)): dict(turgor_fast=at(fast, f, "turgor_mean_kPa"), turgor_slow=at(slow, f, "turgor_mean_kPa"),
                                   volume_fast=at(fast, f, "volume_um3") / V0, volume_slow=at(slow, f, "volume_um3") / V0)
            for f in fractions if f >= end}


def dry(rep, S):
    """Experiment 3: load, figures, measure, text."""
    if not os.path.exists(rep.p("water-dry/tissue-dry.csv")):
        rep.w("### 3. Drying a block", "", "Not run or failed.", "")
        return
    d, slow = dry_load(rep)
    dry_figure(rep, d, slow)
    pic = render(rep, d, S)
    S["dry"] = dry_measure(d, slow)
    if slow is not None:
        T.write_csv(rep.fig("water-dry-slow.csv"), slow, list(slow),
                    "in.tissue-dry, the same block at Lp 1e-4 to 70% water")
    dry_text(rep, S, pic, slow is not None)


def dry_text(rep, S, pic, slowed):
    """The drying's text, tables and pictures."""
    q = S["dry"]
    rep.w("### 3. Drying a block to 20% of its water", "",
          "`in.tissue-dry` after `in.tissue-inflate` on a 2x2x2 coarse block (Pi0 -364 kPa): the solutes stay in their "
          "cells (Eq. W1), water crosses the glued faces (Eqs. W2-W3) and leaves through the exposed faces only "
          "(Eq. W4, the wall facing the outside of the block) to air at psi_ext -3000 kPa (about 98% relative humidity at 20 C), below the cells' potential "
          "at every water content (Pi0/0.2 = -1820 kPa at 20%). Nothing is imposed on the walls. "
          f"Water {q['water0_pg']:.4g} pg down to {q['end_fraction']:.1%} in {q['time_us']:.3g} us.", "",
          "*Rate.* Lp is 2e-4 um/(kPa us), 2e5 times the physical 1e-9, so that the block dries in tens of us "
          "instead of seconds, and a drag of 100 nN us/um on the wall nodes takes out the walls' ringing (as "
          "`in.water-potential` does on every particle). The water goes in tens of us, slow against the cells' mechanical response (sound "
          "crosses a cell in 0.2 us, the inflated walls settle within about 1 us), so the walls stay near the "
          "equilibrium of their water content. Check: a second run at half the conductivity (Lp 1e-4, to 70%) "
          + lp_text(q) + ":", "",
          "| water | turgor Lp 2e-4 (kPa) | turgor Lp 1e-4 (kPa) | volume Lp 2e-4 | volume Lp 1e-4 |",
          "|---|---|---|---|---|")
    for f, v in q.get("lp_check", {}).items():
        rep.w(f"| {float(f):.0%} | {v['turgor_fast']:.4g} | {v['turgor_slow']:.4g} | {v['volume_fast']:.4f} | "
              f"{v['volume_slow']:.4f} |")
    z = "-" if q["turgor_zero_at_fraction"] is None else f"{q['turgor_zero_at_fraction']:.0%}"
    rep.w("", f"![drying]({rep.link('water-dry.png')})", "",
          *([f"![walls]({rep.link(pic)})", ""] if pic else []),
          "| water | enclosed volume | wall area | block size |", "|---|---|---|---|",
          *[f"| {float(f):.0%} | {q['volume_at'][f]:.4f} | {q['area_at'][f]:.4f} | {q['size_at'][f]:.4f} |"
            for f in q["volume_at"]], "",
          "(each / its value at full turgor)", "",
          "*What the model gives.* Turgor goes first: it is gone (mean pressure <= 0) at "
          f"{z} water, while the wall-enclosed volume has fallen by "
          f"{100 * (1 - q['volume_at']['0.9']):.2g}% (at 90%): the stiff walls relax to their rest shape and stop "
          "there. Below zero turgor nothing pulls them further in: the fluid-wall contact (8-4 law, virtual "
          "particles) only pushes, the lamella holds the cells together at their rest shapes, and the walls carry "
          "no compression that would buckle them. From 90% water down to "
          f"{q['end_fraction']:.0%} the enclosed volume varies by {100 * q['below']['volume']:.2g}%, the wall area "
          f"by {100 * q['below']['area']:.2g}% and the block size by {100 * q['below']['size']:.2g}% of their "
          f"values at full turgor, the mean tether stretch stays between {q['below']['stretch'][0]:.5f} and "
          f"{q['below']['stretch'][1]:.5f}: the block stops shrinking and the walls do not wrinkle (pictures). "
          "The cell shape follows the wall: sphericity "
          f"{q['sphericity'][0]:.4f} -> {q['sphericity'][-1]:.4f}, elongation {q['elongation'][0]:.4f} -> "
          f"{q['elongation'][-1]:.4f} (max {q['elongation'][1]:.4f}); broken tethers {q['broken']}, debonded "
          f"lamella bonds {q['debonded']}.", "",
          "*Negative turgor: plasmolysis?* No: the model dries in air (or in a solution that cannot enter the "
          "wall); plasmolysis, where a solution that enters the wall fills the space the protoplast leaves, is not "
          "modelled (fix cell/fluid's `medium solution` is refused). Held by nothing, the protoplasm leaves its wall "
          f"(mean pressure down to {q['turgor_min_kPa']:.4g} kPa) and, being at about its rest density, fills only "
          f"{q['fill_end']:.0%} of the enclosed volume at the end (slices in the pictures). " + fluid_text(S)
          + " With each cell's flux spread over its particles by volume (`share volume`, in.tissue-dry's choice) it "
          "shrinks inside its wall as one body; with the even share of Eq. 10 as written the light particles on "
          "the wall dried first and the fluid broke up into clumps under their tension "
          "(docs/studies/drying-cell.md, \"Continuous drying\").", "",
          "*Published trends (qualitative, from general knowledge of drying studies of apple and potato tissue).* "
          "Turgor is lost early in drying, and cell area and volume then fall steadily with moisture (cells shrink "
          "and their walls fold; tissue shrinkage of the order of the water lost, less at low moisture). The first "
          "holds here. The second does not: in plant tissue the protoplast stays attached to the wall as it dries "
          "in air (the wall collapses with it, cytorrhysis), held by the water in the wall's pores, whereas "
          "here the wall is pushed but never pulled by the fluid: this run has the inputs' defaults, with no "
          "fluid-wall adhesion (fix cell/fluid warns so). Section 4 dries the same block with the adhesion and a wall "
          "that takes no compression.", "",
          f"Data: [water-dry.csv]({rep.link('water-dry.csv')})"
          + (f", [water-dry-slow.csv]({rep.link('water-dry-slow.csv')})" if slowed else "") + ".", "")


def stop_reason(log):
    """The ERROR line that stopped a run, or None."""
    if not os.path.exists(log):
        return None
    err = [ln.strip() for ln in open(log, errors="replace") if ln.startswith("ERROR")]
    return err[-1] if err else None


def dry_hold(rep, S):
    """Experiment 4: the block whose protoplasts hold their walls (issue 31): load, figures,
    measure, text; its settings read back from the run (settings.json)."""
    name = "water-dry-hold"
    if not os.path.exists(rep.p(f"{name}/tissue-dry.csv")):
        rep.w(title_hold(), "", "Not run or failed.", "")
        return
    e = params.run_settings(rep.p(name), "in.tissue-dry")
    d = dry_run(rep, name)
    T.write_csv(rep.fig(f"{name}.csv"), d, list(d),
                f"in.tissue-dry: 2x2x2 coarse block, membrane wall, wrinkle yes, Fa {e['Fa']}, delta {e['delta']}, "
                f"sphstress {e['sphstress']}, dp {e['dp']}, Lp {e['Lp']}")
    dry_figure(rep, d, None, png=f"{name}.png")
    H = {}
    pic = render(rep, d, H, name=name)
    q = dry_measure(d, None)
    q["stop"] = stop_reason(rep.p(f"{name}/log.lammps"))
    q["settings"] = {k: e[k] for k in ("Fa", "delta", "sphstress", "dp", "Lp", "psi", "wall", "wrinkle")}
    q["settings"]["share"] = e.get("share", "particle")
    q["settings"]["sphcoh"] = e.get("sphcoh", 0.0)
    q["settings"]["residual"] = e.get("residual", 0.0)
    q["bvh_gap"] = bvh_gap(d)
    q["rate"] = hold_rate_check(rep, d, name + "-fast")
    q["weak"] = hold_weak_check(rep, name + "-fast", name + "-weak")
    rows = section_rows(rep, name, d)
    q["sections"] = {f"{w:.4f}": v for w, v in rows.items()}
    S["dry_hold"] = q
    dry_hold_text(rep, q, d, pic, name, S.get("dry", {}), rows)


def bvh_gap(d, fractions=(0.9, 0.8, 0.7, 0.6, 0.4, 0.2)):
    """{fraction: enclosed volume / Boyle-van 't Hoff's - 1} at the water contents a drying record
    d reaches. Boyle-van 't Hoff with a slack wall: the enclosed volume follows the water, V/V0 =
    W/W0 times the turgid fluid's density over the rest density (Tait), as in the drying-cell study."""
    x = d["water_fraction"]
    tab = params.table()
    B = tab["rho0"] * tab["c"] ** 2 / 7.0
    bvh = x * (1 + d["turgor_mean_kPa"][0] / B) ** (1 / 7)
    gap = d["volume_um3"] / d["volume_um3"][0] / bvh - 1
    o = np.argsort(x)
    return {str(f): float(np.interp(f, x[o], gap[o])) for f in fractions if f >= x.min() - 1e-3}


def hold_rate_check(rep, d, fast):
    """The held drying against the same at 4x the conductivity (stage FAST), at equal water: mean
    turgor and enclosed volume; None where FAST has not run."""
    if not os.path.exists(rep.p(f"{fast}/tissue-dry.csv")):
        return None
    f_ = read_csv(rep.p(f"{fast}/tissue-dry.csv"))
    e = params.run_settings(rep.p(fast), "in.tissue-dry")
    return dict(Lp=e["Lp"], end_fraction=float(f_["water_fraction"][-1]), stop=stop_reason(rep.p(f"{fast}/log.lammps")),
                rows=rate_rows(f_, d, (0.95, 0.9, 0.8, 0.7, 0.6, 0.4, 0.3, 0.2)))


def hold_weak_check(rep, fast, weak):
    """The held drying with the weak lamella (stage WEAK) against the same with the strong one
    (FAST, the same conductivity) at equal water: mean turgor; the lamella bonds let go."""
    if not (os.path.exists(rep.p(f"{fast}/tissue-dry.csv")) and os.path.exists(rep.p(f"{weak}/tissue-dry.csv"))):
        return None
    f_, w_ = read_csv(rep.p(f"{fast}/tissue-dry.csv")), read_csv(rep.p(f"{weak}/tissue-dry.csv"))
    e = params.run_settings(rep.p(weak), "in.tissue-dry")
    end = max(float(f_["water_fraction"][-1]), float(w_["water_fraction"][-1])) - 1e-3
    # below zero turgor, where the cells pull on each other through the lamella
    rows = {str(w): (at(f_, w, "turgor_mean_kPa"), at(w_, w, "turgor_mean_kPa"))
            for w in (0.8, 0.6, 0.4, 0.2) if w >= end}
    diff = max(abs(a - b) for a, b in rows.values())
    big = max(abs(a) for a, _ in rows.values())
    return dict(sigl=e["sigl"], Gl=e["Gl"], Lp=e["Lp"], end_fraction=float(w_["water_fraction"][-1]),
                debonded=int(w_["debonded"][-1]), rows=rows, diff_kPa=diff, same=diff < 0.1 * big,
                stop=stop_reason(rep.p(f"{weak}/log.lammps")))


def hold_weak_text(w):
    if w is None:
        return "The check with the weak lamella (stage water-dry-hold-weak) has not run."
    at_ = ", ".join(f"{float(k):.0%}: {a:.4g} and {b:.4g} kPa" for k, (a, b) in w["rows"].items())
    return (f"With the weak lamella from the drying's start (sigl {w['sigl']:g} kPa, Gl {w['Gl']:g}, Lp {w['Lp']:g}; "
            f"stage water-dry-hold-weak) {w['debonded']} lamella bonds let go by {w['end_fraction']:.0%} water"
            + (" (where it stopped on an error)" if w["stop"] else "") + f", and the fluid reads "
            + ("the same tension" if w["same"] else "another tension") + f" at equal water (strong, weak: {at_}): "
            + ("the lamella is not what holds the cells against their fluid." if w["same"] else
               "the lamella holds part of it."))


def dry_hold_text(rep, q, d, pic, name, plain, sections):
    """The held drying's text; plain: section 3's numbers (the block not held); sections: the
    walls' mid-plane sections (section_rows)."""
    e = q["settings"]
    lp3 = params.run_settings(rep.p("water-dry"), "in.tissue-dry")["Lp"]
    stop = (f" The run stopped there: `{q['stop']}`" if q["stop"] else "")
    x = d["water_fraction"]
    rows = []
    for f in (0.9, 0.8, 0.7, 0.6, 0.4, 0.2):
        if f < x[-1] - 1e-3:
            continue
        rows.append(f"| {f:.0%} | {at(d, f, 'volume_um3') / d['volume_um3'][0]:.4f} | {q['bvh_gap'][str(f)]:+.1%} | "
                    f"{at(d, f, 'wall_area_um2') / d['wall_area_um2'][0]:.4f} | "
                    f"{np.interp(f, x[::-1], (mean_edge(d) / mean_edge(d)[0])[::-1]):.4f} | "
                    f"{at(d, f, 'turgor_mean_kPa'):.4g} | {at(d, f, 'sphericity'):.4f} |")
    rep.w(title_hold(), "",
          "The same 2x2x2 block inflated with the membrane wall (`-var wall membrane`) and dried by `in.tissue-dry` "
          f"with the wall in tension-field theory (`-var wrinkle {e['wrinkle']}`: a compressed triangle carries "
          "nothing, the slack wall of docs/studies/drying-cell.md) and each cell's fluid held on its own wall: "
          f"`-var Fa {e['Fa']} -var delta {e['delta']}` (the adhesion, pair_coeff ... cell/virtual ... adhere) and "
          f"`-var sphstress {e['sphstress']} -var dp {e['dp']}` (the artificial stress)"
          + (f" and `-var sphcoh {e['sphcoh']:g}` (the fluid's cohesion, pair_style cell/sph cohesion)" if e["sphcoh"] else "")
          + (f", the triangles keeping `-var residual {e['residual']:g}` of their stiffness (Eq. M4)"
             if e["residual"] else "")
          + f", the level-3 values of params.LEVELS; Lp {e['Lp']} ({e['Lp'] / lp3:.3g} times section 3's), air at {e['psi']} kPa. Water "
          f"{q['water0_pg']:.4g} pg down to {q['end_fraction']:.1%} in {q['time_us']:.3g} us.{stop}", "",
          "| water | enclosed volume | vs Boyle-van 't Hoff | wall area | block size | mean turgor (kPa) | sphericity |",
          "|---|---|---|---|---|---|---|", *rows, "",
          "(volume, area and size / their values at full turgor; Boyle-van 't Hoff with a slack wall: the enclosed "
          "volume in proportion to the water, at the fluid's rest density)", "",
          f"![drying, held]({rep.link(name + '.png')})", "",
          *([f"![walls, held]({rep.link(pic)})", ""] if pic else []),
          *hold_rate_text(q.get("rate"), e),
          *section_text(sections),
          "*What the model gives.* Held on their walls, the cells shrink with their water: the enclosed volume stays "
          + bvh_words(q["bvh_gap"]) + f" (the run ends at {q['end_fraction']:.0%}), and the block with "
          f"it (size {q['size_at'].get('0.8', float('nan')):.4f} of its turgid size at 80% water, against "
          f"{plain.get('size_at', {}).get('0.8', float('nan')):.4f} in section 3); the outer walls crumple (pictures). "
          + share_text(q, e) + " " + hold_weak_text(q.get("weak")) + " " + crush_text(q, e) + " "
          + ("Coarse cells only (level 3): with the cohesion the single cell follows the water at level 4 too "
             "(docs/studies/drying-cell.md), but the block has not been run there, so this is not a converged result. "
             if e["sphcoh"] else "Coarse cells only: at level 4 the drying cell's protoplasm tears inside "
             "(docs/studies/drying-cell.md), so this is not a converged result. ")
          + f"Broken walls {q['broken']}, debonded lamella bonds {q['debonded']}.", "",
          f"Data: [{name}.csv]({rep.link(name + '.csv')}).", "")


def share_text(q, e):
    """The fluid's tension, and how each cell's flux was spread over its particles."""
    t = f"The fluid's mean turgor (the mean of its particles') reaches {q['turgor_min_kPa']:.4g} kPa"
    if e.get("share") == "volume":
        return (t + " with each cell's flux spread over its particles by volume (`share volume`, Eq. W5): every "
                "particle's density changes alike. With the even share of Eq. 10 as written the light particles "
                "of the contact layer dry first and hold a tension of hundreds of kPa that no slack wall could "
                "(docs/studies/drying-cell.md, \"Continuous drying\"), and the enclosed volume falls behind.")
    return (t + " with the even share of Eq. 10 (`share particle`): the light particles of the contact layer dry "
            "first and the wall contact holds their tension (docs/studies/drying-cell.md, \"Continuous drying\"); "
            "`share volume` (Eq. W5) keeps one pressure per cell.")


def bvh_band(gap, band=0.05):
    """The lowest water fraction (of gap's keys, '0.9' ...) down to which the enclosed volume stays
    within band of Boyle-van 't Hoff's at every listed fraction, and the listed ones beyond it."""
    keys = sorted(gap, key=float, reverse=True)
    inside = None
    for k in keys:
        if abs(gap[k]) > band:
            break
        inside = k
    return inside, [k for k in keys if inside is None or float(k) < float(inside)]


def bvh_words(gap):
    """'within 5% of Boyle-van 't Hoff's down to 80% water; below that -16% at 40%, -24% at 20%'."""
    inside, beyond = bvh_band(gap)
    head = (f"within 5% of Boyle-van 't Hoff's down to {float(inside):.0%} water" if inside else
            "outside 5% of Boyle-van 't Hoff's from the first record on")
    if not beyond:
        return head
    return head + "; beyond, " + ", ".join(f"{gap[k]:+.0%} at {float(k):.0%}" for k in beyond)


def crush_text(q, e):
    """What the wall's triangles did: crushed in tension-field theory, or held open by the residual
    stiffness (angle_coeff ... residual, Eq. M4)."""
    if not e.get("residual"):
        return ("A wall triangle shrinks in its plane without limit where a real wall would fold out of it, which "
                "ends the run where a triangle is crushed.")
    held = (f"With the residual stiffness (`-var residual {e['residual']:g}`) no triangle is crushed: the block "
            f"dries to {q['end_fraction']:.0%} of its water")
    return held + (" (the run stopped on another error)." if q["stop"] else ", the end of the run.")


def hold_rate_text(r, e):
    """The rate check's sentence and table (lines for rep.w)."""
    if r is None:
        return ["*Rate.* The check at a higher conductivity (stage water-dry-hold-fast) has not run.", ""]
    dv, _ = spread(r["rows"])
    # the tension: the rows below zero turgor
    below = {k: v for k, v in r["rows"].items() if v["turgor_slow"] <= 0.0}
    _, dp = spread(below) if below else (0.0, 0.0)
    stop = " (stopped by an error)" if r["stop"] else ""
    big = max((abs(v["turgor_slow"]) for v in below.values()), default=0.0)
    # a tenth of the tension: the levels' scatter and the drag's share are below it
    verdict = ("the tension is the water content's, not the rate's." if dp < 0.1 * big else
               f"the rate changes the tension by more than a tenth of it ({big:.3g} kPa): it is partly the rate's.")
    return [f"*Rate.* The same drying at {r['Lp'] / e['Lp']:.3g}x the conductivity (Lp {r['Lp']}, to {r['end_fraction']:.0%} water{stop}) "
            f"gives the same enclosed volume to {100 * dv:.2g}% of full turgor's at equal water, and below zero turgor "
            f"the same mean turgor to {dp:.3g} kPa: " + verdict, "",
            "| water | turgor Lp " + f"{e['Lp']:g}" + " (kPa) | turgor Lp " + f"{r['Lp']:g}" + " (kPa) | volume Lp "
            + f"{e['Lp']:g}" + " | volume Lp " + f"{r['Lp']:g}" + " |", "|---|---|---|---|---|",
            *[f"| {float(w):.0%} | {v['turgor_slow']:.4g} | {v['turgor_fast']:.4g} | {v['volume_slow']:.4f} | "
              f"{v['volume_fast']:.4f} |" for w, v in r["rows"].items()], ""]


def title_hold():
    return "### 4. Drying a block whose protoplasts hold their walls"


def section(rep):
    """Append the Water section to rep (a report.Report) and its numbers to rep.S['water']."""
    S = {}
    rep.w("## Water", "",
          "fix cell/fluid with each cell's solutes kept (`solute yes`, Eq. W1), water between glued cells "
          "(`exchange yes`, Eqs. W2-W3) and the outside through the exposed wall only (`external`, Eq. W4: the "
          "wall neither glued to another cell nor facing one within 10 um, `exposed outside`); "
          "see docs/fix_cell_fluid.rst and docs/Howto_tissue.rst. Made by tools/tissue.sh's water stages "
          "(`ONLY=\"gen inflate-pair water-potential water-pair water-inflate water-dry water-dry-slow "
          "water-inflate-hold water-dry-hold water-dry-hold-fast water-dry-hold-weak water-inflate-hold-27 "
          "water-dry-hold-27 water-back-hold water-back-hold-27 report-water\"` runs them alone and writes this section only); wall "
          "times, one core per run: "
          + ", ".join(f"{k} {v[0]} s" for k, v in rep.times.items() if k.startswith("water") or k == "inflate-pair")
          + ".", "")
    from . import waterblock
    for part in (potential, pair, dry, dry_hold, waterblock.dry_hold_27, waterblock.rehydrate):
        try:
            part(rep, S)
        except Exception as e:  # report what is there
            import traceback
            traceback.print_exc()
            rep.w(f"({part.__name__}: failed in the report: {e})", "")
    rep.S["water"] = S
