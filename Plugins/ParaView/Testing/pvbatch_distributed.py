# SPDX-License-Identifier: GPL-2.0-or-later
"""pvbatch: Label Mesher on a label image read by the plugin's reader on every process, each
process's piece of its output fetched to rank 0 and appended there, and written as a .pvtu by
ParaView's parallel writer, summed up as JSON for pvbatch_mpi_test.py to compare between one
process and several.

usage: [mpirun -np N] pvbatch [--no-mpi] pvbatch_distributed.py PLUGIN IMAGE BLOCK_CELLS OUT.json
       mpirun -np N pvbatch --symmetric pvbatch_distributed.py PLUGIN IMAGE BLOCK_CELLS OUT.json OTHER
(every process runs the script; those but rank 0 read OTHER: another image, which the run must
refuse, or one that differs only beyond their slabs, which gives rank 0's image's mesh)
"""
import hashlib
import json
import os
import re
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, SaveData
from paraview.vtk.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkAppendFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

plugin, image_path, block_cells, out_path = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
rank = servermanager.vtkProcessModule.GetProcessModule().GetPartitionId()
if len(sys.argv) > 5 and rank != 0:
    image_path = sys.argv[5]
LoadPlugin(plugin, remote=False, ns=globals())

reader = LabelImageReader(FileName=image_path)  # noqa: F821 (the plugin's proxy)
reader.UpdatePipeline()
mesher = LabelMesher(Input=reader, BlockCells=block_cells)  # noqa: F821 (Distributed: on by default)
mesher.Labels = ["POINTS", "Labels"]
mesher.UpdatePipeline()
# Each process holds the cells of the parts it meshed, every piece with the run's fields: the
# pieces are fetched one by one and appended here (ParaView 5.11's Fetch without a process
# returned rank 0's piece alone here).
processes = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
pieces = [servermanager.Fetch(mesher, r) for r in range(processes)]
append = vtkAppendFilter()
for piece in pieces:
    append.AddInputData(piece)
append.Update()
mesh, first = append.GetOutput(), pieces[0]
piece_processes = [sorted(set(vtk_to_numpy(p.GetCellData().GetArray("Process")).tolist()))
                   if p.GetNumberOfCells() and p.GetCellData().GetArray("Process") else [] for p in pieces]
pvtu = None
if len(sys.argv) == 5 and mesh.GetNumberOfCells() > 0:
    # ParaView's parallel writer: one .vtu piece a process.
    SaveData(out_path + ".pvtu", proxy=mesher)
    if rank == 0:
        # The summary's pieces, each read alone: their cells, in order.
        with open(out_path + ".pvtu") as f:
            sources = re.findall(r'Source="([^"]+)"', f.read())
        piece_reader = vtkXMLUnstructuredGridReader()
        cells_of_pieces = []
        for source in sources:
            piece_reader.SetFileName(os.path.join(os.path.dirname(out_path), source))
            piece_reader.Update()
            cells_of_pieces.append(piece_reader.GetOutput().GetNumberOfCells())
        pvtu = {"piece_cells": cells_of_pieces}
# A filter that does not share its run out meshes the whole image once (for piece 0), not once a
# process.
initial = LabelOctreeMesher(Input=reader)  # noqa: F821
initial.Labels = ["POINTS", "Labels"]
initial.UpdatePipeline()
initial_cells = servermanager.Fetch(initial).GetNumberOfCells()


def field(name):
    array = first.GetFieldData().GetArray(name)
    return None if array is None else [array.GetTuple1(i) for i in range(array.GetNumberOfTuples())]


def summary():
    if mesh.GetNumberOfCells() == 0:
        return {"cells": 0, "initial_cells": initial_cells}
    points = vtk_to_numpy(mesh.GetPoints().GetData())
    materials = vtk_to_numpy(mesh.GetCellData().GetArray("Material"))
    connectivity = vtk_to_numpy(mesh.GetCells().GetConnectivityArray()).reshape(-1, 4)
    # The cells by their corners' positions: the same mesh however its points are numbered.
    cells = sorted((int(m), tuple(sorted(map(tuple, points[c].round(9).tolist()))))
                   for m, c in zip(materials, connectivity))
    process = mesh.GetCellData().GetArray("Process")
    return {
        "cells": len(cells),
        "initial_cells": initial_cells,
        "cells_sha256": hashlib.sha256(repr(cells).encode()).hexdigest(),
        "processes_field": field("Processes"),
        "piece_cells": [p.GetNumberOfCells() for p in pieces],
        "piece_processes": piece_processes,
        "pvtu": pvtu,
        "process_values": sorted(set(vtk_to_numpy(process).tolist())) if process is not None else None,
        "minimum_angle": field("MinimumAngle"),
        "angle_bound": field("AngleBound"),
        "inverted_cells": field("InvertedCells"),
        "bounds_certified": field("HausdorffBoundsCertified"),
        "topology_matches": field("TopologyMatches"),
    }


# --symmetric runs the script on every process: rank 0 alone writes, and every process goes on to
# the end, where ParaView's finalization waits for all.
if rank == 0:
    with open(out_path, "w") as f:
        json.dump(summary(), f)
