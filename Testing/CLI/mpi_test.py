# SPDX-License-Identifier: GPL-2.0-or-later
"""labelmesher under mpirun, one case per ctest test:

    python3 mpi_test.py <path/to/labelmesher> <work dir> <case>

same_mesh: `mpirun -np 2` and `-np 3` (oversubscribed on two cores) write the
same mesh file, byte for byte, as one process, and rank 0's report (measured on
the whole mesh) holds every guarantee; their .pvtu has one piece per process
(each piece the cells of its "Process"), together the one-process .vtu's cells. failing_process: a process that cannot
go on (its input unreadable, its memory limit too small, another image or other
parameters than rank 0's) ends the run with one line from rank 0 naming it,
exit status 1, and no file written; --no-decimate is refused the same way."""

import json
import os
import re
import subprocess
import sys

import numpy as np
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from label_nrrd import three_labels, write_float_image  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader, vtkXMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy

EXE, WORK, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
# -q: without it, mpirun adds its own banner when a process exits non-zero.
MPIRUN = ["mpirun", "-q", "--oversubscribe"]
# mpirun refuses root unless told (CI runs as root); nothing else in its environment changes.
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_mca_base_component_show_load_errors="0")


def path(name):
    return os.path.join(WORK, CASE + "_" + name)


def write_nrrd(name, labels):
    filename = path(name)
    header = ("NRRD0004\ntype: uchar\ndimension: 3\nsizes: {} {} {}\nspacings: 1 1 1\n"
              "encoding: raw\n\n").format(*labels.shape[::-1])
    with open(filename, "wb") as f:
        f.write(header.encode() + labels.astype(np.uint8).tobytes())
    return filename


def run(command):
    return subprocess.run(command, capture_output=True, text=True, timeout=540, env=ENV)


def mesh_args(image, out, *extra, block_cells="2000"):
    # Blocks of 2,000 initial cells: about 20 blocks of the generated image, 10 parts of 2.
    return ["mesh", image, "-o", out, "--block-cells", block_cells, *extra]


# A real label image (the shared data's rat head, ../shared/data/README.md), when it is there.
RAT_HEAD = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "shared", "data", "3d",
                        "iso2mesh_rat_head.nrrd")


def case_same_mesh():
    same_mesh(write_nrrd("three.nrrd", three_labels()), "three", {1, 2, 3}, "2000")
    if os.path.exists(RAT_HEAD):
        same_mesh(RAT_HEAD, "rat", {1}, "20000")  # 10 blocks
    else:
        print("SKIP: the rat head (shared data) is not here")


def read_grid(reader_type, filename):
    reader = reader_type()
    reader.SetFileName(filename)
    reader.Update()
    return reader.GetOutput()


def cells_by_position(grid):
    """The cells as a sorted list of (material, their corners' coordinates sorted): the same for
    the same mesh however its points are numbered or its cells split into pieces."""
    points = vtk_to_numpy(grid.GetPoints().GetData())
    materials = vtk_to_numpy(grid.GetCellData().GetArray("Material"))
    connectivity = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
    return sorted((int(m), tuple(sorted(map(tuple, points[c].round(9).tolist()))))
                  for m, c in zip(materials, connectivity))


def check_pieces(summary, ranks, reference_cells):
    """One piece per process, each the cells of its "Process" value, together the reference."""
    with open(summary) as f:
        sources = [line.split('Source="')[1].split('"')[0] for line in f if 'Source="' in line]
    assert len(sources) == ranks, sources
    for rank, source in enumerate(sources):
        piece = read_grid(vtkXMLUnstructuredGridReader, os.path.join(os.path.dirname(summary), source))
        assert piece.GetNumberOfCells() > 0, f"process {rank}'s piece is empty"
        process = vtk_to_numpy(piece.GetCellData().GetArray("Process"))
        assert (process == rank).all(), f"piece {rank} holds cells of processes {set(process.tolist())}"
    whole = read_grid(vtkXMLPUnstructuredGridReader, summary)
    assert cells_by_position(whole) == reference_cells, "the pieces are not the one-process mesh"


def same_mesh(image, name, labels, block_cells):
    one, one_vtu = path(name + "_one.msh"), path(name + "_one.vtu")
    result = run([EXE, *mesh_args(image, one, "-o", one_vtu, "--no-measure", "-q", block_cells=block_cells)])
    assert result.returncode == 0, result.stderr
    reference = open(one, "rb").read()
    reference_cells = cells_by_position(read_grid(vtkXMLUnstructuredGridReader, one_vtu))
    for ranks in (2, 3):
        out, report_file = path(f"{name}_np{ranks}.msh"), path(f"{name}_np{ranks}.json")
        summary = path(f"{name}_np{ranks}.pvtu")
        for stale in (out, report_file, summary):
            if os.path.exists(stale):
                os.remove(stale)
        result = run([*MPIRUN, "-np", str(ranks), EXE,
                      *mesh_args(image, out, "-o", summary, "--report", report_file, block_cells=block_cells)])
        assert result.returncode == 0, result.stderr
        assert result.stderr.strip() == "", result.stderr
        assert open(out, "rb").read() == reference, f"{ranks} processes wrote another mesh than one"
        check_pieces(summary, ranks, reference_cells)
        with open(report_file) as f:
            report = json.load(f)
        blocks = report["decimation"]["blocks"]
        assert blocks >= 6 and report["decimation"]["parts"] >= 3, report["decimation"]
        assert report["decimation"]["processes"] == ranks, report["decimation"]
        quality, fidelity = report["quality"], report["fidelity"]
        assert quality["minimum_angle_degrees"] >= report["decimation"]["minimum_angle_bound_degrees"] - 1e-9, quality
        assert quality["inverted_cells"] == 0, quality
        assert fidelity["bounds_certified"] is True, fidelity
        materials = report["topology"]["materials"]
        assert {m["material"] for m in materials} >= labels, materials
        assert report["topology"]["all_match"] is True and all(m["matches"] for m in materials), materials
        stages = [t["stage"] for t in report["timings"]]
        assert "waiting for other processes" in stages, stages
        print(f"OK: {name}, {ranks} processes, {blocks} blocks, the same {len(reference)} bytes as one process")


def expect_one_line_failure(result, fragment, out):
    assert result.returncode != 0, "the run did not fail"
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("labelmesher: error: "), result.stderr
    assert fragment in lines[0], lines[0]
    assert not os.path.exists(out), "a failed run wrote its output"
    print("OK:", lines[0])


def case_failing_process():
    image = write_nrrd("three.nrrd", three_labels())
    out = path("mesh.msh")
    if os.path.exists(out):
        os.remove(out)
    # Rank 1 cannot read its input: no file at all, the .pvtu's pieces neither (a failure
    # before meshing; a .pvtu that fails while written is TestvtkLabelMeshWriter's).
    summary = path("mesh.pvtu")
    result = run([*MPIRUN, "-np", "1", EXE, *mesh_args(image, out, "-o", summary), ":",
                  "-np", "1", EXE, *mesh_args(path("missing.nrrd"), out, "-o", summary)])
    expect_one_line_failure(result, "process 1 of 2: ", out)
    left = [f for f in os.listdir(WORK) if f.startswith(CASE + "_mesh")]
    assert not left, left
    assert "missing.nrrd" in result.stderr, result.stderr
    # Rank 2 is refused by its own memory limit.
    result = run([*MPIRUN, "-np", "2", EXE, *mesh_args(image, out), ":",
                  "-np", "1", EXE, *mesh_args(image, out, "--max-memory", "1M")])
    expect_one_line_failure(result, "process 2 of 3: ", out)
    assert "memory limit of 1 MiB" in result.stderr, result.stderr
    # Rank 1 is given another angle bound: the processes would join parts of different meshes.
    result = run([*MPIRUN, "-np", "1", EXE, *mesh_args(image, out), ":",
                  "-np", "1", EXE, *mesh_args(image, out, "--min-angle", "10")])
    expect_one_line_failure(result, "process 1 of 2: it was given another image or other meshing parameters", out)
    # Rank 1 is given another image of the same size. It reads only its slab, whose labels are
    # compared with rank 0's: a voxel differs in every slice, so that any slab shows it.
    other = three_labels()
    other[:, 0, 0] = 3
    other_image = write_nrrd("other.nrrd", other)
    result = run([*MPIRUN, "-np", "1", EXE, *mesh_args(image, out), ":",
                  "-np", "1", EXE, *mesh_args(other_image, out)])
    expect_one_line_failure(result, "process 1 of 2: it was given another image", out)
    # Processes other than the first leave usage errors and --version to it, whichever
    # launcher's variables name their rank (Open MPI's, or MPICH's and Intel MPI's PMI_RANK).
    for variable in ("OMPI_COMM_WORLD_RANK", "PMI_RANK"):
        for rank, speaks in (("1", False), ("0", True)):
            env = {k: v for k, v in ENV.items() if k not in ("OMPI_COMM_WORLD_RANK", "PMI_RANK")}
            env[variable] = rank
            bad = subprocess.run([EXE, "mesh", image, "--no-such-option"], capture_output=True, text=True,
                                 timeout=60, env=env)
            assert bad.returncode == 2, (variable, rank, bad.returncode)
            assert bool(bad.stderr.strip()) == speaks, (variable, rank, bad.stderr)
            version = subprocess.run([EXE, "--version"], capture_output=True, text=True, timeout=60, env=env)
            assert version.returncode == 0 and bool(version.stdout.strip()) == speaks, (variable, rank, version.stdout)
    # A launcher's variables say several processes, but MPI starts this one alone (a launcher of
    # another MPI): refused, rather than each process meshing and writing the whole.
    env = {k: v for k, v in ENV.items() if not k.startswith("OMPI_COMM_WORLD")}
    env.update(PMI_SIZE="2", PMI_RANK="0")
    alone = subprocess.run([EXE, *mesh_args(image, out)], capture_output=True, text=True, timeout=120, env=env)
    expect_one_line_failure(alone, "launched as 2 processes, but this process's MPI sees only itself", out)
    # Nothing to share out without decimation.
    result = run([*MPIRUN, "-np", "2", EXE, "mesh", image, "-o", out, "--no-decimate"])
    expect_one_line_failure(result, "--no-decimate runs on one process", out)


def case_slab_only():
    """A process other than rank 0 reads only the slab of slices its parts need: its file may hold
    anything beyond that slab. Rank 1's parts lie in the top half of a tall image; its file holds a
    non-integer label in the first slice, which it never reads, and the run gives the one-process
    mesh. The same value in its top slice, which it reads, stops the run; so does a slab beyond
    its memory limit."""
    tall = np.concatenate([three_labels(), three_labels()], axis=0).astype(np.float32)
    for name in ("tall.nrrd", "tall_gzip.nrrd.gz", "tall.mha"):
        good = write_float_image(path(name), tall)
        one, out = path("slab_one.msh"), path("slab_np2.msh")
        result = run([EXE, *mesh_args(good, one, "--no-measure", "-q")])
        assert result.returncode == 0, result.stderr
        for where, slice_index in (("bottom", 0), ("top", tall.shape[0] - 1)):
            bad_values = tall.copy()
            bad_values[slice_index, 5, 5] = 0.5
            bad = write_float_image(path(where + "_" + name), bad_values)
            if os.path.exists(out):
                os.remove(out)
            result = run([*MPIRUN, "-np", "1", EXE, *mesh_args(good, out, "--no-measure", "-q"), ":",
                          "-np", "1", EXE, *mesh_args(bad, out, "--no-measure", "-q")])
            if where == "bottom":
                assert result.returncode == 0, result.stderr
                assert open(out, "rb").read() == open(one, "rb").read(), f"{name}: another mesh than one process's"
            else:
                expect_one_line_failure(result, "process 1 of 2: ", out)
                assert "non-integer value 0.5" in result.stderr and f"(5, 5, {slice_index})" in result.stderr, \
                    result.stderr
        print(f"OK: {name}: process 1 read its slab alone, and refused a bad value in it")
    # Its memory limit is checked again once its slab is known. A thin column through a tall image
    # (1,000 slices of 256 x 256) spreads the parts over its height, so process 1's slab is most
    # of the image (~47 MiB). Its limit holds what it needs before that (what it holds on
    # starting, read from a run refused at that point, and the fixed 25 MiB) with 20 MiB to
    # spare, but not the slab too. (Without the second check the run succeeds: checked by hand.)
    _, y, x = np.ogrid[0:1000, 0:256, 0:256]
    column = np.broadcast_to(((y - 128) ** 2 + (x - 128) ** 2 < 16).astype(np.uint8), (1000, 256, 256))
    image, out = write_nrrd("column.nrrd", column), path("column.msh")
    if os.path.exists(out):
        os.remove(out)
    probe = run([*MPIRUN, "-np", "1", EXE, *mesh_args(image, out, "--no-measure", "-q"), ":",
                 "-np", "1", EXE, *mesh_args(image, out, "--no-measure", "-q", "--max-memory", "1M")])
    expect_one_line_failure(probe, "the least a process that reads its slab of the image holds", out)
    held = int(re.search(r"(\d+) MiB of it in use", probe.stderr).group(1))
    limit = f"{held + 25 + 20}M"
    result = run([*MPIRUN, "-np", "1", EXE, *mesh_args(image, out, "--no-measure", "-q"), ":",
                  "-np", "1", EXE, *mesh_args(image, out, "--no-measure", "-q", "--max-memory", limit)])
    expect_one_line_failure(result, "process 1 of 2: this run needs about", out)
    assert "estimated from its slab of" in result.stderr, result.stderr
    os.remove(image)


if __name__ == "__main__":
    os.makedirs(WORK, exist_ok=True)
    globals()["case_" + CASE]()
