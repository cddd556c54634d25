# SPDX-License-Identifier: GPL-2.0-or-later
"""Drives the wrapped vtkBezierCurver from Python behind vtkLabelOctreeMesher, as
a ParaView/Slicer pipeline would, and checks what the filter promises: cubic
VTK_BEZIER_TRIANGLE cells that VTK itself evaluates with a Jacobian of one sign
everywhere (sampled through vtkBezierTriangle, independently of the filter's
own proof), shared edge control points, the Material and Jacobian arrays,
the pixel accuracy of the linear and the curved mesh, meshes in any axis
plane, and clean errors.

Run with PYTHONPATH=<build>/lib/python3/dist-packages (ctest sets it)."""

import unittest

import numpy as np
from vtkmodules.vtkCommonCore import VTK_STRING, mutable, vtkCommand
from vtkmodules.vtkCommonDataModel import VTK_BEZIER_TRIANGLE, vtkImageData, vtkUnstructuredGrid
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

import labelmesher


def disc_image(normal_axis=2, n=48, radius=17.3):
    """A disc of label 4 in an n x n single-slice image lying across `normal_axis`."""
    y, x = np.mgrid[0:n, 0:n]
    labels = np.where((x - 23.6) ** 2 + (y - 24.2) ** 2 <= radius ** 2, 4, 0).astype(np.uint8)
    dims = [n, n, n]
    dims[normal_axis] = 1
    image = vtkImageData()
    image.SetDimensions(*dims)
    image.SetSpacing(0.5, 0.5, 0.5)
    image.SetOrigin(3.0, -2.0, 1.0)
    array = numpy_to_vtk(labels.ravel(), deep=True)
    array.SetName("Labels")
    image.GetPointData().SetScalars(array)
    return image


def run_filter(algorithm, *inputs, **settings):
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(obj, event, message):
        errors.append(message)

    algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)
    for name, value in settings.items():
        getattr(algorithm, "Set" + name)(value)
    for port, data in enumerate(inputs):
        if data is not None:
            algorithm.SetInputDataObject(port, data)
    algorithm.Update()
    return algorithm.GetOutput(), errors


def curve(image, **settings):
    mesher = labelmesher.vtkLabelOctreeMesher()
    mesher.SetInputData(image)
    mesher.Update()
    return run_filter(labelmesher.vtkBezierCurver(), mesher.GetOutput(), image, **settings)


def sampled_jacobians(grid, plane_axes, samples=7):
    """Per cell, det of d(x_a, x_b)/d(r, s) by central differences of VTK's own evaluation at
    interior parametric points: an array cells x samples."""
    h = 1e-6
    sub_id = mutable(0)
    weights = [0.0] * 10
    per_cell = []
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)

        def at(r, s):
            x = [0.0, 0.0, 0.0]
            cell.EvaluateLocation(sub_id, [r, s, 0.0], x, weights)
            return np.array([x[plane_axes[0]], x[plane_axes[1]]])

        dets = []
        for i in range(1, samples):
            for j in range(1, samples - i):
                r, s = i / samples, j / samples
                dr = (at(r + h, s) - at(r - h, s)) / (2 * h)
                ds = (at(r, s + h) - at(r, s - h)) / (2 * h)
                dets.append(dr[0] * ds[1] - dr[1] * ds[0])
        per_cell.append(dets)
    return np.array(per_cell)


def jacobian_signs(grid, plane_axes, samples=7):
    """(min, max) of the sampled det J over every cell (sampled_jacobians)."""
    dets = sampled_jacobians(grid, plane_axes, samples)
    return dets.min(), dets.max()


class DiscTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.image = disc_image()
        cls.grid, cls.errors = curve(cls.image)

    def test_no_errors(self):
        self.assertEqual(self.errors, [])

    def test_cells_are_cubic_bezier_triangles(self):
        self.assertGreater(self.grid.GetNumberOfCells(), 50)
        types = vtk_to_numpy(self.grid.GetCellTypesArray())
        self.assertTrue(np.all(types == VTK_BEZIER_TRIANGLE))
        offsets = vtk_to_numpy(self.grid.GetCells().GetOffsetsArray())
        self.assertTrue(np.all(np.diff(offsets) == 10))

    def test_edge_control_points_are_shared(self):
        conn = vtk_to_numpy(self.grid.GetCells().GetConnectivityArray()).reshape(-1, 10)
        uses = np.bincount(conn[:, 3:9].ravel())
        # An edge point belongs to one cell (boundary edge) or two (interior edge).
        self.assertTrue(set(np.unique(uses[uses > 0])) <= {1, 2})
        self.assertGreater(np.count_nonzero(uses == 2), np.count_nonzero(uses == 1))

    def test_arrays(self):
        cd = self.grid.GetCellData()
        self.assertTrue(np.all(vtk_to_numpy(cd.GetArray("Material")) == 4))
        self.assertTrue(np.all(vtk_to_numpy(cd.GetArray("Valid")) == 1))
        scaled = vtk_to_numpy(cd.GetArray("ScaledJacobian"))
        self.assertTrue(np.all((scaled > 0) & (scaled <= 1 + 1e-12)))
        fd = self.grid.GetFieldData()
        self.assertEqual(fd.GetArray("InvalidCells").GetValue(0), 0)
        self.assertGreater(fd.GetArray("CurvedEdges").GetValue(0), 0)

    def test_vtk_sees_a_jacobian_of_one_sign(self):
        lowest, highest = jacobian_signs(self.grid, (0, 1))
        self.assertTrue(lowest > 0 or highest < 0, (lowest, highest))

    def test_accuracy_is_reported_consistently(self):
        # Every misclassified pixel is missed by its label, claimed by another
        # material, or both (section 5.2.3's two kinds of error).
        fd = self.grid.GetFieldData()
        self.assertEqual(fd.GetArray("Pixels").GetValue(0), 48 * 48)
        self.assertEqual(vtk_to_numpy(fd.GetArray("AccuracyMaterial")).tolist(), [4])
        for kind in ("Linear", "Curved"):
            total = fd.GetArray("MisclassifiedPixels" + kind).GetValue(0)
            missed = vtk_to_numpy(fd.GetArray("MissedPixels" + kind)).sum()
            claimed = vtk_to_numpy(fd.GetArray("ClaimedPixels" + kind)).sum()
            self.assertLessEqual(total, missed + claimed)
            self.assertLessEqual(missed + claimed, 2 * total)
            self.assertLess(total, 0.05 * 48 * 48)

    def test_c1(self):
        grid, errors = curve(self.image, Smoothness=1, Tension=0.25)
        self.assertEqual(errors, [])
        self.assertTrue(np.all(vtk_to_numpy(grid.GetCellData().GetArray("Valid")) == 1))
        self.assertEqual(grid.GetFieldData().GetArray("Smoothness").GetValue(0), 1)


class DecimatedPipelineTest(unittest.TestCase):
    """mesher -> decimator -> curver, as `labelmesher curve` runs them: the
    curves keep the bounds the decimator's output records, do not cross, keep
    the topology, and misclassify fewer pixels than the decimated mesh."""

    @classmethod
    def setUpClass(cls):
        cls.image = disc_image(n=72, radius=27.4)
        mesher = labelmesher.vtkLabelOctreeMesher()
        mesher.SetInputData(cls.image)
        mesher.SetIncludeBackground(True)
        decimator = labelmesher.vtkMeshDecimator()
        decimator.SetInputConnection(0, mesher.GetOutputPort(0))
        decimator.SetInputDataObject(1, cls.image)
        decimator.Update()
        cls.linear = decimator.GetOutput()
        cls.grid, cls.errors = run_filter(labelmesher.vtkBezierCurver(), cls.linear, cls.image)

    def field(self, name):
        array = self.grid.GetFieldData().GetArray(name)
        self.assertIsNotNone(array, name)
        return array.GetValue(0)

    def test_valid_and_seen_valid_by_vtk(self):
        self.assertEqual(self.errors, [])
        self.assertEqual(self.field("InvalidCells"), 0)
        lowest, highest = jacobian_signs(self.grid, (0, 1))
        self.assertTrue(lowest > 0 or highest < 0, (lowest, highest))

    def test_bounds_kept_on_the_curves(self):
        self.assertEqual(self.field("ImageToMeshDistance"), 2.0)
        self.assertEqual(self.field("MeshToImageDistance"), 2.0)
        slack = self.field("CurvedMeasureResolution") + 1e-9
        self.assertLessEqual(self.field("MeasuredImageToMeshDistance"), 2.0 + slack)
        self.assertLessEqual(self.field("MeasuredMeshToImageDistance"), 2.0 + slack)
        self.assertEqual(self.field("InterfaceCrossings"), 0)
        self.assertEqual(self.field("TopologyMatches"), 1)
        self.assertLessEqual(self.field("ShortenedPieces"), self.field("CurvedEdges"))

    def test_more_accurate_than_the_decimated_mesh(self):
        linear = self.field("MisclassifiedPixelsLinear")
        curved = self.field("MisclassifiedPixelsCurved")
        self.assertGreater(linear, 0)
        self.assertLess(curved, 0.75 * linear, (linear, curved))

    def test_bounds_can_be_set(self):
        # Bounds set on the filter override those the input records: looser
        # ones shorten at most as many pieces.
        grid, errors = run_filter(labelmesher.vtkBezierCurver(), self.linear, self.image,
                                  MeshToImageDistance=10.0, ImageToMeshDistance=10.0)
        self.assertEqual(errors, [])
        self.assertEqual(grid.GetFieldData().GetArray("MeshToImageDistance").GetValue(0), 10.0)
        self.assertLessEqual(grid.GetFieldData().GetArray("ShortenedPieces").GetValue(0),
                             self.field("ShortenedPieces"))


def sampled_jacobian_ratios(grid, plane_axes, samples=7):
    """Per cell, the smallest over the largest sampled det J (sampled_jacobians): at least the
    true min det J / max det J of the cell."""
    dets = sampled_jacobians(grid, plane_axes, samples)
    return dets.min(axis=1) / dets.max(axis=1)


class ScaledJacobianTest(unittest.TestCase):
    """The shared digimouse slice through the reader, mesher and decimator: without a scaled
    Jacobian bound some curved cells fall far below 0.1; with the default 0.1 every cell's certified
    ratio is at least that, and VTK's own evaluation of the cells agrees."""

    @classmethod
    def setUpClass(cls):
        import os
        path = os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data", "2d",
                            "digimouse_sagittal.nrrd")
        cls.reader = labelmesher.vtkLabelImageReader()
        cls.reader.SetFileName(path)
        cls.reader.Update()
        mesher = labelmesher.vtkLabelMesher()
        mesher.SetInputConnection(cls.reader.GetOutputPort())
        mesher.Update()
        cls.linear = mesher.GetOutput()

    def curved(self, bound):
        grid, errors = run_filter(labelmesher.vtkBezierCurver(), self.linear, self.reader.GetOutput(),
                                  MinimumScaledJacobian=bound)
        self.assertEqual(errors, [])
        return grid, vtk_to_numpy(grid.GetCellData().GetArray("ScaledJacobian"))

    def test_default_is_a_tenth(self):
        self.assertEqual(labelmesher.vtkBezierCurver().GetMinimumScaledJacobian(), 0.1)

    def test_without_the_bound_cells_fall_below(self):
        _, scaled = self.curved(0.0)
        self.assertLess(scaled.min(), 0.1)

    def test_every_cell_keeps_the_bound(self):
        grid, scaled = self.curved(0.1)
        self.assertGreaterEqual(scaled.min(), 0.1)
        fd = grid.GetFieldData()
        self.assertEqual(fd.GetArray("MinimumScaledJacobianBound").GetValue(0), 0.1)
        self.assertEqual(fd.GetArray("StraightenedForScaledJacobian").GetValue(0), 0)
        self.assertEqual(fd.GetArray("InvalidCells").GetValue(0), 0)
        # The image's axes: the slice lies across one of them.
        dims = self.reader.GetOutput().GetDimensions()
        axes = tuple(a for a in range(3) if dims[a] > 1)
        ratios = sampled_jacobian_ratios(grid, axes)
        self.assertGreaterEqual(ratios.min(), 0.1 - 1e-6)
        self.assertTrue(np.all(ratios >= scaled - 1e-6), "a certified ratio above VTK's sampled one")

    def test_corner_angles_are_measured_from_the_tangents(self):
        grid, _ = self.curved(0.1)
        corners = vtk_to_numpy(grid.GetCellData().GetArray("CornerAngle"))
        self.assertEqual(corners.size, grid.GetNumberOfCells())
        # Recomputed from the written control points (VTK order: corner, then its two neighbours).
        dims = self.reader.GetOutput().GetDimensions()
        axes = [a for a in range(3) if dims[a] > 1]
        points = vtk_to_numpy(grid.GetPoints().GetData())[:, axes]
        cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 10)
        smallest = np.full(len(cells), 180.0)
        for corner, a, b in ((0, 3, 8), (1, 5, 4), (2, 7, 6)):
            u = points[cells[:, a]] - points[cells[:, corner]]
            v = points[cells[:, b]] - points[cells[:, corner]]
            cross = np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
            angle = np.degrees(np.arctan2(cross, np.sum(u * v, axis=1)))
            smallest = np.minimum(smallest, angle)
        np.testing.assert_allclose(corners, smallest, atol=1e-9)
        self.assertGreater(corners.min(), 0.0)


class PlaneTest(unittest.TestCase):
    def test_mesh_in_the_xz_plane(self):
        grid, errors = curve(disc_image(normal_axis=1))
        self.assertEqual(errors, [])
        points = vtk_to_numpy(grid.GetPoints().GetData())
        self.assertTrue(np.allclose(points[:, 1], points[0, 1]))
        self.assertTrue(np.all(vtk_to_numpy(grid.GetCellData().GetArray("Valid")) == 1))
        lowest, highest = jacobian_signs(grid, (0, 2), samples=4)
        self.assertTrue(lowest > 0 or highest < 0, (lowest, highest))


class ErrorTest(unittest.TestCase):
    def expect_error(self, grid, errors, fragment):
        self.assertEqual(grid.GetNumberOfCells(), 0)
        self.assertTrue(any(fragment in e for e in errors), errors)

    def test_no_material_array(self):
        mesher = labelmesher.vtkLabelOctreeMesher()
        mesher.SetInputData(disc_image())
        mesher.Update()
        mesh = vtkUnstructuredGrid()
        mesh.DeepCopy(mesher.GetOutput())
        mesh.GetCellData().RemoveArray("Material")
        grid, errors = run_filter(labelmesher.vtkBezierCurver(), mesh)
        self.expect_error(grid, errors, "Material")

    def test_tetrahedra_are_rejected(self):
        image = vtkImageData()
        image.SetDimensions(8, 8, 8)
        labels = np.zeros((8, 8, 8), dtype=np.uint8)
        labels[2:6, 2:6, 2:6] = 1
        image.GetPointData().SetScalars(numpy_to_vtk(labels.ravel(), deep=True))
        mesher = labelmesher.vtkLabelOctreeMesher()
        mesher.SetInputData(image)
        mesher.Update()
        grid, errors = run_filter(labelmesher.vtkBezierCurver(), mesher.GetOutput())
        self.expect_error(grid, errors, "axis plane")

    def test_3d_image_on_port_1_is_rejected(self):
        mesher = labelmesher.vtkLabelOctreeMesher()
        mesher.SetInputData(disc_image())
        mesher.Update()
        volume = vtkImageData()
        volume.SetDimensions(4, 4, 4)
        volume.GetPointData().SetScalars(numpy_to_vtk(np.ones(64, dtype=np.uint8), deep=True))
        grid, errors = run_filter(labelmesher.vtkBezierCurver(), mesher.GetOutput(), volume)
        self.expect_error(grid, errors, "3D")


if __name__ == "__main__":
    unittest.main()
