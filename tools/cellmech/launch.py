# SPDX-License-Identifier: GPL-2.0-or-later
"""Running LAMMPS on MPI ranks: the one Python form of the launch line (tools/common.sh has the
shell's, mpi_run). Open MPI refuses root without --allow-run-as-root, and the 2-core machines the
package is tested on have fewer slots than ranks asked for, hence --oversubscribe."""
import os

MPI_FLAGS = ("--allow-run-as-root", "--oversubscribe")


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
