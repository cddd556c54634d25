# SPDX-License-Identifier: GPL-2.0-or-later
"""LabelMesher.py's Slicer glue (logic.process and Apply) run with Debian's Python: Slicer's
classes are the fakes of fake_slicer.py, the filters are the real wrapped ones.

What a user would see in Slicer: every material coloured by its own entry of the output's colour
table, "Material" shown as cell data even on a model that already has a display node, no node left
in the scene by an Apply, and an unexpected error in a dialog rather than only in the console.

usage: python3 -m unittest test_slicer_glue   (PYTHONPATH: the wrapped module and
SlicerModule/LabelMesher)
"""
import types
import unittest

import numpy as np
import vtk

import fake_slicer

slicer = fake_slicer.install()
import LabelMesher  # noqa: E402  (needs the fakes in sys.modules first)
from LabelMesherLib import MeshingError, MeshingParameters  # noqa: E402


def two_segments():
    """A 2-segment segmentation node in the fake scene (labels [k, j, i], anisotropic spacing)."""
    shape = (12, 14, 16)
    outer, inner = np.zeros(shape, bool), np.zeros(shape, bool)
    outer[2:10, 3:11, 4:12] = True
    inner[5:8, 6:9, 7:10] = True
    outer &= ~inner
    segments = {"Segment_1": fake_slicer.Segment("liver", (0.8, 0.3, 0.2), outer),
                "Segment_2": fake_slicer.Segment("tumour", (0.1, 0.6, 0.9), inner)}
    node = fake_slicer.SegmentationNode(segments, np.diag([0.5, 0.6, 0.7, 1.0]))
    return slicer.mrmlScene.AddNode(node)


class ProcessTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.logic = LabelMesher.LabelMesherLogic()
        cls.segmentation = two_segments()
        cls.ids = ["Segment_1", "Segment_2"]
        cls.model = slicer.mrmlScene.AddNewNodeByClass("vtkMRMLModelNode", "mesh")
        cls.parameters = MeshingParameters(decimate=False)
        cls.logic.process(cls.segmentation, cls.ids, None, cls.model, cls.parameters)

    def test_every_label_maps_to_its_own_colour_table_entry(self):
        display = self.model.GetDisplayNode()
        self.assertEqual(display.range_flag, slicer.vtkMRMLDisplayNode.UseColorNodeScalarRange)
        table = display.GetColorNode().GetLookupTable()
        self.assertEqual(table.GetNumberOfTableValues(), 3)
        self.assertEqual(table.GetRange(), (0.0, 2.0))
        for label, color in ((0, (0.0, 0.0, 0.0, 0.0)), (1, (0.8, 0.3, 0.2, 1.0)), (2, (0.1, 0.6, 0.9, 1.0))):
            with self.subTest(label=label):
                self.assertEqual(table.GetIndex(label), label)
                np.testing.assert_allclose(table.GetTableValue(table.GetIndex(label)), color, atol=1 / 255)  # kept as bytes

    def test_material_is_the_active_cell_scalar_of_a_model_with_a_display_node(self):
        display = self.model.GetDisplayNode()
        display.SetActiveScalar("something else", vtk.vtkAssignAttribute.POINT_DATA)
        self.logic.process(self.segmentation, self.ids, None, self.model, self.parameters)
        self.assertIs(self.model.GetDisplayNode(), display)
        self.assertEqual((display.active_scalar, display.location), ("Material", vtk.vtkAssignAttribute.CELL_DATA))
        self.assertIsNotNone(self.model.GetMesh().GetCellData().GetArray("Material"))
        self.assertTrue(display.scalar_visibility)

    def test_apply_leaves_no_node_behind(self):
        before = sorted(slicer.mrmlScene.nodes)
        for _ in range(2):
            self.logic.process(self.segmentation, self.ids, None, self.model, self.parameters)
        self.assertEqual(sorted(slicer.mrmlScene.nodes), before)
        names = [n.GetName() for n in slicer.mrmlScene.nodes.values()]
        self.assertFalse([n for n in names if n.endswith("_ColorTable")], names)
        self.assertIn("Labels", names)  # the shared built-in table stays


class CurvedVolumeProcessTest(unittest.TestCase):
    """Curve on a volume: the model holds the quadratic tetrahedra, coloured by Material like the
    linear mesh, and the result the quadratic report."""

    def test_the_model_holds_quadratic_tetrahedra(self):
        model = slicer.mrmlScene.AddNewNodeByClass("vtkMRMLModelNode", "quadratic mesh")
        result = LabelMesher.LabelMesherLogic().process(two_segments(), ["Segment_1", "Segment_2"], None, model,
                                                        MeshingParameters(curve=True))
        mesh = model.GetMesh()
        self.assertIs(mesh, result.mesh)
        self.assertGreater(mesh.GetNumberOfCells(), 0)
        self.assertEqual({mesh.GetCellType(c) for c in range(mesh.GetNumberOfCells())}, {vtk.VTK_QUADRATIC_TETRA})
        display = model.GetDisplayNode()
        self.assertEqual((display.active_scalar, display.location), ("Material", vtk.vtkAssignAttribute.CELL_DATA))
        self.assertEqual(sorted(set(mesh.GetCellData().GetArray("Material").GetValue(c)
                                    for c in range(mesh.GetNumberOfCells()))), [1, 2])
        self.assertEqual(display.GetColorNode().GetColorName(2), "tumour")
        self.assertTrue(result.report["quadratic"]["guarantees_hold"])
        self.assertIn("Quadratic mesh: ", result.summary)


class ApplyErrorTest(unittest.TestCase):
    """Apply with a logic that fails: expected failures are one line, others reach a dialog."""

    def widget_whose_logic_raises(self, error):
        widget = LabelMesher.LabelMesherWidget()
        widget.ui = types.SimpleNamespace(
            applyButton=types.SimpleNamespace(text="Apply"), progressBar=types.SimpleNamespace(value=0, format=""),
            summaryText=types.SimpleNamespace(plainText=""), segmentsList=types.SimpleNamespace(count=0))
        widget._parameterNode = types.SimpleNamespace(
            inputSegmentation=None, inputLabelmap=None, outputModel=None, imageToMeshDistance=2.0,
            meshToImageDistance=2.0, decimate=True, minimumAngle=15.0, includeBackground=False, curve=False,
            smoothness=1, tension=1.0 / 3.0, sliceOrder=3, blockCells=1000000, memoryLimit=0.0)

        def process(*args, **kwargs):
            raise error
        widget.logic = types.SimpleNamespace(process=process)
        return widget

    def setUp(self):
        fake_slicer.dialogs.clear()

    def test_an_unexpected_error_reaches_a_dialog(self):
        widget = self.widget_whose_logic_raises(KeyError("quality"))
        with self.assertRaises(KeyError):  # tryWithErrorDisplay re-raises, after the dialog
            widget.onApplyButton()
        self.assertEqual(len(fake_slicer.dialogs), 1)
        self.assertIn("'quality'", fake_slicer.dialogs[0])
        self.assertEqual(widget.ui.applyButton.text, "Apply")
        self.assertFalse(widget._running)

    def test_a_meshing_error_is_one_line_in_a_dialog(self):
        widget = self.widget_whose_logic_raises(MeshingError("no segment is chosen"))
        widget.onApplyButton()
        self.assertEqual(fake_slicer.dialogs, ["LabelMesher: no segment is chosen"])
        self.assertEqual(widget.ui.applyButton.text, "Apply")


class AngleRangeTest(unittest.TestCase):
    """The minimum angle a user can set reaches the proven bound of a slice (45 degrees), not only
    the 3D one (30), in the parameter node and in the slider alike; the logic then holds each
    image to its own dimension's bound."""

    def test_the_angle_reaches_the_bound_of_a_slice(self):
        import os
        import typing
        import xml.etree.ElementTree as ET

        import labelmesher
        hints = typing.get_type_hints(LabelMesher.LabelMesherParameterNode, include_extras=True)
        low, high = hints["minimumAngle"].__metadata__[0]
        self.assertEqual(high, labelmesher.vtkLabelMesher.GetProvenAngleBound(2))
        self.assertEqual(high, 45.0)
        # The .ui states no bound of its own: setup() sets the slider's end from the filters'.
        ui = os.path.join(os.path.dirname(LabelMesher.__file__), "Resources", "UI", "LabelMesher.ui")
        slider = next(w for w in ET.parse(ui).iter("widget") if w.get("name") == "minimumAngleSlider")
        self.assertFalse([p for p in slider.findall("property") if p.get("name") == "maximum"])
        widget = types.SimpleNamespace(maximum=99.0)  # ctkSliderWidget's own default
        LabelMesher.limitAngleSlider(widget)
        self.assertEqual(widget.maximum, high)
        with self.assertRaisesRegex(MeshingError, r"\(0, 30\] degrees for a 3D image"):
            MeshingParameters(minimum_angle=40.0).validate(3)
        MeshingParameters(minimum_angle=40.0).validate(2)


if __name__ == "__main__":
    unittest.main()
