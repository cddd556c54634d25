# SPDX-License-Identifier: GPL-2.0-or-later
"""3D Slicer scripted module: mesh a segmentation (chosen segments) or a labelmap
volume into a tetrahedral (or, for one slice, triangle) mesh with LabelMesher's
guarantees, optionally curved (a volume: quadratic tetrahedra; a slice: cubic
Bezier triangles), as a model node in the input's RAS geometry.

Only Slicer glue lives here; the IJK to RAS placement and the binding of
vtkLabelMesher and vtkLabelMeshReport (the pipeline and the report every front
end shares) are in LabelMesherLib/meshing.py, which runs without Slicer.
"""
import logging
from typing import Annotated, Optional

import numpy as np
import qt
import slicer
import vtk

import labelmesher
from slicer.ScriptedLoadableModule import (ScriptedLoadableModule, ScriptedLoadableModuleLogic,
                                           ScriptedLoadableModuleTest, ScriptedLoadableModuleWidget)
from slicer.parameterNodeWrapper import WithinRange, parameterNodeWrapper
from slicer.util import VTKObservationMixin

from LabelMesherLib import Material, MeshingCancelled, MeshingError, MeshingParameters, mesh_labels


class LabelMesher(ScriptedLoadableModule):
    def __init__(self, parent):
        ScriptedLoadableModule.__init__(self, parent)
        self.parent.title = "LabelMesher"
        self.parent.categories = ["Segmentation"]
        self.parent.dependencies = []
        self.parent.contributors = ["The LabelMesher developers"]
        self.parent.helpText = (
            "Meshes the chosen segments (or a labelmap volume) into tetrahedra whose dihedral angles are "
            f"at least {labelmesher.vtkLabelMesher.GetProvenAngleBound(3):g} degrees (after decimation: at least "
            "the angle bound), within the two distance "
            "bounds of the segments (in voxels of the smallest spacing), with the topology of every "
            "segment kept. The mesh can also be curved to follow the segments: a volume into quadratic "
            "tetrahedra (with decimation), each cell's scaled Jacobian (min det J / max det J) certified at "
            "least 0.1 by the Bernstein coefficients of det J, both distance bounds certified on the curved "
            "interfaces, every segment's topology kept; a single slice into cubic Bezier triangles or "
            "quadratic triangles (Slice cells), each proven valid, whose curves keep both distance bounds. "
            "The report below the Apply button gives "
            "the measured values.")
        self.parent.acknowledgementText = (
            "Octree refinement and decimation after J. Xu, PhD dissertation, Old Dominion University, 2020.")


# The largest minimum angle a user may ask for: the larger of the proven bounds (a slice's); meshing.py
# holds each image to its own dimension's.
MINIMUM_ANGLE_LIMIT = max(labelmesher.vtkLabelMesher.GetProvenAngleBound(2),
                          labelmesher.vtkLabelMesher.GetProvenAngleBound(3))


_DEFAULTS = MeshingParameters()


def limitAngleSlider(slider):
    """The .ui's slider ends where the proven bounds do (the filters' figure, not a copy of it)."""
    slider.maximum = MINIMUM_ANGLE_LIMIT


@parameterNodeWrapper
class LabelMesherParameterNode:
    """Distances in voxels of the smallest spacing, the angle in degrees."""
    inputSegmentation: slicer.vtkMRMLSegmentationNode
    inputLabelmap: slicer.vtkMRMLLabelMapVolumeNode
    outputModel: slicer.vtkMRMLModelNode
    # The defaults are the filter's (MeshingParameters takes them from vtkLabelMesher).
    imageToMeshDistance: Annotated[float, WithinRange(0.0, 64.0)] = _DEFAULTS.image_to_mesh_distance
    meshToImageDistance: Annotated[float, WithinRange(0.0, 64.0)] = _DEFAULTS.mesh_to_image_distance
    decimate: bool = _DEFAULTS.decimate
    minimumAngle: Annotated[float, WithinRange(1.0, MINIMUM_ANGLE_LIMIT)] = _DEFAULTS.minimum_angle
    includeBackground: bool = _DEFAULTS.include_background
    curve: bool = _DEFAULTS.curve
    smoothness: Annotated[int, WithinRange(1, 2)] = _DEFAULTS.smoothness
    tension: Annotated[float, WithinRange(0.0, 1.0)] = _DEFAULTS.tension
    sliceOrder: Annotated[int, WithinRange(2, 3)] = _DEFAULTS.slice_order
    blockCells: Annotated[int, WithinRange(0, 2147483647)] = _DEFAULTS.block_cells
    memoryLimit: Annotated[float, WithinRange(0.0, 1.0e7)] = _DEFAULTS.memory_limit


class LabelMesherWidget(ScriptedLoadableModuleWidget, VTKObservationMixin):
    def __init__(self, parent=None):
        ScriptedLoadableModuleWidget.__init__(self, parent)
        VTKObservationMixin.__init__(self)
        self.logic = None
        self._parameterNode = None
        self._parameterNodeGuiTag = None
        self._running = False
        self._cancelRequested = False

    def setup(self):
        ScriptedLoadableModuleWidget.setup(self)
        uiWidget = slicer.util.loadUI(self.resourcePath("UI/LabelMesher.ui"))
        self.layout.addWidget(uiWidget)
        self.ui = slicer.util.childWidgetVariables(uiWidget)
        limitAngleSlider(self.ui.minimumAngleSlider)
        uiWidget.setMRMLScene(slicer.mrmlScene)
        self.logic = LabelMesherLogic()
        self.addObserver(slicer.mrmlScene, slicer.mrmlScene.StartCloseEvent, self.onSceneStartClose)
        self.addObserver(slicer.mrmlScene, slicer.mrmlScene.EndCloseEvent, self.onSceneEndClose)
        self.ui.applyButton.connect("clicked(bool)", self.onApplyButton)
        self.ui.inputSegmentationSelector.connect("currentNodeChanged(vtkMRMLNode*)", self.onSegmentationChanged)
        self.initializeParameterNode()

    def cleanup(self):
        self.removeObservers()

    def enter(self):
        self.initializeParameterNode()

    def exit(self):
        if self._parameterNode:
            self._parameterNode.disconnectGui(self._parameterNodeGuiTag)
            self._parameterNodeGuiTag = None

    def onSceneStartClose(self, caller, event):
        self.setParameterNode(None)

    def onSceneEndClose(self, caller, event):
        if self.parent.isEntered:
            self.initializeParameterNode()

    def initializeParameterNode(self):
        self.setParameterNode(self.logic.getParameterNode())
        if not self._parameterNode.inputSegmentation and not self._parameterNode.inputLabelmap:
            self._parameterNode.inputSegmentation = slicer.mrmlScene.GetFirstNodeByClass("vtkMRMLSegmentationNode")

    def setParameterNode(self, inputParameterNode: Optional[LabelMesherParameterNode]):
        if self._parameterNode:
            self._parameterNode.disconnectGui(self._parameterNodeGuiTag)
        self._parameterNode = inputParameterNode
        if self._parameterNode:
            self._parameterNodeGuiTag = self._parameterNode.connectGui(self.ui)
            self.onSegmentationChanged(self._parameterNode.inputSegmentation)

    def onSegmentationChanged(self, node):
        """Lists the segmentation's segments, all checked."""
        self.ui.segmentsList.clear()
        if not node:
            return
        segmentation = node.GetSegmentation()
        for index in range(segmentation.GetNumberOfSegments()):
            segmentId = segmentation.GetNthSegmentID(index)
            item = qt.QListWidgetItem(segmentation.GetSegment(segmentId).GetName())
            item.setData(qt.Qt.UserRole, segmentId)
            item.setFlags(item.flags() | qt.Qt.ItemIsUserCheckable)
            item.setCheckState(qt.Qt.Checked)
            self.ui.segmentsList.addItem(item)

    def checkedSegmentIds(self):
        items = (self.ui.segmentsList.item(i) for i in range(self.ui.segmentsList.count))
        return [item.data(qt.Qt.UserRole) for item in items if item.checkState() == qt.Qt.Checked]

    def onApplyButton(self):
        # Apply becomes Cancel while meshing: the filters stop at their next progress report.
        if self._running:
            self._cancelRequested = True
            return
        self._running, self._cancelRequested = True, False
        self.ui.applyButton.text = "Cancel"
        self.ui.progressBar.value = 0
        self.ui.summaryText.plainText = ""

        def progress(fraction, text):
            self.ui.progressBar.value = int(round(100 * fraction))
            self.ui.progressBar.format = f"{text} %p%" if text else "%p%"
            slicer.app.processEvents()  # keeps the GUI (and the Cancel button) alive

        try:
            # Expected failures are one plain line; anything else (a bug, a Slicer API change) gets
            # Slicer's error dialog with the traceback as details, as the module template does,
            # instead of going only to the Python console. tryWithErrorDisplay re-raises after it.
            with slicer.util.tryWithErrorDisplay("LabelMesher failed unexpectedly; no mesh was made."):
                try:
                    p = self._parameterNode
                    result = self.logic.process(
                        p.inputSegmentation, self.checkedSegmentIds(), p.inputLabelmap, p.outputModel,
                        MeshingParameters(image_to_mesh_distance=p.imageToMeshDistance,
                                          mesh_to_image_distance=p.meshToImageDistance, decimate=p.decimate,
                                          minimum_angle=p.minimumAngle, include_background=p.includeBackground,
                                          curve=p.curve, smoothness=p.smoothness, tension=p.tension,
                                          slice_order=p.sliceOrder,
                                          block_cells=p.blockCells, memory_limit=p.memoryLimit),
                        progress, lambda: self._cancelRequested)
                    self.ui.summaryText.plainText = result.summary
                except MeshingCancelled:
                    self.ui.summaryText.plainText = "Cancelled: no mesh was made."
                except MeshingError as e:
                    slicer.util.errorDisplay(f"LabelMesher: {e}")
        finally:
            self._running = False
            self.ui.applyButton.text = "Apply"


class LabelMesherLogic(ScriptedLoadableModuleLogic):
    """Slicer nodes to arrays and back; the meshing itself is LabelMesherLib's."""

    def getParameterNode(self):
        return LabelMesherParameterNode(super().getParameterNode())

    def labelArrayFromSegmentation(self, segmentationNode, segmentIds):
        """(labels [k, j, i], IJK to RAS, materials): segment i of segmentIds gets label i + 1."""
        if not segmentIds:
            raise MeshingError("no segment is chosen")
        colorNodesBefore = {node.GetID() for node in slicer.util.getNodesByClass("vtkMRMLColorNode")}
        labelmap = slicer.mrmlScene.AddNewNodeByClass("vtkMRMLLabelMapVolumeNode")
        try:
            ids = vtk.vtkStringArray()
            for segmentId in segmentIds:
                ids.InsertNextValue(segmentId)
            slicer.modules.segmentations.logic().ExportSegmentsToLabelmapNode(segmentationNode, ids, labelmap)
            labels, matrix = self.labelArrayFromVolume(labelmap)
        finally:
            self.removeTemporaryLabelmap(labelmap, colorNodesBefore)
        segmentation = segmentationNode.GetSegmentation()
        materials = [Material(index + 1, segmentation.GetSegment(segmentId).GetName(),
                              tuple(segmentation.GetSegment(segmentId).GetColor()))
                     for index, segmentId in enumerate(segmentIds)]
        return labels, matrix, materials

    def removeTemporaryLabelmap(self, labelmap, colorNodesBefore):
        """Removes the export's labelmap with the nodes the export made for it: its display node and
        the `<labelmap>_ColorTable` ExportSegmentsToLabelmapNode adds to the scene
        (vtkSlicerSegmentationsModuleLogic.cxx); colour nodes that existed before are shared and stay."""
        display = labelmap.GetDisplayNode()
        color = display.GetColorNode() if display else None
        made = [labelmap, display]
        if color and color.GetID() not in colorNodesBefore:
            made.append(color)
        for node in made:
            if node and slicer.mrmlScene.IsNodePresent(node):
                slicer.mrmlScene.RemoveNode(node)

    def labelArrayFromVolume(self, volumeNode):
        matrix = vtk.vtkMatrix4x4()
        volumeNode.GetIJKToRASMatrix(matrix)
        if volumeNode.GetParentTransformNode():
            raise MeshingError("the volume is under a transform: harden the transform first")
        return slicer.util.arrayFromVolume(volumeNode).copy(), slicer.util.arrayFromVTKMatrix(matrix)

    def process(self, segmentationNode, segmentIds, labelmapNode, outputModel, parameters,
                progress=None, shouldAbort=None):
        """Meshes the chosen segments (or the labelmap) into outputModel; returns the MeshingResult
        (its report and summary)."""
        if segmentationNode:
            labels, matrix, materials = self.labelArrayFromSegmentation(segmentationNode, segmentIds)
        elif labelmapNode:
            labels, matrix = self.labelArrayFromVolume(labelmapNode)
            materials = self.materialsFromColorTable(labelmapNode, labels)
        else:
            raise MeshingError("choose a segmentation or a labelmap volume")
        result = mesh_labels(labels, matrix, materials, parameters, progress=progress, should_abort=shouldAbort)
        if not outputModel:
            outputModel = slicer.mrmlScene.AddNewNodeByClass("vtkMRMLModelNode", "LabelMesher mesh")
        outputModel.SetAndObserveMesh(result.mesh)
        outputModel.CreateDefaultDisplayNodes()
        display = outputModel.GetDisplayNode()
        # "Material" is cell data; SetActiveScalarName alone keeps the location at point data, and a
        # model that already has a display node would then not be coloured.
        display.SetActiveScalar("Material", vtk.vtkAssignAttribute.CELL_DATA)
        display.SetScalarVisibility(True)
        display.SetAndObserveColorNodeID(self.materialColorNode(materials, display.GetColorNode()).GetID())
        display.SetScalarRangeFlag(slicer.vtkMRMLDisplayNode.UseColorNodeScalarRange)
        logging.info("LabelMesher: %s", result.summary.replace("\n", "; "))
        return result

    def materialsFromColorTable(self, labelmapNode, labels):
        colors = labelmapNode.GetDisplayNode().GetColorNode() if labelmapNode.GetDisplayNode() else None
        materials = []
        for label in (int(v) for v in np.unique(labels) if v):
            rgba = [0.0, 0.0, 0.0, 0.0]
            if colors and colors.GetColor(label, rgba):
                materials.append(Material(label, colors.GetColorName(label), tuple(rgba[:3])))
            else:
                materials.append(Material(label, f"label_{label}"))
        return materials

    def materialColorNode(self, materials, current=None):
        """The output's own colour table, refilled on every Apply (one node per output, not per run)."""
        node = current
        if not (node and node.IsA("vtkMRMLColorTableNode") and node.GetName().startswith("LabelMesher materials")):
            node = slicer.mrmlScene.AddNewNodeByClass("vtkMRMLColorTableNode", "LabelMesher materials")
        node.SetTypeToUser()
        node.SetNumberOfColors(0)  # drop the previous run's entries before refilling
        count = max([m.label for m in materials] + [0]) + 1
        node.SetNumberOfColors(count)
        # A new table's range is 0..255 (vtkMRMLColorTableNode.cxx); with UseColorNodeScalarRange labels
        # 1..N would all map to entry 0, the transparent background. Entry i must be label i, as
        # vtkSlicerSegmentationsModuleLogic.cxx sets it for exported labelmaps.
        node.GetLookupTable().SetRange(0, count - 1)
        node.SetColor(0, "background", 0.0, 0.0, 0.0, 0.0)
        for m in materials:
            r, g, b = m.color if m.color is not None else (0.5, 0.5, 0.5)
            node.SetColor(m.label, m.name, r, g, b, 1.0)
        return node


class LabelMesherTest(ScriptedLoadableModuleTest):
    """Runs inside Slicer only (Slicer's self-test); CI runs LabelMesherLib's tests without Slicer."""

    def setUp(self):
        slicer.mrmlScene.Clear()

    def runTest(self):
        self.setUp()
        self.test_TwoSegmentsInAnObliqueVolume()
        self.test_CurvedSlice()
        self.test_QuadraticVolume()

    def test_TwoSegmentsInAnObliqueVolume(self):
        labels = np.zeros((16, 18, 20), dtype=np.uint8)
        labels[3:13, 4:14, 5:15] = 1
        labels[6:10, 7:11, 8:12] = 2
        volume = slicer.util.addVolumeFromArray(labels, nodeClassName="vtkMRMLLabelMapVolumeNode")
        volume.SetSpacing(0.5, 0.6, 0.7)
        volume.SetIJKToRASDirections([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
        segmentation = slicer.mrmlScene.AddNewNodeByClass("vtkMRMLSegmentationNode")
        slicer.modules.segmentations.logic().ImportLabelmapToSegmentationNode(volume, segmentation)
        ids = [segmentation.GetSegmentation().GetNthSegmentID(i) for i in range(2)]
        model = slicer.mrmlScene.AddNewNodeByClass("vtkMRMLModelNode")
        report = LabelMesherLogic().process(segmentation, ids, None, model, MeshingParameters()).report
        self.assertGreater(model.GetMesh().GetNumberOfCells(), 0)
        self.assertGreaterEqual(report["quality"]["minimum_angle_degrees"], 15.0)
        self.assertTrue(report["fidelity"]["bounds_certified"])
        self.assertTrue(report["topology"]["all_match"])
        self.delayDisplay("LabelMesher test passed")

    def test_CurvedSlice(self):
        labels = np.zeros((1, 40, 40), dtype=np.uint8)
        yy, xx = np.mgrid[0:40, 0:40]
        labels[0][(xx - 20) ** 2 + (yy - 20) ** 2 <= 12 ** 2] = 1
        labels[0][(xx - 20) ** 2 + (yy - 20) ** 2 <= 5 ** 2] = 2
        volume = slicer.util.addVolumeFromArray(labels, nodeClassName="vtkMRMLLabelMapVolumeNode")
        model = slicer.mrmlScene.AddNewNodeByClass("vtkMRMLModelNode")
        curve = LabelMesherLogic().process(None, [], volume, model, MeshingParameters(curve=True)).report["curve"]
        self.assertEqual(model.GetMesh().GetCellType(0), vtk.VTK_BEZIER_TRIANGLE)
        self.assertTrue(curve["validity"]["valid"])
        self.assertTrue(curve["curved_mesh"]["within_bounds"])
        quadratic = LabelMesherLogic().process(None, [], volume, model,
                                               MeshingParameters(curve=True, slice_order=2)).report["curve"]
        self.assertEqual(model.GetMesh().GetCellType(0), vtk.VTK_QUADRATIC_TRIANGLE)
        self.assertEqual(quadratic["curved_mesh"]["order"], 2)
        self.assertTrue(quadratic["validity"]["valid"])
        self.assertTrue(quadratic["curved_mesh"]["within_bounds"])
        self.delayDisplay("LabelMesher curved slice test passed")

    def test_QuadraticVolume(self):
        labels = np.zeros((16, 18, 20), dtype=np.uint8)
        labels[3:13, 4:14, 5:15] = 1
        labels[6:10, 7:11, 8:12] = 2
        volume = slicer.util.addVolumeFromArray(labels, nodeClassName="vtkMRMLLabelMapVolumeNode")
        volume.SetIJKToRASDirections([[-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]])
        model = slicer.mrmlScene.AddNewNodeByClass("vtkMRMLModelNode")
        quadratic = LabelMesherLogic().process(None, [], volume, model, MeshingParameters(curve=True)).report["quadratic"]
        self.assertEqual(model.GetMesh().GetCellType(0), vtk.VTK_QUADRATIC_TETRA)
        self.assertTrue(quadratic["guarantees_hold"])
        self.assertGreaterEqual(quadratic["certified_minimum_scaled_jacobian"], quadratic["scaled_jacobian_bound"])
        self.assertGreaterEqual(quadratic["minimum_corner_angle_degrees"], quadratic["corner_angle_bound_degrees"] - 1e-9)
        self.delayDisplay("LabelMesher quadratic volume test passed")
