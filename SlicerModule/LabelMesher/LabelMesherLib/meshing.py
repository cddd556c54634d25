# SPDX-License-Identifier: GPL-2.0-or-later
"""The LabelMesher module's logic without 3D Slicer: a label array, its IJK to RAS
placement and the segments' names and colours in; the filters (the wrapped VTK
module ``labelmesher``) run; a tetrahedral/triangle mesh in RAS (for one slice on
request curved: cubic Bezier triangles, vtkBezierCurver) and a quality report out. Slicer's own classes appear only in ``LabelMesher.py``; this file
needs numpy and VTK's Python bindings, so it is tested with Debian's Python.

Placement: Slicer's IJK to RAS matrix is M = [R diag(s) | o] for a volume with
spacing s, direction R and origin o. The mesh is made in the image's own frame
(spacing s, origin 0, axis-aligned, so the filters' distance bounds are in
voxels of the smallest spacing and their angle bounds hold as proved), then
every point p is placed at R p + o. R is orthogonal, so angles, distances and
topology are unchanged; a reflection (det R < 0, common for LPS files) would
turn every tetrahedron inside out, so two of its vertices are swapped back. A
sheared matrix has no such rigid placement and is refused.
"""
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkDoubleArray, vtkIntArray, vtkPoints, vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkUnstructuredGrid

import labelmesher

# Field-data arrays of the materials, as the I/O layer writes them (Filters/IO/MaterialTable.h).
MATERIAL_LABEL, MATERIAL_NAME, MATERIAL_COLOR = "MaterialLabel", "MaterialName", "MaterialColor"


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
    image_to_mesh_distance: float = 2.0
    mesh_to_image_distance: float = 2.0
    decimate: bool = True
    minimum_angle: float = 15.0  # the decimator keeps every angle at least this (<= 30 in 3D, 45 in 2D)
    include_background: bool = False
    curve: bool = False  # one slice only: curve the mesh (vtkBezierCurver), keeping validity and both bounds
    smoothness: int = 1  # 1 (C1, fitted to the image) or 2 (C2) at the curves' joints
    tension: float = 1.0 / 3.0  # C1 handle length factor, dimensionless, [0, 1]
    block_cells: int = 1000000  # decimating: initial cells per block (0: one block), vtkLabelMesher's BlockCells
    memory_limit: float = 0.0  # MiB the process may hold; a run estimated above it is refused (0: available memory)

    def validate(self, dimension: int):
        for name in ("image_to_mesh_distance", "mesh_to_image_distance"):
            value = getattr(self, name)
            if not (0.0 <= value <= 64.0):
                raise MeshingError(f"{name.replace('_', ' ')} must be within 0..64 voxels, not {value}")
        limit = labelmesher.vtkLabelOctreeMesher.GetProvenAngleBound(dimension)
        if self.decimate and not (0.0 < self.minimum_angle <= limit):
            raise MeshingError(
                f"minimum angle must be within (0, {limit:g}] degrees for a {dimension}D image, not {self.minimum_angle}")
        if not (isinstance(self.block_cells, int) and 0 <= self.block_cells < 2**63):
            raise MeshingError(f"block cells must be a whole number of cells, 0 or more, not {self.block_cells}")
        if not (0.0 <= self.memory_limit < float("inf")):
            raise MeshingError(f"memory limit must be 0 (the memory available) or more MiB, not {self.memory_limit}")
        if self.curve:
            if dimension != 2:
                raise MeshingError("curving needs a 2D image (a single slice); this one is 3D")
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
    mesh: vtkUnstructuredGrid          # in RAS, cell data "Material"; curved: VTK_BEZIER_TRIANGLE cells
    interfaces: object                 # vtkPolyData of the linear mesh's interfaces (port 1), in RAS
    report: Dict = field(default_factory=dict)


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


def _watch(algorithm, start: float, share: float, progress, should_abort, errors: List[str]):
    """Forwards the filter's progress to progress(fraction, text) and asks it to
    stop (AbortExecute) as soon as should_abort() says so."""
    def on_progress(obj, _event):
        if progress:
            progress(start + share * obj.GetProgress(), obj.GetProgressText() or "")
        if should_abort and should_abort():
            obj.SetAbortExecute(1)

    @calldata_type(VTK_STRING)
    def on_error(_obj, _event, message):
        # VTK's message is "ERROR: In FILE, line N\nvtkClass (0x...): text": keep the text.
        errors.append(str(message).strip().splitlines()[-1].split("): ", 1)[-1])

    algorithm.AddObserver(vtkCommand.ProgressEvent, on_progress)
    algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)


def _update(algorithm, errors: List[str], should_abort):
    # The filters report bad input as an error event and an empty output (never a crash).
    algorithm.Update()
    if algorithm.GetAbortExecute() or (should_abort and should_abort()):
        raise MeshingCancelled()
    if errors:
        raise MeshingError(f"{algorithm.GetClassName()}: {errors[0]}")


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


def _reorient_tetrahedra(grid: vtkUnstructuredGrid):
    # A reflection makes every tetrahedron's signed volume negative: swap vertices 1 and 2.
    cells = grid.GetCells()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    connectivity = vtk_to_numpy(cells.GetConnectivityArray()).copy()
    types = vtk_to_numpy(grid.GetCellTypesArray())
    starts = offsets[:-1][(types == 10) & (np.diff(offsets) == 4)]
    connectivity[starts + 1], connectivity[starts + 2] = connectivity[starts + 2].copy(), connectivity[starts + 1].copy()
    cells.SetData(numpy_to_vtk(offsets, deep=1), numpy_to_vtk(connectivity, deep=1))
    grid.SetCells(grid.GetCellTypesArray(), cells)


def attach_materials(mesh, materials: Sequence[Material]):
    """MaterialLabel / MaterialName / MaterialColor, as the CLI's files carry them."""
    labels, names, colors = vtkIntArray(), vtkStringArray(), vtkDoubleArray()
    labels.SetName(MATERIAL_LABEL)
    names.SetName(MATERIAL_NAME)
    colors.SetName(MATERIAL_COLOR)
    colors.SetNumberOfComponents(3)
    for m in sorted(materials, key=lambda m: m.label):
        labels.InsertNextValue(int(m.label))
        names.InsertNextValue(m.name)
        colors.InsertNextTuple3(*(m.color if m.color is not None else (-1.0, -1.0, -1.0)))
    for array in (labels, names, colors):
        mesh.GetFieldData().AddArray(array)


def mesh_labels(labels_kji, ijk_to_ras, materials: Sequence[Material] = (),
                parameters: MeshingParameters = None, selected: Optional[Sequence[int]] = None,
                progress: Optional[Callable[[float, str], None]] = None,
                should_abort: Optional[Callable[[], bool]] = None) -> MeshingResult:
    """Meshes a label array placed by ijk_to_ras: vtkLabelMesher (mesher and decimator, block
    by block), or vtkLabelOctreeMesher alone (not parameters.decimate), then (parameters.curve,
    one slice) vtkBezierCurver; returns the mesh in RAS and its report. Raises MeshingError
    (bad input, a filter's error, an untangling failure) or MeshingCancelled."""
    parameters = parameters or MeshingParameters()
    placement = placement_from_ijk_to_ras(ijk_to_ras)
    image = label_image(labels_kji, placement.spacing, selected)
    dims = image.GetDimensions()
    dimension = 2 if 1 in dims else 3
    parameters.validate(dimension)

    errors: List[str] = []
    if parameters.decimate:
        # Mesher and decimator in one filter, block by block: the initial mesh is never whole.
        mesher = labelmesher.vtkLabelMesher()
        mesher.SetMinimumAngle(parameters.minimum_angle)
        mesher.SetBlockCells(parameters.block_cells)
    else:
        mesher = labelmesher.vtkLabelOctreeMesher()
    mesher.SetMemoryLimit(parameters.memory_limit)
    mesher.SetInputData(image)
    mesher.SetImageToMeshDistance(parameters.image_to_mesh_distance)
    mesher.SetMeshToImageDistance(parameters.mesh_to_image_distance)
    mesher.SetIncludeBackground(parameters.include_background)
    mesher.SetMeasureOutput(True)
    curve_start = _curve_start(parameters)
    _watch(mesher, 0.0, curve_start, progress, should_abort, errors)
    _update(mesher, errors, should_abort)
    last = mesher
    curver = None
    if parameters.curve:
        # The curver keeps the bounds the linear mesh records and measures the curves itself.
        curver = labelmesher.vtkBezierCurver()
        curver.SetInputConnection(0, last.GetOutputPort(0))
        curver.SetInputData(1, image)
        curver.SetSmoothness(parameters.smoothness)
        curver.SetTension(parameters.tension)
        _watch(curver, curve_start, 1.0 - curve_start, progress, should_abort, errors)
        _update(curver, errors, should_abort)

    linear = vtkUnstructuredGrid()
    linear.DeepCopy(last.GetOutputDataObject(0))
    mesh = linear
    if curver is not None:
        mesh = vtkUnstructuredGrid()
        mesh.DeepCopy(curver.GetOutputDataObject(0))
    interfaces = last.GetOutputDataObject(1).NewInstance()
    interfaces.DeepCopy(last.GetOutputDataObject(1))
    place(mesh, placement)
    place(interfaces, placement)
    present = set(int(v) for v in np.unique(vtk_to_numpy(mesh.GetCellData().GetArray("Material"))))
    known = {m.label: m for m in materials}
    table = [known.get(label, Material(label, f"label_{label}")) for label in sorted(present)]
    attach_materials(mesh, table)
    attach_materials(linear, table)
    report = quality_report(linear, dims, placement, parameters)
    if curver is not None:
        report["curved_mesh"] = curve_report(mesh, parameters)
    if progress:
        progress(1.0, "done")
    return MeshingResult(mesh=mesh, interfaces=interfaces, report=report)


def _curve_start(parameters: MeshingParameters):
    """Where the curver's progress starts in the run's: the rough weights on real images of
    meshing (1), meshing and decimating (2) and curving (0.5), over the stages run."""
    meshing = 2.0 if parameters.decimate else 1.0
    curving = 0.5 if parameters.curve else 0.0
    return meshing / (meshing + curving)


def _field(mesh, name, tuple_index=0):
    array = mesh.GetFieldData().GetArray(name)
    if array is None or tuple_index >= array.GetNumberOfTuples():
        return None
    return float(array.GetComponent(tuple_index, 0))


def quality_report(mesh, dims, placement: Placement, parameters: MeshingParameters) -> Dict:
    """What the filters measured, under the keys of `labelmesher mesh --report`'s JSON."""
    dimension = 2 if 1 in dims else 3
    materials = vtk_to_numpy(mesh.GetCellData().GetArray("Material"))
    names = mesh.GetFieldData().GetAbstractArray(MATERIAL_NAME)
    labels = mesh.GetFieldData().GetArray(MATERIAL_LABEL)
    name_of = {int(labels.GetValue(i)): names.GetValue(i) for i in range(labels.GetNumberOfTuples())}
    fd = mesh.GetFieldData()
    topology = []
    topo_materials = fd.GetArray("TopologyMaterial")
    for t in range(topo_materials.GetNumberOfTuples() if topo_materials else 0):
        topology.append({
            "material": int(topo_materials.GetComponent(t, 0)),
            "image_components": int(_field(mesh, "ImageComponents", t)),
            "image_euler_characteristic": int(_field(mesh, "ImageEulerCharacteristic", t)),
            "mesh_components": int(_field(mesh, "MeshComponents", t)),
            "mesh_euler_characteristic": int(_field(mesh, "MeshEulerCharacteristic", t)),
            "matches": bool(_field(mesh, "TopologyMatches", t)),
        })
    decimation = None
    if fd.GetArray("Merges") is not None:
        decimation = {key: _field(mesh, array) for key, array in (
            ("minimum_angle_bound_degrees", "AngleBound"), ("cells_before", "CellsBefore"),
            ("cells_after", "CellsAfter"), ("merges", "Merges"))}
        if fd.GetArray("Blocks") is not None:
            decimation["blocks"] = int(_field(mesh, "Blocks"))
    return {
        "image": {"dimensions": list(dims), "spacing": placement.spacing.tolist(),
                  "ijk_to_ras_rotation": placement.rotation.tolist(), "origin_ras": placement.origin.tolist()},
        "parameters": {"image_to_mesh": parameters.image_to_mesh_distance,
                       "mesh_to_image": parameters.mesh_to_image_distance,
                       "include_background": parameters.include_background,
                       "distance_unit": _field(mesh, "VoxelSize")},
        "mesh": {"dimension": dimension, "cell_type": "tetra" if dimension == 3 else "triangle",
                 "points": mesh.GetNumberOfPoints(), "cells": mesh.GetNumberOfCells(),
                 "cells_per_material": {str(int(m)): int(n) for m, n in zip(*np.unique(materials, return_counts=True))}},
        "material_table": [{"label": label, "name": name} for label, name in sorted(name_of.items())],
        "decimation": decimation,
        "quality": {"angle_kind": "dihedral" if dimension == 3 else "planar",
                    "angle_bound_degrees": (parameters.minimum_angle if parameters.decimate
                                            else labelmesher.vtkLabelOctreeMesher.GetProvenAngleBound(dimension)),
                    "minimum_angle_degrees": _field(mesh, "MinimumAngle"),
                    "maximum_angle_degrees": _field(mesh, "MaximumAngle"),
                    "inverted_cells": _field(mesh, "InvertedCells")},
        "fidelity": {"unit": "voxels of the smallest spacing",
                     "image_to_mesh": _field(mesh, "MeasuredImageToMeshDistance"),
                     "mesh_to_image": _field(mesh, "MeasuredMeshToImageDistance"),
                     "bounds_certified": _field(mesh, "HausdorffBoundsCertified") == 1.0},
        "topology": {"all_match": bool(topology) and all(t["matches"] for t in topology), "materials": topology},
    }


def curve_report(curved, parameters: MeshingParameters) -> Dict:
    """What the curver made and measured, under the keys of `labelmesher curve --report`'s
    "curved_mesh" and "validity" objects (distances in voxels of the smallest spacing)."""
    fd, cd = curved.GetFieldData(), curved.GetCellData()
    scaled = vtk_to_numpy(cd.GetArray("ScaledJacobian")) if cd.GetArray("ScaledJacobian") else np.zeros(0)
    valid = vtk_to_numpy(cd.GetArray("Valid")) if cd.GetArray("Valid") else np.zeros(0)
    crossings, topology = _field(curved, "InterfaceCrossings"), _field(curved, "TopologyMatches")
    resolution = _field(curved, "CurvedMeasureResolution") or 0.0
    image_to_mesh = _field(curved, "MeasuredImageToMeshDistance")
    mesh_to_image = _field(curved, "MeasuredMeshToImageDistance")
    within = (image_to_mesh is not None and image_to_mesh <= parameters.image_to_mesh_distance + resolution + 1e-9
              and mesh_to_image is not None and mesh_to_image <= parameters.mesh_to_image_distance + resolution + 1e-9
              and crossings == 0 and topology == 1.0)
    return {
        "cell_type": "bezier_triangle_degree_3",
        "cells": curved.GetNumberOfCells(), "control_points": curved.GetNumberOfPoints(),
        "smoothness": parameters.smoothness, "tension": parameters.tension,
        "curved_edges": int(_field(curved, "CurvedEdges") or 0),
        "valid": bool(valid.size == curved.GetNumberOfCells() and np.all(valid != 0)),
        "invalid_cells": int(_field(curved, "InvalidCells") or 0),
        "minimum_scaled_jacobian": float(scaled.min()) if scaled.size else None,
        "measure_resolution": resolution,
        "measured_image_to_mesh": image_to_mesh, "measured_mesh_to_image": mesh_to_image,
        "interface_crossings": None if crossings is None else int(crossings),
        "topology_matches": None if topology is None else topology == 1.0,
        "within_bounds": bool(within),
    }


def summary_text(report: Dict) -> str:
    """A few lines for the module's panel."""
    q, f, m = report["quality"], report["fidelity"], report["mesh"]
    lines = [f"{m['cells']} {'tetrahedra' if m['dimension'] == 3 else 'triangles'}, {m['points']} points",
             f"smallest {q['angle_kind']} angle {q['minimum_angle_degrees']:.2f} deg "
             f"(bound {q['angle_bound_degrees']:g}), inverted cells {int(q['inverted_cells'] or 0)}",
             f"distances (voxels): image to mesh {f['image_to_mesh']:.3f}, mesh to image {f['mesh_to_image']:.3f}, "
             f"bounds {'certified' if f['bounds_certified'] else 'NOT certified'}",
             f"topology of every material {'matches' if report['topology']['all_match'] else 'DOES NOT match'}"]
    c = report.get("curved_mesh")
    if c:
        lines += [f"curved: {c['cells']} cubic Bezier triangles (C{c['smoothness']}), {c['curved_edges']} curved edges, "
                  f"{'every cell proven valid' if c['valid'] else 'INVALID CELLS REMAIN'} "
                  f"(smallest scaled Jacobian {c['minimum_scaled_jacobian']:.3f})",
                  f"curves (voxels): image to mesh {c['measured_image_to_mesh']:.3f}, mesh to image "
                  f"{c['measured_mesh_to_image']:.3f}, crossings {c['interface_crossings']}, "
                  f"{'within the bounds with the topology kept' if c['within_bounds'] else 'A BOUND OR THE TOPOLOGY IS BROKEN'}"]
    return "\n".join(lines)
