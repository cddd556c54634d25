# SPDX-License-Identifier: GPL-2.0-or-later
"""Label Mesher in pvbatch under `mpirun -np 2` gives the same mesh as in one pvbatch process:
every process reads the image with the plugin's reader, each meshes its parts, rank 0 joins
them and hands each process the cells it meshed (cell array Process); the pieces fetched to
rank 0 hold the same cells (compared by their corners' positions), each piece its own process's
cells, every guarantee measured on the whole, and ParaView's parallel writer writes one .pvtu
piece a process; Label Octree
Mesher, which does not share its run out, meshes the image once, not once a process. A process given
another image than rank 0's makes the run refuse, in one error line naming it, with no mesh; so
does one whose reader fails. A process other than rank 0 reads only the slab of the image its
parts need.

usage: python3 pvbatch_mpi_test.py PVBATCH PLUGIN IMAGE BLOCK_CELLS WORKDIR
(PYTHONPATH: ParaView's Python packages, as for pvbatch.)
"""
import json
import os
import subprocess
import sys

import numpy as np

pvbatch, plugin, image, block_cells, workdir = sys.argv[1:6]
os.makedirs(workdir, exist_ok=True)
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "pvbatch_distributed.py")
# mpirun refuses root unless told (CI runs as root).
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(prefix, name, *other, image=image, block_cells=block_cells):
    out = os.path.join(workdir, name + ".json")
    if os.path.exists(out):
        os.remove(out)
    result = subprocess.run([*prefix, script, plugin, image, block_cells, out, *other],
                            capture_output=True, text=True, timeout=540, env=env)
    assert result.returncode == 0 and os.path.exists(out), (result.returncode, result.stdout, result.stderr)
    with open(out) as f:
        return json.load(f), result.stderr


one, _ = run([pvbatch, "--no-mpi"], "one")
two, _ = run(["mpirun", "-q", "-np", "2", pvbatch], "two")
print("one process:", one)
print("two processes:", two)
assert one["cells"] > 0, one
assert one["processes_field"] == [1.0] and one["process_values"] is None, one
assert two["processes_field"] == [2.0], f"the run was not shared out: {two}"
assert two["process_values"] == [0, 1], f"not both processes meshed cells: {two['process_values']}"
assert (two["cells"], two["cells_sha256"]) == (one["cells"], one["cells_sha256"]), \
    "two processes gave another mesh than one"
# Each process holds the cells it meshed (a parallel pipeline asks each for its piece), and
# ParaView's parallel writer writes one piece a process.
assert two["piece_processes"] == [[0], [1]] and min(two["piece_cells"]) > 0, \
    f"each process does not hold its own piece: {two['piece_processes']}, {two['piece_cells']} cells"
assert two["pvtu"] == {"piece_cells": two["piece_cells"]} and one["pvtu"] == {"piece_cells": [one["cells"]]}, \
    (one["pvtu"], two["pvtu"])
assert two["initial_cells"] == one["initial_cells"] > 0, \
    f"Label Octree Mesher on two processes: {two['initial_cells']} cells, on one {one['initial_cells']}"
for summary in (one, two):
    assert summary["minimum_angle"][0] >= summary["angle_bound"][0] - 1e-9, summary
    assert summary["inverted_cells"] == [0.0] and summary["bounds_certified"] == [1.0], summary
    assert summary["topology_matches"] and all(m == 1 for m in summary["topology_matches"]), summary
print(f"OK: pvbatch under mpirun -np 2: the same {one['cells']} cells as one process, every guarantee holds")

# Rank 1 reads another image (the same labels with a voxel changed in every slice, as raw NRRD):
# refused, the difference found by the hash of the slab it reads (any slab shows it).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../Testing/Support"))
from label_nrrd import read_label_nrrd, three_labels, write_float_image  # noqa: E402

labels, spacing = read_label_nrrd(image)
labels = labels.copy()
labels[:, 0, 0] = [1 if v != 1 else 2 for v in labels[:, 0, 0]]
other = os.path.join(workdir, "other.nrrd")
with open(other, "wb") as f:
    f.write(("NRRD0004\ntype: {}\ndimension: 3\nsizes: {} {} {}\nspacings: {} {} {}\nencoding: raw\n\n".format(
        {1: "uint8", 2: "uint16", 4: "uint32"}[labels.dtype.itemsize], *labels.shape[::-1], *spacing)).encode())
    f.write(labels.astype(labels.dtype.newbyteorder("<")).tobytes())
refused, stderr = run(["mpirun", "-q", "-np", "2", pvbatch, "--symmetric"], "refused", other)
assert refused["cells"] == 0, refused
errors = [line for line in stderr.splitlines() if "ERR|" in line]
assert errors and all("process 1 of 2: it was given another image" in line for line in errors), stderr
print("OK: a process given another image is named, no mesh:", errors[0].split("): ", 1)[-1])

# Rank 1's reader fails (its file is missing): its image is empty, and it is named for that, not
# for another image.
missing, stderr = run(["mpirun", "-q", "-np", "2", pvbatch, "--symmetric"], "missing",
                      os.path.join(workdir, "missing.nrrd"))
assert missing["cells"] == 0, missing
errors = [line for line in stderr.splitlines() if "vtkLabelMesher" in line and "ERR|" in line]
assert errors and all("process 1 of 2: its input image is empty" in line for line in errors), stderr
assert "missing.nrrd': no such file" in stderr, stderr
print("OK: a process whose reader failed is named for its empty image, no mesh")

# Rank 1 reads only the slab its parts need (through ParaView's post filter): its file holds a
# non-integer label in the first slice of a tall image, beyond its slab, and the mesh is the one
# process's mesh of the right image.
tall = np.concatenate([three_labels(), three_labels()], axis=0).astype(np.float32)
good = write_float_image(os.path.join(workdir, "tall.nrrd"), tall)
tall[0, 5, 5] = 0.5
beyond = write_float_image(os.path.join(workdir, "tall_bottom.nrrd"), tall)
alone, _ = run([pvbatch, "--no-mpi"], "tall_one", image=good, block_cells="2000")
slabs, stderr = run(["mpirun", "-q", "-np", "2", pvbatch, "--symmetric"], "tall_two", beyond, image=good,
                    block_cells="2000")
assert alone["cells"] > 0 and (slabs["cells"], slabs["cells_sha256"]) == (alone["cells"], alone["cells_sha256"]), \
    (alone, slabs, stderr)
assert slabs["process_values"] == [0, 1], slabs
print(f"OK: process 1 read only its slab: the same {alone['cells']} cells, its file's bad slice never read")
