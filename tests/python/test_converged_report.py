# SPDX-License-Identifier: GPL-2.0-or-later
"""cellmech.tissue.converged (issue 29): the modulus is the slope of the line through the stress
over its window, and a condition counts as converged only when the plates balance and the two
speeds' curves agree."""
import numpy as np

from cellmech import quasistatic as Q
from cellmech.tissue import converged as C
from cellmech.tissue.tissuedata import COMPRESS, fmt

# the two experiments the report judges (the Kind each of its functions is given)
COMP, TENS = C.KINDS["compress"], C.KINDS["tension"]


def record(strain, stress, a0=1.0e4, ke=0.0):
    d = {name: np.zeros_like(strain) for name in COMPRESS}
    d["strain"], d["stress_kPa"] = strain, stress
    d["F_top_nN"] = d["F_bottom_nN"] = stress * a0
    d["time_us"] = strain * 100.0
    d["P_mean_kPa"] = np.full_like(strain, 364.0)
    d[Q.KE] = np.full_like(strain, ke)
    d[Q.WORK] = np.cumsum(stress) * 1e3 + 1.0
    return d


def flat_runs(root, stage, pi, lam, speeds, args=None):
    """Run folders STAGE{PI}-{LAM}-{SPEED} holding a flat record over 0-10% strain, each with the
    settings.json of in.tissue-STAGE given the -var args (none: no settings.json)."""
    from cellmech import params
    e = np.linspace(0.0, 0.1, 21)
    rows = np.column_stack([np.arange(len(e))] + [e if n == "strain" else np.ones_like(e) for n in COMPRESS])
    for speed in speeds:
        d = root / f"{stage}{pi}-{lam}-{speed:g}"
        d.mkdir()
        np.savetxt(d / f"tissue-{stage}.dat", rows)
        if args is not None:
            params.write_settings(["-in", f"{params.INPUTS}/in.tissue-{stage}", *args], str(d))


def test_modulus_is_the_slope_over_its_window():
    e = np.linspace(0.0, 0.1, 201)
    s = 700.0 * e + 3.0 * np.sin(200 * e) * (e > 0.05)     # linear in the window, noisy after it
    assert abs(C.modulus(record(e, s), 0.02, 0.04) - 700.0) < 1e-6


def test_converged_needs_balance_and_agreement_of_speeds():
    e = np.linspace(0.0, 0.1, 201)
    slow = record(e, 800.0 * e)
    same = C.measure(COMP, slow, record(e, 800.0 * e))
    assert same["converged"] and abs(same["E"] - 800.0) < 1e-6
    moved = C.measure(COMP, slow, record(e, 900.0 * e))          # the fast curve 12.5% stiffer
    assert not moved["converged"] and moved["rate"] > Q.TOL_RATE
    off = record(e, 800.0 * e)
    off["F_bottom_nN"] = 0.8 * off["F_top_nN"]             # plates 22% apart
    assert not C.measure(COMP, off, record(e, 800.0 * e))["converged"]


def test_each_condition_is_judged_on_its_two_slowest_rungs(tmp_path):
    e = np.linspace(0.0, 0.1, 21)
    rows = np.column_stack([np.arange(len(e))] + [e if n == "strain" else np.ones_like(e) for n in COMPRESS])
    for speed in (1.0, 0.5, 0.25, 0.2):          # 0.2 has no rung at twice its speed
        d = tmp_path / f"compress-364-strong-{speed:g}"
        d.mkdir()
        np.savetxt(d / "tissue-compress.dat", rows)
    found = C.load_runs(COMP, str(tmp_path))
    assert list(found) == [(-364, "strong")] and found[-364, "strong"][0] == 0.25


def test_the_block_is_described_from_its_generator_statistics():
    cell = {"fluid": 440}
    gen = {"cells": 27, "seeds": "lattice sc 3x3x3, constant 48.36", "wall_nodes_per_cell": 642,
           "volume_mean": 48.0 ** 3, "faces_mean": 6.0, "neighbours_mean": 4.0, "cell": [cell] * 27}
    words = C.block_words(gen)
    assert "3x3x3 block of 27 cells" in words and "about 440 fluid" in words and "about 48 um" in words
    assert C.surface(gen).startswith("26 of its 27 cells")      # one inner cell
    assert C.surface(dict(gen, cells=8)).startswith("every cell")
    assert C.surface(dict(gen, cells=125)).startswith("98 of its 125")


def test_a_random_block_gives_its_seed_inner_faces_unglued_faces_and_air():
    cells = [{"fluid": 400, "faces": 16, "free_faces": 0}] + [{"fluid": 400, "faces": 9, "free_faces": 2}] * 26
    gen = {"cells": 27, "seeds": "random 27 seeds (seed 4, min distance 33.85)", "wall_nodes_per_cell": 642,
           "volume_mean": 46.0 ** 3, "volume_rel_spread": 0.11, "faces_mean": 9.3, "neighbours_mean": 6.2,
           "porosity": 0.11, "cell": cells,
           "unglued_faces": [{"cells": [1, 17], "face_area": 181.2}, {"cells": [2, 13], "face_area": 134.9}]}
    words = C.block_words(gen)
    assert "random Laguerre block of 27 cells" in words and "seed 4" in words
    assert "16 faces for its 1 inner cell;" in words
    assert "2 faces of the diagram, 316 um^2, without a lamella bond" in words and "porosity 0.11" in words
    # the surface is counted from the cells' free faces, not from a cube's count
    assert C.surface(dict(gen, cell=cells[:1] * 3 + cells[1:])).startswith("24 of its 27")


def test_a_run_stopped_by_an_error_is_named_with_where_it_stopped(tmp_path):
    e = np.linspace(0.0, 0.1, 21)
    rows = np.column_stack([np.arange(len(e))] + [e if n == "strain" else np.ones_like(e) for n in COMPRESS])
    for speed in (0.5, 0.25):
        d = tmp_path / f"compress-100-weak-{speed:g}"
        d.mkdir()
        np.savetxt(d / "tissue-compress.dat", rows[: 11 if speed == 0.25 else 21])
        # the slow run blew up inside its run; the fast one ended its run, then met a bad input line
        run = "Per MPI rank memory allocation (min/avg/max) = 20 | 20 | 20 Mbytes\n"
        (d / "log.lammps").write_text(run + ("ERROR on proc 0: Bond style cell/tether: atom 7 moved\n"
                                             if speed == 0.25 else
                                             "Loop time of 60 on 1 procs\nERROR: Unknown command: rea\n"))
    v, slow, fast, errors = C.load_runs(COMP, str(tmp_path))[-100, "weak"]
    notes = C.stop_notes(v, slow, fast, errors)
    assert v == 0.25 and len(notes) == 1
    assert notes[0].startswith("the run at 0.25 m/s stopped at 5.0% strain: ERROR on proc 0: Bond style")
    assert "Stopped early" in C.stopped_text({(-100, "weak"): {"notes": notes}})


def test_a_block_burst_before_loading_gives_no_failure_stress():
    e = np.linspace(0.0, 0.1, 201)
    burst = record(e, 100.0 * e)
    burst["broken_tethers"] = np.where(e > 0.005, 40.0, 0.0)     # walls broken at 0.5% strain
    m = C.measure(COMP, burst, burst)
    assert m["burst"] and not m["failure_converged"] and "burst before loading" in C.table(COMP, {(-600, "weak"): dict(m, v=0.25)})


def test_a_stress_still_rising_at_the_end_is_no_failure_stress():
    e = np.linspace(0.0, 0.1, 201)
    m = C.measure(COMP, record(e, 800.0 * e), record(e, 800.0 * e))
    assert m["rising"] and not m["failure_converged"] and "| > 7" in C.table(COMP, {(-100, "weak"): dict(m, v=0.25)})


def test_the_lamellae_are_read_from_the_runs_settings(tmp_path):
    """The report names each lamella as its runs were given it (settings.json), not as restated."""
    from cellmech import params
    for lam, sigl in (("strong", 42.0), ("weak", 7.0)):
        flat_runs(tmp_path, "compress", -364, lam, (0.5, 0.25), ["-var", "sigl", str(sigl), "-var", "Gl", "250",
                                                                 "-var", "lamf", "1.05"])
    lams = C.lamella_settings(COMP, str(tmp_path), C.load_runs(COMP, str(tmp_path)))
    assert (lams["strong"]["sigl"], lams["weak"]["sigl"], lams["weak"]["Gl"]) == (42.0, 7.0, 250.0)
    assert C.lamella_words(lams) == ("a strong (sigl 42 kPa, Gl 0.25 J/m^2) and a weak lamella "
                                     "(7 kPa, 0.25 J/m^2)")
    # a run older than settings.json: the named lamella of cellmech.params
    (tmp_path / "compress-364-weak-0.25" / "settings.json").unlink()
    assert C.run_settings(COMP, str(tmp_path), -364, "weak", 0.25)["sigl"] == params.lamellae()["weak"]["sigl"]


def test_the_summary_says_what_ran_and_what_passed():
    e = np.linspace(0.0, 0.1, 201)
    m = C.measure(COMP, record(e, 800.0 * e), record(e, 800.0 * e))
    rows = {(-100, "weak"): dict(m, v=0.25), (-364, "weak"): dict(m, v=0.125)}
    gen = {"cells": 8, "seeds": "lattice sc 2x2x2, constant 48.36", "wall_nodes_per_cell": 642,
           "volume_mean": 48.0 ** 3, "faces_mean": 6.0, "neighbours_mean": 3.0, "cell": [{"fluid": 440}] * 8}
    text = C.summary(COMP, rows, gen, {"weak": {"sigl": 30.0, "Gl": 100.0}}, 1.04)
    assert "inflated at Pi -100 and -364 kPa with a weak lamella (sigl 30 kPa, Gl 0.1 J/m^2)" in text
    assert "at v = 0.125 and 0.25 m/s" in text and "critical stretch 1.04" in text
    assert "The modulus converged in 2 of 2 conditions" in text and ": 800 kPa." in text
    assert "First failure: none" in text and "in 2 of 2 conditions" in text


def test_a_tension_is_judged_on_the_rise_to_its_peak():
    """Past the peak the lamella lets go faster than any grip moves: the checks of a tension end
    there, so a fast run that parts from the slow one only after the peak still agrees."""
    e = np.linspace(0.0, 0.06, 241)
    rise = np.where(e < 0.03, 300.0 * e, 9.0 - 400.0 * (e - 0.03))      # peak 9 kPa at 3%
    slow = record(e, rise)
    m = C.measure(TENS, slow, record(e, np.where(e < 0.03, rise, 0.5 * rise)))
    assert abs(m["judged"][1] - 0.03) < 1e-3 and m["judged"][0] == TENS.start
    assert m["converged"] and abs(m["E"] - 300.0) < 1e-6 and m["rate"] < 1e-12
    # the same fast run judged as a compression (to the end of the record) has not converged
    assert not C.measure(COMP, slow, record(e, np.where(e < 0.03, rise, 0.5 * rise)))["converged"]


def test_a_tension_run_folder_is_read_as_such(tmp_path):
    flat_runs(tmp_path, "tension", -100, "weak", (0.125, 0.0625))
    (tmp_path / "compress-100-weak-0.25").mkdir()           # the other experiment's runs are not read
    found = C.load_runs(TENS, str(tmp_path))
    assert list(found) == [(-100, "weak")] and found[-100, "weak"][0] == 0.0625


def test_a_tension_gives_no_modulus_once_its_lamella_lets_go():
    e = np.linspace(0.0, 0.06, 241)
    rise = np.where(e < 0.03, 300.0 * e, 9.0 - 400.0 * (e - 0.03))
    intact = C.measure(TENS, record(e, rise), record(e, rise))
    peeling = record(e, rise)
    peeling["debonded_bonds"] = np.where(e > 0.012, 5.0, 0.0)     # bonds let go inside the 1-2% window
    peeled = C.measure(TENS, peeling, record(e, rise))
    assert np.isfinite(intact["E"]) and not np.isfinite(peeled["E"]) and not peeled["converged"]


def test_the_report_is_written_as_the_kind_named(tmp_path):
    """main() hands the kind it is named (its KIND argument) to every step: a tension's report has
    the tension's title, grips, windows and run-info lines, and reads only the tension's runs."""
    import json
    e = np.linspace(0.0, 0.06, 241)
    rise = np.where(e < 0.03, 300.0 * e, 9.0 - 400.0 * (e - 0.03))
    for stage in ("tension", "compress"):
        for speed in (0.125, 0.0625):
            d = tmp_path / f"{stage}-100-weak-{speed:g}"
            d.mkdir()
            r = record(e, rise if stage == "tension" else 2 * rise)
            np.savetxt(d / f"tissue-{stage}.dat", np.column_stack([np.arange(len(e))] + [r[n] for n in COMPRESS]))
    (tmp_path / "gen").mkdir()
    (tmp_path / "gen" / "block.json").write_text(json.dumps(
        {"cells": 8, "seeds": "lattice sc 2x2x2, constant 48.36", "wall_nodes_per_cell": 642,
         "volume_mean": 48.0 ** 3, "faces_mean": 6.0, "neighbours_mean": 3.0, "cell": [{"fluid": 440}] * 8}))
    (tmp_path / "run-info.txt").write_text("RES=coarse BLOCK=2x2x2\nEXP=tension RES=coarse BLOCK=2x2x2\n")
    C.main([str(tmp_path), str(tmp_path), "tq", "tension"])
    md = (tmp_path / "tq.md").read_text()
    assert md.startswith(f"# {TENS.title}\n") and "(EXP=tension RES=coarse BLOCK=2x2x2)" in md
    assert "| modulus 1%-2% (kPa) |" in md and "| grips (worst) |" in md
    row = next(ln for ln in md.split("\n") if ln.startswith("| -100 | weak |"))
    assert row.split("|")[3].strip() == "0.0625" and abs(float(row.split("|")[5]) - 300.0) < 1e-6


def peaked(e, top=9.0, at=0.06, rupture=0.055):
    """A stress that rises linearly to `top` at strain `at` and falls after it (a failure), the walls
    beginning to rupture at strain `rupture`."""
    s = np.where(e < at, top * e / at, top - 400.0 * (e - at))
    d = record(e, s)
    d["broken_tethers"] = np.where(e >= rupture, 10.0, 0.0)
    return d


def test_the_failure_stress_converges_only_where_the_2v_peak_agrees():
    """Both speeds begin to fail at the same strain, but the peak stress or its strain moves with the
    speed: the failure has not converged, and the report gives both."""
    e = np.linspace(0.0, 0.1, 401)
    slow = peaked(e)
    assert C.measure(COMP, slow, peaked(e))["failure_converged"]            # the same peak: converged
    higher = C.measure(COMP, slow, peaked(e, top=9.0 * 1.1))                 # 10% higher at 2v
    later = C.measure(COMP, slow, peaked(e, at=0.075))                      # 1.5% strain later at 2v
    for m in (higher, later):
        assert m["first_converged"] and not m["rising"] and not m["failure_converged"]
    p, p2 = higher["fail"]["peak_kPa"], higher["fail_fast"]["peak_kPa"]
    assert p2 > (1 + Q.TOL_RATE) * p                                      # beyond the tolerance
    cell = f"not converged ({fmt(p)} at v; {fmt(p2)} at 2v)"
    assert C.failure_cells(higher)[0] == cell and f"| {cell} |" in C.table(COMP, {(-100, "weak"): dict(higher, v=0.25)})
    a, b = later["fail"]["strain_at_peak"], later["fail_fast"]["strain_at_peak"]
    assert b - a > C.TOL_STRAIN and C.failure_cells(later)[1] == f"({a:.1%} at v; {b:.1%} at 2v)"


def test_one_judgement_of_the_windows_decides_and_the_verdict_says_it():
    """The modulus's `converged`, the `converged from` strain and the verdict come from one
    judgement of the windows (balance and rate, as the speed ladder's): a window whose plates part
    makes the modulus unconverged and the verdict names the check; the kinetic energy is printed
    but decides nothing (the coarse fluid holds 3-10% of the work at any speed)."""
    e = np.linspace(0.0, 0.1, 201)

    def ringing(share):
        d = record(e, 800.0 * e)
        d[Q.KE] = share * d[Q.WORK]
        return d
    loud = C.measure(COMP, ringing(2 * Q.TOL_KE), record(e, 800.0 * e))
    assert loud["converged"] and loud["start"] == COMP.start and abs(loud["ke"] - 2 * Q.TOL_KE) < 1e-9
    assert "ke_over_work" not in loud["verdict"] and loud["verdict"].startswith("converged")
    # the plates part before the modulus window ends: not converged, and the verdict says balance
    d = record(e, 800.0 * e)
    d["F_bottom_nN"] = np.where(e < 0.05, 0.8 * d["F_bottom_nN"], d["F_bottom_nN"])
    m = C.measure(COMP, d, record(e, 800.0 * e))
    assert not m["converged"] and m["start"] is not None and m["start"] >= 0.05 - 1e-9
    assert "balance" in m["verdict"] and C.modulus_cell(m) == "not converged (800 at v)"


def stopped_runs(tmp_path, ends):
    """Run folders of condition Pi -364, strong at 0.25 and 0.5 m/s, both peaking at 6% strain; the
    run at each speed in `ends` stops there with an ERROR inside its run."""
    e = np.linspace(0.0, 0.1, 401)
    for speed in (0.25, 0.5):
        d = tmp_path / f"compress-364-strong-{speed:g}"
        d.mkdir()
        r, keep = peaked(e), e <= ends.get(speed, 1.0) + 1e-12
        np.savetxt(d / "tissue-compress.dat", np.column_stack([np.arange(keep.sum())] + [r[n][keep] for n in COMPRESS]))
        run = "Per MPI rank memory allocation (min/avg/max) = 20 | 20 | 20 Mbytes\n"
        (d / "log.lammps").write_text(run + ("ERROR on proc 0: Bond style cell/tether: atom 7 moved\n"
                                             if speed in ends else "Loop time of 60 on 1 procs\n"))
    return C.conditions(COMP, str(tmp_path))[1][-364, "strong"]


def test_a_failure_next_to_an_error_stop_has_not_converged(tmp_path):
    """The run at 2v blew up 0.5% strain after its peak: its peak may be the blow-up's, so the
    failure has not converged and the row says where the run stopped."""
    (tmp_path / "a").mkdir()
    assert stopped_runs(tmp_path / "a", {})["failure_converged"]           # no error: converged
    (tmp_path / "b").mkdir()
    m = stopped_runs(tmp_path / "b", {0.5: 0.065})
    assert m["first_converged"] and not m["rising"] and not m["failure_converged"]
    assert C.failure_cells(m)[0] == "run at 2v stopped at 6.5% (error)"
    # the run at v stopped there: the table names the error, not a stress still rising
    (tmp_path / "c").mkdir()
    m = stopped_runs(tmp_path / "c", {0.25: 0.065})
    assert not m["failure_converged"] and C.failure_cells(m)[0] == "run stopped at 6.5% (error)"
    # an error 3% of strain past the peak, the stress long fallen: the peak stands
    (tmp_path / "d").mkdir()
    assert stopped_runs(tmp_path / "d", {0.5: 0.09})["failure_converged"]


def test_a_tension_says_what_its_grips_held(tmp_path):
    """in.tissue-tension -var jaws cells: the report says the end cells were held whole and that the
    strain is over the gauge; runs older than the setting (no jaws in settings.json) held nodes."""
    flat_runs(tmp_path, "tension", -364, "strong", (0.25, 0.125), ["-var", "jaws", "cells", "-var", "grip", "10"])
    lams = C.lamella_settings(TENS, str(tmp_path), C.load_runs(TENS, str(tmp_path)))
    assert C.jaws_cells(lams)
    words = C.protocol(TENS, lams)
    assert "`-var jaws cells`" in words and "within 10 um of an end" in words and "gauge" in words
    assert C.strain_label(TENS, lams) == "strain (opening of the grips / gauge between the held cells)"
    old = {"strong": {"sigl": 300.0, "Gl": 1000.0}}
    assert not C.jaws_cells(old) and C.protocol(TENS, old) == TENS.protocol
    assert C.strain_label(TENS, old) == "strain (opening of the grips / initial height)"


def test_a_compression_by_held_cells_says_it_has_grips(tmp_path):
    """in.tissue-compress -var jaws cells: no plates; the report's words and tables name grips, the
    strain is over the gauge; a compression between plates keeps the plates' words."""
    flat_runs(tmp_path, "compress", -364, "strong", (0.25, 0.125), ["-var", "jaws", "cells", "-var", "grip", "2"])
    lams = C.lamella_settings(COMP, str(tmp_path), C.load_runs(COMP, str(tmp_path)))
    kind = C.held_kind(COMP, lams)
    assert kind.ends == "grips" and "`in.tissue-compress -var jaws cells`" in C.protocol(kind, lams)
    assert "within 2 um of an end" in kind.protocol and kind.window == COMP.window
    assert C.strain_label(kind, lams) == "strain (closing of the grips / gauge between the held cells)"
    plates = {"strong": {"sigl": 300.0, "Gl": 1000.0, "jaws": "plates"}}
    assert C.held_kind(COMP, plates) is COMP and C.protocol(COMP, plates) == COMP.protocol
    assert C.strain_label(COMP, plates) == "strain (closing of the plates / initial height)"


def test_where_says_a_debond_next_to_the_held_layers():
    """where_text: a debonding only at the interfaces with end layers held whole is named as such;
    one between two free layers, or with the ends held by nodes, is not."""
    def row(faces, held):
        return {"where": dict(layers=3, kinds={"lamella debonding": {"bottom": 9, "middle": 9}},
                              interfaces=faces, held_whole=held)}
    jaws = C.where_text({(-364, "strong"): row({"bottom-middle": 765}, True)})
    assert "the debonded bonds by interface: bottom-middle 765" in jaws
    assert "(only at the interfaces with the end layers the grips hold whole)" in jaws
    assert "hold whole" not in C.where_text({(-364, "strong"): row({"bottom-middle": 765}, False)})
    assert "hold whole" not in C.where_text({(-364, "strong"): row({"middle-middle": 5}, True)})
    # a random block's thirds by centroid are not the held cells: no remark, and the list says so
    thirds = C.where_text({(-364, "strong"): row({"bottom-middle": 765}, True)}, thirds=True)
    assert "hold whole" not in thirds and "thirds of the cells by their centroids" in thirds
    r = row({"bottom-middle": 765}, True)
    r["where"]["held_interfaces"] = {"held-free": 20, "free-free": 745}
    words = C.where_text({(-364, "strong"): r}, thirds=True)
    assert "by whether the grips hold the cells whole: held-free 20, free-free 745" in words
    assert "only in" not in words
    # in a layered block the remark on the held layers still comes with the count by grips
    r["where"]["kinds"] = {"lamella debonding": {"bottom": 9, "top": 9}}
    assert "(only in the layers the plates or grips hold)" in C.where_text({(-364, "strong"): r})


def test_p_at_start_is_not_the_first_record_alone():
    """Under respa the record at step 0 reads the turgor several percent low; the report's P at
    start is the median over the smooth start, so one such record does not move it."""
    e = np.linspace(0.0, 0.1, 201)
    d = record(e, 800.0 * e)
    d["P_mean_kPa"][0] = 336.0
    assert C.measure(COMP, d, record(e, 800.0 * e))["P0"] == 364.0
