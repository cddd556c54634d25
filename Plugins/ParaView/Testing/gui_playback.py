# SPDX-License-Identifier: GPL-2.0-or-later
"""ParaView's GUI under xvfb-run: load the LabelMesher plugin, open a label
image, apply Label Octree Mesher from its menu, colour by Material (the events
of TestMesherGUI.xml), and check the picture ParaView saves: the playback
succeeded, and the view shows the mesh in several material colours, not a
blank background.

usage: python3 gui_playback.py PARAVIEW PLUGIN_DIR PARAVIEW_PYTHONPATH EVENTS.xml WORKDIR
(system Python with Debian's VTK: it writes the input image and reads the picture)
"""
import os
import shutil
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter

paraview, plugin_dir, pythonpath, events, work = sys.argv[1:6]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)

# Three materials: a disk with a core, and a second disk beside it.
ny, nx = 48, 64
y, x = np.mgrid[0:ny, 0:nx]
labels = np.zeros((ny, nx), np.uint8)
labels[(x - 20) ** 2 + (y - 24) ** 2 <= 14 ** 2] = 1
labels[(x - 44) ** 2 + (y - 24) ** 2 <= 12 ** 2] = 2
labels[(x - 20) ** 2 + (y - 24) ** 2 <= 6 ** 2] = 3
image = vtkImageData()
image.SetDimensions(nx, ny, 1)
array = numpy_to_vtk(labels.ravel(), deep=1)
array.SetName("Labels")
image.GetPointData().SetScalars(array)
writer = vtkXMLImageDataWriter()
writer.SetFileName(os.path.join(work, "disks.vti"))
writer.SetInputData(image)
assert writer.Write() == 1

# No baseline on purpose: ParaView then saves its view as the missing baseline's
# name (and reports it missing); the picture is judged here, independent of the renderer.
picture = os.path.join(work, "view.png")
env = dict(os.environ, PV_PLUGIN_PATH=plugin_dir, PYTHONPATH=pythonpath)
run = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", paraview, "--dr",
                      "--plugins=LabelMesher", "--data=" + os.path.join(work, "disks.vti"),
                      "--test-script=" + events, "--test-directory=" + work,
                      "--test-baseline=" + picture, "--exit"],
                     capture_output=True, text=True, timeout=300, env=env)
log = run.stdout + run.stderr
print(log[-3000:])
assert "is finished. Success =  true" in log, "the GUI playback failed"
assert os.path.exists(picture), "ParaView saved no picture of the view"

reader = vtkPNGReader()
reader.SetFileName(picture)
reader.Update()
dims = reader.GetOutput().GetDimensions()
pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).reshape(dims[1], dims[0], -1)[:, :, :3].astype(int)
background = np.median(pixels.reshape(-1, 3), axis=0)
drawn = np.any(np.abs(pixels - background) > 30, axis=2)
assert drawn.mean() > 0.1, f"only {drawn.mean():.1%} of the view differs from the background"
# The three materials in the default colour map: blue (1), grey-white (2), red (3).
r, g, b = pixels[:, :, 0], pixels[:, :, 1], pixels[:, :, 2]
blue = np.mean((b > r + 60) & (b > g + 40))
red = np.mean((r > b + 60) & (r > g + 60))
grey = np.mean((abs(r - g) < 20) & (abs(g - b) < 20) & (r > 150))
assert min(blue, red, grey) > 0.01, f"material colours missing: blue {blue:.3f}, red {red:.3f}, grey {grey:.3f}"
print(f"OK: view {dims[0]}x{dims[1]}, {drawn.mean():.1%} drawn; blue {blue:.1%}, red {red:.1%}, grey {grey:.1%}")
