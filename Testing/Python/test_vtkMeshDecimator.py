# SPDX-License-Identifier: GPL-2.0-or-later
"""Drives the wrapped vtkMeshDecimator from Python behind vtkLabelOctreeMesher, as
the README shows, and checks what the filter promises, independently of its
own measurements where numpy can: fewer cells, every dihedral angle at or above
MinimumAngle (computed here from the written points), positive tetrahedra,
the material kept, the same physical place as the initial mesh, the counts in
the field data, the bounds taken from the mesher, and clean errors.

Run with PYTHONPATH=<build>/lib/python3/dist-packages (ctest sets it)."""

import unittest

import numpy as np
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy

import labelmesher
from test_vtkLabelOctreeMesher import ball, cells_of, dihedral_angles, make_image


def record_errors(algorithm):
    """The messages of the algorithm's error events, as they come."""
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(obj, event, message):
        errors.append(message)

    algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)
    return errors


def decimate(image, include_background=True, **settings):
    mesher = labelmesher.vtkLabelOctreeMesher()
    mesher.SetInputData(image)
    mesher.SetIncludeBackground(include_background)
    mesher.SetMeasureOutput(False)
    decimator = labelmesher.vtkMeshDecimator()
    errors = record_errors(decimator)
    for name, value in settings.items():
        getattr(decimator, "Set" + name)(value)
    decimator.SetInputConnection(0, mesher.GetOutputPort(0))
    decimator.SetInputData(1, image)
    decimator.Update()
    return mesher, decimator, errors


class DecimatedBallTest(unittest.TestCase):
    """Two nested balls (label 2 inside label 1) in an 18^3 image, spacing 0.5."""

    @classmethod
    def setUpClass(cls):
        labels = ball(18, (8.5, 8.5, 8.5), 7.0) + ball(18, (8.5, 8.5, 8.5), 3.5)
        cls.image = make_image(labels, spacing=(0.5, 0.5, 0.5), origin=(1.0, 2.0, 3.0))
        cls.mesher, cls.decimator, cls.errors = decimate(cls.image, MinimumAngle=12.0)
        cls.grid = cls.decimator.GetOutput()
        cls.points = vtk_to_numpy(cls.grid.GetPoints().GetData()).astype(float)
        _, cls.tets = cells_of(cls.grid)

    def test_no_errors_and_fewer_cells(self):
        self.assertEqual(self.errors, [])
        initial = vtk_to_numpy(self.mesher.GetOutput().GetCellData().GetArray("Material"))
        self.assertLess(3 * self.grid.GetNumberOfCells(), np.count_nonzero(initial))

    def test_angles_at_least_the_bound_and_cells_positive(self):
        angles, volumes = dihedral_angles(self.points, self.tets)
        self.assertGreaterEqual(angles.min(), 12.0 - 1e-9)
        self.assertTrue(np.all(volumes > 0))

    def test_materials_kept_background_dropped(self):
        material = vtk_to_numpy(self.grid.GetCellData().GetArray("Material"))
        self.assertEqual(set(np.unique(material)), {1, 2})

    def test_same_place_and_volume_as_the_image(self):
        _, volumes = dihedral_angles(self.points, self.tets)
        material = vtk_to_numpy(self.grid.GetCellData().GetArray("Material"))
        labels = vtk_to_numpy(self.image.GetPointData().GetScalars())
        # A ball of radius r voxels whose boundary stays within h = 2 voxels of
        # the sphere, with its topology, lies between the balls of radius r - h
        # and r + h: that brackets the volume of its cells.
        for ball_labels, radius in (((1, 2), 7.0), ((2,), 3.5)):
            mesh_volume = volumes[np.isin(material, ball_labels)].sum()
            voxel_volume = np.count_nonzero(np.isin(labels, ball_labels)) * 0.125
            ratio = mesh_volume / voxel_volume
            self.assertGreater(ratio, ((radius - 2.0) / radius) ** 3, ball_labels)
            self.assertLess(ratio, ((radius + 2.0) / radius) ** 3, ball_labels)
        centroid = (self.points[self.tets].mean(axis=1) * volumes[:, None]).sum(axis=0) / volumes.sum()
        np.testing.assert_allclose(centroid, np.array([1.0, 2.0, 3.0]) + 0.5 * 8.5, atol=0.5)

    def test_field_data(self):
        fd = self.grid.GetFieldData()
        value = lambda name: fd.GetArray(name).GetValue(0)
        self.assertEqual(value("AngleBound"), 12.0)
        self.assertEqual(value("ImageToMeshDistance"), 2.0)  # the mesher's default, recorded
        self.assertEqual(value("CellsAfter"), self.grid.GetNumberOfCells())
        self.assertGreater(value("Merges"), 0)
        self.assertGreaterEqual(value("MinimumAngle"), 12.0 - 1e-9)
        self.assertEqual(value("HausdorffBoundsCertified"), 1.0)
        matches = fd.GetArray("TopologyMatches")
        self.assertTrue(all(matches.GetValue(i) for i in range(matches.GetNumberOfTuples())))


class ErrorsTest(unittest.TestCase):

    def test_mesh_without_background_is_refused(self):
        image = make_image(ball(12, (5.5, 5.5, 5.5), 4.0))
        _, decimator, errors = decimate(image, include_background=False)
        self.assertEqual(decimator.GetOutput().GetNumberOfCells(), 0)
        self.assertEqual(len(errors), 1)
        self.assertIn("IncludeBackground", errors[0])

    def test_angle_above_the_proven_bound_is_refused(self):
        _, decimator, errors = decimate(make_image(ball(12, (5.5, 5.5, 5.5), 4.0)), MinimumAngle=35.0)
        self.assertEqual(decimator.GetOutput().GetNumberOfCells(), 0)
        self.assertEqual(len(errors), 1)
        self.assertIn("minimum angle", errors[0])


if __name__ == "__main__":
    unittest.main()
