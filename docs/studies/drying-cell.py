# SPDX-License-Identifier: GPL-2.0-or-later
"""The drying cell (docs/studies/drying-cell.md): one coarse cell (level 3) inflated at Pi0 by
in.inflate, then in.water-potential with the solutes kept from psi_ext = 0 to PSIEND, and:
  inflate  cellgen.py cell and in.inflate (inflated.restart)
  ac [RESTART [DELTA]]  the wall area per own-cell fluid-virtual contact within r0 + delta
           (A_c of Fa >= |P| A_c), the contact counts and the fluid's nearest-neighbour distance
  run TAG  in.water-potential with the extra -var NAME VALUE pairs that follow (TAG.csv)
  rehydrate TAG  the same from the last state of a run (its save 1) back to pure water (TAG.csv)
  cavity RESTART  the fluid-free space inside the wall of a state (-var save 1 of a run)
  section RESTART [PNG]  the wall's mid-plane section and the fluid near it: the folds' amplitude,
           count and wavelength (and a picture)
  table TAG...  the levels of the runs against the reference (wall law + Young-Laplace above zero
           turgor, Boyle-van 't Hoff with a slack wall below)
LEVEL=4 and WALL=bending in the environment change the resolution and the wall (the same for
every step); PSIEND and NLEVELS the last external water potential and the number of levels. Run it from an empty folder with the environment of tests/ (LMP, CELLMECH_PLUGIN,
PYTHONPATH=tools); the study's runs (a), (b) and one of the Fa-delta scan (the others alike):
  python3 docs/studies/drying-cell.py inflate
  python3 docs/studies/drying-cell.py ac inflated.restart 0.2
  python3 docs/studies/drying-cell.py run a
  python3 docs/studies/drying-cell.py run b Fa 2e4 delta 0.2 sphstress 0.2 save 1
  python3 docs/studies/drying-cell.py run s Fa 1e4 delta 0.8 sphstress 0.2
  python3 docs/studies/drying-cell.py cavity water-potential.restart
  python3 docs/studies/drying-cell.py table a b
"""
import os
import subprocess
import sys

import numpy as np
from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from cellmech import params  # noqa: E402
from cellmech.validation.references import young_laplace_stretch  # noqa: E402

INPUTS = os.path.join(ROOT, "lammps-inputs")
LMP = os.environ.get("LMP", "lmp")
LEVEL = 3
LEVEL = int(os.environ.get("LEVEL", LEVEL))          # LEVEL=4: the paper's resolution
WALL = os.environ.get("WALL", "tether")               # WALL=bending: the plate wall (hinges)
MODEL = dict(params.model_vars(LEVEL), wall=WALL)
PI0 = -364.0
PSIEND, NLEVELS = -910.0, 20          # 2.5 Pi0 in steps of Pi0 / 8
# PSIEND=-1820 NLEVELS=40: to 5 Pi0, where Boyle-van 't Hoff leaves 20% of the water
PSIEND = float(os.environ.get("PSIEND", PSIEND))
NLEVELS = int(os.environ.get("NLEVELS", NLEVELS))
NINFL = 25000
T = params.table()
B = T["rho0"] * T["c"] ** 2 / 7.0     # Tait stiffness, kPa


def lmp(inp, log, **var):
    cmd = [LMP, "-in", inp, "-log", log, "-screen", "none"]
    for k, v in dict(MODEL, dir=INPUTS, **var).items():
        cmd += ["-var", k, str(v)]
    subprocess.run(cmd, check=True, env=dict(os.environ, LAMMPS_PLUGIN_PATH=os.path.dirname(
        os.environ.get("CELLMECH_PLUGIN", ""))))


def inflate():
    lv = params.LEVELS[LEVEL]
    subprocess.run([sys.executable, os.path.join(ROOT, "tools", "cellgen.py"), "cell", "-o", "cell.data",
                    "--level", str(LEVEL), "--nfluid", str(lv["nfluid"]), "--inset", str(lv["r0"])]
                   + (["--bending"] if WALL == "bending" else []),
                   check=True, stdout=subprocess.DEVNULL)
    lmp(os.path.join(INPUTS, "in.inflate"), "log.inflate", data="cell.data", nsteps=NINFL,
        every=500, restart_out="inflated.restart")


def triangles(data="cell.data"):
    """The wall triangles: the angles of the data file (atom IDs)."""
    lines = open(data).read().split("\n")
    k = lines.index("Angles") + 2
    tri = []
    while k < len(lines) and lines[k].strip():
        tri.append([int(x) for x in lines[k].split()[2:5]])
        k += 1
    return np.array(tri)


def positions(restart):
    """id -> (type, x) of a restart's atoms (a run 0 and a dump)."""
    with open("in.dump", "w") as f:
        f.write("include ${dir}/cell-restart.lmp\nrun 0\n"
                "write_dump all custom state.dump id type x y z modify sort id format float %.17g\n")
    lmp("in.dump", "log.dump", restart=restart)
    a = np.loadtxt("state.dump", skiprows=9)
    return a[:, 0].astype(int), a[:, 1].astype(int), a[:, 2:5]


def contacts(restart="inflated.restart", delta=None):
    """Wall area, own-cell fluid-virtual pairs within r0 + delta and within r0, and A_c."""
    ids, typ, x = positions(restart)
    pos = dict(zip(ids, x))
    tri = triangles()
    p = np.array([[pos[i] for i in t] for t in tri])
    bary = p.mean(axis=1)
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum()
    fluid = x[typ == 2]
    d = np.linalg.norm(fluid[:, None, :] - bary[None, :, :], axis=2)
    r0, delta = MODEL["r0"], float(delta or MODEL["delta"])
    n_well = int((d < r0 + delta).sum())
    n_in = int((d < r0).sum())
    layer = int(((d < r0 + delta).any(axis=1)).sum())
    nn = np.sort(np.linalg.norm(fluid[:, None] - fluid[None], axis=2), axis=1)[:, 1]
    return dict(area=area, pairs=n_well, pairs_inside_r0=n_in, fluid_in_well=layer,
                nfluid=len(fluid), A_c=area / n_well, nn_median=float(np.median(nn)),
                nn_min=float(nn.min()))


def cavity(restart):
    """The largest fluid-free sphere inside the wall nodes' convex hull, 4 um clear of the nodes
    (1 um grid), the share of that interior more than 8 um from any fluid particle, the nodes'
    radii about their centre, the fluid's median nearest-neighbour distance and its mean number of
    SPH neighbours (within 2s)."""
    from scipy.spatial import cKDTree, Delaunay
    _, typ, x = positions(restart)
    wall, fluid = x[typ == 1], x[typ == 2]
    c = wall.mean(axis=0)
    g = np.mgrid[-40:40:1.0, -40:40:1.0, -40:40:1.0].reshape(3, -1).T + c
    clear, _ = cKDTree(wall).query(g)
    inside = (Delaunay(wall).find_simplex(g) >= 0) & (clear > 4.0)
    d, _ = cKDTree(fluid).query(g[inside])
    r = np.linalg.norm(wall - c, axis=1)
    tree = cKDTree(fluid)
    nn, _ = tree.query(fluid, k=2)
    # the SPH pairs each particle has: other fluid particles within the kernel's support 2s
    pairs = np.array([len(n) - 1 for n in tree.query_ball_point(fluid, 2 * MODEL["s"])])
    return dict(empty_sphere=d.max(), far_share=(d > 8.0).mean(), r_min=r.min(), r_mean=r.mean(),
                r_max=r.max(), nn_median=float(np.median(nn[:, 1])), neighbours=pairs.mean())


def section(restart, png=None):
    """The wall's mid-plane section (where the wall triangles cross z = the nodes' mean z) with the
    fluid particles within r0 of that plane, and the section's radius r(phi) about its centre:
    the folds' amplitude (standard deviation of r), their count round the section (the strongest
    Fourier mode m >= 3 of r(phi)) and wavelength 2 pi <r> / m. png: draw it."""
    ids, typ, x = positions(restart)
    pos = dict(zip(ids, x))
    p = np.array([[pos[i] for i in t] for t in triangles()])
    c = x[typ == 1].mean(axis=0)
    seg, lines = [], []
    for t in p:
        h = t[:, 2] - c[2]
        cut = [t[a] + (t[b] - t[a]) * h[a] / (h[a] - h[b])
               for a, b in ((0, 1), (1, 2), (2, 0)) if h[a] * h[b] < 0]
        seg += cut
        if len(cut) == 2:
            lines.append([cut[0][:2] - c[:2], cut[1][:2] - c[:2]])
    seg = np.array(seg)[:, :2] - c[:2]
    phi, r = np.arctan2(seg[:, 1], seg[:, 0]), np.linalg.norm(seg, axis=1)
    order = np.argsort(phi)
    grid = np.linspace(-np.pi, np.pi, 512, endpoint=False)
    rg = np.interp(grid, phi[order], r[order], period=2 * np.pi)
    spec = np.abs(np.fft.rfft(rg - rg.mean()))
    m = 3 + int(np.argmax(spec[3:64]))
    fl = x[(typ == 2) & (np.abs(x[:, 2] - c[2]) < MODEL["r0"])] - c
    if png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.collections import LineCollection
        fig, ax = plt.subplots(figsize=(4, 4))
        ax.add_collection(LineCollection(lines, colors="k", linewidths=0.8))
        ax.plot(fl[:, 0], fl[:, 1], "o", ms=2, color="tab:blue", label="fluid within r0 of z")
        ax.set_aspect("equal")
        ax.set_xlim(-34, 34)
        ax.set_ylim(-34, 34)
        ax.set_xlabel("x (um)")
        ax.set_ylabel("y (um)")
        ax.set_title(f"{os.path.basename(png)[:-4]}: level {LEVEL}, {WALL}", fontsize=9)
        fig.tight_layout()
        fig.savefig(png, dpi=120)
    return dict(r_mean=r.mean(), r_std=rg.std(), mode=m, wavelength=2 * np.pi * rg.mean() / m,
                fluid_in_slab=len(fl), fluid_r_max=np.linalg.norm(fl[:, :2], axis=1).max())


def run(tag, extra, back=False):
    """in.water-potential from psi_ext = 0 to PSIEND on the inflated cell, or (back) from a run's
    last state (-var save 1) from PSIEND back to pure water."""
    ends = dict(restart="water-potential.restart", psistart=PSIEND, psiend=0.0) if back else \
        dict(restart="inflated.restart", psiend=PSIEND)
    lmp(os.path.join(INPUTS, "in.water-potential"), f"log.{tag}", solute="yes", nlevels=NLEVELS,
        out=f"{tag}.csv", **ends, **extra)


def load(tag):
    a = np.genfromtxt(f"{tag}.csv", delimiter=",", names=True)
    return a


def reference(a):
    """Per level the reference of the first level's state (psi_ext = 0): above zero turgor the
    water W that fills the wall law's Young-Laplace volume at P = psi - Pi0 W0 / W (fluid and
    enclosed volume in a fixed ratio, the fluid's density from the Tait law at P); below zero
    turgor (where that P would be < 0) the slack wall: P = 0, W/W0 = Pi0/psi (Boyle-van 't Hoff)
    and the enclosed volume following the fluid's."""
    R, G, t0 = params.CELL["R"], T["G"], T["t0"]
    P0 = a["turgor_kPa"][0]
    lam0 = young_laplace_stretch(P0, R, G, t0)
    rho = lambda P: (1 + P / B) ** (1 / 7)                     # noqa: E731  rho/rho0
    out = []
    for psi in a["psi_ext_kPa"]:
        def gap(w):  # water that fills the wall at its turgor, minus w
            P = psi - PI0 / w
            return (young_laplace_stretch(max(P, 0.0), R, G, t0) / lam0) ** 3 * rho(P) / rho(P0) - w
        if psi - PI0 / (young_laplace_stretch(0.0, R, G, t0) / lam0) ** 3 >= 0:
            w = brentq(gap, 0.5, 1.5)
            P = psi - PI0 / w
            v = (young_laplace_stretch(P, R, G, t0) / lam0) ** 3
        else:
            w, P = PI0 / psi, 0.0
            v = w * rho(P0) / rho(0.0)
        out.append((w, P, v))
    return np.array(out)


def table(tags):
    runs = {t: load(t) for t in tags}
    a0 = runs[tags[0]]
    ref = reference(a0)
    head = "psi_ext   ref W/W0  P_ref  V/V0_ref"
    for t in tags:
        head += f" | {t}: W/W0  P(kPa) P_osm  V/V0  Vf/Vf0  A/A0  errV%  errW%"
    print(head)
    for k, psi in enumerate(a0["psi_ext_kPa"]):
        line = f"{psi:7.1f}  {ref[k, 0]:7.4f} {ref[k, 1]:7.1f} {ref[k, 2]:7.4f}"
        for t in tags:
            a = runs[t]
            W0, V0, A0, P0 = (a["water_pg"][0], a["volume_um3"][0], a["area_um2"][0],
                              a["turgor_kPa"][0])
            w = a["water_pg"][k] / W0
            P = a["turgor_kPa"][k]
            Posm = psi - PI0 / w                                # the osmotic equilibrium's P
            vf = w * (1 + P0 / B) ** (1 / 7) / (1 + P / B) ** (1 / 7)
            v = a["volume_um3"][k] / V0
            line += (f" | {w:7.4f} {P:7.1f} {Posm:6.1f} {v:6.4f} {vf:6.4f} {a['area_um2'][k] / A0:6.4f}"
                     f" {100 * (v / ref[k, 2] - 1):6.2f} {100 * (w / ref[k, 0] - 1):6.2f}")
        print(line)


if __name__ == "__main__":
    what = sys.argv[1]
    if what == "inflate":
        inflate()
    elif what == "ac":
        for k, v in contacts(*sys.argv[2:4]).items():
            print(f"{k} {v:.6g}")
    elif what == "cavity":
        for k, v in cavity(sys.argv[2]).items():
            print(f"{k} {v:.6g}")
    elif what == "section":
        for k, v in section(*sys.argv[2:4]).items():
            print(f"{k} {v:.6g}")
    elif what in ("run", "rehydrate"):
        extra = dict(zip(sys.argv[3::2], sys.argv[4::2]))
        run(sys.argv[2], extra, back=what == "rehydrate")
    elif what == "table":
        table(sys.argv[2:])
