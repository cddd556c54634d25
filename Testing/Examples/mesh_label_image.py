# SPDX-License-Identifier: GPL-2.0-or-later
"""The README's Python pipeline, run as a test (Testing/Examples): a label image
(.vti) through the wrapped vtkLabelMesher (mesher and decimator) into a .vtu. The block between
the README markers is what the README shows (check_examples.py compares them).

usage: PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 mesh_label_image.py LABELS.vti MESH.vtu
"""
import sys

from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

# README:begin
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
import labelmesher

reader = vtkXMLImageDataReader()
reader.SetFileName(sys.argv[1])
mesher = labelmesher.vtkLabelMesher()              # mesher and decimator, block by block
mesher.SetInputConnection(reader.GetOutputPort())
mesher.SetMeshToImageDistance(1.0)
mesher.Update()
mesh = mesher.GetOutput()                         # vtkUnstructuredGrid
field = mesh.GetFieldData()
print(field.GetArray("CellsBefore").GetValue(0), "->", field.GetArray("CellsAfter").GetValue(0))
print(field.GetArray("MinimumAngle").GetValue(0))  # measured, >= 15
# README:end

writer = vtkXMLUnstructuredGridWriter()
writer.SetInputData(mesh)
writer.SetFileName(sys.argv[2])
sys.exit(0 if writer.Write() == 1 else 1)
