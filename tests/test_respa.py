# SPDX-License-Identifier: GPL-2.0-or-later
"""Issue 12, target 3: multiple time stepping (run_style respa) in the compression
(lammps-inputs/in.compress -var respa N: the wall's tethers, triangles and hinges and the plates
(fix cell/plates, its force the mean over the inner steps) on the inner level with step dt, the
fluid and every contact on the outer level with step N dt).

The coarse stiff cell, inflated, is pressed by the top plate at 0.5 m/s for 12.8 us to 10% strain
(lammps-inputs/in.compress). Asserted:
 * respa with one level is Verlet: every recorded column equal to round-off (1e-12 relative);
   fix cell/fluid then advances density and mass by the same step at the same place of the step;
 * respa 3 (outer step 0.003 us, the fluid's acoustic limit 0.25 s/c at level 4) reproduces the
   single-level run, each quantity averaged over the second half of the run, their relative
   difference taken for each of 6 microstates of the inflated cell (the inflation as it is, and 5
   with its fluid displaced by 1e-9 um at the start, in.inflate -var jitter; each compressed both
   ways from its own restart) and averaged over them: mean pressure and enclosed volume within 1%
   (the issue's criterion; halving the single-level step moves them by 0.2% and 0.005%, printed).
   One microstate is not enough: the mean pressure of this 461-particle fluid is its density to
   1e-5 (kappa / P = 30), which the fluid's packing against the wall sets, and respa 3's shift of
   it ranges over 0.0-1.5% between microstates (6 of them with this code; 0.3-1.3% with the
   kernel's arithmetic of the previous version, another order of roundings and nothing else): a
   single one failed 1% for a quarter of them, which round-off picks. Their mean is what respa
   does to this cell, and is what the 1% applies to: +0.73% +- 0.22% (printed with its standard
   error) with the plates on the outer level, +0.40% +- 0.17% since they act on the inner one
   (fix cell/plates). Respa's impulses from the fluid every 3 wall steps do pack it differently.
   Each microstate more costs about 12 s. The
   equatorial force and the plate force within 5%: this coarse cell's
   contact-by-contact forces move by about 1% when the single-level step is merely halved
   (printed), and respa's impulses from the fluid every 3 wall steps shift them by 1-3% (plate
   force -1.2%, equatorial force +2.3% on average). The failure this bound is for is larger: fix
   wall/harmonic on the inner level, its force sampled at the last inner step, read 10% low in
   this run (22-28% at level 4, docs/studies/performance.md);
 * the same with 'hybrid 2 2 2' in place of 'pair 2', and with respa from the run 0 on (the
   fix's setup under respa), to round-off;
 * 2 ranks give the 1-rank run to 1e-4 under respa 3 as under Verlet (ghost velocities);
 * bad input stops with a message: -var respa not a whole number >= 1, -var jitter not a whole
   number >= 0 (in.compress); pair cell/sph on an inner level with fix cell/fluid, by the 'pair'
   keyword (fix cell/fluid) and by the 'hybrid' keyword (pair cell/sph's check in the run's
   setup).
"""
import numpy as np
import pytest

import lmptest as T

COARSE = dict(T.COARSE)
# a record every 0.06 us: whole outer steps for respa 1, 2, 3 (in.compress counts every in dt)
NSTATES = 6      # inflated microstates the respa-Verlet comparison is averaged over
RUN = dict(COARSE, dir=T.INPUTS, restart="inflated.restart", vplate=0.5, strain=0.10, every=60)
COLUMNS = ("t", "eps", "Ftop", "Fbot", "Feq", "P", "broken", "leak", "V", "Vfluid", "pz", "ke", "W")


def compress(d, tag, text=None, check=True, nprocs=1, **extra):
    """Run in.compress (or its text with another run_style) and return (rc, log, record)."""
    src = open(T.INPUTS + "/in.compress").read() if text is None else text
    path = f"{d}/in.compress-{tag}"
    with open(path, "w") as f:
        f.write(src)
    rc, log = T.lmp(path, cwd=d, log=f"log.{tag}", check=check, nprocs=nprocs,
                    variables=dict(RUN, out=f"{tag}.dat", **extra))
    return rc, log, (T.load(f"{d}/{tag}.dat") if rc == 0 else None)


def with_run_style(line, after=None):
    """in.compress with `line` right after respa.lmp has chosen its run_style (overriding it), or
    after the first line that starts with `after`."""
    src = open(T.INPUTS + "/in.compress").read()
    key = "include         ${dir}/respa.lmp"
    assert src.count(key) == 1, "in.compress no longer chooses its run_style in respa.lmp"
    lines = src.splitlines()
    k = next(i for i, l in enumerate(lines) if l.startswith(key if after is None else after))
    lines.insert(k + 1, line)
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def inflated(rundir):
    T.inflate_coarse(rundir, nsteps=4000, every=1000)
    return rundir


@pytest.fixture(scope="module")
def verlet(inflated):
    """The compression under Verlet (dt 0.001), microstate 0."""
    return compress(inflated, "verlet")[2]


@pytest.fixture(scope="module")
def r3(inflated):
    """The compression under respa 3, microstate 0."""
    return compress(inflated, "respa3", respa=3)[2]


def test_respa_one_level_is_verlet(inflated, verlet):
    d = inflated
    _, log1, one = compress(d, "respa1", with_run_style("run_style respa 1"))
    T.check("run_style respa 1 is in use", "\nrun_style respa 1\n" in log1)
    rel = np.abs(one - verlet) / np.maximum(np.abs(verlet), 1e-300)
    worst = np.unravel_index(np.argmax(rel), rel.shape)
    print(f"respa with one level against Verlet: {len(one)} records, largest relative difference "
          f"{rel.max():.2e} ({COLUMNS[worst[1] - 1] if worst[1] else 'step'})")
    T.check("respa with one level = Verlet to round-off", one.shape == verlet.shape and rel.max() < 1e-12,
            f"{rel.max():.2e}")


@pytest.fixture(scope="module")
def ensemble(inflated, verlet, r3):
    """Verlet with half the step, and the ensemble of microstates compressed both ways."""
    d = inflated
    _, _, half = compress(d, "verlet-half", dt=0.0005, every=120)
    # the ensemble: this inflated cell (microstate 0) and NSTATES - 1 more, inflated from the
    # fluid displaced by 1e-9 um (in.inflate -var jitter), each compressed both ways
    ens = {"verlet": [verlet], "respa3": [r3]}
    for k in range(1, NSTATES):
        T.inflate_coarse(d, nsteps=4000, every=1000, jitter=k)
        ens["verlet"].append(compress(d, f"verlet-j{k}", restart=f"inflated-j{k}.restart")[2])
        ens["respa3"].append(compress(d, f"respa3-j{k}", restart=f"inflated-j{k}.restart",
                                      respa=3)[2])
    return half, ens


def test_runs_record_same_times(ensemble):
    half, ens = ensemble
    # a record every 0.06 us in each run; their first records depend on the restart's step count
    # modulo each run's record interval
    runs = [half] + ens["verlet"] + ens["respa3"]
    spans = [(a[1, 1] - a[0, 1], a[-1, 1]) for a in runs]
    T.check(f"the {len(runs)} runs record every 0.06 us up to the same time",
            all(abs(dt - 0.06) < 1e-9 and abs(end - spans[0][1]) < 0.06 for dt, end in spans),
            " ".join(f"{dt:.4g}/{end:.4g}" for dt, end in spans))


def test_respa3_matches_single_level(ensemble, verlet):
    half, ens = ensemble

    def late(a):
        """the second half of the run, 3-10% strain: past the first contact's transient"""
        return a[a[:, 1] >= 0.5 * verlet[-1, 1]]

    T.check("the top plate presses the wall over the second half", np.all(late(verlet)[:, 3] > 0),
            f"{len(late(verlet))} records")
    # means over it: at one instant the plate force follows the wall's rings and the fluid rings
    # with acoustic waves whose phase depends on the step
    quantities = {    # name: (column(s) of step t eps Ftop Fbot Feq P broken leak V Vf, tolerance)
        "mean pressure P": ((6,), 0.01),
        "enclosed volume V": ((9,), 0.01),
        "equatorial force Feq": ((5,), 0.05),
        "plate force (Ftop + Fbot) / 2": ((3, 4), 0.05),
    }
    for name, (cols, tol) in quantities.items():
        q = {k: np.array([late(a)[:, cols].mean() for a in v]) for k, v in ens.items()}
        err_dt = late(half)[:, cols].mean() / q["verlet"][0] - 1
        # respa 3 against Verlet from the same inflated cell, one difference per microstate
        rel = q["respa3"] / q["verlet"] - 1
        mean, sem = rel.mean(), rel.std(ddof=1) / np.sqrt(len(rel))
        print(f"{name}: dt 0.001 {q['verlet'][0]:.6g} (microstate 0; over the {len(rel)} "
              f"microstates {np.ptp(q['verlet']) / q['verlet'].mean():.2%} apart); dt 0.0005 "
              f"{err_dt:+.3%} (microstate 0); respa 3 per microstate "
              + " ".join(f"{x:+.2%}" for x in rel) + f", mean {mean:+.3%} +- {sem:.3%} "
              f"(tolerance {tol:.0%})")
        T.check(f"respa 3 = single level: {name} (mean over {len(rel)} microstates)",
                abs(mean) <= tol, f"{mean:+.3%} vs {tol:.0%}")


def test_bad_respa_inputs_refused(inflated):
    d = inflated
    rc, log, _ = compress(d, "bad-respa", check=False, respa=2.5)
    T.check("-var respa 2.5: in.compress stops with its message", rc != 0 and
            "in.compress: -var respa 2.5: expected a whole number >= 1" in log)
    rc, log, _ = compress(d, "bad-jitter", check=False, jitter=0.5)
    T.check("-var jitter 0.5: in.compress stops with its message", rc != 0 and
            "in.compress: -var jitter 0.5: expected a whole number >= 0" in log)
    rc, log, _ = compress(d, "bad-pair", with_run_style("run_style respa 2 3 pair 1 bond 1 angle 1"),
                          check=False)
    T.check("pair styles on the inner level: fix cell/fluid stops with its message", rc != 0 and
            "needs the pair styles (cell/sph) on the outermost level: expected 'run_style respa 2 "
            "... pair 2', got pair 1" in log)
    rc, log, _ = compress(d, "bad-hybrid", with_run_style(
        "run_style respa 2 3 hybrid 1 2 2 bond 1 angle 1"), check=False)
    T.check("cell/sph on the inner level by 'hybrid': pair cell/sph stops with its message",
            rc != 0 and "must be on the outermost level, where the fix advances the density: "
            "expected level 2 for cell/sph" in log)


def test_hybrid_outer_levels_as_pair2(inflated, r3):
    d = inflated
    rc, log, good = compress(d, "hybrid", with_run_style(
        "run_style respa 2 3 hybrid 2 2 2 bond 1 angle 1"), respa=3)
    T.check("'hybrid' with every sub-style outside = 'pair 2' (respa 3) to round-off",
            good.shape == r3.shape and np.allclose(good, r3, rtol=1e-12, atol=0),
            f"{np.max(np.abs(good - r3) / np.maximum(np.abs(r3), 1e-300)):.2e}")


def test_respa_from_first_run(inflated, r3):
    d = inflated
    # respa from the first run on: fix cell/fluid's setup (cells, pressures) under respa
    _, _, early = compress(d, "respa3-early", with_run_style(
        "run_style respa 2 3 bond 1 angle 1 dihedral 1 pair 2", "include"), respa=3)
    diff = np.max(np.abs(early - r3) / np.maximum(np.abs(r3), 1e-300)) if early.shape == r3.shape else np.inf
    T.check("respa 3 from the run 0 on = respa 3 after it, to round-off", diff < 1e-12, f"{diff:.2e}")


# 2 ranks: the ghosts' velocities (contact damping, viscosity, continuity on the outer level)
# must be the owners' after the inner levels' last half kick. Over 3% strain 1 and 2 ranks
# differ by round-off grown by the fluid's chaos: P, Feq and V by < 1e-8, 1e-7, 0 under Verlet,
# < 2e-7, 5e-6, 1e-8 under respa 3; with stale ghost velocities by 3e-2, 2e-2 and 6e-4.
@pytest.mark.parametrize("name, extra", (("single level", {}), ("respa 3", dict(respa=3))))
def test_ranks_agree(inflated, name, extra):
    d = inflated
    cols = {"P": 6, "Feq": 5, "V": 9}
    runs = [compress(d, f"ranks{n}-{extra.get('respa', 1)}", nprocs=n, strain=0.03, **extra)[2]
            for n in (1, 2)]
    rel = {c: np.max(np.abs(runs[1][:, k] / runs[0][:, k] - 1)) if runs[0].shape == runs[1].shape
           else np.inf for c, k in cols.items()}
    print(f"{name}, 1 against 2 ranks, largest relative difference: "
          + " ".join(f"{c} {v:.1e}" for c, v in rel.items()))
    T.check(f"{name}: 2 ranks = 1 rank within 1e-4 (P, Feq, V)", max(rel.values()) < 1e-4,
            f"{max(rel.values()):.1e}")
