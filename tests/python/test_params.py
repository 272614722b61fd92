# SPDX-License-Identifier: GPL-2.0-or-later
"""cellmech.params: Table I read from lammps-inputs/cell-model.lmp, the level table, and the command
line the shell scripts read them with (one source for the generator, inputs, scripts and tests)."""
import os
import re
import subprocess
import sys

import pytest

from cellmech import params

ROOT = params.ROOT


def test_table_is_cell_model_lmp():
    """Every `variable NAME index VALUE` line of cell-model.lmp, first definition, numbers as floats."""
    t = params.table()
    lines = re.findall(r"^variable\s+(\w+)\s+index\s+(\S+)", open(params.MODEL_FILE).read(), re.M)
    print(f"{len(t)} parameters: {t}")
    assert len(lines) >= 13 and len(t) == len({k for k, _ in lines})
    for k, v in lines:
        assert str(t[k]) == v or t[k] == float(v)
    # the stiff cell of the paper's Table I, in units micro
    assert (t["G"], t["t0"], t["rho0"], t["c"]) == (8.0e5, 0.126, 1.0, 264.6)
    assert t["wall"] == "tether"


def test_the_lamella_is_set_in_tissue_model_lmp_alone():
    """One source for the middle lamella's settings: tissue-model.lmp (the tissue report reads it)."""
    cell = params.table()
    tissue = params.table(os.path.join(ROOT, "lammps-inputs", "tissue-model.lmp"))
    assert not {"Gl", "gl", "lamlog"} & set(cell)
    assert (tissue["sigl"], tissue["Gl"], tissue["lamlog"]) == (300.0, 1000.0, "debond.log")


def test_table_first_definition_and_overrides_win(tmp_path):
    """As in LAMMPS: an index variable defined twice keeps its first value; -var (overrides) wins."""
    f = tmp_path / "m.lmp"
    f.write_text("variable G index 1.0  # a\nvariable G index 2.0\n  variable s index 3\n"
                 "variable x equal 4\nvariable name index abc\n")
    assert params.table(str(f)) == {"G": 1.0, "s": 3.0, "name": "abc"}
    assert params.table(str(f), {"s": 9.0}) == {"G": 1.0, "s": 9.0, "name": "abc"}


def test_level_table():
    """Level 4 is cell-model.lmp's defaults; a level coarser doubles r0 and reach, f0 grows 2^3."""
    t = params.table()
    for k in ("s", "r0", "f0", "reach", "delta", "dp"):
        assert params.LEVELS[4][k] == t[k], k
    for lv in (3, 4):
        fine, coarse = params.LEVELS[lv + 1], params.LEVELS[lv]
        assert coarse["r0"] == 2 * fine["r0"] and coarse["reach"] == 2 * fine["reach"]
        assert coarse["f0"] == 8 * fine["f0"]
    assert [params.wall_nodes(lv) for lv in (3, 4, 5)] == [642, 2562, 10242]
    assert params.LEVELS[5]["s"] == 2.07 and params.LEVELS[5]["dt"] == 0.0005
    assert params.model_vars(3) == dict(s=6.4, r0=3.2, f0=8.0e4, reach=4.0, dt=0.001, delta=0.2, dp=4.57)
    with pytest.raises(ValueError, match="level must be one of 3, 4, 5, got 7"):
        params.level(7)


def cli(*args):
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "tools"))
    p = subprocess.run([sys.executable, "-m", "cellmech.params", *map(str, args)], env=env,
                       capture_output=True, text=True, timeout=60)
    print(args, p.returncode, p.stdout.strip(), p.stderr.strip())
    return p


def test_command_line():
    assert cli("level", 4, "nfluid", "s", "r0", "f0", "reach", "dt", "nodes").stdout.split() == \
        ["3500", "3.2", "1.6", "10000.0", "2.0", "0.001", "2562"]
    assert cli("table", "G", "t0", "c").stdout.split() == ["800000.0", "0.126", "264.6"]
    assert cli("cell", "R", "M_wall", "P").stdout.split() == ["30.0", "13000.0", "364.0"]
    p = cli("level", 7, "s")
    assert p.returncode == 2 and "level must be one of 3, 4, 5, got 7" in p.stderr
    p = cli("level", 4, "bogus")
    assert p.returncode == 2 and "unknown bogus" in p.stderr


def test_shell_scripts_read_the_table():
    """tools/common.sh's level_params gives the shell the same row (level 5: s = 2.07 um, where the
    formula 3.2 2^(4-level) of the old experiments.sh gave 1.6)."""
    p = subprocess.run(["bash", "-c", f"source {ROOT}/tools/common.sh && level_params 5 s r0 f0 dt"],
                       capture_output=True, text=True, timeout=60)
    print(p.stdout, p.stderr)
    assert p.returncode == 0 and p.stdout.split() == ["2.07", "0.8", "1250.0", "0.0005"]
    for script in ("main-job.sh", "experiments.sh", "tissue.sh", "benchmark.sh", "benchmark-tissue.sh",
                   "validate-inflation.sh"):
        text = open(os.path.join(ROOT, "tools", script)).read()
        assert "level_params" in text, script
        assert not re.search(r"\bs=?6\.4\b|8\.0e4|1\.0e4\*k", text), f"{script} has its own level table"


def test_named_lamellae_strong_is_tissue_model_default():
    """One definition of each named lamella: strong is tissue-model.lmp's default, weak a tenth of it."""
    tissue = params.table(params.TISSUE_FILE)
    lam = params.lamellae()
    assert lam["strong"] == dict(sigl=tissue["sigl"], Gl=tissue["Gl"])
    assert lam["weak"] == dict(sigl=tissue["sigl"] / 10, Gl=tissue["Gl"] / 10)
    assert cli("lamella", "weak", "sigl", "Gl").stdout.split() == ["30.0", "100.0"]
    assert cli("lamella", "strong", "Gl").stdout.split() == [f"{tissue['Gl']}"]
    assert cli("lamella", "medium").returncode == 2


def test_defaults_follow_includes_first_definition_wins(tmp_path):
    """An input's index settings and those of the files it includes from ${dir}, in LAMMPS's order."""
    (tmp_path / "in.x").write_text("variable a index 1\ninclude ${dir}/m.lmp\nvariable b index 9\n"
                                   'if "1 > 0" then "include ${dir}/n.lmp"\n')
    (tmp_path / "m.lmp").write_text("variable a index 2\nvariable b index 3\nvariable w index tether\n")
    (tmp_path / "n.lmp").write_text("variable c index 4\n")
    assert params.defaults(str(tmp_path / "in.x"), str(tmp_path)) == {"a": 1.0, "b": 3.0, "w": "tether"}
    inp = os.path.join(params.INPUTS, "in.tissue-compress")
    d = params.defaults(inp)
    # in.tissue-compress's own, tissue-model.lmp's lamella and cell-model.lmp's wall, through the includes
    assert d["lamf"] == 1.04 and d["sigl"] == params.lamellae()["strong"]["sigl"]
    assert d["G"] == params.table()["G"]


def test_first_var_of_a_name_wins_as_in_lammps():
    """LAMMPS keeps the first -var of a name (an index variable is not redefined): tools/tissue.sh
    gives the held drying's -var wall membrane before its model's -var wall tether, and the run has
    the membrane wall; settings.json must record that one."""
    inp, var = params.lammps_vars(["-in", "in.x", "-var", "wall", "membrane", "-var", "s", "6.4",
                                   "-var", "wall", "tether"])
    assert inp == "in.x" and var == {"wall": "membrane", "s": 6.4}


def test_settings_json_holds_the_vars_passed_and_the_defaults(tmp_path):
    """settings.json, written before a run: every -var passed, and the defaults that applied; one
    entry per input; run_settings reads it back (and falls back to the defaults without it)."""
    inp = os.path.join(params.INPUTS, "in.tissue-compress")
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "tools"))
    argv = ["-in", inp, "-screen", "none", "-var", "dir", params.INPUTS, "-var", "Pi", "-100",
            "-var", "sigl", "30", "-var", "Gl", "100", "-var", "vplate", "0.5"]
    p = subprocess.run([sys.executable, "-m", "cellmech.params", "settings", "--", *argv], env=env,
                       cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, p.stderr
    s = params.run_settings(str(tmp_path), "in.tissue-compress")
    assert (s["Pi"], s["sigl"], s["Gl"], s["vplate"]) == (-100.0, 30.0, 100.0, 0.5)
    assert s["lamf"] == params.defaults(inp)["lamf"] and s["respa"] == params.defaults(inp)["respa"]
    params.write_settings(["-in", os.path.join(params.INPUTS, "in.tissue-inflate"), "-var", "Pi", "-600"],
                          str(tmp_path))
    import json
    data = json.load(open(tmp_path / "settings.json"))
    assert set(data) == {"in.tissue-compress", "in.tissue-inflate"}
    assert data["in.tissue-compress"]["var"]["vplate"] == 0.5
    assert set(data["in.tissue-compress"]) == {"var", "settings"}
    # a second run of the same input under its own key (tools/experiments.sh: its log name) keeps
    # the first; run_settings reads each back by its key
    params.write_settings(["-in", inp, "-var", "dir", params.INPUTS, "-var", "vplate", "0.25"], str(tmp_path),
                          key="log.slow")
    data = json.load(open(tmp_path / "settings.json"))
    assert set(data) == {"in.tissue-compress", "in.tissue-inflate", "log.slow"}
    assert data["log.slow"]["input"] == "in.tissue-compress"
    assert params.run_settings(str(tmp_path), "in.tissue-compress", key="log.slow")["vplate"] == 0.25
    assert params.run_settings(str(tmp_path), "in.tissue-compress")["vplate"] == 0.5
    assert params.recorded_settings(str(tmp_path), "log.fast") is None
    old = params.run_settings(str(tmp_path / "none"), "in.tissue-compress", {"sigl": 30.0})
    assert old["sigl"] == 30.0 and old["vplate"] == params.defaults(inp)["vplate"]
    p = subprocess.run([sys.executable, "-m", "cellmech.params", "settings", "--", "-var", "a", "1"],
                       env=env, cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert p.returncode == 2 and "no -in FILE" in p.stderr


def test_settings_json_has_the_model_lengths_of_the_data(tmp_path):
    """The model lengths come with the data (cellgen.py writes DATA.lmp, in.tissue-inflate writes
    RESTART.lmp beside its restart) and the inputs include them before their own defaults, the
    paper's level 4: settings.json must record the data's (s 6.4 for a coarse block, not 3.2)."""
    lv3 = params.level(3)
    lengths = "".join(f"variable {k} index {lv3[k]}\n" for k in ("s", "r0", "f0", "reach"))
    (tmp_path / "block.data.lmp").write_text(lengths + "variable special index 27\n")
    (tmp_path / "block.restart.lmp").write_text(lengths)
    inflate = params.write_settings(["-in", os.path.join(params.INPUTS, "in.tissue-inflate"), "-var", "data",
                                     str(tmp_path / "block.data")], str(tmp_path))
    compress = params.write_settings(["-in", os.path.join(params.INPUTS, "in.tissue-compress"), "-var", "restart",
                                      str(tmp_path / "block.restart")], str(tmp_path))
    for eff in (inflate, compress):
        assert [eff[k] for k in ("s", "r0", "f0", "reach")] == [lv3[k] for k in ("s", "r0", "f0", "reach")]
    assert lv3["s"] != params.defaults(os.path.join(params.INPUTS, "in.tissue-compress"))["s"]
    # no companion file: the input's defaults, as LAMMPS would stop on (tissue-restart.lmp's error)
    bare = params.write_settings(["-in", os.path.join(params.INPUTS, "in.tissue-compress"), "-var", "restart",
                                  str(tmp_path / "none.restart")], str(tmp_path))
    assert bare["s"] == params.defaults(os.path.join(params.INPUTS, "in.tissue-compress"))["s"]
