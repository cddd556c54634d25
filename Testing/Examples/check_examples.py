# SPDX-License-Identifier: GPL-2.0-or-later
"""Helpers of the example tests (Testing/Examples/CMakeLists.txt):

  check_examples.py image LABELS.vti        writes a two-material label image
  check_examples.py mesh MESH.vtu            asserts the example's mesh keeps the guarantees
                                             its field data records (angle >= 15, both
                                             distance bounds certified, topology per material)
  check_examples.py gmsh MESH.msh            asserts gmsh -check and meshio read the example's
                                             Gmsh file: tetrahedra of both materials, named
  check_examples.py picture PICTURE.png      asserts mesh_picture.py drew a mesh and a histogram
  check_examples.py readme README.md FILE... each file's README:begin..end block appears in
                                             the README as it is (the README cannot drift)
"""
import sys

import numpy as np


def write_image(path):
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
    n = 24
    z, y, x = np.mgrid[0:n, 0:n, 0:n]
    labels = np.zeros((n, n, n), np.uint8)
    labels[(x - 11.5) ** 2 + (y - 11.5) ** 2 + (z - 11.5) ** 2 <= 81] = 1
    labels[(x - 11.5) ** 2 + (y - 11.5) ** 2 + (z - 11.5) ** 2 <= 20] = 2
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(0.5, 0.5, 0.5)
    array = numpy_to_vtk(labels.ravel(), deep=1)
    array.SetName("Labels")
    image.GetPointData().SetScalars(array)
    writer = vtkXMLImageDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    assert writer.Write() == 1


def check_mesh(path):
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    mesh = reader.GetOutput()
    fd = mesh.GetFieldData()
    value = lambda name, i=0: fd.GetArray(name).GetTuple1(i)
    assert mesh.GetNumberOfCells() > 0, "empty mesh"
    assert value("CellsAfter") < value("CellsBefore"), "nothing was decimated"
    assert value("MinimumAngle") >= 15.0 - 1e-9, value("MinimumAngle")
    assert value("HausdorffBoundsCertified") == 1, "distance bounds not certified"
    matches = fd.GetArray("TopologyMatches")
    assert all(matches.GetTuple1(i) == 1 for i in range(matches.GetNumberOfTuples())), "topology differs"
    print("OK:", mesh.GetNumberOfCells(), "cells, minimum angle", value("MinimumAngle"))


def check_gmsh(path):
    import subprocess

    import meshio  # Debian's python3-meshio
    check = subprocess.run(["gmsh", path, "-check"], capture_output=True, text=True)
    assert check.returncode == 0 and "Error" not in check.stdout + check.stderr, check.stdout + check.stderr
    mesh = meshio.read(path)
    tags = np.concatenate([t for c, t in zip(mesh.cells, mesh.cell_data["gmsh:physical"]) if c.type == "tetra"])
    assert sorted(set(tags.tolist())) == [1, 2], sorted(set(tags.tolist()))
    assert {"label_1", "label_2"} <= set(mesh.field_data), mesh.field_data
    print("OK:", len(tags), "tetrahedra of materials 1 and 2, gmsh -check passes")


def check_picture(path):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    w, h, _ = reader.GetOutput().GetDimensions()
    rgb = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3].astype(int)
    ink = np.any(rgb < 235, axis=2)  # the background is white
    left, right = ink[:, : int(0.62 * w)].mean(), ink[:, int(0.62 * w):].mean()
    assert left > 0.05, f"the mesh view is (nearly) blank: {left:.1%} drawn"
    assert right > 0.02, f"the histogram is (nearly) blank: {right:.1%} drawn"
    # Coloured by material: the example's two materials show as two hues (shading changes
    # brightness, not hue), each on at least 5 % of the drawn pixels.
    drawn = rgb[:, : int(0.62 * w)][ink[:, : int(0.62 * w)]].astype(float)
    top, low = drawn.max(axis=1), drawn.min(axis=1)
    saturated = drawn[(top - low) > 40]
    r, g, b = saturated.T
    hue = (np.degrees(np.arctan2(np.sqrt(3) * (g - b), 2 * r - g - b)) + 360) % 360
    bins = np.bincount((hue // 30).astype(int), minlength=12) / max(len(drawn), 1)
    hues = int(np.count_nonzero(bins > 0.05))
    assert hues >= 2, f"the mesh view shows {hues} hue(s): not coloured by material"
    print(f"OK: {w}x{h}, mesh view {left:.1%} drawn in {hues} hues, histogram {right:.1%}")


def block(path):
    lines = open(path).read().splitlines()
    begin = next(i for i, l in enumerate(lines) if l.strip().endswith("README:begin"))
    end = next(i for i, l in enumerate(lines) if l.strip().endswith("README:end"))
    body = lines[begin + 1:end]
    indent = min(len(l) - len(l.lstrip()) for l in body if l.strip())
    return "\n".join(l[indent:] for l in body)


def check_readme(readme, files):
    text = open(readme).read()
    for path in files:
        assert block(path) in text, f"the README does not show {path}'s example as it is"
        print("OK: README shows", path)


if __name__ == "__main__":
    command = sys.argv[1]
    if command == "image":
        write_image(sys.argv[2])
    elif command == "mesh":
        check_mesh(sys.argv[2])
    elif command == "gmsh":
        check_gmsh(sys.argv[2])
    elif command == "picture":
        check_picture(sys.argv[2])
    else:
        check_readme(sys.argv[2], sys.argv[3:])
