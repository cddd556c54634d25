# SPDX-License-Identifier: GPL-2.0-or-later
"""Independent checks of labelmesher's mesh files: each written format is read
back by Debian's meshio (and the .msh by gmsh -check, the .vtp by VTK) and
compared with the .vtu of the same run, itself read by meshio: the same points
(to the last bit where the format is text; float32 for STL), the same cells
with the same material, every material's name where the format carries names,
and the interface faces once each with their pair of materials.

check_exports(vtu, outputs, names) returns a list of failures (empty: all good).
"""
import os
import re
import shutil
import subprocess

import numpy as np


def _meshio():
    import meshio  # Debian's python3-meshio (module version 5.0)
    return meshio


def tetra10_jacobians(nodes, steps=4):
    """det J of quadratic tetrahedra (nodes: array (cells, 10, 3), VTK's order: corners, then the
    mid-nodes of edges 0-1, 1-2, 2-0, 0-3, 1-3, 2-3) on the barycentric lattice of step 1/steps,
    from the Lagrange shape functions: an evaluation independent of the C++ certificate.
    Returns an array (cells, samples)."""
    edges = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
    dets = []
    for i in range(steps + 1):
        for j in range(steps + 1 - i):
            for k in range(steps + 1 - i - j):
                l = np.array([steps - i - j - k, i, j, k], dtype=float) / steps
                dl = [nodes[:, c] * (4 * l[c] - 1) for c in range(4)]
                for e, (a, b) in enumerate(edges):
                    dl[a] = dl[a] + nodes[:, 4 + e] * 4 * l[b]
                    dl[b] = dl[b] + nodes[:, 4 + e] * 4 * l[a]
                J = np.stack([dl[1] - dl[0], dl[2] - dl[0], dl[3] - dl[0]], axis=-1)
                dets.append(np.linalg.det(J))
    return np.stack(dets, axis=-1)


def decode_strings(byte_array):
    """The strings of a field array the writers stored as NUL-ended UTF-8 bytes."""
    raw = bytes(np.asarray(byte_array, dtype=np.uint8))
    return [s.decode("utf-8") for s in raw.split(b"\0")[:-1]]


def abaqus_name(name):
    """The ELSET spelling of AbaqusWriter (letters, digits, _; starts with a letter; 80 chars)."""
    s = "".join(c if c.isascii() and c.isalnum() else "_" for c in name)
    if not s or not s[0].isalpha():
        s = "M_" + s
    return s[:80]


def _rows(cells):
    """Cells as sorted node tuples, for comparing connectivity as sets."""
    return np.sort(np.asarray(cells, dtype=np.int64), axis=1)


def _same_cells(failures, what, got_cells, got_labels, want_cells, want_labels):
    if len(got_cells) != len(want_cells):
        failures.append("%s: %d cells, the .vtu has %d" % (what, len(got_cells), len(want_cells)))
        return
    a = np.column_stack([_rows(got_cells), np.asarray(got_labels, dtype=np.int64)])
    b = np.column_stack([_rows(want_cells), np.asarray(want_labels, dtype=np.int64)])
    a = a[np.lexsort(a.T[::-1])]
    b = b[np.lexsort(b.T[::-1])]
    if not np.array_equal(a, b):
        failures.append("%s: cells or their materials differ from the .vtu" % what)


def _counts(labels):
    values, counts = np.unique(np.asarray(labels), return_counts=True)
    return {int(v): int(c) for v, c in zip(values, counts)}


def _interface_faces(vtp):
    """(faces as point coordinates, pairs) from the .vtp, through VTK."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(vtp)
    reader.Update()
    surface = reader.GetOutput()
    points = vtk_to_numpy(surface.GetPoints().GetData())
    pairs = np.sort(vtk_to_numpy(surface.GetCellData().GetArray("Materials")), axis=1)
    polys = surface.GetPolys() if surface.GetNumberOfPolys() else surface.GetLines()
    conn = vtk_to_numpy(polys.GetConnectivityArray()).reshape(surface.GetNumberOfCells(), -1)
    return points[conn], pairs


def check_exports(vtu, outputs, names, dimension):
    """`outputs`: {".msh": path, ...} (any subset; ".msh22" for an MSH 2.2 file);
    `names`: {label: expected name}; `dimension`: 2 or 3."""
    meshio = _meshio()
    failures = []
    ref = meshio.read(vtu)
    cell_type = "tetra" if dimension == 3 else "triangle"
    face_type = "triangle" if dimension == 3 else "line"
    ref_cells = np.concatenate([c.data for c in ref.cells if c.type == cell_type])
    ref_labels = np.concatenate([d for c, d in zip(ref.cells, ref.cell_data["Material"]) if c.type == cell_type]).astype(np.int64)
    materials = sorted(set(ref_labels.tolist()))
    largest = max(materials)

    # The .vtu's own material table (strings stored as bytes for meshio).
    table = dict(zip(ref.field_data["MaterialLabel"].tolist(), decode_strings(ref.field_data["MaterialName"])))
    for label in materials:
        want = names.get(label, "label_%d" % label)
        if table.get(label) != want:
            failures.append(".vtu: material %d is named %r, expected %r" % (label, table.get(label), want))
    # A 2D mesh in an axis plane: planar formats keep the two other axes.
    flat = [a for a in range(3) if dimension == 2 and np.all(ref.points[:, a] == ref.points[0, a])]
    planar_axes = [a for a in range(3) if not flat or a != flat[-1]]

    faces = pairs = None
    if ".vtp" in outputs:
        faces, pairs = _interface_faces(outputs[".vtp"])

    for key, path in outputs.items():
        what = os.path.basename(path)
        if key == ".vtp":
            continue
        mesh = meshio.read(path)
        points = mesh.points
        if key in (".msh", ".msh22", ".obj"):
            if not np.array_equal(points, ref.points):
                failures.append("%s: points differ from the .vtu's" % what)
        elif key in (".inp", ".mesh"):
            want = ref.points[:, planar_axes] if points.shape[1] == len(planar_axes) else ref.points
            if not np.array_equal(points, want):
                failures.append("%s: points differ from the .vtu's" % what)
        blocks = [(i, c) for i, c in enumerate(mesh.cells) if c.type == cell_type]
        volume = [c.data for _, c in blocks]
        if key in (".msh", ".msh22"):
            physical = [mesh.cell_data["gmsh:physical"][i] for i, _ in blocks]
            labels = np.concatenate(physical).astype(np.int64)
            labels[labels == largest + 1] = 0  # the background's tag
            _same_cells(failures, what, np.concatenate(volume), labels, ref_cells, ref_labels)
            for label in materials:
                name = names.get(label, "label_%d" % label)
                tag = label if label > 0 else largest + 1
                entry = mesh.field_data.get(name)
                if entry is None or int(entry[0]) != tag or int(entry[1]) != dimension:
                    failures.append("%s: no physical group %r with tag %d, dimension %d (got %s)" % (what, name, tag, dimension, entry))
            if shutil.which("gmsh"):
                check = subprocess.run(["gmsh", path, "-check"], capture_output=True, text=True)
                if check.returncode != 0 or "Error" in check.stdout + check.stderr:
                    failures.append("%s: gmsh -check failed: %s" % (what, (check.stdout + check.stderr)[-500:]))
            else:
                failures.append("gmsh is not installed (python3-meshio and gmsh are test dependencies)")
        elif key == ".inp":
            cells = np.concatenate(volume)
            labels = np.full(len(cells), -1, dtype=np.int64)
            for label in materials:
                name = abaqus_name(names.get(label, "label_%d" % label))
                sets = {k.upper(): v for k, v in mesh.cell_sets.items()}
                if name.upper() not in sets:
                    failures.append("%s: no ELSET %s" % (what, name))
                    continue
                offset = 0
                for (i, c), ids in zip(enumerate(mesh.cells), sets[name.upper()]):
                    labels[offset + np.asarray(ids, dtype=np.int64)] = label
                    offset += len(c.data)
            _same_cells(failures, what, cells, labels, ref_cells, ref_labels)
        elif key == ".mesh":
            refs = np.concatenate([mesh.cell_data["medit:ref"][i] for i, _ in blocks]).astype(np.int64)
            _same_cells(failures, what, np.concatenate(volume), refs, ref_cells, ref_labels)
        if key in (".mesh", ".msh", ".msh22", ".obj", ".stl") and faces is not None:
            got = [c.data for c in mesh.cells if c.type == face_type]
            n = sum(len(g) for g in got)
            if key == ".obj" and face_type == "line":
                with open(path) as f:  # meshio's OBJ reader skips `l` elements
                    n = sum(1 for line in f if line.startswith("l "))
            if n != len(faces):
                failures.append("%s: %d interface faces, the .vtp has %d" % (what, n, len(faces)))
            elif key == ".mesh":
                # Reference a * (L + 1) + b of the pair a < b.
                coded = np.concatenate([mesh.cell_data["medit:ref"][i] for i, c in enumerate(mesh.cells) if c.type == face_type])
                decoded = np.column_stack([coded // (largest + 1), coded % (largest + 1)])
                if _counts(decoded[:, 0] * (largest + 1) + decoded[:, 1]) != _counts(pairs[:, 0] * (largest + 1) + pairs[:, 1]):
                    failures.append("%s: interface references do not match the .vtp's pairs" % what)
            elif key == ".stl":
                want = np.sort(faces.reshape(-1, 3).astype(np.float32), axis=0)
                have = np.sort(mesh.points[np.concatenate(got)].reshape(-1, 3).astype(np.float32), axis=0)
                if not np.array_equal(want, have):
                    failures.append("%s: facet corners differ from the .vtp's" % what)
        if key in (".msh", ".msh22", ".inp", ".mesh"):
            counts = _counts(ref_labels)
            print("%s: %d points, %s" % (what, len(points), ", ".join(
                "%s %d" % (names.get(l, "label_%d" % l), counts[l]) for l in materials)))
    return failures
