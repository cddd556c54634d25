# SPDX-License-Identifier: GPL-2.0-or-later
"""pvbatch: the plugin's reader and writers as a ParaView user meets them. Opens the shared gzip
NRRD with Label Image Reader and compares it voxel for voxel with numpy's decoding (the
format ParaView's own NRRD reader misreads); opens a 3D Slicer segmentation and finds its names in
the field data; meshes it with Label Mesher and saves .msh, .inp and .mesh through File > Save
Data's writers (SaveData); reads each back with meshio (cells, materials and their names) and the
.msh with `gmsh -check`; a bad file is one error and an empty output.

usage: pvbatch --no-mpi pvbatch_io.py PLUGIN GZIP_NRRD WORKDIR
"""
import os
import shutil
import subprocess
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import LoadPlugin, SaveData
from paraview.vtk.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../../../Testing/Support"))
sys.path.insert(0, os.path.join(HERE, "../../../Testing/CLI"))
from export_checks import abaqus_name  # noqa: E402
from label_nrrd import read_label_nrrd  # noqa: E402
from segmentation_fixture import write_seg_nrrd  # noqa: E402

plugin, nrrd_path, workdir = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(workdir, exist_ok=True)
LoadPlugin(plugin, remote=False, ns=globals())

# ---- gzip NRRD, voxel for voxel ----
reader = LabelImageReader(FileName=nrrd_path)  # noqa: F821 (the plugin's proxy)
reader.UpdatePipeline()
image = servermanager.Fetch(reader)
want, spacing = read_label_nrrd(nrrd_path)
assert image.GetDimensions() == tuple(want.shape[::-1]), image.GetDimensions()
assert np.allclose(image.GetSpacing(), spacing), image.GetSpacing()
got = vtk_to_numpy(image.GetPointData().GetArray("Labels")).reshape(want.shape)
assert np.array_equal(got, want), "the reader's labels differ from the file's"
print(f"gzip NRRD: {got.size} voxels as numpy decodes them, labels {sorted(set(np.unique(got).tolist()))}")

# ---- a 3D Slicer segmentation, meshed and saved for three solvers ----
shape = (12, 14, 16)
z, y, x = np.mgrid[0:shape[0], 0:shape[1], 0:shape[2]]
layer = np.zeros(shape, dtype=np.uint8)
layer[(x - 5) ** 2 + (y - 6.5) ** 2 + (z - 5.5) ** 2 <= 12] = 1
layer[(x - 11) ** 2 + (y - 6.5) ** 2 + (z - 5.5) ** 2 <= 6] = 2
segmentation = os.path.join(workdir, "organs.seg.nrrd")
write_seg_nrrd(segmentation, [layer], [
    {"name": "Liver", "color": (0.86, 0.51, 0.40), "label": 1, "layer": 0},
    {"name": "left kidney", "color": (0.73, 0.30, 0.20), "label": 2, "layer": 0}])
names = {1: "Liver", 2: "left kidney"}
organs = LabelImageReader(FileName=segmentation)  # noqa: F821
organs.UpdatePipeline()
fd = servermanager.Fetch(organs).GetFieldData()
read_names = {int(fd.GetArray("MaterialLabel").GetValue(i)): fd.GetAbstractArray("MaterialName").GetValue(i)
              for i in range(fd.GetArray("MaterialLabel").GetNumberOfTuples())}
assert read_names == names, read_names

mesher = LabelMesher(Input=organs)  # noqa: F821
mesher.UpdatePipeline()
mesh = servermanager.Fetch(mesher)
materials = vtk_to_numpy(mesh.GetCellData().GetArray("Material")).astype(np.int64)
counts = {int(m): int(np.sum(materials == m)) for m in np.unique(materials)}
assert set(counts) == {1, 2}, counts

import meshio  # noqa: E402  (Debian's python3-meshio)
for extension in (".msh", ".inp", ".mesh"):
    path = os.path.join(workdir, "organs" + extension)
    if os.path.exists(path):
        os.remove(path)
    SaveData(path, proxy=mesher)
    assert os.path.exists(path), f"SaveData wrote no {path}"
    back = meshio.read(path)
    tets = [(i, c) for i, c in enumerate(back.cells) if c.type == "tetra"]
    assert sum(len(c.data) for _, c in tets) == mesh.GetNumberOfCells(), (extension, [len(c.data) for _, c in tets])
    if extension == ".msh":
        tags = np.concatenate([back.cell_data["gmsh:physical"][i] for i, _ in tets]).astype(np.int64)
        for label, name in names.items():
            assert name in back.field_data and int(back.field_data[name][0]) == label, (name, back.field_data)
        check = subprocess.run([shutil.which("gmsh") or "gmsh", path, "-check"], capture_output=True, text=True)
        assert check.returncode == 0 and "Error" not in check.stdout + check.stderr, check.stdout + check.stderr
    elif extension == ".inp":
        sets = {k.upper(): v for k, v in back.cell_sets.items()}
        tags = np.full(sum(len(c.data) for _, c in tets), -1, dtype=np.int64)
        for label, name in names.items():
            offset = 0
            for (i, c), ids in zip(enumerate(back.cells), sets[abaqus_name(name).upper()]):
                tags[offset + np.asarray(ids, dtype=np.int64)] = label
                offset += len(c.data)
    else:
        tags = np.concatenate([back.cell_data["medit:ref"][i] for i, _ in tets]).astype(np.int64)
    got_counts = {int(m): int(np.sum(tags == m)) for m in np.unique(tags)}
    assert got_counts == counts, (extension, got_counts, counts)
    print(f"{os.path.basename(path)}: {len(back.points)} points, cells per material {got_counts}, names kept")

# ---- a bad file: one error, empty output ----
bad = os.path.join(workdir, "bad.nrrd")
with open(bad, "w") as f:
    f.write("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 4 4\nencoding: raw\n\n" + "x" * 10)
broken = LabelImageReader(FileName=bad)  # noqa: F821
broken.UpdatePipeline()
assert servermanager.Fetch(broken).GetNumberOfPoints() == 0, "a truncated file gave an image"
print("OK")
