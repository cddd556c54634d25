#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""A picture of a LabelMesher mesh: the cells coloured by material with their
edges, a 3D mesh cut in half (whole cells kept, so the interior tetrahedra show)
and beside it the histogram of the cells' smallest angles (dihedral in 3D,
planar in 2D) with the bound marked.

usage: /usr/bin/python3 Resources/Scripts/mesh_picture.py MESH.vtu PICTURE.png
       [--no-cut] [--bound DEGREES] [--size W H]

Debian's VTK renders through GLX only: without a display the script runs
itself again under xvfb-run (package xvfb).
"""
import argparse
import os
import shutil
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401  (the charts' OpenGL backend)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkChartsCore import vtkAxis, vtkChart, vtkChartXY
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkLookupTable
from vtkmodules.vtkCommonCore import vtkVariant
from vtkmodules.vtkCommonDataModel import vtkPlane, vtkTable
from vtkmodules.vtkFiltersCore import vtkThreshold
from vtkmodules.vtkFiltersExtraction import vtkExtractGeometry
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkFiltersVerdict import vtkMeshQuality
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingContext2D import vtkContextActor, vtkContextScene
from vtkmodules.vtkRenderingCore import (vtkActor, vtkDataSetMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)

# Distinct material colours (Glasbey-like), repeated for many labels.
PALETTE = [(0.90, 0.30, 0.24), (0.20, 0.55, 0.85), (0.30, 0.70, 0.35), (0.95, 0.70, 0.20),
           (0.60, 0.40, 0.75), (0.40, 0.80, 0.80), (0.85, 0.45, 0.65), (0.55, 0.55, 0.30),
           (0.95, 0.55, 0.40), (0.35, 0.40, 0.60), (0.70, 0.85, 0.45), (0.75, 0.25, 0.40)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh")
    parser.add_argument("picture")
    parser.add_argument("--no-cut", action="store_true", help="show the whole 3D mesh, not its half")
    parser.add_argument("--bound", type=float, default=None, help="angle bound to mark, degrees")
    parser.add_argument("--size", type=int, nargs=2, default=(1200, 600))
    args = parser.parse_args()
    if not os.environ.get("DISPLAY") and not os.environ.get("LABELMESHER_PICTURE_XVFB"):
        if not shutil.which("xvfb-run"):
            sys.exit("mesh_picture: error: no display and no xvfb-run (apt-get install xvfb)")
        env = dict(os.environ, LABELMESHER_PICTURE_XVFB="1")
        sys.exit(subprocess.call(["xvfb-run", "-a", "-s", "-screen 0 1920x1080x24", sys.executable] + sys.argv, env=env))

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(args.mesh)
    reader.Update()
    mesh = reader.GetOutput()
    if mesh.GetNumberOfCells() == 0 or mesh.GetCellData().GetArray("Material") is None:
        sys.exit(f"mesh_picture: error: '{args.mesh}' has no cells with a Material array")
    three_d = mesh.GetCell(0).GetCellDimension() == 3

    # Foreground only (label 0 kept with --include-background would hide the rest).
    foreground = vtkThreshold()
    foreground.SetInputData(mesh)
    foreground.SetInputArrayToProcess(0, 0, 0, 1, "Material")  # cells
    foreground.SetLowerThreshold(0.5)
    foreground.SetUpperThreshold(float(2 ** 31))
    foreground.SetThresholdFunction(vtkThreshold.THRESHOLD_BETWEEN)
    foreground.Update()
    shown = foreground.GetOutput()
    if three_d and not args.no_cut:
        bounds = shown.GetBounds()
        plane = vtkPlane()
        plane.SetOrigin((bounds[0] + bounds[1]) / 2, 0, 0)
        plane.SetNormal(1, 0, 0)
        cut = vtkExtractGeometry()  # whole cells on one side: the interior tetrahedra show
        cut.SetInputData(shown)
        cut.SetImplicitFunction(plane)
        cut.ExtractInsideOn()
        cut.ExtractBoundaryCellsOn()
        cut.Update()
        shown = cut.GetOutput()

    labels = vtk_to_numpy(mesh.GetCellData().GetArray("Material"))
    materials = sorted(int(m) for m in np.unique(labels) if m != 0)
    lut = vtkLookupTable()
    lut.SetNumberOfTableValues(len(materials))
    lut.IndexedLookupOn()
    for i, m in enumerate(materials):
        lut.SetTableValue(i, *PALETTE[i % len(PALETTE)], 1.0)
        lut.SetAnnotation(vtkVariant(m), str(m))
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(shown)
    mapper = vtkDataSetMapper()
    mapper.SetInputConnection(surface.GetOutputPort())
    mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray("Material")
    mapper.SetLookupTable(lut)
    mapper.ScalarVisibilityOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().EdgeVisibilityOn()
    actor.GetProperty().SetEdgeColor(0.1, 0.1, 0.1)
    actor.GetProperty().SetLineWidth(0.6)
    view = vtkRenderer()
    view.SetViewport(0.0, 0.0, 0.62, 1.0)
    view.SetBackground(1, 1, 1)
    view.AddActor(actor)
    camera = view.GetActiveCamera()
    if three_d:
        camera.SetPosition(1, -0.6, 0.5)  # looking at the cut face
        camera.SetViewUp(0, 0, 1)
    view.ResetCamera()

    # Histogram of each cell's smallest angle.
    quality = vtkMeshQuality()
    quality.SetInputData(mesh)
    quality.SetTetQualityMeasureToMinAngle()
    quality.SetTriangleQualityMeasureToMinAngle()
    quality.Update()
    angles = vtk_to_numpy(quality.GetOutput().GetCellData().GetArray("Quality"))[labels != 0]
    top = 75.0 if three_d else 65.0
    counts, edges = np.histogram(angles, bins=int(top), range=(0.0, top))
    table = vtkTable()
    x, y = vtkFloatArray(), vtkFloatArray()
    x.SetName("smallest angle (degrees)")
    y.SetName("cells")
    for c, e in zip(counts, edges[:-1]):
        x.InsertNextValue(e + 0.5)
        y.InsertNextValue(float(c))
    table.AddColumn(x)
    table.AddColumn(y)
    chart = vtkChartXY()
    bars = chart.AddPlot(vtkChart.BAR)
    bars.SetInputData(table, 0, 1)
    bars.SetColor(70, 110, 170, 255)
    kind = "dihedral" if three_d else "planar"
    chart.SetTitle(f"{len(angles)} cells; smallest {kind} angle {angles.min():.2f} deg")
    chart.GetAxis(vtkAxis.BOTTOM).SetTitle(f"smallest {kind} angle of a cell (degrees)")
    chart.GetAxis(vtkAxis.LEFT).SetTitle("cells")
    chart.GetAxis(vtkAxis.BOTTOM).SetRange(0.0, top)
    chart.GetAxis(vtkAxis.BOTTOM).SetBehavior(vtkAxis.FIXED)
    if args.bound is not None:
        line_table = vtkTable()
        lx, ly = vtkFloatArray(), vtkFloatArray()
        lx.SetName("bound")
        ly.SetName("bound cells")
        for v in (0.0, float(counts.max())):
            lx.InsertNextValue(args.bound)
            ly.InsertNextValue(v)
        line_table.AddColumn(lx)
        line_table.AddColumn(ly)
        line = chart.AddPlot(vtkChart.LINE)
        line.SetInputData(line_table, 0, 1)
        line.SetColor(200, 40, 40, 255)
        line.SetWidth(2.0)
    scene = vtkContextScene()
    scene.AddItem(chart)
    context = vtkContextActor()
    context.SetScene(scene)
    plot = vtkRenderer()
    plot.SetViewport(0.62, 0.0, 1.0, 1.0)
    plot.SetBackground(1, 1, 1)
    plot.AddActor(context)
    scene.SetRenderer(plot)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*args.size)
    window.AddRenderer(view)
    window.AddRenderer(plot)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(args.picture)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    if writer.GetErrorCode() != 0 or not os.path.getsize(args.picture):
        sys.exit(f"mesh_picture: error: cannot write '{args.picture}'")
    print(f"wrote {args.picture}: {len(angles)} cells, {len(materials)} materials, smallest angle {angles.min():.2f} deg")


if __name__ == "__main__":
    main()
