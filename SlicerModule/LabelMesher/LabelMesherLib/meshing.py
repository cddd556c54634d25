# SPDX-License-Identifier: GPL-2.0-or-later
"""The LabelMesher module's logic without 3D Slicer: a label array, its IJK to RAS
placement and the segments' names and colours in; vtkLabelMesher (the wrapped VTK
module ``labelmesher``: mesher, decimator and, on request, curver: a slice's
cubic Bezier triangles, a volume's quadratic tetrahedra) run; a tetrahedral or
triangle mesh in RAS (curved: cubic Bezier triangles for a slice, quadratic
tetrahedra for a volume) and vtkLabelMeshReport's report out, the same the CLI
writes. Slicer's own classes appear only in ``LabelMesher.py``; this file needs
numpy and VTK's Python bindings, so it is tested with Debian's Python.

Placement: Slicer's IJK to RAS matrix is M = [R diag(s) | o] for a volume with
spacing s, direction R and origin o. The mesh is made in the image's own frame
(spacing s, origin 0, axis-aligned, so the filters' distance bounds are in
voxels of the smallest spacing and their angle bounds hold as proved), then
every point p is placed at R p + o. R is orthogonal, so angles, distances and
topology are unchanged; a reflection (det R < 0, common for LPS files) would
turn every tetrahedron inside out, so two of its corners are swapped back (a
quadratic tetrahedron's mid-nodes with them). A sheared matrix has no such
rigid placement and is refused.
"""
import json
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkDoubleArray, vtkIntArray, vtkPoints, vtkStringArray
from vtkmodules.vtkCommonDataModel import VTK_QUADRATIC_TETRA, VTK_TETRA, vtkImageData, vtkUnstructuredGrid

import labelmesher

_MESHER = labelmesher.vtkLabelMesher
_DEFAULTS = _MESHER()


class MeshingError(Exception):
    """Input the filters cannot mesh, or a filter's error; one plain sentence."""


class MeshingCancelled(Exception):
    """The user stopped the run (should_abort returned True)."""


@dataclass
class Material:
    label: int
    name: str
    color: Optional[Tuple[float, float, float]] = None  # RGB in [0, 1]


@dataclass
class MeshingParameters:
    """Distances in voxels of the smallest spacing; angle in degrees."""
    # h(I,M) (MesherParameters.h): every point of the image boundary lies within this of the mesh
    # boundary, per material; h(M,I): every point of the mesh boundary between two materials lies
    # within this of the image boundary between them.
    # Every default is vtkLabelMesher's own (_DEFAULTS, a filter as constructed).
    image_to_mesh_distance: float = _DEFAULTS.GetImageToMeshDistance()
    mesh_to_image_distance: float = _DEFAULTS.GetMeshToImageDistance()
    decimate: bool = _DEFAULTS.GetDecimate()
    minimum_angle: float = _DEFAULTS.GetMinimumAngle()  # the decimator keeps every angle at least this (<= GetProvenAngleBound)
    include_background: bool = _DEFAULTS.GetIncludeBackground()
    # Curve the mesh, keeping both distance bounds and every material's topology: a slice into cubic
    # Bezier triangles (vtkLabelMesher's Curve: every cell proven valid), a volume into quadratic
    # tetrahedra (its Order 2, with decimation only: every cell's scaled Jacobian certified at least
    # MinimumScaledJacobian, 0.1, by the Bernstein coefficients of det J).
    curve: bool = _DEFAULTS.GetCurve()
    smoothness: int = _DEFAULTS.GetSmoothness()  # a slice's curves: 1 (C1, fitted to the image) or 2 (C2) at their joints
    tension: float = _DEFAULTS.GetTension()  # a slice's C1 curves: handle length factor, dimensionless, [0, 1]
    # A slice's curved cells: 3, cubic Bezier triangles (Curve); 2, quadratic triangles (6 nodes,
    # vtkLabelMesher's Order 2 of a 2D image: the same certificates, curves of one control point;
    # decimation only).
    slice_order: int = 3
    block_cells: int = _DEFAULTS.GetBlockCells()  # decimating: initial cells per block (0: one block)
    memory_limit: float = _DEFAULTS.GetMemoryLimit()  # MiB the process may hold; a run estimated above it is refused (0: available memory)

    def validate(self, dimension: int):
        for name in ("image_to_mesh_distance", "mesh_to_image_distance"):
            value = getattr(self, name)
            if not (0.0 <= value <= 64.0):
                raise MeshingError(f"{name.replace('_', ' ')} must be within 0..64 voxels, not {value}")
        limit = _MESHER.GetProvenAngleBound(dimension)
        if self.decimate and not (0.0 < self.minimum_angle <= limit):
            raise MeshingError(
                f"minimum angle must be within (0, {limit:g}] degrees for a {dimension}D image, not {self.minimum_angle}")
        if not (isinstance(self.block_cells, int) and 0 <= self.block_cells < 2**63):
            raise MeshingError(f"block cells must be a whole number of cells, 0 or more, not {self.block_cells}")
        if not (0.0 <= self.memory_limit < float("inf")):
            raise MeshingError(f"memory limit must be 0 (the memory available) or more MiB, not {self.memory_limit}")
        if self.curve and dimension == 3 and not self.decimate:
            # vtkLabelMesher refuses Order 2 without Decimate: its quadratic cells are the decimated ones.
            raise MeshingError("curving a volume (quadratic tetrahedra) needs decimation: turn decimation on")
        if self.curve and dimension == 2:
            if self.slice_order not in (2, 3):
                raise MeshingError(f"a slice's curved cells are of order 2 or 3, not {self.slice_order}")
            if self.slice_order == 2 and not self.decimate:
                raise MeshingError("curving a slice into quadratic triangles needs decimation: turn decimation on")
            if self.smoothness not in (1, 2):
                raise MeshingError(f"smoothness must be 1 (C1) or 2 (C2), not {self.smoothness}")
            if not (0.0 <= self.tension <= 1.0):
                raise MeshingError(f"tension must be within [0, 1], not {self.tension}")


@dataclass
class Placement:
    spacing: np.ndarray    # (3,) mm
    rotation: np.ndarray   # (3, 3), orthogonal
    origin: np.ndarray     # (3,) RAS of voxel (0, 0, 0)

    @property
    def reflects(self) -> bool:
        return bool(np.linalg.det(self.rotation) < 0.0)


@dataclass
class MeshingResult:
    # In RAS, cell data "Material". Curved: a slice's VTK_BEZIER_TRIANGLE (or, slice_order 2,
    # VTK_QUADRATIC_TRIANGLE) cells, or a volume's
    # VTK_QUADRATIC_TETRA cells (10 nodes in VTK's order, cell data "ScaledJacobian": each cell's
    # certified lower bound of min det J / max det J); the linear mesh is then only in the report.
    mesh: vtkUnstructuredGrid
    interfaces: object                 # vtkPolyData of the linear mesh's interfaces (port 1), in RAS
    # vtkLabelMeshReport's JSON of the linear mesh (`labelmesher mesh --report`'s keys), its "image"
    # with the placement added; a curved slice's "curve" holds the curve report (`labelmesher curve
    # --report`'s), a curved volume's "quadratic" the quadratic mesh's part (`labelmesher mesh
    # --order 2 --report`'s; null otherwise).
    report: Dict = field(default_factory=dict)
    summary: str = ""                  # vtkLabelMeshReport's text summary (the CLI's)


def placement_from_ijk_to_ras(ijk_to_ras, tolerance: float = 1e-6) -> Placement:
    """Splits a 4x4 IJK to RAS matrix into spacing, rotation and origin."""
    m = np.asarray(ijk_to_ras, dtype=float).reshape(4, 4)
    if not np.all(np.isfinite(m)) or np.any(m[3] != (0.0, 0.0, 0.0, 1.0)):
        raise MeshingError("the IJK to RAS matrix is not an affine placement")
    columns = m[:3, :3]
    # The column norms give the spacing up to rounding (0.8 comes back as 0.7999999999999999);
    # 12 digits recover the volume's own spacing, so the mesh equals the one made from it.
    spacing = np.array([float(f"{s:.12g}") for s in np.linalg.norm(columns, axis=0)])
    if np.any(spacing <= 0.0):
        raise MeshingError(f"the volume has zero spacing ({spacing.tolist()})")
    rotation = columns / spacing
    if np.max(np.abs(rotation.T @ rotation - np.eye(3))) > tolerance:
        raise MeshingError("the volume's IJK to RAS matrix is sheared: its axes are not perpendicular, "
                           "so no mesh in RAS can keep the proven angles; resample the volume first")
    return Placement(spacing=spacing, rotation=rotation, origin=m[:3, 3].copy())


def label_image(labels_kji: np.ndarray, spacing: Sequence[float], selected: Optional[Sequence[int]] = None):
    """vtkImageData of the labels in the image's own frame. ``labels_kji`` is
    indexed [k, j, i] (Slicer's arrayFromVolume); labels not in ``selected`` become
    background."""
    labels = np.asarray(labels_kji)
    if labels.ndim == 2:
        labels = labels[np.newaxis]
    if labels.ndim != 3 or labels.size == 0:
        raise MeshingError(f"the label array must be 2D or 3D and non-empty, not of shape {labels.shape}")
    if not np.issubdtype(labels.dtype, np.integer):
        raise MeshingError(f"labels must be integers, not {labels.dtype}")
    if labels.min() < 0 or labels.max() > np.iinfo(np.int32).max:
        raise MeshingError("labels must lie within 0..2147483647")
    labels = labels.astype(np.int32)
    if selected is not None:
        labels = np.where(np.isin(labels, np.asarray(list(selected), dtype=np.int32)), labels, 0).astype(np.int32)
    if not labels.any():
        raise MeshingError("no labelled voxel: every voxel is background (or no segment is selected)")
    image = vtkImageData()
    image.SetDimensions(labels.shape[2], labels.shape[1], labels.shape[0])
    image.SetSpacing(*[float(s) for s in spacing])
    scalars = numpy_to_vtk(labels.ravel(order="C"), deep=1)
    scalars.SetName("Labels")
    image.GetPointData().SetScalars(scalars)
    return image


def _watch(algorithm, progress, should_abort, errors: List[str]):
    """Forwards the filter's progress to progress(fraction, text) and asks it to
    stop (AbortExecute) as soon as should_abort() says so."""
    def on_progress(obj, _event):
        if progress:
            progress(obj.GetProgress(), obj.GetProgressText() or "")
        if should_abort and should_abort():
            obj.SetAbortExecute(1)

    @calldata_type(VTK_STRING)
    def on_error(_obj, _event, message):
        # VTK's message is "ERROR: In FILE, line N\nvtkClass (0x...): text": keep the text.
        errors.append(str(message).strip().splitlines()[-1].split("): ", 1)[-1])

    algorithm.AddObserver(vtkCommand.ProgressEvent, on_progress)
    algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)


def place(data, placement: Placement):
    """Moves data's points from the image frame into RAS, in place."""
    points = data.GetPoints()
    if points is None or points.GetNumberOfPoints() == 0:
        return
    xyz = vtk_to_numpy(points.GetData()).astype(float)
    ras = xyz @ placement.rotation.T + placement.origin
    placed = vtkPoints()
    placed.SetDataTypeToDouble()
    placed.SetData(numpy_to_vtk(np.ascontiguousarray(ras), deep=1))
    data.SetPoints(placed)
    if placement.reflects and isinstance(data, vtkUnstructuredGrid):
        _reorient_tetrahedra(data)


# A reflection makes every tetrahedron's det J negative: its corners 1 and 2 are swapped back, and a
# quadratic tetrahedron's mid-nodes with them (VTK's order: corners 0-3, then the mid-nodes of edges
# (0,1), (1,2), (2,0), (0,3), (1,3), (2,3); edge (0,1) becomes (0,2), (1,3) becomes (2,3)).
_REORIENTED_NODES = {VTK_TETRA: [0, 2, 1, 3], VTK_QUADRATIC_TETRA: [0, 2, 1, 3, 6, 5, 4, 7, 9, 8]}


def _reorient_tetrahedra(grid: vtkUnstructuredGrid):
    cells = grid.GetCells()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    connectivity = vtk_to_numpy(cells.GetConnectivityArray()).copy()
    types = vtk_to_numpy(grid.GetCellTypesArray())
    for cell_type, order in _REORIENTED_NODES.items():
        starts = offsets[:-1][(types == cell_type) & (np.diff(offsets) == len(order))]
        nodes = starts[:, np.newaxis] + np.arange(len(order))
        connectivity[nodes] = connectivity[nodes][:, order]
    cells.SetData(numpy_to_vtk(offsets, deep=1), numpy_to_vtk(connectivity, deep=1))
    grid.SetCells(grid.GetCellTypesArray(), cells)


def attach_materials(data, materials: Sequence[Material]):
    """The material table (MaterialLabel / MaterialName / MaterialColor), as the CLI's files carry
    it; on the image, the filters pass it to the mesh."""
    labels, names, colors = vtkIntArray(), vtkStringArray(), vtkDoubleArray()
    labels.SetName(_MESHER.GetMaterialLabelArrayName())
    names.SetName(_MESHER.GetMaterialNameArrayName())
    colors.SetName(_MESHER.GetMaterialColorArrayName())
    colors.SetNumberOfComponents(3)
    for m in sorted(materials, key=lambda m: m.label):
        labels.InsertNextValue(int(m.label))
        names.InsertNextValue(m.name)
        colors.InsertNextTuple3(*(m.color if m.color is not None else (-1.0, -1.0, -1.0)))
    for array in (labels, names, colors):
        data.GetFieldData().AddArray(array)


def mesh_labels(labels_kji, ijk_to_ras, materials: Sequence[Material] = (),
                parameters: MeshingParameters = None, selected: Optional[Sequence[int]] = None,
                progress: Optional[Callable[[float, str], None]] = None,
                should_abort: Optional[Callable[[], bool]] = None) -> MeshingResult:
    """Meshes a label array placed by ijk_to_ras with vtkLabelMesher (mesher and decimator block by
    block, or the mesher alone without parameters.decimate; then, with parameters.curve, a slice's
    cubic curver (Curve) or quadratic triangles (Order 2, parameters.slice_order 2) or a volume's
    quadratic tetrahedra (Order 2)); returns the mesh in RAS (the
    curved one when curving) and vtkLabelMeshReport's report. Raises MeshingError (bad input, the
    filter's error, an untangling failure) or MeshingCancelled."""
    parameters = parameters or MeshingParameters()
    placement = placement_from_ijk_to_ras(ijk_to_ras)
    image = label_image(labels_kji, placement.spacing, selected)
    dimension = _MESHER.GetImageDimension(image)
    parameters.validate(dimension)
    quadratic = parameters.curve and dimension == 3  # a volume's curved cells: quadratic tetrahedra
    # A slice's curved cells: cubic Bezier triangles (Curve) or quadratic triangles (Order 2).
    cubic = parameters.curve and dimension == 2 and parameters.slice_order == 3
    known = {m.label: m for m in materials}
    present = sorted(int(v) for v in np.unique(vtk_to_numpy(image.GetPointData().GetScalars()))
                     if v or parameters.include_background)
    table = [known.get(label, Material(label, f"label_{label}")) for label in present]
    attach_materials(image, table)  # passed by the filter to its outputs, named in the report

    mesher = _MESHER()
    mesher.SetInputData(image)
    mesher.SetDecimate(parameters.decimate)
    mesher.SetImageToMeshDistance(parameters.image_to_mesh_distance)
    mesher.SetMeshToImageDistance(parameters.mesh_to_image_distance)
    mesher.SetMinimumAngle(parameters.minimum_angle)
    mesher.SetBlockCells(parameters.block_cells)
    mesher.SetIncludeBackground(parameters.include_background)
    mesher.SetMemoryLimit(parameters.memory_limit)
    mesher.SetMeasureOutput(True)
    mesher.SetCurve(cubic)
    mesher.SetOrder(2 if parameters.curve and not cubic else 1)
    mesher.SetSmoothness(parameters.smoothness)
    mesher.SetTension(parameters.tension)
    errors: List[str] = []
    _watch(mesher, progress, should_abort, errors)
    mesher.Update()
    if mesher.GetAbortExecute() or (should_abort and should_abort()):
        raise MeshingCancelled()
    if errors:
        raise MeshingError(f"vtkLabelMesher: {errors[0]}")

    linear = vtkUnstructuredGrid()
    linear.DeepCopy(mesher.GetOutput())
    interfaces = mesher.GetInterfacesOutput().NewInstance()
    interfaces.DeepCopy(mesher.GetInterfacesOutput())
    mesh = linear
    builder = labelmesher.vtkLabelMeshReport()
    builder.SetImage(image)
    builder.SetMesh(linear)
    if parameters.curve:
        mesh = vtkUnstructuredGrid()
        mesh.DeepCopy(mesher.GetCurvedOutput())
        builder.SetCurvedMesh(mesh)
    report = json.loads(builder.GetMeshJSON())
    report["image"].update(ijk_to_ras_rotation=placement.rotation.tolist(), origin_ras=placement.origin.tolist())
    if parameters.curve and not quadratic:  # a volume's quadratic part is the mesh report's "quadratic"
        report["curve"] = json.loads(builder.GetCurveJSON())
    summary = builder.GetSummary()
    place(mesh, placement)
    place(interfaces, placement)
    if progress:
        progress(1.0, "done")
    return MeshingResult(mesh=mesh, interfaces=interfaces, report=report, summary=summary)
