# SPDX-License-Identifier: GPL-2.0-or-later
"""pvbatch: load the LabelMesher plugin, mesh a real label image with
Label Octree Mesher, decimate it with Mesh Decimator (and curve a 2D one with
Bezier Curver), and assert the guarantees the filters record in their field
data: the angle bounds, both Hausdorff bounds certified, no inverted cell, the
topology of every material, a valid curved mesh.

usage: pvbatch --no-mpi pvbatch_guarantees.py PLUGIN IMAGE(.nrrd gzip/raw | .png)
"""
import os
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, PVTrivialProducer, PNGSeriesReader, UpdatePipeline
from paraview.vtk.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../Testing/Support"))
from label_nrrd import read_label_nrrd  # noqa: E402

plugin, image_path = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, remote=False, ns=globals())


def read_nrrd(path):
    """The shared volumes are gzip NRRD, which VTK's NRRD reader misreads: read
    them with the tests' numpy reader (Testing/Support/label_nrrd.py)."""
    labels, spacing = read_label_nrrd(path)
    image = vtkImageData()
    image.SetDimensions(*(list(labels.shape[::-1]) + [1] * (3 - labels.ndim)))
    image.SetSpacing(*spacing)
    scalars = numpy_to_vtk(labels.ravel(), deep=1)
    scalars.SetName("Labels")
    image.GetPointData().SetScalars(scalars)
    producer = PVTrivialProducer()
    producer.GetClientSideObject().SetOutput(image)
    return producer


def field(data, name):
    array = data.GetFieldData().GetArray(name)
    assert array is not None, f"no field array {name}"
    return [array.GetTuple1(i) for i in range(array.GetNumberOfTuples())]


def check_linear(proxy, bound, what):
    proxy.UpdatePipeline()
    data = servermanager.Fetch(proxy)
    cells = data.GetNumberOfCells()
    assert cells > 0, f"{what}: no cells"
    minimum = field(data, "MinimumAngle")[0]
    assert minimum >= bound - 1e-9, f"{what}: minimum angle {minimum} < {bound}"
    assert field(data, "InvertedCells")[0] == 0, f"{what}: inverted cells"
    assert field(data, "HausdorffBoundsCertified")[0] == 1, f"{what}: distance bounds not certified"
    for side in ("ImageToMesh", "MeshToImage"):
        measured, limit = field(data, "Measured" + side + "Distance")[0], field(data, side + "Distance")[0]
        assert measured <= limit + 1e-9, f"{what}: h {side} {measured} > {limit}"
    matches = field(data, "TopologyMatches")
    assert matches and all(m == 1 for m in matches), f"{what}: topology differs: {matches}"
    print(f"{what}: {cells} cells, minimum angle {minimum:.3f} >= {bound}, bounds certified, topology matches")
    return data


if image_path.endswith(".png"):
    image = PNGSeriesReader(FileNames=[image_path])
    dimension = 2
else:
    image = read_nrrd(image_path)
    dimension = 3
UpdatePipeline(proxy=image)

mesher = LabelOctreeMesher(Input=image)
mesher.IncludeBackground = 1
check_linear(mesher, 30.0 if dimension == 3 else 45.0, "Label Octree Mesher")
boundary = servermanager.Fetch(mesher, idx=1)
assert boundary.GetNumberOfCells() > 0 and boundary.GetCellData().GetArray("Materials"), "no interface surface on port 1"

decimator = MeshDecimator(Input=mesher, Image=image)
decimator.MinimumAngle = 15.0
decimated = check_linear(decimator, 15.0, "Mesh Decimator")
initial = servermanager.Fetch(mesher)
assert decimated.GetNumberOfCells() < initial.GetNumberOfCells(), "the decimator removed nothing"

# Mesher and decimator in one filter, in blocks small enough that the image crosses borders.
streamed = LabelMesher(Input=image)
streamed.MinimumAngle = 15.0
streamed.BlockCells = 5000
streamed_mesh = check_linear(streamed, 15.0, "Label Mesher (streamed)")
assert field(streamed_mesh, "Blocks")[0] > 1, "the image fit in one block: the test crosses no border"

if dimension == 2:
    curver = BezierCurver(Input=decimator, Image=image)
    curver.UpdatePipeline()
    curved = servermanager.Fetch(curver)
    assert field(curved, "InvalidCells")[0] == 0, "Bezier Curver left invalid cells"
    assert field(curved, "InterfaceCrossings")[0] == 0, "curved interfaces cross"
    print(f"Bezier Curver: {curved.GetNumberOfCells()} cells, all valid, no crossing")

    # Every stage in the one filter: the same curved mesh on port 2, the linear mesh on port 0.
    everything = LabelMesher(Input=image)
    everything.MinimumAngle = 15.0
    everything.BlockCells = 0  # one block: the mesher followed by the decimator, as above
    everything.Curve = 1
    everything.UpdatePipeline()
    linear = servermanager.Fetch(everything, idx=0)
    all_curved = servermanager.Fetch(everything, idx=2)
    assert linear.GetNumberOfCells() == decimated.GetNumberOfCells(), "port 0 is not the decimated mesh"
    assert all_curved.GetNumberOfCells() == curved.GetNumberOfCells(), "port 2 is not the curver's mesh"
    assert all_curved.GetCellType(0) == 76, "port 2 holds no Bezier triangles"  # VTK_BEZIER_TRIANGLE
    assert field(all_curved, "InvalidCells")[0] == 0, "Label Mesher's curves left invalid cells"
    print(f"Label Mesher (all stages): {all_curved.GetNumberOfCells()} curved cells on port 2")

    initial_only = LabelMesher(Input=image)
    initial_only.Decimate = 0
    initial_only.IncludeBackground = 1
    initial_only.UpdatePipeline()
    assert servermanager.Fetch(initial_only).GetNumberOfCells() == initial.GetNumberOfCells(), \
        "Decimate off is not the mesher's mesh"
else:
    # A 3D image: the quadratic tetrahedra of Order 2 on port 2, certified and measured.
    quadratic = LabelMesher(Input=image)
    quadratic.Order = 2
    quadratic.UpdatePipeline()
    tetra10 = servermanager.Fetch(quadratic, idx=2)
    assert tetra10.GetNumberOfCells() == servermanager.Fetch(quadratic, idx=0).GetNumberOfCells(), \
        "port 2 does not hold the decimated mesh's cells"
    assert tetra10.GetCellType(0) == 24, "port 2 holds no quadratic tetrahedra"  # VTK_QUADRATIC_TETRA
    bound = field(tetra10, "MinimumScaledJacobianBound")[0]
    assert field(tetra10, "CertifiedMinimumScaledJacobian")[0] >= bound, "a cell below the scaled Jacobian bound"
    assert field(tetra10, "SampledMinimumScaledJacobian")[0] >= bound, "sampled scaled Jacobian below the bound"
    slack = field(tetra10, "CurvedMeasureResolution")[0] + 1e-9
    assert field(tetra10, "MeasuredImageToMeshDistance")[0] <= field(tetra10, "ImageToMeshDistance")[0] + slack
    assert field(tetra10, "MeasuredMeshToImageDistance")[0] <= field(tetra10, "MeshToImageDistance")[0] + slack
    assert field(tetra10, "MisclassifiedVoxelsQuadratic")[0] < field(tetra10, "MisclassifiedVoxelsLinear")[0]
    print(f"Label Mesher, Order 2: {tetra10.GetNumberOfCells()} quadratic tetrahedra, scaled Jacobian >= {bound}")
print("OK")
