# SPDX-License-Identifier: GPL-2.0-or-later
"""The 3D Slicer module's logic (SlicerModule/LabelMesher/LabelMesherLib), run
without Slicer: Debian's Python, the wrapped filters, shared real images.

usage: python3 -m unittest test_slicer_logic   (PYTHONPATH: the wrapped module,
SlicerModule/LabelMesher and Testing/Support; LABELMESHER_DATA: ../shared/data)
"""
import math
import os
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import VTK_BEZIER_TRIANGLE, VTK_QUADRATIC_TETRA, VTK_QUADRATIC_TRIANGLE

from label_nrrd import read_label_nrrd
from LabelMesherLib.meshing import (Material, MeshingCancelled, MeshingError, MeshingParameters,
                                    mesh_labels, placement_from_ijk_to_ras)

DATA = os.environ.get("LABELMESHER_DATA", os.path.join(os.path.dirname(__file__), "../../../shared/data"))


def oblique_ijk_to_ras(spacing, origin, reflect=True):
    """A rotation by 30 degrees about (1, 2, 2)/3, then (optionally) a mirror of the
    k axis (volumes stored bottom-up), times the spacing: nothing in it is axis-aligned."""
    axis = np.array([1.0, 2.0, 2.0]) / 3.0
    a = np.radians(30.0)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    rotation = np.eye(3) + np.sin(a) * k + (1 - np.cos(a)) * k @ k
    if reflect:
        rotation = rotation @ np.diag([1.0, 1.0, -1.0])
    m = np.eye(4)
    m[:3, :3] = rotation * np.asarray(spacing, dtype=float)
    m[:3, 3] = origin
    return m


def points(mesh):
    return vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)


def tetrahedra(mesh):
    return vtk_to_numpy(mesh.GetCells().GetConnectivityArray()).reshape(-1, 4)


def two_boxes():
    """A small 3D label volume [k, j, i]: a box of label 1 holding a cube of label 2."""
    labels = np.zeros((20, 20, 20), dtype=np.uint8)
    labels[4:16, 5:15, 3:17] = 1
    labels[8:12, 8:12, 8:12] = 2
    return labels


def check_guarantees(test, report, bound):
    q, f = report["quality"], report["fidelity"]
    test.assertGreaterEqual(q["minimum_angle_degrees"], bound - 1e-9)
    test.assertEqual(q["inverted_cells"], 0)
    test.assertTrue(f["bounds_certified"])
    test.assertLessEqual(f["image_to_mesh"], report["parameters"]["image_to_mesh"] + 1e-9)
    test.assertLessEqual(f["mesh_to_image"], report["parameters"]["mesh_to_image"] + 1e-9)
    test.assertTrue(report["topology"]["all_match"], report["topology"])


class ObliquePlacementTest(unittest.TestCase):
    """The rat head (shared, real) meshed once in the image frame and once placed by
    an oblique, reflecting IJK to RAS matrix with anisotropic spacing."""

    @classmethod
    def setUpClass(cls):
        cls.labels, _ = read_label_nrrd(os.path.join(DATA, "3d/iso2mesh_rat_head.nrrd"))
        cls.spacing = np.array([1.0, 0.8, 1.3])
        cls.origin = np.array([-40.0, 12.5, 7.25])
        cls.matrix = oblique_ijk_to_ras(cls.spacing, cls.origin)
        cls.framed = mesh_labels(cls.labels, np.diag(list(cls.spacing) + [1.0]))
        cls.placed = mesh_labels(cls.labels, cls.matrix, [Material(1, "rat head", (0.8, 0.5, 0.4))])

    def test_points_are_the_framed_mesh_placed_rigidly(self):
        rotation = self.matrix[:3, :3] / self.spacing
        expected = points(self.framed.mesh) @ rotation.T + self.origin
        np.testing.assert_allclose(points(self.placed.mesh), expected, atol=1e-9)
        self.assertEqual(self.placed.mesh.GetNumberOfCells(), self.framed.mesh.GetNumberOfCells())

    def test_every_tetrahedron_keeps_positive_volume_after_the_reflection(self):
        self.assertLess(np.linalg.det(self.matrix[:3, :3]), 0.0)
        for result in (self.framed, self.placed):
            p = points(result.mesh)
            t = tetrahedra(result.mesh)
            a, b, c, d = (p[t[:, i]] for i in range(4))
            volumes = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a)
            self.assertTrue(np.all(volumes > 0.0), f"{np.sum(volumes <= 0)} of {len(volumes)} not positive")

    def test_cells_lie_on_their_voxels_in_ras(self):
        # Back from RAS to continuous IJK through the inverse matrix: each cell's centroid
        # must be within the mesh-to-image bound (2 voxels) of a voxel of its label.
        p = points(self.placed.mesh)
        t = tetrahedra(self.placed.mesh)
        centroids = p[t].mean(axis=1)
        ijk = (np.linalg.inv(self.matrix) @ np.c_[centroids, np.ones(len(centroids))].T).T[:, :3]
        nearest = np.clip(np.rint(ijk).astype(int), 0, np.array(self.labels.shape[::-1]) - 1)
        on_label = self.labels[nearest[:, 2], nearest[:, 1], nearest[:, 0]] == 1
        self.assertGreater(on_label.mean(), 0.95)
        reach = 2
        padded = np.pad(self.labels == 1, reach)
        grown = np.zeros_like(padded)
        for dk in range(-reach, reach + 1):
            for dj in range(-reach, reach + 1):
                for di in range(-reach, reach + 1):
                    grown |= np.roll(padded, (dk, dj, di), axis=(0, 1, 2))
        near = grown[nearest[:, 2] + reach, nearest[:, 1] + reach, nearest[:, 0] + reach]
        self.assertTrue(np.all(near), f"{np.sum(~near)} cells far from the label")

    def test_block_by_block_keeps_the_guarantees(self):
        result = mesh_labels(self.labels, self.matrix, parameters=MeshingParameters(block_cells=20000))
        check_guarantees(self, result.report, 15.0)
        self.assertGreater(result.report["decimation"]["blocks"], 1)
        self.assertEqual(self.placed.report["decimation"]["blocks"], 1)  # the default: one block here

    def test_report_and_materials(self):
        for result in (self.framed, self.placed):
            check_guarantees(self, result.report, 15.0)
            self.assertLess(result.report["decimation"]["cells_after"], result.report["decimation"]["cells_before"])
        self.assertEqual([(m["label"], m["name"], m["color"]) for m in self.placed.report["material_table"]],
                         [(1, "rat head", [0.8, 0.5, 0.4])])
        fd = self.placed.mesh.GetFieldData()
        self.assertEqual(fd.GetAbstractArray("MaterialName").GetValue(0), "rat head")
        self.assertEqual(fd.GetArray("MaterialColor").GetTuple3(0), (0.8, 0.5, 0.4))
        self.assertEqual([(m["label"], m["name"], m["color"]) for m in self.framed.report["material_table"]],
                         [(1, "label_1", None)])
        bounds = self.placed.interfaces.GetBounds()
        mesh_bounds = self.placed.mesh.GetBounds()
        np.testing.assert_allclose(bounds, mesh_bounds, atol=1e-9)  # interfaces placed with the mesh


class SelectedSegmentsTest(unittest.TestCase):
    """TotalSegmentator's output (shared, real): three chosen segments, with names and colours."""

    def test_only_the_chosen_segments_are_meshed_with_their_names(self):
        labels, spacing = read_label_nrrd(os.path.join(DATA, "3d/totalseg_example_seg.nrrd"))
        present = [int(v) for v in np.unique(labels) if v]
        chosen = present[:3]
        materials = [Material(v, f"segment {v}", (v / 255.0, 0.5, 0.25)) for v in present]
        matrix = oblique_ijk_to_ras(spacing, (10.0, -20.0, 30.0), reflect=False)
        result = mesh_labels(labels, matrix, materials, MeshingParameters(minimum_angle=20.0), selected=chosen)
        check_guarantees(self, result.report, 20.0)
        self.assertEqual(sorted(int(m) for m in result.report["mesh"]["cells_per_material"]), chosen)
        self.assertEqual([m["name"] for m in result.report["material_table"]], [f"segment {v}" for v in chosen])


class SliceTest(unittest.TestCase):
    """A 2D label image (shared, real), one slice placed obliquely."""

    def test_slice_meshes_with_the_2d_bound(self):
        labels, spacing = read_label_nrrd(os.path.join(DATA, "2d/digimouse_sagittal.nrrd"))
        result = mesh_labels(labels, oblique_ijk_to_ras(spacing[:2].tolist() + [0.2], (1.0, 2.0, 3.0)),
                             parameters=MeshingParameters(minimum_angle=30.0))
        self.assertEqual(result.report["mesh"]["cell_type"], "triangle")
        check_guarantees(self, result.report, 30.0)
        # The triangles lie in the slice's plane: normal = the placed k axis.
        normal = oblique_ijk_to_ras((1, 1, 1), (0, 0, 0))[:3, 2]
        offsets = (points(result.mesh) - (1.0, 2.0, 3.0)) @ normal
        self.assertLess(np.max(np.abs(offsets)), 1e-9)


# VTK_BEZIER_TRIANGLE's degree-3 control points by barycentric multi-index (i, j, k): corners,
# two per edge 0-1, 1-2, 2-0, then the interior one.
CUBIC_INDEX = {(3, 0, 0): 0, (0, 3, 0): 1, (0, 0, 3): 2, (2, 1, 0): 3, (1, 2, 0): 4, (0, 2, 1): 5,
               (0, 1, 2): 6, (1, 0, 2): 7, (2, 0, 1): 8, (1, 1, 1): 9}


def sampled_jacobians(control, n=16):
    """det J of each planar cubic Bezier triangle (control: cells x 10 x 2) on a barycentric grid of
    n steps per side, corners included: exact derivatives, not the curver's Bernstein bound."""
    grid = np.array([(1.0 - (i + j) / n, i / n, j / n) for i in range(n + 1) for j in range(n + 1 - i)])
    u, v, w = grid.T
    derivative = {axis: np.zeros((control.shape[0], grid.shape[0], 2)) for axis in range(3)}
    for a, b, c in [(2, 0, 0), (0, 2, 0), (0, 0, 2), (1, 1, 0), (0, 1, 1), (1, 0, 1)]:
        basis = 3.0 * (2.0 / (math.factorial(a) * math.factorial(b) * math.factorial(c))) * u**a * v**b * w**c
        for axis, raised in enumerate([(a + 1, b, c), (a, b + 1, c), (a, b, c + 1)]):
            derivative[axis] += basis[None, :, None] * control[:, None, CUBIC_INDEX[raised], :]
    dx, dy = derivative[1] - derivative[0], derivative[2] - derivative[0]  # x = v, y = w, u = 1 - x - y
    return dx[..., 0] * dy[..., 1] - dx[..., 1] * dy[..., 0]


class CurvedSliceTest(unittest.TestCase):
    """A 2D label image (shared, real) curved, placed obliquely with a reflection."""

    @classmethod
    def setUpClass(cls):
        cls.labels, spacing = read_label_nrrd(os.path.join(DATA, "2d/digimouse_sagittal.nrrd"))
        cls.matrix = oblique_ijk_to_ras(spacing[:2].tolist() + [0.2], (1.0, 2.0, 3.0))
        cls.result = mesh_labels(cls.labels, cls.matrix,
                                 parameters=MeshingParameters(curve=True, smoothness=2, minimum_angle=20.0))

    def test_the_linear_mesh_keeps_its_guarantees(self):
        check_guarantees(self, self.result.report, 20.0)
        self.assertEqual(self.result.report["mesh"]["cell_type"], "triangle")

    def test_curved_report_states_the_guarantees(self):
        curve = self.result.report["curve"]  # `labelmesher curve --report`'s JSON
        c, validity = curve["curved_mesh"], curve["validity"]
        self.assertEqual(c["cells"], self.result.mesh.GetNumberOfCells())
        self.assertEqual(curve["parameters"]["smoothness"], 2)
        self.assertTrue(validity["valid"])
        self.assertEqual(validity["invalid_cells"], 0)
        self.assertGreater(validity["minimum_scaled_jacobian"], 0.0)
        self.assertGreater(c["curved_edges"], 0)
        self.assertEqual(c["interface_crossings"], 0)
        self.assertTrue(c["topology_matches"])
        for side in ("image_to_mesh", "mesh_to_image"):
            self.assertLessEqual(c[f"measured_{side}"], 2.0 + c["measure_resolution"] + 1e-9)
        self.assertTrue(c["within_bounds"])
        self.assertIn("every cell proven valid", self.result.summary)

    def test_every_curved_cell_is_valid_by_sampled_jacobian(self):
        mesh = self.result.mesh
        types = vtk_to_numpy(mesh.GetCellTypesArray())
        self.assertTrue(np.all(types == VTK_BEZIER_TRIANGLE))
        connectivity = vtk_to_numpy(mesh.GetCells().GetConnectivityArray()).reshape(-1, 10)
        # The control points lie in the slice's plane; in the slice's own (i, j) axes they are the
        # curver's planar cells, placed rigidly.
        normal = self.matrix[:3, 2] / np.linalg.norm(self.matrix[:3, 2])
        self.assertLess(np.max(np.abs((points(mesh) - (1.0, 2.0, 3.0)) @ normal)), 1e-9)
        axes = self.matrix[:3, :2] / np.linalg.norm(self.matrix[:3, :2], axis=0)
        planar = (points(mesh) - (1.0, 2.0, 3.0)) @ axes
        jacobians = sampled_jacobians(planar[connectivity])
        sign = np.sign(jacobians[0, 0])
        self.assertTrue(np.all(jacobians * sign > 0.0), f"smallest {np.min(jacobians * sign)}")

    def test_curving_a_volume_without_decimation_or_a_bad_smoothness_is_one_plain_error(self):
        volume = np.zeros((6, 6, 6), dtype=np.uint8)
        volume[1:5, 1:5, 1:5] = 1
        with self.assertRaisesRegex(MeshingError, "^curving a volume \\(quadratic tetrahedra\\) needs decimation") as caught:
            mesh_labels(volume, np.eye(4), parameters=MeshingParameters(curve=True, decimate=False))
        self.assertNotIn("\n", str(caught.exception))
        with self.assertRaisesRegex(MeshingError, "smoothness"):
            mesh_labels(self.labels, self.matrix, parameters=MeshingParameters(curve=True, smoothness=3))
        with self.assertRaisesRegex(MeshingError, "tension"):
            mesh_labels(self.labels, self.matrix, parameters=MeshingParameters(curve=True, tension=1.5))

    def test_cancel_while_curving(self):
        asked = []
        with self.assertRaises(MeshingCancelled):
            mesh_labels(self.labels, self.matrix, parameters=MeshingParameters(curve=True),
                        progress=lambda f, text: asked.append((f, text)),
                        should_abort=lambda: any(f >= 0.8 for f, _ in asked))  # the curver's share starts at 0.8
        self.assertGreaterEqual(max(f for f, _ in asked), 0.8)


# VTK_QUADRATIC_TETRA's nodes: corners 0-3, then the mid-nodes of these edges.
QUADRATIC_EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
# Every barycentric point whose coordinates are multiples of 1/4 (35, the corners among them).
QUARTER_GRID = np.array([(a, b, c, 4 - a - b - c) for a in range(5) for b in range(5 - a)
                         for c in range(5 - a - b)], dtype=float) / 4.0


def quadratic_positions(nodes, barycentric):
    """x at each barycentric point (points x 4) of each quadratic tetrahedron (nodes: cells x 10 x 3):
    the shape functions L_i (2 L_i - 1) at corner i, 4 L_i L_j at the mid-node of edge (i, j)."""
    L = barycentric
    shape = np.concatenate([L * (2.0 * L - 1.0), np.stack([4.0 * L[:, i] * L[:, j] for i, j in QUADRATIC_EDGES], 1)], 1)
    return np.einsum("pn,cnx->cpx", shape, nodes)


def quadratic_jacobians(nodes, barycentric):
    """det J (cells x points) of each quadratic tetrahedron at each barycentric point, exactly from
    the shape functions (x(r, s, t) with r, s, t = L1, L2, L3, L0 = 1 - r - s - t): positive where the
    cell is oriented as a linear tetrahedron (b - a, c - a, d - a) of positive volume."""
    L = barycentric
    along = []  # dx/dL_k, the L's taken as independent
    for k in range(4):
        g = (4.0 * L[:, k] - 1.0)[None, :, None] * nodes[:, None, k, :]
        for e, (i, j) in enumerate(QUADRATIC_EDGES):
            if k in (i, j):
                g = g + 4.0 * L[:, j if k == i else i][None, :, None] * nodes[:, None, 4 + e, :]
        along.append(g)
    return np.linalg.det(np.stack([along[1] - along[0], along[2] - along[0], along[3] - along[0]], axis=-1))



class QuadraticSliceTest(unittest.TestCase):
    """The same slice as quadratic triangles (slice_order 2: vtkLabelMesher's Order 2 of a 2D
    image), placed obliquely with a reflection: 6-node cells in the slice's plane, positive det J
    from the written nodes, and the curve report of an order-2 run."""

    @classmethod
    def setUpClass(cls):
        cls.labels, spacing = read_label_nrrd(os.path.join(DATA, "2d/digimouse_sagittal.nrrd"))
        cls.matrix = oblique_ijk_to_ras(spacing[:2].tolist() + [0.2], (1.0, 2.0, 3.0))
        cls.result = mesh_labels(cls.labels, cls.matrix, parameters=MeshingParameters(curve=True, slice_order=2))

    def test_quadratic_triangles_valid_from_their_nodes(self):
        mesh = self.result.mesh
        self.assertTrue(np.all(vtk_to_numpy(mesh.GetCellTypesArray()) == VTK_QUADRATIC_TRIANGLE))
        connectivity = vtk_to_numpy(mesh.GetCells().GetConnectivityArray()).reshape(-1, 6)
        axes = self.matrix[:3, :2] / np.linalg.norm(self.matrix[:3, :2], axis=0)
        planar = ((points(mesh) - (1.0, 2.0, 3.0)) @ axes)[connectivity]
        dets = []
        for r, t in ((0.1, 0.1), (0.8, 0.1), (0.1, 0.8), (0.45, 0.45), (1 / 3, 1 / 3), (0.0, 0.5), (0.5, 0.0)):
            u = 1 - r - t
            # derivatives of u(2u-1), r(2r-1), t(2t-1), 4ur, 4rt, 4tu along r and t
            dr = np.array([1 - 4 * u, 4 * r - 1, 0, 4 * (u - r), 4 * t, -4 * t])
            dt = np.array([1 - 4 * u, 0, 4 * t - 1, -4 * r, 4 * r, 4 * (u - t)])
            xr, xt = np.einsum("k,ckd->cd", dr, planar), np.einsum("k,ckd->cd", dt, planar)
            dets.append(xr[:, 0] * xt[:, 1] - xr[:, 1] * xt[:, 0])
        dets = np.array(dets) * np.sign(dets[0][0])
        self.assertTrue(np.all(dets > 0.0), f"smallest {dets.min()}")

    def test_report_is_the_curve_report_of_order_2(self):
        curve = self.result.report["curve"]
        self.assertEqual(curve["curved_mesh"]["order"], 2)
        self.assertEqual(curve["curved_mesh"]["cell_type"], "quadratic_triangle")
        self.assertTrue(curve["validity"]["valid"] and curve["validity"]["scaled_jacobian_bound_holds"])
        self.assertTrue(curve["curved_mesh"]["within_bounds"])
        self.assertLess(curve["accuracy"]["misclassified_curved"], curve["accuracy"]["misclassified_linear"])
        self.assertIn("quadratic triangles", self.result.summary)

    def test_bad_order_or_no_decimation_is_one_plain_error(self):
        with self.assertRaisesRegex(MeshingError, "order 2 or 3"):
            mesh_labels(self.labels, self.matrix, parameters=MeshingParameters(curve=True, slice_order=4))
        with self.assertRaisesRegex(MeshingError, "^curving a slice into quadratic triangles needs decimation"):
            mesh_labels(self.labels, self.matrix,
                        parameters=MeshingParameters(curve=True, slice_order=2, decimate=False))


class QuadraticVolumeTest(unittest.TestCase):
    """A small 3D label volume curved (quadratic tetrahedra, vtkLabelMesher's Order 2), placed by the
    oblique matrix with anisotropic spacing, with and without its reflection."""

    @classmethod
    def setUpClass(cls):
        cls.labels = two_boxes()
        spacing, origin = (1.0, 0.8, 1.3), (-4.0, 12.5, 7.25)
        cls.matrices = {reflect: oblique_ijk_to_ras(spacing, origin, reflect) for reflect in (False, True)}
        cls.progress = []
        cls.results = {reflect: mesh_labels(cls.labels, matrix, [Material(2, "core", (0.1, 0.6, 0.9))],
                                            MeshingParameters(curve=True),
                                            progress=(lambda f, text: cls.progress.append(f)) if reflect else None)
                       for reflect, matrix in cls.matrices.items()}

    def nodes(self, mesh):
        connectivity = vtk_to_numpy(mesh.GetCells().GetConnectivityArray()).reshape(-1, 10)
        return points(mesh)[connectivity]

    def test_only_quadratic_tetrahedra_with_their_materials(self):
        for reflect, result in self.results.items():
            with self.subTest(reflect=reflect):
                mesh = result.mesh
                self.assertGreater(mesh.GetNumberOfCells(), 0)
                self.assertTrue(np.all(vtk_to_numpy(mesh.GetCellTypesArray()) == VTK_QUADRATIC_TETRA))
                self.assertTrue(np.all(np.diff(vtk_to_numpy(mesh.GetCells().GetOffsetsArray())) == 10))
                material = vtk_to_numpy(mesh.GetCellData().GetArray("Material"))
                counts = {str(m): int(n) for m, n in zip(*np.unique(material, return_counts=True))}
                self.assertEqual(counts, {m: n for m, n in result.report["mesh"]["cells_per_material"].items()})
                self.assertEqual(mesh.GetFieldData().GetAbstractArray("MaterialName").GetValue(1), "core")
        self.assertEqual(self.progress, sorted(self.progress))
        self.assertEqual(self.progress[-1], 1.0)

    def test_report_states_the_quadratic_guarantees(self):
        for reflect, result in self.results.items():
            with self.subTest(reflect=reflect):
                report, q = result.report, result.report["quadratic"]
                check_guarantees(self, report, 15.0)  # the linear mesh's, as before
                self.assertNotIn("curve", report)
                self.assertEqual(q["cells"], result.mesh.GetNumberOfCells())
                self.assertEqual(q["nodes"], result.mesh.GetNumberOfPoints())
                self.assertTrue(q["guarantees_hold"])
                self.assertEqual(q["scaled_jacobian_bound"], 0.1)
                self.assertGreaterEqual(q["certified_minimum_scaled_jacobian"], q["scaled_jacobian_bound"])
                self.assertGreaterEqual(q["sampled_minimum_scaled_jacobian"], q["certified_minimum_scaled_jacobian"] - 1e-12)
                self.assertGreater(q["curved_edges"], 0)
                # The corners keep the decimator's angle (15 degrees), exactly and as measured.
                self.assertEqual(q["corner_angle_bound_degrees"], 15.0)
                self.assertGreaterEqual(q["minimum_corner_angle_degrees"], 15.0 - 1e-9)
                self.assertGreaterEqual(q["measured_minimum_corner_angle_degrees"], 15.0 - 1e-6)
                for side in ("image_to_mesh", "mesh_to_image"):
                    self.assertLessEqual(q[f"measured_{side}"], report["parameters"][side] + q["measure_resolution"] + 1e-9)
                self.assertIsNotNone(q["misclassified_quadratic"])
                self.assertIn("Quadratic mesh: ", result.summary)
                self.assertIn("(bound 0.100)", result.summary)

    def test_every_cell_has_positive_jacobian_in_ras(self):
        self.assertLess(np.linalg.det(self.matrices[True][:3, :3]), 0.0)
        for reflect, result in self.results.items():
            with self.subTest(reflect=reflect):
                nodes = self.nodes(result.mesh)
                jacobians = quadratic_jacobians(nodes, QUARTER_GRID)
                self.assertTrue(np.all(jacobians > 0.0), f"{np.sum(np.any(jacobians <= 0.0, axis=1))} of "
                                f"{len(nodes)} cells not positive")
                # min / max of the samples bounds each cell's scaled Jacobian from above: it holds the
                # certified lower bound (cell data ScaledJacobian) and the asked 0.1.
                ratio = jacobians.min(axis=1) / jacobians.max(axis=1)
                certified = vtk_to_numpy(result.mesh.GetCellData().GetArray("ScaledJacobian"))
                self.assertTrue(np.all(ratio >= certified - 1e-9))
                self.assertGreaterEqual(ratio.min(), 0.1)
                # The helper itself: straight cells (mid-nodes halfway) have det J = 6 x their volume.
                straight = np.concatenate([nodes[:, :4], (nodes[:, [i for i, _ in QUADRATIC_EDGES]]
                                                         + nodes[:, [j for _, j in QUADRATIC_EDGES]]) / 2.0], 1)
                a, b, c, d = (nodes[:, i] for i in range(4))
                volumes = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a)
                np.testing.assert_allclose(quadratic_jacobians(straight, QUARTER_GRID),
                                           np.repeat(volumes[:, None], len(QUARTER_GRID), 1), rtol=1e-9)

    def test_cells_lie_on_their_voxels_in_ras(self):
        # Every sample point of every cell, back from RAS to continuous IJK, lies within the
        # mesh-to-image bound (2 voxels) of a voxel of the cell's material; the cells' centres on one.
        reach = 2
        for reflect, result in self.results.items():
            with self.subTest(reflect=reflect):
                inverse = np.linalg.inv(self.matrices[reflect])
                material = vtk_to_numpy(result.mesh.GetCellData().GetArray("Material"))
                nodes = self.nodes(result.mesh)
                for grid, near_share in ((np.full((1, 4), 0.25), 1.0), (QUARTER_GRID, 0.0)):
                    ras = quadratic_positions(nodes, grid)
                    ijk = np.einsum("ij,cpj->cpi", inverse[:3, :3], ras) + inverse[:3, 3]
                    nearest = np.clip(np.rint(ijk).astype(int), 0, np.array(self.labels.shape[::-1]) - 1)
                    labels = self.labels[nearest[..., 2], nearest[..., 1], nearest[..., 0]]
                    if near_share:
                        self.assertGreaterEqual(np.mean(labels == material[:, None]), 0.9)
                    for m in np.unique(material):
                        padded = np.pad(self.labels == m, reach)
                        grown = np.zeros_like(padded)
                        for dk in range(-reach, reach + 1):
                            for dj in range(-reach, reach + 1):
                                for di in range(-reach, reach + 1):
                                    grown |= np.roll(padded, (dk, dj, di), axis=(0, 1, 2))
                        own = nearest[material == m] + reach
                        near = grown[own[..., 2], own[..., 1], own[..., 0]]
                        self.assertTrue(np.all(near), f"material {m}: {np.sum(~near)} points far from it")

    def test_cancel_while_making_quadratic_cells(self):
        asked = []
        with self.assertRaises(MeshingCancelled):
            mesh_labels(self.labels, self.matrices[True], parameters=MeshingParameters(curve=True),
                        progress=lambda f, text: asked.append(text),
                        should_abort=lambda: asked[-1].startswith("quadratic"))
        # The filter stopped within the quadratic stage: it never went on to measure.
        self.assertTrue(asked[-1].startswith("quadratic"), asked[-3:])
        self.assertFalse([text for text in asked if text.startswith("measure")])


class ProgressCancelAndErrorsTest(unittest.TestCase):

    def setUp(self):
        self.labels = two_boxes()

    def test_progress_then_cancel_then_a_new_run(self):
        seen = []
        result = mesh_labels(self.labels, np.eye(4), progress=lambda f, text: seen.append((f, text)))
        fractions = [f for f, _ in seen]
        self.assertEqual(fractions, sorted(fractions))
        self.assertEqual(fractions[-1], 1.0)
        self.assertTrue(any(0.0 < f < 0.5 for f in fractions) and any(0.5 < f < 1.0 for f in fractions))
        self.assertGreater(result.mesh.GetNumberOfCells(), 0)

        asked = []
        with self.assertRaises(MeshingCancelled):
            mesh_labels(self.labels, np.eye(4), progress=lambda f, text: asked.append(f),
                        should_abort=lambda: any(f > 0.0 for f in asked))
        self.assertTrue(max(asked) < 0.5, "cancelled within the mesher")
        again = mesh_labels(self.labels, np.eye(4))
        self.assertEqual(again.mesh.GetNumberOfCells(), result.mesh.GetNumberOfCells())

    def test_bad_input_is_one_plain_error(self):
        sheared = np.eye(4)
        sheared[0, 1] = 0.3
        cases = [
            (dict(ijk_to_ras=sheared), "sheared"),
            (dict(ijk_to_ras=np.diag([1.0, 0.0, 1.0, 1.0])), "zero spacing"),
            (dict(ijk_to_ras=np.eye(4), selected=[7]), "no labelled voxel"),
            (dict(ijk_to_ras=np.eye(4), parameters=MeshingParameters(minimum_angle=31.0)), "minimum angle"),
            (dict(ijk_to_ras=np.eye(4), parameters=MeshingParameters(image_to_mesh_distance=-1.0)), "0..64"),
            (dict(ijk_to_ras=np.eye(4), parameters=MeshingParameters(block_cells=-5)), "block cells"),
            (dict(ijk_to_ras=np.eye(4), parameters=MeshingParameters(memory_limit=1.0)), "memory limit of 1 MiB"),
        ]
        for kwargs, fragment in cases:
            with self.subTest(fragment=fragment):
                with self.assertRaisesRegex(MeshingError, fragment):
                    mesh_labels(self.labels, **kwargs)
        with self.assertRaisesRegex(MeshingError, "integers"):
            mesh_labels(self.labels.astype(float), np.eye(4))
        self.assertTrue(placement_from_ijk_to_ras(np.eye(4)).rotation.tolist() == np.eye(3).tolist())


if __name__ == "__main__":
    unittest.main()
