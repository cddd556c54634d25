# SPDX-License-Identifier: GPL-2.0-or-later
"""Imports `labelmesher` and LabelMesherLib from an extension's qt-scripted-modules folder (given,
and on PYTHONPATH as it is on Slicer's sys.path) and meshes a two-label image through meshing.py.
Exits non-zero with one line if anything comes from elsewhere or the mesh is not right."""
import os
import sys

import numpy as np

folder = os.path.realpath(sys.argv[1])


def fail(message):
    sys.exit(f"mesh_from_extension: {message}")


import labelmesher  # noqa: E402

if getattr(labelmesher, "__file__", None) is None:
    fail(f"labelmesher is a namespace package without __init__.py ({list(labelmesher.__path__)})")
if not os.path.realpath(labelmesher.__file__).startswith(folder + os.sep):
    fail(f"labelmesher came from {labelmesher.__file__}, not {folder}")
for name in ("vtkLabelMesher", "vtkLabelMeshReport", "vtkLabelOctreeMesher", "vtkMeshDecimator", "vtkBezierCurver"):
    if not hasattr(labelmesher, name):
        fail(f"labelmesher has no {name}")

from LabelMesherLib import MeshingParameters, mesh_labels  # noqa: E402
import LabelMesherLib  # noqa: E402

if not os.path.realpath(LabelMesherLib.__file__).startswith(folder + os.sep):
    fail(f"LabelMesherLib came from {LabelMesherLib.__file__}, not {folder}")

labels = np.zeros((14, 16, 18), dtype=np.uint8)
labels[2:12, 3:13, 4:14] = 1
labels[5:9, 6:10, 7:11] = 2
result = mesh_labels(labels, np.diag([0.5, 0.6, 0.7, 1.0]), parameters=MeshingParameters(minimum_angle=15.0))
report = result.report
present = sorted(int(m) for m in report["mesh"]["cells_per_material"])
if result.mesh.GetNumberOfCells() == 0 or present != [1, 2]:
    fail(f"the mesh has {result.mesh.GetNumberOfCells()} cells, materials {present}")
if report["quality"]["minimum_angle_degrees"] < 15.0 or not report["fidelity"]["bounds_certified"] \
        or not report["topology"]["all_match"]:
    fail(f"a guarantee is not met: {report['quality']}, {report['fidelity']}, {report['topology']}")
print(f"mesh_from_extension: {result.mesh.GetNumberOfCells()} cells from {folder}")
