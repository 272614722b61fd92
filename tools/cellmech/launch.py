# SPDX-License-Identifier: GPL-2.0-or-later
"""Running LAMMPS on MPI ranks: the one Python form of the launch line (tools/common.sh has the
shell's, mpi_run). Open MPI refuses root without --allow-run-as-root, and the 2-core machines the
package is tested on have fewer slots than ranks asked for, hence --oversubscribe."""
import os

MPI_FLAGS = ("--allow-run-as-root", "--oversubscribe")


def stage_times(run):
    """{stage: (seconds, status)} from the times.txt that the stage runners of tools/experiments.sh
    and tools/tissue.sh write in a run folder (one line 'NAME SECONDS STATUS' per stage run; a
    later line of the same stage wins); {} without one."""
    t = {}
    p = os.path.join(run, "times.txt")
    if os.path.exists(p):
        for line in open(p):
            w = line.split()
            if len(w) >= 3:
                t[w[0]] = (int(w[1]), w[2])
    return t


def mpiexec():
    """The MPI launcher: $MPIEXEC (CTest passes the one CMake found), else mpirun."""
    return os.environ.get("MPIEXEC") or "mpirun"


def mpi_command(cmd, nprocs=1, launcher=None):
    """cmd (a list) as it runs on nprocs MPI ranks: unchanged on one rank (no MPI launcher
    needed), else prefixed by the launcher and its -np."""
    cmd = [str(c) for c in cmd]
    if int(nprocs) < 1:
        raise ValueError(f"nprocs must be >= 1, got {nprocs}")
    if int(nprocs) == 1:
        return cmd
    return [launcher or mpiexec(), *MPI_FLAGS, "-np", str(int(nprocs)), *cmd]
