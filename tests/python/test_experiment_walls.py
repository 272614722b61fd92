# SPDX-License-Identifier: GPL-2.0-or-later
"""The two-wall section of the experiments report (cellmech.experiments.walls): the tether numbers
read back from a report's tables, the side-by-side rows worked out from both walls' numbers, the
splice that leaves the rest of the report alone, and tools/experiments.sh with WALL=membrane at the
paper's resolution, which wrote the membrane's report over the tether report in docs/ before."""
import math
import os
import subprocess

import numpy as np

from cellmech.experiments import walls

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# a tether report in the format of report.py (only the tables the section reads)
TETHER_MD = """# The paper's experiments (paper resolution)

## Paper against ours

| experiment | paper (docs/model.md sec. 4) | ours | difference | why / note |
|---|---|---|---|---|
| compression: force at eps = 19% (Fig. 4) | follows | 699 uN at 0.5 m/s (mean of both plates over 18-20%); membrane theory (tools/membrane.py, same turgor and wall) 589 uN (Neo-Hookean), 663 uN (tether-network law) | +19% |  |
| impact stiff: transmitted force (Fig. 9) | lags | 1 mPa s: reaches 1.54e+05 nN (20% of the largest quasistatic force) +5.5% strain later than quasistatic; mean over eps = 19+-1%: impact 8.86e+05 nN, quasistatic 6.89e+05 nN |  |  |

## Details

**Relaxation, stiff cell** (initial deviation d0; ...):

| case | d0 (uN) | t_first (us) | tau_e (us) | tau_fit (us) | offset | period (us) | sign changes | regime |
|---|---|---|---|---|---|---|---|---|
| 1 mPa s | 223 | 0.22 | 3.11 | 6.73 | +0.19 | 1.43 | 7 | oscillating |
| 1000 mPa s | 230 | 0.41 | 0.41 | 0.265 | +0.01 | n/a | 0 | overdamped |

**Relaxation, soft cell** (initial deviation d0; ...):

| case | d0 (uN) | t_first (us) | tau_e (us) | tau_fit (us) | offset | period (us) | sign changes | regime |
|---|---|---|---|---|---|---|---|---|
| 100 mPa s | 0.237 | n/a | n/a (record too short) | 166 (extrapolated) | +0.60 | n/a | 0 | overdamped |

**Impact-zone shear stress (Pa)** at eps = 4% and 10% (mean over eps +- 0.5%):

| cell | 1 mPa s 4% / 10% | 10 mPa s 4% / 10% | 100 mPa s 4% / 10% | 1000 mPa s 4% / 10% |
|---|---|---|---|---|
| stiff | 231 / 287 | 2038 / 1945 | 16145 / 11213 | 133267 / 45996 |
| soft | 470 / 440 | n/a | n/a | 103901 / nan |

**Failure** (lamf = 1.04):

| run | eps_f | first broken nodes: mean latitude (range) | span after 0.2 us, speed of its ends | broken tethers at end | 90% of them after | fluid outside before / at end | escaping fluid median / 90th pct speed |
|---|---|---|---|---|---|---|---|
| qs | 13.2% | 56.5 deg (54.7 to 58.6) | -65 to 80 deg, 412 m/s | 349 | 0.2 us | 0 / 2929 | 6.79 / 8.35 m/s |

## Plots and pictures

**Fig. 4** keep this

## Wall time of each run

| run | wall time (s) | status |
|---|---|---|
| inflate | 150 | ok |
"""


def test_tether_numbers_from_report_tables():
    T = walls.tether_numbers(TETHER_MD)
    print(T)
    r = T["relax"][("stiff", "1")]
    assert (r["t_first"], r["tau_e"], r["tau_fit"], r["period"], r["crossings"], r["regime"]) == \
        (0.22, 3.11, 6.73, 1.43, 7, "oscillating")
    assert math.isnan(T["relax"][("stiff", "1000")]["period"])
    s = T["relax"][("soft", "100")]
    assert math.isnan(s["tau_e"]) and s["tau_fit"] == 166.0
    assert T["shear"][("stiff", 1)] == (231.0, 287.0)
    assert ("soft", 10) not in T["shear"] and math.isnan(T["shear"][("soft", 1000)][1])
    f = T["failure"]["qs"]
    assert (f["eps_f"], f["lat"], f["lat_range"], f["span"], f["speed"]) == \
        (0.132, 56.5, (54.7, 58.6), (-65.0, 80.0), 412.0)
    assert (f["n_final"], f["t_90"], f["jet"]) == (349.0, 0.2, (6.79, 8.35))
    assert T["theory"] == dict(neohookean=589.0, network=663.0)
    t = T["transmitted"]["stiff"]
    assert (t["f_imp"], t["f_qs"], t["eps"]) == (8.86e5, 6.89e5, 0.19) and abs(t["lag"] - 0.055) < 1e-15


def _numbers(period, regime_1000, eps_f, lat):
    return dict(relax={("stiff", "1"): dict(t_first=0.2, tau_e=3.0, tau_fit=6.0, period=period, crossings=7,
                                            regime="oscillating"),
                       ("stiff", "1000"): dict(t_first=0.4, tau_e=0.4, tau_fit=0.3, period=float("nan"),
                                               crossings=0 if regime_1000 == "overdamped" else 4,
                                               regime=regime_1000)},
                shear={("stiff", 1): (200.0, 300.0)}, transmitted={},
                failure={"qs": dict(eps_f=eps_f, lat=lat, lat_range=(lat - 1, lat + 1), span=(-60.0, 80.0),
                                    speed=400.0, n_final=300.0, t_90=0.2, jet=(6.0, 8.0))})


def test_compare_rows_work_out_the_why():
    T = _numbers(1.0, "overdamped", 0.132, 56.5)
    # the membrane's period longer by sqrt(1.5): the shear-modulus explanation holds
    M = _numbers(math.sqrt(1.5), "overdamped", 0.134, 55.0)
    cont = {"qs": dict(eps=0.134, lam=1.0325, kind="hoop", lat=56.0, lat_edge=62.5, lam_eq=1.021, eps_lamf=0.17)}
    rows = {r[0]: r for r in walls.compare_rows(T, M, cont)}
    for r in rows.values():
        print(" | ".join(r))
    per = rows["relaxation stiff, 1 mPa s: period, tau_e (us)"]
    assert per[1] == "1, 3" and per[2] == "1.22, 3" and "period membrane/tether 1.22" in per[4]
    assert "set by the wall's shear stiffness" in per[4]
    assert "shear part of the mode's stiffness is 2 (q - 1) = 100%" in per[4]
    reg = rows["relaxation stiff: damping regime"]
    assert "overdamped at 1000" in reg[1] and "the same regime at every viscosity" in reg[4]
    fq = rows["failure qs: eps_f; first broken nodes' latitude (deg)"]
    assert fq[1] == "13.2%; 56.5" and fq[2] == "13.4%; 55"
    assert "hoop one at latitude 56 deg, 6 deg below the contact edge (62 deg)" in fq[4]
    assert "reaches lamf at eps = 17.0%" in fq[4] and "that is where both walls' cracks start" in fq[4]
    assert rows["impact stiff, 1 mPa s: shear stress at eps = 4% (10%) (Pa)"][2] == "200 (300)"
    # a period ratio far from sqrt(1.5), and a regime that differs: the why says so
    M2 = _numbers(1.02, "oscillating", 0.134, 55.0)
    rows2 = {r[0]: r for r in walls.compare_rows(T, M2)}
    assert "the mode also stretches the wall's area" in rows2["relaxation stiff, 1 mPa s: period, tau_e (us)"][4]
    assert "the regimes differ at 1000 mPa s" in rows2["relaxation stiff: damping regime"][4]
    assert "Continuum" not in rows2["failure qs: eps_f; first broken nodes' latitude (deg)"][4]


def test_splice_replaces_or_inserts_and_keeps_the_rest(tmp_path):
    p = tmp_path / "experiments.md"
    p.write_text(TETHER_MD)
    walls.splice(str(p), ["## Membrane wall", "", "FIRST-VERSION"])
    text = p.read_text()
    assert text.index("FIRST-VERSION") < text.index("## Plots and pictures") and "**Fig. 4** keep this" in text
    walls.splice(str(p), ["## Membrane wall", "", "second"])
    text = p.read_text()
    print(text[-600:])
    assert "second" in text and "FIRST-VERSION" not in text and text.count("## Membrane wall") == 1
    assert text.replace("## Membrane wall\n\nsecond\n\n", "") == TETHER_MD
    assert walls.section_of(str(p)) == ["## Membrane wall", "", "second", ""]


def _membrane_run(run, period):
    """A run folder with the stiff cell's relaxation: F_eq relaxing to the free cell's 100 nN as a
    damped cosine of the given period (tau 3 us)."""
    os.makedirs(run)
    t = np.arange(0.0, 5.0, 0.001)
    feq = 100.0 + 2.0e5 * np.exp(-t / 3.0) * np.cos(2 * math.pi * t / period)
    z = np.zeros_like(t)
    np.savetxt(os.path.join(run, "relax-stiff-1.dat"), np.c_[np.arange(len(t)), t, feq, z, z, z, z, z])
    load = np.c_[np.arange(10), np.zeros(10), np.zeros(10), np.zeros(10), np.zeros(10), np.full(10, 100.0),
                 np.zeros(10)]
    np.savetxt(os.path.join(run, "stiff-compressed.restart.load.dat"), load)
    with open(os.path.join(run, "times.txt"), "w") as f:
        f.write("relax-stiff-1 10 ok\n")


def test_experiments_sh_membrane_paper_keeps_the_tether_report(tmp_path):
    # a copy of the project's layout: tools and inputs as they are, a docs/ with a tether report,
    # a build/ whose environment file is never used (no stage runs: ONLY=report)
    root = tmp_path / "root"
    (root / "docs").mkdir(parents=True)
    (root / "build").mkdir()
    (root / "build" / "cellmech-env.sh").write_text("export LMP=/bin/false\n")
    os.symlink(os.path.join(ROOT, "tools"), root / "tools")
    os.symlink(os.path.join(ROOT, "lammps-inputs"), root / "lammps-inputs")
    (root / "docs" / "experiments.md").write_text(TETHER_MD)
    _membrane_run(str(root / "results" / "experiments-paper-membrane"), 1.8)
    env = dict(os.environ, WALL="membrane", RES="paper", ONLY="report", CELLMECH_ROOT=str(root))
    env.pop("REPORT", None)
    p = subprocess.run(["bash", str(root / "tools" / "experiments.sh")], env=env, capture_output=True,
                       text=True, timeout=120)
    print(p.stdout, p.stderr)
    assert p.returncode == 0
    text = (root / "docs" / "experiments.md").read_text()
    # the tether report is still there, word for word, and the membrane section beside it
    assert text.replace("\n".join(walls.section_of(str(root / "docs" / "experiments.md"))), "") \
        .replace("\n\n## Plots", "\n## Plots") == TETHER_MD
    row = next(ln for ln in text.split("\n") if ln.startswith("| relaxation stiff, 1 mPa s"))
    print(row)
    cells = [c.strip() for c in row.strip("|").split("|")]
    assert cells[1] == "1.43, 3.11"
    assert abs(float(cells[2].split(",")[0]) - 1.8) < 0.05     # the period measured from the run
    assert os.path.exists(root / "docs" / "experiments" / "membrane-relax-stiff.png")


def _oscillator(t, zeta, period, amp):
    """A damped oscillator released from rest at -amp."""
    wd = 2 * math.pi / period
    w = wd / math.sqrt(1 - zeta ** 2)
    return -amp * np.exp(-zeta * w * t) * (np.cos(wd * t) + zeta / math.sqrt(1 - zeta ** 2) * np.sin(wd * t))


def test_soft_damping_note_reads_the_diagnostic_releases(tmp_path):
    t = np.arange(0.0, 200.0, 0.1)
    z = np.zeros_like(t)
    free = 0.1
    # damping ratio of the shape: 0.3 at 1 mPa s, about the same with 100x less viscosity, 0.1 without
    # the contact damping
    for k, zeta in (("1", 0.3), ("mu0.01", 0.28), ("gc0", 0.1)):
        d = _oscillator(t, zeta, 90.0, 8.0)
        np.savetxt(tmp_path / f"relax-soft-{k}.dat",
                   np.c_[np.arange(len(t)), t, free - 0.025 * d, z, z, 60 + 0.5 * d, 60 - 0.5 * d, z])
        (tmp_path / f"log.relax-soft-{k}").write_text("Total wall time: 0:01:00\n")
    (tmp_path / "times.txt").write_text("relax-soft-1 60 ok\n")
    np.savetxt(tmp_path / "soft-compressed.restart.load.dat", np.c_[np.zeros((6, 5)), np.full(6, free), np.zeros(6)])
    L = walls.soft_damping_note(str(tmp_path))
    print("\n".join(L))
    rows = [ln for ln in L if ln.startswith("| ") and "regime |" not in ln]
    zetas = [float(r.rstrip(" |").split(", ")[-3]) for r in rows]
    assert [abs(x - y) < 0.02 for x, y in zip(zetas, (0.3, 0.28, 0.1))] == [True] * 3
    text = " ".join(L)
    assert "the fluid's viscosity takes little of what the first swing loses" in text
    assert "the fluid-wall contact damping (gc) takes most of what the first swing loses" in text
    # a release still running (no end in its log) is left out
    (tmp_path / "log.relax-soft-gc0").write_text("Step\n")
    assert "gc" not in " ".join(walls.soft_damping_note(str(tmp_path)))
    os.remove(tmp_path / "relax-soft-mu0.01.dat")
    assert walls.soft_damping_note(str(tmp_path)) == []


def test_shape_relaxation_damping_ratio():
    """H - W of a damped oscillator released from rest: regime, period and damping ratio back from
    the record (the overshoot exp(-zeta pi / sqrt(1 - zeta^2)))."""
    for zeta, period in ((0.3, 90.0), (0.1, 1.5)):
        wd = 2 * math.pi / period
        w = wd / math.sqrt(1 - zeta ** 2)
        t = np.linspace(0.0, 2.2 * period, 4001)
        d = -8.0 * np.exp(-zeta * w * t) * (np.cos(wd * t) + zeta / math.sqrt(1 - zeta ** 2) * np.sin(wd * t))
        z = np.zeros_like(t)
        a = np.c_[np.arange(len(t)), t, z, z, z, 60.0 + 0.5 * d, 60.0 - 0.5 * d, z]
        r = walls.shape_relaxation(a)
        print(zeta, period, "->", r["regime"], r["period"], r["overshoot"], r["zeta"])
        assert r["regime"] == "oscillating"
        assert abs(r["zeta"] - zeta) < 0.02 and abs(r["period"] / period - 1) < 0.05
        # the next swing: the overshoot factor again; the record (2.2 periods) holds it whole
        x = math.exp(-zeta * math.pi / math.sqrt(1 - zeta ** 2))
        assert abs(r["swing2"] - x) < 0.03 and not r["swing2_open"]
    # overdamped: no overshoot
    t = np.linspace(0.0, 100.0, 2001)
    d = -8.0 * np.exp(-t / 20.0)
    z = np.zeros_like(t)
    r = walls.shape_relaxation(np.c_[np.arange(len(t)), t, z, z, z, 60.0 + d, 60.0 + z, z])
    assert r["regime"] == "overdamped" and r["overshoot"] == 0.0 and math.isnan(r["zeta"])
