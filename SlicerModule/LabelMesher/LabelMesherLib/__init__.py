# SPDX-License-Identifier: GPL-2.0-or-later
"""The LabelMesher module's Slicer-free logic (tested with Debian's Python)."""
from .meshing import (Material, MeshingCancelled, MeshingError, MeshingParameters, MeshingResult,  # noqa: F401
                      mesh_labels, placement_from_ijk_to_ras)
