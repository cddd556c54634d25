# SPDX-License-Identifier: GPL-2.0-or-later
"""Drives the wrapped vtkLabelOctreeMesher from Python, as a ParaView/Slicer user
would, and checks the properties the filter promises on small synthetic images:
labelled tetrahedra with the proven angle bounds (30 degrees dihedral, 45 degrees
planar in 2D), no background cells by default, points in physical coordinates
(origin, spacing, direction honoured), triangles in the image plane for
single-slice images, and clean errors.

Run with PYTHONPATH=<build>/lib/python3/dist-packages (ctest sets it)."""

import unittest

import numpy as np
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkFloatArray, vtkShortArray
from vtkmodules.vtkCommonDataModel import VTK_TETRA, VTK_TRIANGLE, vtkImageData
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

import labelmesher

# The angle bounds the initial mesh is proved to keep (TestAngleBoundEnumeration,
# README "What it guarantees"): above the dissertation's asin(1/3) = 19.47 degrees.
DIHEDRAL_BOUND = 30.0  # degrees, tetrahedra (3D)
PLANAR_BOUND = 45.0  # degrees, triangles (2D)


def make_image(labels, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), direction=None,
               array_type=np.int16):
    """labels: numpy array indexed [z, y, x] (VTK's x-fastest order when raveled)."""
    nz, ny, nx = labels.shape
    image = vtkImageData()
    image.SetDimensions(nx, ny, nz)
    image.SetSpacing(*spacing)
    image.SetOrigin(*origin)
    if direction is not None:
        image.SetDirectionMatrix(*np.asarray(direction, dtype=float).ravel())
    array = numpy_to_vtk(np.ascontiguousarray(labels.astype(array_type)).ravel(), deep=True)
    array.SetName("Labels")
    image.GetPointData().SetScalars(array)
    return image


def ball(n, centre, radius, label=1):
    z, y, x = np.mgrid[0:n, 0:n, 0:n]
    inside = (x - centre[0]) ** 2 + (y - centre[1]) ** 2 + (z - centre[2]) ** 2 <= radius ** 2
    return np.where(inside, label, 0)


def run(image, **settings):
    mesher = labelmesher.vtkLabelOctreeMesher()
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(obj, event, message):
        errors.append(message)

    mesher.AddObserver(vtkCommand.ErrorEvent, on_error)
    for name, value in settings.items():
        getattr(mesher, "Set" + name)(value)
    mesher.SetInputData(image)
    mesher.Update()
    return mesher, errors


def cells_of(grid):
    """(types, connectivity as an (ncells, nverts) array) of a single-type grid."""
    types = vtk_to_numpy(grid.GetCellTypesArray())
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    nverts = 4 if len(types) and types[0] == VTK_TETRA else 3
    return types, conn.reshape(-1, nverts)


def dihedral_angles(points, tets):
    """All six dihedral angles (degrees) of every tetrahedron, and signed volumes."""
    p = points[tets]  # (n, 4, 3)
    # Face k is opposite vertex k; its outward normal points away from vertex k.
    normals = []
    for k in range(4):
        a, b, c = [p[:, i] for i in range(4) if i != k]
        n = np.cross(b - a, c - a)
        away = np.einsum("ij,ij->i", n, a - p[:, k])
        n = n * np.sign(away)[:, None]
        normals.append(n / np.linalg.norm(n, axis=1)[:, None])
    angles = []
    for k in range(4):
        for l in range(k + 1, 4):
            cos = -np.einsum("ij,ij->i", normals[k], normals[l])
            angles.append(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))
    volumes = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]),
                        p[:, 3] - p[:, 0]) / 6.0
    return np.stack(angles, axis=1), volumes


def triangle_angles(points, tris):
    p = points[tris]
    angles = []
    for k in range(3):
        u = p[:, (k + 1) % 3] - p[:, k]
        v = p[:, (k + 2) % 3] - p[:, k]
        cos = np.einsum("ij,ij->i", u, v) / (np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1))
        angles.append(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))
    return np.stack(angles, axis=1)


class SphereTest(unittest.TestCase):
    """A ball of radius 5 voxels in a 16^3 image, spacing 0.5, origin (10, -5, 2)."""

    spacing = (0.5, 0.5, 0.5)
    origin = (10.0, -5.0, 2.0)
    centre = (7.5, 7.5, 7.5)
    radius = 5.0

    @classmethod
    def setUpClass(cls):
        cls.image = make_image(ball(16, cls.centre, cls.radius), cls.spacing, cls.origin)
        cls.mesher, cls.errors = run(cls.image)
        cls.grid = cls.mesher.GetOutput()
        cls.points = vtk_to_numpy(cls.grid.GetPoints().GetData()).astype(float)
        cls.types, cls.tets = cells_of(cls.grid)

    def test_no_errors_and_cells(self):
        self.assertEqual(self.errors, [])
        self.assertGreater(self.grid.GetNumberOfCells(), 0)
        self.assertTrue(np.all(self.types == VTK_TETRA))

    def test_material_array_present_and_foreground_only(self):
        material = self.grid.GetCellData().GetArray("Material")
        self.assertIsNotNone(material)
        values = vtk_to_numpy(material)
        self.assertEqual(len(values), self.grid.GetNumberOfCells())
        self.assertEqual(set(np.unique(values)), {1}, "background cells must be dropped by default")

    def test_minimum_dihedral_angle_at_least_30_degrees(self):
        angles, volumes = dihedral_angles(self.points, self.tets)
        self.assertGreaterEqual(angles.min(), DIHEDRAL_BOUND - 1e-6)
        self.assertTrue(np.all(volumes > 0), "tetrahedra must be positively oriented")

    def test_volume_and_centroid_in_physical_coordinates(self):
        # The mesh of the ball must sit where the ball is in physical space:
        # centre = origin + spacing * centre index, volume close to the voxel volume.
        _, volumes = dihedral_angles(self.points, self.tets)
        centroids = self.points[self.tets].mean(axis=1)
        centroid = (centroids * volumes[:, None]).sum(axis=0) / volumes.sum()
        expected = np.array(self.origin) + np.array(self.spacing) * np.array(self.centre)
        np.testing.assert_allclose(centroid, expected, atol=0.5 * self.spacing[0])
        voxel_volume = np.count_nonzero(ball(16, self.centre, self.radius)) * np.prod(self.spacing)
        self.assertAlmostEqual(volumes.sum() / voxel_volume, 1.0, delta=0.25)

    def test_points_within_fidelity_bound_of_the_image(self):
        # h(M, I) <= 2 voxels: no mesh point lies further than 2 voxels (plus the
        # half voxel to the voxel boundary) outside the labelled voxels' box.
        lo = np.array(self.origin) + np.array(self.spacing) * (np.array(self.centre) - self.radius - 0.5)
        hi = np.array(self.origin) + np.array(self.spacing) * (np.array(self.centre) + self.radius + 0.5)
        slack = 2.0 * self.spacing[0] + 1e-9
        self.assertTrue(np.all(self.points.min(axis=0) >= lo - slack))
        self.assertTrue(np.all(self.points.max(axis=0) <= hi + slack))

    def test_boundary_surface_output(self):
        surface = self.mesher.GetInterfacesOutput()
        self.assertGreater(surface.GetNumberOfPolys(), 0)
        materials = vtk_to_numpy(surface.GetCellData().GetArray("Materials"))
        self.assertEqual(materials.shape, (surface.GetNumberOfCells(), 2))
        self.assertTrue(np.all(materials[:, 0] != materials[:, 1]))
        self.assertEqual(set(np.unique(materials)), {0, 1})

    def test_field_data_records_parameters(self):
        fd = self.grid.GetFieldData()
        self.assertEqual(fd.GetArray("ImageToMeshDistance").GetValue(0), 2.0)
        self.assertEqual(fd.GetArray("MeshToImageDistance").GetValue(0), 2.0)
        self.assertEqual(fd.GetArray("VoxelSize").GetValue(0), 0.5)
        # MeasureOutput is on by default: the measurements must be there.
        for name in ("MinimumAngle", "MeasuredImageToMeshDistance", "MeasuredMeshToImageDistance",
                     "TopologyMatches"):
            self.assertIsNotNone(fd.GetArray(name), "field array %s is missing" % name)
        angles, _ = dihedral_angles(self.points, self.tets)
        self.assertAlmostEqual(fd.GetArray("MinimumAngle").GetValue(0), angles.min(), places=3)
        self.assertGreaterEqual(fd.GetArray("MinimumAngle").GetValue(0), DIHEDRAL_BOUND - 1e-6)
        # the measured two-sided distances respect the requested bounds
        self.assertLessEqual(fd.GetArray("MeasuredImageToMeshDistance").GetValue(0), 2.0 + 1e-9)
        self.assertLessEqual(fd.GetArray("MeasuredMeshToImageDistance").GetValue(0), 2.0 + 1e-9)
        self.assertTrue(all(fd.GetArray("TopologyMatches").GetValue(i)
                            for i in range(fd.GetArray("TopologyMatches").GetNumberOfTuples())))


class OptionsTest(unittest.TestCase):

    def test_include_background_keeps_label_zero(self):
        image = make_image(ball(12, (5.5, 5.5, 5.5), 3.5))
        mesher, errors = run(image, IncludeBackground=True)
        self.assertEqual(errors, [])
        values = set(np.unique(vtk_to_numpy(mesher.GetOutput().GetCellData().GetArray("Material"))))
        self.assertEqual(values, {0, 1})

    def test_two_labels_any_integer_type(self):
        labels = ball(12, (5.5, 5.5, 5.5), 4.5) + ball(12, (5.5, 5.5, 5.5), 2.5)  # 2 inside 1
        for array_type in (np.uint8, np.int32, np.uint16, np.int64):
            with self.subTest(array_type=array_type):
                mesher, errors = run(make_image(labels, array_type=array_type))
                self.assertEqual(errors, [])
                values = vtk_to_numpy(mesher.GetOutput().GetCellData().GetArray("Material"))
                self.assertEqual(set(np.unique(values)), {1, 2})

    def test_anisotropic_spacing_is_resampled_to_the_smallest(self):
        labels = np.zeros((6, 12, 12), dtype=np.int16)
        labels[1:5, 3:9, 3:9] = 1  # a box of 6 x 6 x 4 voxels
        # Tight bounds (0.5 voxel) so that the mesh must follow the box closely.
        mesher, errors = run(make_image(labels, spacing=(1.0, 1.0, 2.0)),
                             ImageToMeshDistance=0.5, MeshToImageDistance=0.5)
        self.assertEqual(errors, [])
        grid = mesher.GetOutput()
        self.assertEqual(grid.GetFieldData().GetArray("VoxelSize").GetValue(0), 1.0)
        points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
        _, tets = cells_of(grid)
        _, volumes = dihedral_angles(points, tets)
        # physical box (voxel faces): x, y in [2.5, 8.5]; z voxels 1..4 of size 2,
        # centred at 2..8, so z in [1, 9]; volume 6 * 6 * 8 = 288
        self.assertAlmostEqual(volumes.sum() / 288.0, 1.0, delta=0.15)
        slack = 0.5 + 1e-9
        np.testing.assert_allclose(points.min(axis=0), [2.5, 2.5, 1.0], atol=slack)
        np.testing.assert_allclose(points.max(axis=0), [8.5, 8.5, 9.0], atol=slack)

    def test_direction_matrix_is_honoured(self):
        # 90 degree rotation about z: index x maps to physical y, index y to -x.
        rotation = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]
        labels = np.zeros((10, 10, 16), dtype=np.int16)
        labels[3:7, 3:7, 2:14] = 1  # long along index x
        mesher, errors = run(make_image(labels, direction=rotation))
        self.assertEqual(errors, [])
        grid = mesher.GetOutput()
        points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
        extent = points.max(axis=0) - points.min(axis=0)
        self.assertGreater(extent[1], extent[0] + 4)  # the long axis is now physical y
        self.assertLessEqual(points[:, 0].max(), 0.0 - 2.5 + 2.0 + 1e-9)  # x = -index y <= -2.5 (+ slack)
        _, tets = cells_of(grid)
        _, volumes = dihedral_angles(points, tets)
        self.assertTrue(np.all(volumes > 0), "orientation must stay positive after a rotation")

    def test_single_slice_images_give_triangles_in_the_image_plane(self):
        disk = ball(14, (6.5, 6.5, 6.5), 4.5)[6]  # (y, x)
        cases = {
            "z": (disk[None, :, :], 2),
            "y": (disk[:, None, :], 1),
            "x": (disk[:, :, None], 0),
        }
        for axis, (labels, normal) in cases.items():
            with self.subTest(single_slice_axis=axis):
                origin = [1.0, 2.0, 3.0]
                mesher, errors = run(make_image(labels, origin=origin))
                self.assertEqual(errors, [])
                grid = mesher.GetOutput()
                types, tris = cells_of(grid)
                self.assertGreater(len(types), 0)
                self.assertTrue(np.all(types == VTK_TRIANGLE))
                points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
                np.testing.assert_allclose(points[:, normal], origin[normal])
                self.assertGreaterEqual(triangle_angles(points, tris).min(), PLANAR_BOUND - 1e-6)
                boundary = mesher.GetInterfacesOutput()
                self.assertGreater(boundary.GetNumberOfLines(), 0)


class ProgressAndAbortTest(unittest.TestCase):

    def test_progress_is_reported_and_abort_gives_empty_output(self):
        mesher = labelmesher.vtkLabelOctreeMesher()
        mesher.SetInputData(make_image(ball(24, (11.5, 11.5, 11.5), 9.0)))
        seen = []

        def on_progress(obj, event):
            seen.append((obj.GetProgress(), obj.GetProgressText()))
            if obj.GetProgress() > 0.0:
                obj.SetAbortExecute(1)

        warnings = []
        mesher.AddObserver(vtkCommand.WarningEvent, lambda obj, event: warnings.append(event))
        tag = mesher.AddObserver(vtkCommand.ProgressEvent, on_progress)
        mesher.Update()
        self.assertTrue(any(progress > 0.0 and text for progress, text in seen), seen)
        self.assertEqual(len(warnings), 1, "an aborted run says so")
        self.assertEqual(mesher.GetOutput().GetNumberOfCells(), 0)
        # The next run, not aborted, meshes again.
        mesher.RemoveObserver(tag)
        mesher.Modified()
        mesher.Update()
        self.assertGreater(mesher.GetOutput().GetNumberOfCells(), 0)


class InvalidInputTest(unittest.TestCase):
    """Bad input: an error event and empty output, never a crash."""

    def expect_error(self, image, fragment):
        mesher, errors = run(image)
        self.assertEqual(len(errors), 1, errors)
        self.assertIn(fragment, errors[0])
        self.assertEqual(mesher.GetOutput().GetNumberOfCells(), 0)
        return mesher

    def test_no_foreground(self):
        self.expect_error(make_image(np.zeros((4, 4, 4))), "foreground")

    def test_negative_label(self):
        labels = ball(8, (3.5, 3.5, 3.5), 2.5)
        labels[0, 0, 0] = -3
        self.expect_error(make_image(labels), "negative")

    def test_float_scalars(self):
        image = make_image(ball(8, (3.5, 3.5, 3.5), 2.5))
        floats = vtkFloatArray()
        floats.DeepCopy(image.GetPointData().GetScalars())
        image.GetPointData().SetScalars(floats)
        self.expect_error(image, "integer")

    def test_multi_component_scalars(self):
        image = make_image(ball(8, (3.5, 3.5, 3.5), 2.5))
        pairs = vtkShortArray()
        pairs.SetNumberOfComponents(2)
        pairs.SetNumberOfTuples(image.GetNumberOfPoints())
        pairs.Fill(1)
        image.GetPointData().SetScalars(pairs)
        self.expect_error(image, "components")

    def test_no_scalars(self):
        image = vtkImageData()
        image.SetDimensions(4, 4, 4)
        self.expect_error(image, "scalars")

    def test_empty_extent(self):
        image = vtkImageData()
        image.SetExtent(0, -1, 0, -1, 0, -1)
        self.expect_error(image, "extent")

    def test_label_too_large_for_int32(self):
        labels = ball(8, (3.5, 3.5, 3.5), 2.5).astype(np.int64)
        labels[labels == 1] = 2 ** 40
        self.expect_error(make_image(labels, array_type=np.int64), "32-bit")


if __name__ == "__main__":
    unittest.main()
