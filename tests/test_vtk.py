# SPDX-License-Identifier: GPL-2.0-or-later
"""fix cell/vtk: the wall as a VTK PolyData surface, read back with the VTK library.

A coarse wall (642 nodes, 1280 triangles) is stretched isotropically by lam = 1.01 about its
centre (lammps-inputs/in.breathing with 0 steps) and written by fix cell/vtk on 1 and 2 MPI ranks.
Exact expectations: every triangle's area strain is lam^2 - 1, every tether's stretch lam, every
node (on the sphere of radius R = 30 um) displaced radially by (lam - 1) R; no triangle broken; the
triangles' normals point outward (the generator's orientation survives the output).
"""
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

import lmptest as T

LAM, R = 1.01, 30.0


def test_vtk_surface_of_stretched_wall(rundir):
    d = rundir
    T.cellgen("cell", "-o", "wall.data", "--level", 3, "--nfluid", 0, cwd=d)
    for n in (1, 2):
        T.lmp(f"include {T.INPUTS}/in.breathing\nfix surf all cell/vtk 100 walls{n}\nrun 0\n", cwd=d,
              nprocs=n, variables=dict(data="wall.data", nsteps=0, lam=LAM, dir=T.INPUTS), log=f"log.{n}")
        reader = vtk.vtkPolyDataReader()
        reader.SetFileName(f"{d}/walls{n}.0.vtk")
        reader.ReadAllScalarsOn()
        reader.ReadAllVectorsOn()
        reader.Update()
        poly = reader.GetOutput()
        pts = vtk_to_numpy(poly.GetPoints().GetData())
        cd, pd = poly.GetCellData(), poly.GetPointData()
        strain = vtk_to_numpy(cd.GetArray("area_strain"))
        stretch = vtk_to_numpy(cd.GetArray("max_stretch"))
        broken = vtk_to_numpy(pd.GetArray("broken"))
        disp = vtk_to_numpy(pd.GetArray("displacement"))
        ids = vtk_to_numpy(pd.GetArray("id"))
        print(f"{n} rank(s): {poly.GetNumberOfPoints()} points, {poly.GetNumberOfCells()} triangles, "
              f"area strain {strain.min():.10f}..{strain.max():.10f} (lam^2-1 = {LAM ** 2 - 1:.10f}), "
              f"stretch {stretch.min():.10f}..{stretch.max():.10f}")
        T.check(f"{n}: 642 points with IDs 1..642, 1280 triangles",
                poly.GetNumberOfPoints() == 642 and poly.GetNumberOfCells() == 1280
                and sorted(ids) == list(range(1, 643)))
        T.check(f"{n}: area strain = lam^2 - 1", np.allclose(strain, LAM ** 2 - 1, atol=1e-8))
        T.check(f"{n}: tether stretch = lam", np.allclose(stretch, LAM, atol=1e-9))
        T.check(f"{n}: no broken tether", np.all(broken == 0))
        radial = np.einsum("ij,ij->i", disp, pts) / np.linalg.norm(pts, axis=1)
        T.check(f"{n}: displacement radial, (lam - 1) R", np.allclose(radial, (LAM - 1) * R, atol=1e-8)
                and np.allclose(np.linalg.norm(disp, axis=1), (LAM - 1) * R, atol=1e-8))
        normals = vtk.vtkPolyDataNormals()
        normals.SetInputData(poly)
        normals.ComputeCellNormalsOn()
        normals.ComputePointNormalsOff()
        normals.AutoOrientNormalsOff()
        normals.ConsistencyOff()
        normals.SplittingOff()
        normals.Update()
        nrm = vtk_to_numpy(normals.GetOutput().GetCellData().GetNormals())
        centres = vtk.vtkCellCenters()
        centres.SetInputData(poly)
        centres.Update()
        cpos = vtk_to_numpy(centres.GetOutput().GetPoints().GetData())
        T.check(f"{n}: triangle normals point outward", np.all(np.einsum("ij,ij->i", nrm, cpos) > 0))
