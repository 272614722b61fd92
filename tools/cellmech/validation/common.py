# SPDX-License-Identifier: GPL-2.0-or-later
"""Running LAMMPS and cellgen for the validation cases; the resolutions of the model.

A run is skipped when its outputs exist and were made with the same arguments (a stamp file per
run), so that cases sharing an inflation (and a resumed paper-resolution run) do not repeat it.
"""
import hashlib
import json
import os
import re
import subprocess
import sys
import time

from .. import params
from ..launch import mpi_command, mpiexec
from ..params import LEVELS, SOFT, model_vars, wall_nodes  # noqa: F401 (names the cases import)

ROOT = os.environ.get("CELLMECH_ROOT", params.ROOT)
# the driver points this to a copy of lammps-inputs taken when it starts: LAMMPS reads its input
# as it goes, so a long validation run must not see the inputs edited under it
INPUTS = os.environ.get("CELLMECH_INPUTS", os.path.join(ROOT, "lammps-inputs"))
CELLGEN = os.path.join(ROOT, "tools", "cellgen.py")
SPECTRUM = os.environ.get("CELLMECH_SPECTRUM", os.path.join(ROOT, "build", "cellmech-spectrum"))

# osmotic inflation time (us): level 5 reaches its turgor by 3 us (measured: 363.8 kPa at 2 us);
# 10 us leave 7 us (several relaxation times) for the inflation's oscillation to die out, at half
# the cost of the 20 us that levels 3 and 4 can afford
T_INFLATE = {3: 20.0, 4: 20.0, 5: 10.0}
# time (us) a cell brought down from 364 kPa settles at its turgor (in.turgor's default is level 4's
# 20000 steps of 1 ns: turgor within 0.25% of -Pi, fluid mass steady to 4e-5 per 4 us). The
# coarse 3 kPa cell comes up to its turgor from below more slowly: measured 1.35% short after
# 20 us, 0.6% after 40 and 0.4% after 60 us (its mass still creeping by 1e-4 per 4 us)
T_SETTLE = {3: 40.0, 4: 20.0, 5: 20.0}


def prep_times(level, t_inflate=None, t_settle=None):
    """(inflation, settling) time in us of a turgid cell at `level`: the given ones, else the
    level's T_INFLATE and T_SETTLE."""
    return t_inflate or T_INFLATE[level], t_settle or T_SETTLE[level]

# the stiff cell of Table I (docs/model.md section 3.1), units micro: from cell-model.lmp and params
_T = params.table()
R0, M_WALL, RHO0, C_PHYS = params.CELL["R"], params.CELL["M_wall"], _T["rho0"], _T["c"]
STIFF = params.stiff()


_CODE = []
USED_INPUTS = ("cell-model.lmp", "cell-wall.lmp", "in.inflate", "in.compress", "in.breathing", "in.breathing-fluid",
               "in.sheet", "in.turgor")


def code_version():
    """Digest of the LAMMPS inputs and the plugin library: a run made with other inputs or
    another build of the plugin is not reused."""
    if not _CODE:
        h = hashlib.sha1()
        for f in USED_INPUTS:
            h.update(f.encode() + open(os.path.join(INPUTS, f), "rb").read())
        plugin = os.path.join(os.environ.get("LAMMPS_PLUGIN_PATH", os.path.join(ROOT, "build")),
                              "cellmechplugin.so")
        if os.path.exists(plugin):
            h.update(open(plugin, "rb").read())
        _CODE.append(h.hexdigest()[:16])
    return _CODE[0]


def log_wall_time(text):
    """Seconds of 'Total wall time: H:MM:SS' in a LAMMPS log (0 if absent)."""
    m = re.findall(r"Total wall time: (\d+):(\d+):(\d+)", text)
    if not m:
        return 0.0
    h, mi, se = map(int, m[-1])
    return 3600.0 * h + 60.0 * mi + se


class Runner:
    def __init__(self, work, nprocs=1, log=print, wall="tether", variant=None):
        self.work = work
        # -var settings of a variant study (VARS), over those of every run
        self.variant = dict(variant or {})
        self.nprocs = nprocs
        self.wall = wall          # the default wall of the runs (-var wall, cell-wall.lmp)
        self.lmp_exe = os.environ.get("LMP", "lmp")
        self.mpiexec = mpiexec()
        self.say = log
        # the outputs of the runs made or reused here: {file: digest of the settings that made it}
        self.made = {}
        # LAMMPS wall time of the runs a case used, reused ones included, and the time spent
        # here in runs made now: the driver reports a case's cost as the first plus its own
        # analysis time, the same whether its runs were made now or by an earlier case
        self.reset_time()
        os.makedirs(work, exist_ok=True)

    def reset_time(self):
        self.seconds = self.fresh_seconds = 0.0
        self.counted = set()

    def _count(self, log, text):
        if log not in self.counted:       # a run used twice by one case counts once
            self.counted.add(log)
            self.seconds += log_wall_time(text)

    def path(self, *p):
        return os.path.join(self.work, *p)

    def _fresh(self, stamp, key):
        try:
            return json.load(open(stamp)) == key
        except (OSError, ValueError):
            return False

    def cellgen(self, out, *args):
        """Write data file `out` (in the work folder); return (wall nodes, fluid per cell)."""
        stamp = self.path(out + ".stamp")
        key = [str(a) for a in args]
        if not self._fresh(stamp, key) or not os.path.exists(self.path(out)):
            p = subprocess.run([sys.executable, CELLGEN, *key[:1], "-o", out, *key[1:]],
                               cwd=self.work, check=True, capture_output=True, text=True)
            with open(self.path(out + ".info"), "w") as f:
                f.write(p.stdout)
            json.dump(key, open(stamp, "w"))
        info = open(self.path(out + ".info")).read()
        m = re.search(r"\((\d+) wall nodes\), (\d+) fluid per cell", info)
        return (int(m.group(1)), int(m.group(2))) if m else (None, None)

    def lmp(self, script, log, outputs=(), **variables):
        """Run lmp on lammps-inputs/`script` with -var settings; skip if `outputs` (files in the
        work folder) exist from a run with the same settings, inputs and plugin. Returns the log
        text. The wall is the Runner's unless `wall` is given; the tethers' runs carry no -var
        wall (cell-wall.lmp's default)."""
        wall = variables.pop("wall", self.wall)
        if wall != "tether":
            variables["wall"] = wall
        variables.update(self.variant)
        stamp = self.path(log + ".stamp")
        key = dict(script=script, nprocs=self.nprocs, code=code_version(),
                   **{k: str(v) for k, v in variables.items()})
        # a run that reads another run's output (a restart) is keyed by that run's settings too:
        # the same file name made with other settings (a longer settling, say) makes it stale
        upstream = {str(v): self.made[str(v)] for v in variables.values()
                    if str(v) in self.made and str(v) not in outputs}
        if upstream:
            key["upstream"] = upstream
        made = hashlib.sha1(json.dumps(key, sort_keys=True).encode()).hexdigest()[:16]
        if outputs and self._fresh(stamp, key) and all(os.path.exists(self.path(o)) for o in outputs):
            text = open(self.path(log)).read()
            self._count(log, text)
            self.made.update({o: made for o in outputs})
            return text
        if "\n" in script:    # an input text (e.g. 'include in.inflate' plus commands)
            with open(self.path("in." + log), "w") as f:
                f.write(script)
            inp = self.path("in." + log)
        else:
            inp = os.path.join(INPUTS, script)
        cmd = [self.lmp_exe, "-in", inp, "-log", log, "-screen", "none"]
        # the inputs include their wall (cell-wall.lmp) and model files from there
        variables.setdefault("dir", INPUTS)
        for k, v in variables.items():
            cmd += ["-var", k, str(v)]
        cmd = mpi_command(cmd, self.nprocs, self.mpiexec)
        t = time.time()
        p = subprocess.run(cmd, cwd=self.work, capture_output=True, text=True)
        text = open(self.path(log)).read() if os.path.exists(self.path(log)) else ""
        if p.returncode != 0:
            raise RuntimeError(f"lmp failed (rc {p.returncode}): {' '.join(cmd)}\n{text[-2000:]}"
                               f"\n{p.stdout[-1000:]}\n{p.stderr[-1000:]}")
        self.say(f"    {log}: {time.time() - t:.0f} s")
        self._count(log, text)
        self.fresh_seconds += time.time() - t
        json.dump(key, open(stamp, "w"))
        self.made.update({o: made for o in outputs})
        return text

    def spectrum(self, datafile, tcol=2, ycol=3):
        """(omega, amplitude, peaks[(omega, amplitude)]) from tools/spectrum (FFTW)."""
        out = subprocess.run([SPECTRUM, self.path(datafile), str(tcol), str(ycol)],
                             capture_output=True, text=True, check=True).stdout
        w, a, peaks = [], [], []
        for line in out.splitlines():
            if line.startswith("# peak"):
                peaks.append(tuple(float(x) for x in line.split()[2:4]))
            elif line and not line.startswith("#"):
                x, y = line.split()[:2]
                w.append(float(x))
                a.append(float(y))
        return w, a, peaks

    # ---- the standard cell runs, shared between cases -----------------------------------

    def cell(self, level, wall=None):
        # the bending wall's hinges are in the data file (cellgen.py --bending)
        bend = (wall or self.wall) == "bending"
        data = f"cell{level}{'-bending' if bend else ''}.data"
        nw, nf = self.cellgen(data, "cell", "--level", level, "--nfluid", LEVELS[level]["nfluid"],
                              "--inset", LEVELS[level]["r0"], *(["--bending"] if bend else []))
        return data, nw, nf

    def inflate(self, level, P=STIFF["P"], c=C_PHYS, t_us=None, wall=None, model=None, name=""):
        """Inflate the stiff cell at `level` to turgor P (kPa) with sound speed c and the wall
        `wall` (default the Runner's); return (restart file, inflate.dat name, wall nodes, fluid
        particles). `model`: -var settings over the level's (model_vars), named by `name` in the
        files, so that runs of another model never share them."""
        wall = wall or self.wall
        data, nw, nf = self.cell(level, wall)
        tag = f"L{level}-P{P:g}-c{c:g}" + ("" if wall == "tether" else f"-{wall}") + name
        mv = run_vars(level, model)
        nsteps = int(round(prep_times(level, t_inflate=t_us)[0] / mv["dt"]))
        self.lmp("in.inflate", f"log.inflate-{tag}", outputs=(f"inflate-{tag}.dat", f"inflated-{tag}.restart"),
                 dir=INPUTS, data=data, Pi=-P, c=c, nsteps=nsteps, every=nsteps // 20,
                 out=f"inflate-{tag}.dat", restart_out=f"inflated-{tag}.restart", wall=wall, **mv)
        return f"inflated-{tag}.restart", f"inflate-{tag}.dat", nw, nf

    def turgid(self, level, P, wall=None, model=None, name="", t_inflate=None, t_settle=None):
        """The stiff cell at turgor P (kPa) as the package makes one (lammps-inputs/in.turgor):
        inflated to the paper's 364 kPa, then brought to P by osmosis. A cell pumped up directly
        to a low turgor is still taking in water after tens of us (docs/studies/membrane-wall.rst). Returns
        (restart file, record of its last stage: inflate-*.dat or settle-*.dat, wall nodes,
        fluid particles). t_inflate, t_settle: the stages' times in us (T_INFLATE, T_SETTLE)."""
        restart, infl, nw, nf = self.inflate(level, STIFF["P"], t_us=t_inflate, wall=wall,
                                             model=model, name=name)
        if P == STIFF["P"]:
            return restart, infl, nw, nf
        wall = wall or self.wall
        tag = f"L{level}-P{P:g}" + ("" if wall == "tether" else f"-{wall}") + name
        mv = run_vars(level, model)
        dt = mv.pop("dt")       # in.turgor's step is dtset
        self.lmp("in.turgor", f"log.settle-{tag}", outputs=(f"settle-{tag}.dat", f"settled-{tag}.restart"),
                 dir=INPUTS, restart=restart, turgor=P, compress=0, dtset=dt,
                 nsettle=int(round(prep_times(level, t_settle=t_settle)[1] / dt)),
                 setout=f"settle-{tag}.dat", settled=f"settled-{tag}.restart", wall=wall, **mv)
        return f"settled-{tag}.restart", f"settle-{tag}.dat", nw, nf


def run_vars(level, model=None):
    """The level's -var settings of cell-model.lmp (model_vars) with a case's own over them."""
    return dict(model_vars(level), **(model or {}))


def resolution(level, fluid=True, nw=None, nf=None):
    return dict(level=level, wall_nodes=nw if nw is not None else wall_nodes(level),
                fluid_particles=(nf if nf is not None else LEVELS[level]["nfluid"]) if fluid else 0)
