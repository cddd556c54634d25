# SPDX-License-Identifier: GPL-2.0-or-later
"""Drives the wrapped vtkLabelMesher (mesher and decimator block by block) from
Python, and checks what it promises independently of its own measurements where
numpy can: every dihedral angle at or above MinimumAngle (computed here from the
written points), positive tetrahedra, both materials kept and the background
dropped, volumes within the distance bound of the balls, the streaming figures in the field
data, the same mesh as vtkLabelOctreeMesher + vtkMeshDecimator with one block,
and clean errors.

Run with PYTHONPATH=<build>/lib/python3/dist-packages (ctest sets it)."""

import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import labelmesher
from test_vtkLabelOctreeMesher import ball, cells_of, dihedral_angles, make_image
from test_vtkMeshDecimator import decimate, record_errors


def field(data, name):
    return data.GetFieldData().GetArray(name).GetValue(0)


def mesh(image, **settings):
    mesher = labelmesher.vtkLabelMesher()
    errors = record_errors(mesher)
    for name, value in settings.items():
        getattr(mesher, "Set" + name)(value)
    mesher.SetInputData(image)
    mesher.Update()
    return mesher, errors


class StreamedBallsTest(unittest.TestCase):
    """Two nested balls (label 2 inside label 1) in a 22^3 image, spacing 0.5, blocks small
    enough that the borders cut both interfaces."""

    @classmethod
    def setUpClass(cls):
        labels = ball(22, (10.5, 10.5, 10.5), 9.0) + ball(22, (10.5, 10.5, 10.5), 4.5)
        cls.image = make_image(labels, spacing=(0.5, 0.5, 0.5), origin=(1.0, 2.0, 3.0))
        cls.mesher, cls.errors = mesh(cls.image, MinimumAngle=12.0, BlockCells=4000)
        cls.grid = cls.mesher.GetOutput()
        cls.points = vtk_to_numpy(cls.grid.GetPoints().GetData()).astype(float)
        _, cls.tets = cells_of(cls.grid)

    def test_no_errors_and_several_blocks(self):
        self.assertEqual(self.errors, [])
        self.assertGreater(field(self.grid, "Blocks"), 2)
        self.assertGreater(field(self.grid, "AssembledCells"), 0)
        self.assertLess(3 * self.grid.GetNumberOfCells(), field(self.grid, "CellsBefore"))

    def test_angles_at_least_the_bound_and_cells_positive(self):
        angles, volumes = dihedral_angles(self.points, self.tets)
        self.assertGreaterEqual(angles.min(), 12.0 - 1e-9)
        self.assertTrue(np.all(volumes > 0))

    def test_materials_kept_background_dropped(self):
        material = vtk_to_numpy(self.grid.GetCellData().GetArray("Material"))
        self.assertEqual(set(np.unique(material)), {1, 2})

    def test_volumes_within_the_distance_bound_of_the_balls(self):
        # A ball of radius r voxels whose boundary stays within h = 2 voxels of the sphere lies
        # between the balls of radius r - h and r + h: the inner ball (label 2) and both (1, 2).
        _, volumes = dihedral_angles(self.points, self.tets)
        material = vtk_to_numpy(self.grid.GetCellData().GetArray("Material"))
        ball_volume = lambda r: 4.0 / 3.0 * np.pi * (0.5 * r) ** 3  # spacing 0.5
        for radius, labels in ((4.5, (2,)), (9.0, (1, 2))):
            volume = volumes[np.isin(material, labels)].sum()
            self.assertGreater(volume, ball_volume(radius - 2.0), labels)
            self.assertLess(volume, ball_volume(radius + 2.0), labels)

    def test_measured_guarantees(self):
        self.assertEqual(field(self.grid, "HausdorffBoundsCertified"), 1)
        self.assertEqual(field(self.grid, "InvertedCells"), 0)
        topology = self.grid.GetFieldData().GetArray("TopologyMatches")
        self.assertTrue(all(topology.GetValue(t) == 1 for t in range(topology.GetNumberOfTuples())))


class OneBlockTest(unittest.TestCase):
    def test_one_block_is_the_mesher_then_the_decimator(self):
        labels = ball(16, (7.5, 7.5, 7.5), 6.0) + ball(16, (7.5, 7.5, 7.5), 3.0)
        image = make_image(labels)
        streamed, errors = mesh(image, BlockCells=0, MeasureOutput=False)
        _, decimator, _ = decimate(image, MeasureOutput=False)
        self.assertEqual(errors, [])
        a, b = streamed.GetOutput(), decimator.GetOutput()
        self.assertEqual(a.GetNumberOfCells(), b.GetNumberOfCells())
        np.testing.assert_array_equal(vtk_to_numpy(a.GetPoints().GetData()), vtk_to_numpy(b.GetPoints().GetData()))
        np.testing.assert_array_equal(cells_of(a)[1], cells_of(b)[1])


class ErrorsTest(unittest.TestCase):
    def test_angle_above_the_proven_bound_is_one_error(self):
        mesher, errors = mesh(make_image(ball(10, (4.5, 4.5, 4.5), 3.0)), MinimumAngle=40.0)
        self.assertEqual(len(errors), 1)
        self.assertIn("minimum angle", errors[0])
        self.assertEqual(mesher.GetOutput().GetNumberOfCells(), 0)


if __name__ == "__main__":
    unittest.main()
