# SPDX-License-Identifier: GPL-2.0-or-later
"""Just enough of 3D Slicer's Python API (slicer, qt, the scripted-module base classes) to import
SlicerModule/LabelMesher/LabelMesher.py with Debian's Python and run its logic and Apply.

Each fake does what the named Slicer 5.6/5.8 source does, for the calls LabelMesher.py makes and
nothing more; VTK objects (lookup tables, matrices, meshes) are Debian's real ones:
- vtkMRMLColorTableNode: SetTypeToUser makes a lookup table with range 0..255
  (Libs/MRML/Core/vtkMRMLColorTableNode.cxx, SetType); SetNumberOfColors only resizes it.
- vtkMRMLDisplayNode: SetActiveScalarName keeps the attribute location, point data by default;
  SetActiveScalar(name, location) sets both (Libs/MRML/Core/vtkMRMLDisplayNode.h).
- ExportSegmentsToLabelmapNode: creates the labelmap's display node and, as its colour node is not
  of type User, adds a `<labelmap>_ColorTable` node to the scene
  (Modules/Loadable/Segmentations/Logic/vtkSlicerSegmentationsModuleLogic.cxx).
- RemoveNode removes that node only (Libs/MRML/Core/vtkMRMLScene.cxx).
- slicer.util.tryWithErrorDisplay: on an exception, errorDisplay(message + details), then re-raise
  (Base/Python/slicer/util.py).
install() puts the fakes into sys.modules; every errorDisplay call is kept in `dialogs`.
"""
import contextlib
import sys
import types

import numpy as np
import vtk

dialogs = []


class Node:
    classes = ()  # the classes IsA answers yes for, besides its own

    def __init__(self, class_name, name=None):
        self.class_name, self.name, self.id, self.scene = class_name, name or class_name, None, None

    def GetID(self):
        return self.id

    def GetName(self):
        return self.name

    def GetScene(self):
        return self.scene

    def IsA(self, class_name):
        return class_name == self.class_name or class_name in self.classes


class ColorTableNode(Node):
    classes = ("vtkMRMLColorNode",)
    User, Labels = 13, 1

    def __init__(self, class_name="vtkMRMLColorTableNode", name=None):
        super().__init__(class_name, name)
        self.type, self.names, self.lut = None, {}, None

    def SetTypeToUser(self):
        self.type = self.User
        if self.lut is None:
            self.lut = vtk.vtkLookupTable()
            self.lut.SetTableRange(0, 255)

    def GetType(self):
        return self.type

    def GetLookupTable(self):
        return self.lut

    def SetNumberOfColors(self, n):
        self.lut.SetNumberOfTableValues(n)

    def GetNumberOfColors(self):
        return self.lut.GetNumberOfTableValues()

    def SetColor(self, index, name, r, g, b, a=1.0):
        self.names[index] = name
        self.lut.SetTableValue(index, r, g, b, a)

    def GetColorName(self, index):
        return self.names.get(index, "")


class DisplayNode(Node):
    UseColorNodeScalarRange = 2
    POINT_DATA = vtk.vtkAssignAttribute.POINT_DATA

    def __init__(self, class_name, name=None):
        super().__init__(class_name, name)
        self.active_scalar, self.location = None, self.POINT_DATA
        self.color_id, self.scalar_visibility, self.range_flag = None, False, None

    def SetActiveScalarName(self, name):
        self.active_scalar = name

    def SetActiveScalar(self, name, location):
        self.active_scalar, self.location = name, location

    def SetScalarVisibility(self, visible):
        self.scalar_visibility = bool(visible)

    def SetAndObserveColorNodeID(self, node_id):
        self.color_id = node_id

    def GetColorNode(self):
        return self.scene.GetNodeByID(self.color_id) if self.color_id else None

    def SetScalarRangeFlag(self, flag):
        self.range_flag = flag


class DisplayableNode(Node):
    display_class = "vtkMRMLDisplayNode"

    def __init__(self, class_name, name=None):
        super().__init__(class_name, name)
        self.display_id = None

    def CreateDefaultDisplayNodes(self):
        if self.GetDisplayNode() is None:
            self.display_id = self.scene.AddNode(DisplayNode(self.display_class)).GetID()

    def GetDisplayNode(self):
        return self.scene.GetNodeByID(self.display_id) if self.display_id else None

    def GetParentTransformNode(self):
        return None


class ModelNode(DisplayableNode):
    display_class = "vtkMRMLModelDisplayNode"

    def __init__(self, class_name="vtkMRMLModelNode", name=None):
        super().__init__(class_name, name)
        self.mesh = None

    def SetAndObserveMesh(self, mesh):
        self.mesh = mesh

    def GetMesh(self):
        return self.mesh


class LabelMapVolumeNode(DisplayableNode):
    display_class = "vtkMRMLLabelMapVolumeDisplayNode"

    def __init__(self, class_name="vtkMRMLLabelMapVolumeNode", name=None):
        super().__init__(class_name, name)
        self.array, self.ijk_to_ras = None, np.eye(4)

    def CreateDefaultDisplayNodes(self):
        super().CreateDefaultDisplayNodes()
        # A labelmap's default colours are the scene's shared "Labels" table, not a User one.
        labels = self.scene.GetFirstNodeByName("Labels")
        self.GetDisplayNode().SetAndObserveColorNodeID(labels.GetID())

    def GetIJKToRASMatrix(self, matrix):
        matrix.DeepCopy(self.ijk_to_ras.ravel())


class Segment:
    def __init__(self, name, color, mask):
        self.name, self.color, self.mask = name, color, mask

    def GetName(self):
        return self.name

    def GetColor(self):
        return self.color


class Segmentation:
    def __init__(self, segments):
        self.segments = segments  # {id: Segment}

    def GetNumberOfSegments(self):
        return len(self.segments)

    def GetNthSegmentID(self, index):
        return list(self.segments)[index]

    def GetSegment(self, segment_id):
        return self.segments[segment_id]


class SegmentationNode(DisplayableNode):
    def __init__(self, segments, ijk_to_ras, name="Segmentation"):
        super().__init__("vtkMRMLSegmentationNode", name)
        self.segmentation, self.ijk_to_ras = Segmentation(segments), ijk_to_ras

    def GetSegmentation(self):
        return self.segmentation


class Scene:
    def __init__(self):
        self.nodes, self.count = {}, 0
        labels = ColorTableNode(name="Labels")  # Slicer's built-in labelmap colours
        labels.SetTypeToUser()
        labels.type = ColorTableNode.Labels
        self.AddNode(labels)

    def AddNode(self, node):
        self.count += 1
        node.id, node.scene = f"{node.class_name}{self.count}", self
        self.nodes[node.id] = node
        return node

    def AddNewNodeByClass(self, class_name, name=None):
        factories = {"vtkMRMLModelNode": ModelNode, "vtkMRMLLabelMapVolumeNode": LabelMapVolumeNode,
                     "vtkMRMLColorTableNode": ColorTableNode}
        return self.AddNode(factories[class_name](class_name, name))

    def RemoveNode(self, node):
        del self.nodes[node.GetID()]

    def IsNodePresent(self, node):
        return int(self.nodes.get(node.GetID()) is node)

    def GetNodeByID(self, node_id):
        return self.nodes.get(node_id)

    def GetFirstNodeByName(self, name):
        return next((n for n in self.nodes.values() if n.GetName() == name), None)

    def GetFirstNodeByClass(self, class_name):
        return next((n for n in self.nodes.values() if n.IsA(class_name)), None)


class SegmentationsLogic:
    def ExportSegmentsToLabelmapNode(self, segmentation_node, ids, labelmap):
        chosen = [ids.GetValue(i) for i in range(ids.GetNumberOfValues())]
        segments = segmentation_node.GetSegmentation().segments
        array = np.zeros(next(iter(segments.values())).mask.shape, dtype=np.uint8)
        for index, segment_id in enumerate(chosen):
            array[segments[segment_id].mask] = index + 1
        labelmap.array, labelmap.ijk_to_ras = array, segmentation_node.ijk_to_ras
        labelmap.CreateDefaultDisplayNodes()
        display = labelmap.GetDisplayNode()
        if display.GetColorNode() is None or display.GetColorNode().GetType() != ColorTableNode.User:
            table = ColorTableNode(name=labelmap.GetName() + "_ColorTable")
            table.SetTypeToUser()
            labelmap.GetScene().AddNode(table)
            display.SetAndObserveColorNodeID(table.GetID())


def error_display(text, **kwargs):
    dialogs.append(text)


@contextlib.contextmanager
def try_with_error_display(message=None, show=True, waitCursor=False):
    try:
        yield
    except Exception as e:
        if show:
            error_display(f"{message}\n\n{e}" if message is not None else str(e))
        raise


def install():
    """Puts fake slicer/qt modules into sys.modules and returns the fake slicer module."""
    dialogs.clear()
    slicer = types.ModuleType("slicer")
    slicer.mrmlScene = Scene()
    slicer.modules = types.SimpleNamespace(segmentations=types.SimpleNamespace(logic=SegmentationsLogic))
    for name in ("vtkMRMLSegmentationNode", "vtkMRMLLabelMapVolumeNode", "vtkMRMLModelNode"):
        setattr(slicer, name, type(name, (Node,), {}))
    slicer.vtkMRMLDisplayNode = DisplayNode

    util = types.ModuleType("slicer.util")
    util.errorDisplay = error_display
    util.tryWithErrorDisplay = try_with_error_display
    util.getNodesByClass = lambda class_name, scene=None: [
        n for n in list((scene or slicer.mrmlScene).nodes.values()) if n.IsA(class_name)]
    util.arrayFromVolume = lambda node: node.array
    util.arrayFromVTKMatrix = lambda m: np.array([[m.GetElement(i, j) for j in range(4)] for i in range(4)])
    util.VTKObservationMixin = type("VTKObservationMixin", (), {"__init__": lambda self: None})
    slicer.util = util

    scripted = types.ModuleType("slicer.ScriptedLoadableModule")
    for name in ("ScriptedLoadableModule", "ScriptedLoadableModuleLogic", "ScriptedLoadableModuleTest",
                 "ScriptedLoadableModuleWidget"):
        setattr(scripted, name, type(name, (), {"__init__": lambda self, parent=None: None}))
    wrapper = types.ModuleType("slicer.parameterNodeWrapper")
    wrapper.parameterNodeWrapper = lambda cls: cls
    wrapper.WithinRange = lambda low, high: (low, high)

    qt = types.ModuleType("qt")
    qt.Qt = types.SimpleNamespace(UserRole=32, Checked=2, ItemIsUserCheckable=16)
    sys.modules.update({"slicer": slicer, "slicer.util": util, "slicer.ScriptedLoadableModule": scripted,
                        "slicer.parameterNodeWrapper": wrapper, "qt": qt})
    return slicer
