# SPDX-License-Identifier: GPL-2.0-or-later
"""The README's shortest pipeline, run as a test (Testing/Examples): a label file read with the
checked reader, meshed and decimated by vtkLabelMesher and written for a solver by
vtkLabelMeshWriter (the format from the extension). The block between the README markers is what
the README shows (check_examples.py compares them).

usage: PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 mesh_to_gmsh.py LABELS MESH.msh
"""
import sys

# README:begin
import labelmesher

reader = labelmesher.vtkLabelImageReader()      # .nrrd (gzip too), .seg.nrrd, .nii(.gz), .mha, .vti, .png
reader.SetFileName(sys.argv[1])
mesher = labelmesher.vtkLabelMesher()            # every guarantee; defaults: h = 2 voxels, 15 degrees
mesher.SetInputConnection(reader.GetOutputPort())
writer = labelmesher.vtkLabelMeshWriter()        # .msh .inp .mesh .vtu .vtk .vtp .stl .obj
writer.SetInputConnection(mesher.GetOutputPort())
writer.SetFileName(sys.argv[2])
sys.exit(0 if writer.Write() == 1 else 1)        # 0 on any error, one line, no file left
# README:end
