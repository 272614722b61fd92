# SPDX-License-Identifier: GPL-2.0-or-later
"""tools/cellmech/scaling.py: what it reads from a LAMMPS log, and the parallel-efficiency model of
tools/benchmark-tissue.sh against its limiting cases."""
import math

import pytest

from cellmech import scaling

# the tail of a LAMMPS log as LAMMPS 4 Jul 2026 writes it (2 ranks, an uneven split)
LOG = """
Loop time of 6.60278 on 2 procs for 1000 steps with 29110 atoms

Performance: 13085396.975 ns/day, 0.000 hours/ns, 151.451 timesteps/s, 4.409 Matom-step/s
99.0% CPU use with 2 MPI tasks x no OpenMP threads

MPI task timing breakdown:
Section |  min time  |  avg time  |  max time  |%varavg| %total
---------------------------------------------------------------
Pair    | 0.65132    | 1.053      | 1.4546     |  39.1 | 15.95
Bond    | 0.60294    | 1.0427     | 1.4824     |  43.1 | 15.79
Neigh   | 2.5496     | 2.5497     | 2.5498     |   0.0 | 38.62
Comm    | 0.062097   | 0.063744   | 0.06539    |   0.7 |  0.97
Output  | 0.010215   | 0.010432   | 0.010649   |   0.2 |  0.16
Modify  | 1.7332     | 1.7984     | 1.8635     |   4.9 | 27.24
Other   |            | 0.08491    |            |       |  1.29

Nlocal:          14555 ave       20990 max        8120 min
Histogram: 1 0 0 0 0 0 0 0 0 1
Nghost:          828.5 ave         844 max         813 min
Histogram: 1 0 0 0 0 0 0 0 0 1

Total # of neighbors = 0
Neighbor list builds = 65
Dangerous builds = 0
"""


def test_parse_log_reads_every_field():
    r = scaling.parse_log("Loop time of 1 on 1 procs for 5 steps with 7 atoms\n" + LOG)
    print(r)
    assert (r["loop"], r["ranks"], r["steps"], r["atoms"], r["builds"]) == (6.60278, 2, 1000, 29110, 65)
    assert r["sections"]["Pair"] == (0.65132, 1.053, 1.4546)
    assert r["sections"]["Modify"] == (1.7332, 1.7984, 1.8635)
    assert set(r["sections"]) == set(scaling.SECTIONS)
    assert r["nlocal"] == (14555.0, 20990.0, 8120.0) and r["nghost"] == (828.5, 844.0, 813.0)
    assert scaling.imbalance(r) == pytest.approx(20990 / 14555, rel=1e-15)


def test_parse_log_refuses_an_unfinished_run():
    with pytest.raises(ValueError, match="did not finish"):
        scaling.parse_log("LAMMPS (4 Jul 2026)\nrun 1000\n")


def test_ghost_shell_of_a_cube():
    """8 unit cells of one atom each: a cube of edge 2, its shell of thickness 0.5 is 3^3 - 2^3."""
    assert scaling.ghost_atoms(8, 1.0, 1.0, 0.5) == pytest.approx(19.0, rel=1e-14)
    # thin, the shell is six faces of L^2 times the thickness, to first order
    n = scaling.ghost_atoms(1e6, 1.0, 1.0, 1e-3)
    assert n == pytest.approx(6 * 100 ** 2 * 1e-3, rel=1e-4)


def test_collective_and_halo_costs():
    assert scaling.allreduce_time(1, 1000, 2e-6, 5e9) == 0.0
    # a power of two: log2 P latencies plus 2 (P-1)/P of the message over the bandwidth
    assert scaling.allreduce_time(256, 1000, 2e-6, 5e9) == pytest.approx(8 * 2e-6 + 2 * 255 / 256 * 8000 / 5e9)
    assert scaling.halo_time(0, 2e-6, 5e9) == pytest.approx(scaling.HALO_EXCHANGES * 6 * 2e-6)
    assert scaling.halo_time(1000, 0.0, 1e9) == pytest.approx(8 * scaling.HALO_DOUBLES * 1000 / 1e9)


def test_projection_limits():
    args = dict(ncells=1000, t_cell=4e-4, cell_volume=1.13e5, atoms_per_cell=1100, cutoff=13.8)
    # one rank: the serial time, nothing lost
    one = scaling.project(1, ghost_cost=1e-8, imbalance=1.0, alpha=2e-6, beta=5e9, **args)
    assert one["efficiency"] == pytest.approx(1.0, rel=1e-14) and one["nghost"] == 0.0
    # a free network and free ghosts: only the imbalance is lost
    free = scaling.project(64, ghost_cost=0.0, imbalance=1.25, alpha=0.0, beta=math.inf, **args)
    assert free["efficiency"] == pytest.approx(0.8, rel=1e-14)
    # more ranks, smaller subdomains: relatively more ghosts and latency, lower efficiency
    eff = [scaling.project(p, ghost_cost=1e-8, imbalance=1.01, alpha=2e-6, beta=5e9, **args)["efficiency"]
           for p in (2, 8, 64, 256)]
    print("efficiency at 2, 8, 64, 256 ranks:", [f"{e:.4f}" for e in eff])
    assert all(a > b for a, b in zip(eff, eff[1:])) and 0 < eff[-1] < 1


def test_work_imbalance_sees_the_pair_time():
    r = scaling.parse_log(LOG)
    # the log's Pair spread (1.4546 / 1.053) is below its particle imbalance (20990 / 14555)
    assert scaling.work_imbalance(r) == pytest.approx(20990 / 14555, rel=1e-15)
    r["nlocal"] = (100.0, 100.0, 100.0)
    assert scaling.work_imbalance(r) == pytest.approx(1.4546 / 1.053, rel=1e-15)


def _log(loop, ranks, atoms, nghost):
    return (LOG.replace("6.60278 on 2 procs", f"{loop} on {ranks} procs").replace("29110 atoms", f"{atoms} atoms")
            .replace("Nghost:          828.5", f"Nghost:          {nghost}") + "ghost atom cutoff = 9.6\n")


def test_report_opens_with_a_summary_of_the_measured_and_projected_efficiency(tmp_path):
    import json
    for case, cells, one, two in (("block2", 8, 4.0, 2.5), ("block3", 27, 13.0, 7.0)):
        json.dump(dict(cells=cells, neighbours_mean=3.0 if cells == 8 else 4.0, box_volume=3e4 * cells),
                  open(tmp_path / f"{case}.json", "w"))
        (tmp_path / f"log.{case}.1.0").write_text(_log(one, 1, 1100 * cells, 0))
        (tmp_path / f"log.{case}.2.0").write_text(_log(two, 2, 1100 * cells, 300 * cells ** (2 / 3)))
    text = scaling.report(str(tmp_path), 1000, 300, 500, "0", "x", load_after="0")
    lines = text.split("\n")
    print("\n".join(lines[:4]))
    assert lines[0] == "# Tissue benchmark" and lines[2].startswith("**Summary.** ")
    # the measured efficiencies: 4 / 2.5 / 2 = 80% (block2) and 13 / 7 / 2 = 93% (block3)
    assert "runs from 80% (block2, 2 ranks, balance off) to 93% (block3, 2 ranks, balance off)" in lines[2]
    rows = [ln for ln in lines if ln.startswith("| 64 |") or ln.startswith("| 256 |")]
    assert f"{rows[0].split(' | ')[-1].rstrip(' |')} on 64 ranks and {rows[1].split(' | ')[-1].rstrip(' |')} on 256" \
        in lines[2]
