# SPDX-License-Identifier: GPL-2.0-or-later
"""Command-line tests of labelmesher, one case per ctest test:

    python3 cli_test.py <path/to/labelmesher> <work dir> <case>

Bad input must give a non-zero exit status and exactly one line on stderr that
names the problem; good input must give a readable mesh and a JSON report whose
figures agree with the mesh."""

import json
import math
import os
import resource
import subprocess
import sys

import numpy as np
from vtkmodules.vtkCommonDataModel import VTK_BEZIER_TRIANGLE, VTK_TETRA, VTK_TRIANGLE, vtkImageData
from vtkmodules.vtkIOImage import vtkNIFTIImageWriter, vtkPNGWriter
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

EXE, WORK, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
PROVEN_BOUND = {3: 30.0, 2: 45.0}  # the initial mesh's, degrees (TestAngleBoundEnumeration)
DEFAULT_MIN_ANGLE = 15.0           # the decimator's default --min-angle
REPORT_KEYS = {"input", "output", "image", "parameters", "mesh", "decimation", "measured", "quality",
               "fidelity", "topology", "timings", "total_seconds", "memory"}


def path(name):
    return os.path.join(WORK, CASE + "_" + name)


def run(*args):
    return subprocess.run([EXE, *args], capture_output=True, text=True, timeout=540)


def write_nrrd(name, labels, nrrd_type, spacing=(1, 1, 1), truncate=0, extra="", detached=False):
    """Raw NRRD of a [z, y, x] array (written by hand: no writer can be trusted
    to produce the broken files we need); detached: a header NAME (.nhdr) and its
    data file NAME.raw beside it, which the header names."""
    data = np.ascontiguousarray(labels).tobytes()
    if truncate:
        data = data[: len(data) - truncate]
    nz, ny, nx = labels.shape
    header = (
        "NRRD0004\n"
        f"type: {nrrd_type}\n"
        "dimension: 3\n"
        "space dimension: 3\n"
        f"sizes: {nx} {ny} {nz}\n"
        f"space directions: ({spacing[0]},0,0) (0,{spacing[1]},0) (0,0,{spacing[2]})\n"
        "space origin: (0,0,0)\n"
        "endian: little\n"
        "encoding: raw\n" + extra
        + (f"data file: {os.path.basename(path(name))}.raw\n" if detached else "") + "\n"
    )
    with open(path(name), "wb") as f:
        f.write(header.encode("ascii") + (b"" if detached else data))
    if detached:
        with open(path(name) + ".raw", "wb") as f:
            f.write(data)
    return path(name)


def write_mha(name, labels, spacing, truncate=0, detached=False):
    """MetaImage of uint8 labels; detached: a header NAME (.mhd) and its data file NAME.raw."""
    data = np.ascontiguousarray(labels.astype(np.uint8)).tobytes()
    if truncate:
        data = data[: len(data) - truncate]
    nz, ny, nx = labels.shape
    data_file = os.path.basename(path(name)) + ".raw" if detached else "LOCAL"
    header = (
        "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
        "CompressedData = False\n"
        f"ElementSpacing = {spacing[0]} {spacing[1]} {spacing[2]}\n"
        f"DimSize = {nx} {ny} {nz}\nElementType = MET_UCHAR\nElementDataFile = {data_file}\n"
    )
    with open(path(name), "wb") as f:
        f.write(header.encode("ascii") + (b"" if detached else data))
    if detached:
        with open(path(name) + ".raw", "wb") as f:
            f.write(data)
    return path(name)


def write_png(name, pixels):
    """pixels: [y, x] or [y, x, channels] uint8."""
    pixels = np.asarray(pixels, dtype=np.uint8)
    channels = 1 if pixels.ndim == 2 else pixels.shape[2]
    image = vtkImageData()
    image.SetDimensions(pixels.shape[1], pixels.shape[0], 1)
    array = numpy_to_vtk(pixels.reshape(-1, channels), deep=True)
    image.GetPointData().SetScalars(array)
    writer = vtkPNGWriter()
    writer.SetFileName(path(name))
    writer.SetInputData(image)
    writer.Write()
    return path(name)


def write_nifti(name, labels, spacing=(1.0, 1.0, 1.0)):
    """NIfTI-1 of a [z, y, x] array (.nii.gz is gzip-compressed)."""
    nz, ny, nx = labels.shape
    image = vtkImageData()
    image.SetDimensions(nx, ny, nz)
    image.SetSpacing(*spacing)
    image.GetPointData().SetScalars(numpy_to_vtk(np.ascontiguousarray(labels).ravel(), deep=True))
    writer = vtkNIFTIImageWriter()
    writer.SetFileName(path(name))
    writer.SetInputData(image)
    writer.Write()
    return path(name)


def ball(n, radius, label=1):
    c = (n - 1) / 2.0
    z, y, x = np.mgrid[0:n, 0:n, 0:n]
    return np.where((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2 <= radius ** 2, label, 0)


def expect_failure(result, fragment, status=1):
    err = result.stderr.strip()
    assert result.returncode == status, f"exit status {result.returncode}, expected {status}: {err!r}"
    assert err and "\n" not in err, f"expected one line on stderr, got {result.stderr!r}"
    assert err.startswith("labelmesher:"), err
    assert fragment.lower() in err.lower(), f"{fragment!r} not in {err!r}"
    print("OK:", err)


def read_mesh(filename):
    reader = vtkXMLUnstructuredGridReader() if filename.endswith(".vtu") else vtkUnstructuredGridReader()
    reader.SetFileName(filename)
    reader.Update()
    return reader.GetOutput()


def check_mesh_and_report(mesh_file, report_file, cell_type, labels):
    grid = read_mesh(mesh_file)
    assert grid.GetNumberOfCells() > 0, "empty mesh"
    types = vtk_to_numpy(grid.GetCellTypesArray())
    assert np.all(types == cell_type), set(types)
    material = vtk_to_numpy(grid.GetCellData().GetArray("Material"))
    assert set(np.unique(material)) == set(labels), (set(np.unique(material)), labels)
    with open(report_file) as f:
        report = json.load(f)
    missing = REPORT_KEYS - set(report)
    assert not missing, f"report lacks {missing}"
    assert report["mesh"]["cells"] == grid.GetNumberOfCells()
    assert report["mesh"]["points"] == grid.GetNumberOfPoints()
    per_material = {int(k): v for k, v in report["mesh"]["cells_per_material"].items()}
    expected = {int(m): int(np.count_nonzero(material == m)) for m in np.unique(material)}
    assert per_material == expected, (per_material, expected)
    stages = [t["stage"] for t in report["timings"]]
    assert stages[0] == "read" and stages[-1] == "write", stages
    assert all(t["seconds"] >= 0 for t in report["timings"])
    decimation = report["decimation"]
    bound = PROVEN_BOUND[report["mesh"]["dimension"]] if decimation is None else decimation["minimum_angle_bound_degrees"]
    assert report["quality"]["angle_bound_degrees"] == bound, report["quality"]
    if decimation is not None:
        assert decimation["cells_after"] == grid.GetNumberOfCells(), decimation
        assert decimation["cells_after"] <= decimation["cells_before"], decimation
        assert decimation["merges"] > 0, decimation
        assert any(t["stage"] == "decimation" for t in report["timings"]), report["timings"]
    if report["measured"]:
        assert report["quality"]["minimum_angle_degrees"] >= bound - 1e-9, report["quality"]
        assert report["fidelity"]["bounds_certified"] is True, report["fidelity"]
        assert report["quality"]["inverted_cells"] == 0
        assert {e["material"] for e in report["topology"]["materials"]} >= set(labels) - {0}
        for key in ("image_to_mesh", "mesh_to_image"):
            assert report["fidelity"][key] is not None
    print("OK:", grid.GetNumberOfCells(), "cells", per_material)
    return grid, report


def case_missing_file():
    expect_failure(run("mesh", path("nothing.nrrd"), "-o", path("out.vtu")), "no such file")


def case_rgb_png():
    rgb = np.zeros((8, 8, 3), dtype=np.uint8)
    rgb[2:6, 2:6] = (255, 0, 0)
    expect_failure(run("mesh", write_png("rgb.png", rgb), "-o", path("out.vtu")), "RGB")


def case_float_image():
    labels = ball(8, 2.5).astype(np.float32)
    labels[4, 4, 4] = 1.5
    expect_failure(run("mesh", write_nrrd("float.nrrd", labels, "float"), "-o", path("out.vtu")),
                   "non-integer value 1.5")


def case_nan_image():
    labels = ball(8, 2.5).astype(np.float64)
    labels[0, 0, 1] = np.nan
    expect_failure(run("mesh", write_nrrd("nan.nrrd", labels, "double"), "-o", path("out.vtu")),
                   "NaN")


def case_negative_label():
    labels = ball(8, 2.5).astype(np.int16)
    labels[0, 0, 0] = -2
    expect_failure(run("mesh", write_nrrd("negative.nrrd", labels, "short"), "-o", path("out.vtu")),
                   "negative label -2")


def case_empty_image():
    labels = np.zeros((6, 6, 6), dtype=np.uint8)
    expect_failure(run("mesh", write_nrrd("empty.nrrd", labels, "uchar"), "-o", path("out.vtu")),
                   "no foreground")


def case_truncated_raw():
    labels = ball(10, 3.5).astype(np.uint8)
    expect_failure(run("mesh", write_nrrd("truncated.nrrd", labels, "uchar", truncate=300),
                       "-o", path("out.vtu")), "truncated")


def case_detached_headers():
    # A .nhdr or .mhd and its data file mesh as the attached file does; a data file that is
    # missing, a folder or short gives one line naming it, and no output.
    labels = ball(10, 3.5).astype(np.uint8)
    writers = {"ball.nhdr": lambda **kw: write_nrrd("ball.nhdr", labels, "uchar", **kw),
               "ball.mhd": lambda **kw: write_mha("ball.mhd", labels, (1, 1, 1), **kw)}
    for name, write in writers.items():
        header = write(detached=True)
        result = run("mesh", header, "-o", path("mesh.vtu"), "--report", path("report.json"))
        assert result.returncode == 0, result.stderr
        check_mesh_and_report(path("mesh.vtu"), path("report.json"), VTK_TETRA, {1})
        os.remove(header + ".raw")
        expect_failure(run("mesh", header, "-o", path("out.vtu")), name + ".raw' does not exist")
        os.mkdir(header + ".raw")
        try:
            expect_failure(run("mesh", header, "-o", path("out.vtu")), name + ".raw' is a folder")
        finally:
            os.rmdir(header + ".raw")
        write(truncate=300, detached=True)
        expect_failure(run("mesh", header, "-o", path("out.vtu")), "truncated")
        assert not os.path.exists(path("out.vtu"))


def case_truncated_nifti():
    # ITK 5.2 reads a NIfTI whose data stops half way without complaint.
    name = write_nifti("truncated.nii", ball(12, 4.5).astype(np.int16))
    size = os.path.getsize(name)
    with open(name, "r+b") as f:
        f.truncate(size - 1000)
    expect_failure(run("mesh", name, "-o", path("out.vtu")), "truncated")


def case_good_nifti_gz():
    labels = (ball(12, 4.5, 1) * 7).astype(np.int32)
    name = write_nifti("ball.nii.gz", labels, spacing=(0.8, 0.8, 1.6))
    result = run("mesh", name, "-o", path("mesh.vtu"), "--report", path("report.json"))
    assert result.returncode == 0, result.stderr
    grid, report = check_mesh_and_report(path("mesh.vtu"), path("report.json"), VTK_TETRA, {7})
    assert np.allclose(report["image"]["spacing"], [0.8, 0.8, 1.6]), report["image"]  # float32 in NIfTI
    assert abs(report["parameters"]["distance_unit"] - 0.8) < 1e-6


def case_compressed_metaimage():
    """A zlib-compressed MetaImage (CompressedData = True, as ITK writes it): the truncation check
    took its data for raw and refused it (found seeding the fuzzers); a truncated raw one still fails."""
    import zlib
    labels = ball(10, 3.5, 2).astype(np.uint8)
    body = zlib.compress(labels.tobytes())
    header = ("ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
              f"CompressedData = True\nCompressedDataSize = {len(body)}\nTransformMatrix = 1 0 0 0 1 0 0 0 1\n"
              "Offset = 0 0 0\nElementSpacing = 1 1 1\nDimSize = 10 10 10\nElementType = MET_UCHAR\n"
              "ElementDataFile = LOCAL\n")
    with open(path("compressed.mha"), "wb") as f:
        f.write(header.encode() + body)
    result = run("mesh", path("compressed.mha"), "-o", path("mha.vtu"), "--report", path("mha.json"))
    assert result.returncode == 0, result.stderr
    check_mesh_and_report(path("mha.vtu"), path("mha.json"), VTK_TETRA, {2})
    raw = header.replace("CompressedData = True", "CompressedData = False").replace(
        f"CompressedDataSize = {len(body)}\n", "")
    with open(path("short.mha"), "wb") as f:
        f.write(raw.encode() + labels.tobytes()[:500])
    expect_failure(run("mesh", path("short.mha"), "-o", path("out.vtu")), "truncated")
    # ITK 5.2's MetaIO returns uninitialised memory as voxels when CompressedDataSize is missing,
    # and takes a stream cut short or inflating to too few bytes without complaint.
    cases = {"no_size.mha": (header.replace(f"CompressedDataSize = {len(body)}\n", ""), body,
                             "needs a positive CompressedDataSize"),
             "size_beyond_file.mha": (header, body[: len(body) - 10], "its CompressedDataSize is"),
             "cut_stream.mha": (header.replace(f"= {len(body)}\n", f"= {len(body) // 2}\n"), body[: len(body) // 2],
                                "its compressed data ends after"),
             "few_bytes.mha": (header.replace(f"= {len(body)}\n", f"= {len(zlib.compress(b'x' * 500))}\n"),
                               zlib.compress(b"x" * 500), "inflates to 500"),
             "not_zlib.mha": (header, bytes(len(body)), "not a zlib stream")}
    for name, (text, data, message) in cases.items():
        with open(path(name), "wb") as f:
            f.write(text.encode() + data)
        expect_failure(run("mesh", path(name), "-o", path("out.vtu")), message)
    # Fields that MetaIO reads otherwise than the checks above (it matches names exactly; they
    # ignore case and spaces, to refuse more): without the check, the first two are meshed from
    # uninitialised memory with exit 0; so is compressed data placed by a HeaderSize.
    garbled = {"garbled_compressed.mha": (raw.replace("CompressedData = False", "CompressedData = True\n"
                                                       "Compressed Data = False"), labels.tobytes(),
                                           "does not read its CompressedData as written"),
               "garbled_size.mha": (header.replace("ElementType", "compressed datasize = 99\nElementType"), body,
                                    "does not read its CompressedDataSize as written"),
               "header_size.mha": (header.replace("ElementType", "HeaderSize = -1\nElementType"), body,
                                   "compressed voxels after a HeaderSize")}
    for name, (text, data, message) in garbled.items():
        with open(path(name), "wb") as f:
            f.write(text.encode() + data)
        expect_failure(run("mesh", path(name), "-o", path("out.vtu")), message)
    # Voxels stored as text are refused: ITK 5.2 frees memory it does not own on 1D and 2D ones.
    text = raw.replace("BinaryData = True", "BinaryData = False")
    with open(path("text.mha"), "wb") as f:
        f.write(text.encode() + " ".join(str(v) for v in labels.ravel()).encode())
    expect_failure(run("mesh", path("text.mha"), "-o", path("out.vtu")), "stores its voxels as text")


def case_negative_spacing():
    # ITK reads a negative spacing as a positive one with the axis direction
    # flipped: the same physical positions. The mesh must land there (at
    # negative y) with positively oriented tetrahedra.
    labels = np.zeros((8, 8, 8), dtype=np.uint8)
    labels[2:6, 2:6, 2:6] = 1  # voxel faces at index 1.5 .. 5.5 on every axis
    image = write_mha("negative_spacing.mha", labels, (1, -1, 1))
    result = run("mesh", image, "-o", path("mesh.vtu"), "--report", path("report.json"))
    assert result.returncode == 0, result.stderr
    grid, _ = check_mesh_and_report(path("mesh.vtu"), path("report.json"), VTK_TETRA, {1})
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    slack = 2.0 + 1e-9
    assert points[:, 1].max() <= -1.5 + slack and points[:, 1].min() >= -5.5 - slack, points[:, 1]
    assert points[:, 0].min() >= 1.5 - slack and points[:, 0].max() <= 5.5 + slack
    tets = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
    p = points[tets]
    volumes = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
    assert np.all(volumes > 0), "tetrahedra must stay positively oriented under a reflection"


def case_bad_option():
    expect_failure(run("mesh", "in.nrrd", "-o", path("out.vtu"), "--hausdorff", "-1"),
                   "non-negative", status=2)
    expect_failure(run("mesh", "in.nrrd", "-o", path("out.stl.gz")), "unknown extension", status=2)
    expect_failure(run("mesh", "in.nrrd"), "missing -o", status=2)


def case_good_3d():
    labels = (ball(14, 5.5, 1) + ball(14, 2.5, 1)).astype(np.uint8)  # 2 inside 1
    image = write_nrrd("two_labels.nrrd", labels, "uchar", spacing=(0.5, 0.5, 0.5))
    result = run("mesh", image, "-o", path("mesh.vtu"), "--report", path("report.json"),
                 "--image-to-mesh", "1.5", "--mesh-to-image", "2")
    assert result.returncode == 0, result.stderr
    assert "Minimum" in result.stdout or "not measured" in result.stdout, result.stdout
    grid, report = check_mesh_and_report(path("mesh.vtu"), path("report.json"), VTK_TETRA, {1, 2})
    assert report["parameters"]["image_to_mesh"] == 1.5
    assert report["parameters"]["mesh_to_image"] == 2.0
    assert report["parameters"]["distance_unit"] == 0.5
    points = vtk_to_numpy(grid.GetPoints().GetData())
    # physical coordinates: voxel faces span [-0.25, 6.75]; allow the 2-voxel bound
    assert points.min() >= -0.25 - 1.0 - 1e-9 and points.max() <= 6.75 + 1.0 + 1e-9, (points.min(), points.max())


def case_good_2d_png():
    disk = np.zeros((20, 24), dtype=np.uint8)
    y, x = np.mgrid[0:20, 0:24]
    disk[(x - 11.5) ** 2 + (y - 9.5) ** 2 <= 49] = 3
    result = run("mesh", write_png("disk.png", disk), "-o", path("mesh.vtu"),
                 "--report", path("report.json"))
    assert result.returncode == 0, result.stderr
    grid, report = check_mesh_and_report(path("mesh.vtu"), path("report.json"), VTK_TRIANGLE, {3})
    assert report["mesh"]["dimension"] == 2
    assert np.allclose(vtk_to_numpy(grid.GetPoints().GetData())[:, 2], 0.0)


def case_good_legacy_vtk():
    image = write_nrrd("ball.nrrd", ball(10, 3.5).astype(np.uint8), "uchar")
    result = run("mesh", image, "-o", path("mesh.vtk"), "--report", path("report.json"),
                 "--include-background", "--hausdorff", "2")
    assert result.returncode == 0, result.stderr
    check_mesh_and_report(path("mesh.vtk"), path("report.json"), VTK_TETRA, {0, 1})


def case_quiet():
    image = write_nrrd("ball.nrrd", ball(10, 3.5).astype(np.uint8), "uchar")
    result = run("mesh", image, "-o", path("mesh.vtu"), "--quiet")
    assert result.returncode == 0, result.stderr
    assert result.stdout == "" and result.stderr == "", (result.stdout, result.stderr)
    assert read_mesh(path("mesh.vtu")).GetNumberOfCells() > 0
    print("OK: quiet")


def case_no_measure():
    image = write_nrrd("ball.nrrd", ball(10, 3.5).astype(np.uint8), "uchar")
    result = run("mesh", image, "-o", path("mesh.vtu"), "--report", path("report.json"), "--no-measure")
    assert result.returncode == 0, result.stderr
    assert "not measured" in result.stdout and "Hausdorff" not in result.stdout, result.stdout
    with open(path("report.json")) as f:
        report = json.load(f)
    assert report["measured"] is False, report
    assert not any(t["stage"].startswith("measure") for t in report["timings"]), report["timings"]
    assert read_mesh(path("mesh.vtu")).GetNumberOfCells() > 0
    print("OK: no measure")


def interface_faces(labels):
    """Voxel faces between different labels, outside = 0 (numpy, independent of the tool)."""
    padded = np.pad(labels, 1)
    return sum(int(np.count_nonzero(np.diff(padded, axis=a))) for a in range(padded.ndim))


def case_memory_limit():
    """A run that cannot fit is refused before it starts: one line, exit 1, nothing written."""
    labels = ball(24, 9.5).astype(np.uint8)
    labels[12:, :, :] *= 2
    image = write_nrrd("ball.nrrd", labels, "uchar")
    out, report_file = path("mesh.vtu"), path("report.json")
    for stale in (out, report_file):
        if os.path.exists(stale):
            os.remove(stale)
    # Refused by the estimate from the image, before meshing (not by the decimator's, after it).
    refusal = run("mesh", image, "-o", out, "--report", report_file, "--max-memory", "1M")
    expect_failure(refusal, "voxel faces between labels")
    assert "memory limit of 1 MiB" in refusal.stderr, refusal.stderr
    assert not os.path.exists(out) and not os.path.exists(report_file), "a refused run wrote a file"
    expect_failure(run("mesh", image, "-o", out, "--max-memory", "lots"), "--max-memory", 2)

    result = run("mesh", image, "-o", out, "--report", report_file, "--no-measure")
    assert result.returncode == 0, result.stderr
    assert "Memory: peak" in result.stdout and "estimated beforehand" in result.stdout, result.stdout
    with open(report_file) as f:
        memory = json.load(f)["memory"]
    assert memory["interface_faces"] == interface_faces(labels), (memory, interface_faces(labels))
    assert memory["estimated_run_mib"] > 0 and memory["peak_mib"] >= memory["after_reading_mib"] > 0, memory
    # A generous limit is no refusal.
    result = run("mesh", image, "-o", out, "--no-measure", "-q", "--max-memory", "64G")
    assert result.returncode == 0, result.stderr

    # Under ulimit -v: every run either meshes or ends with one plain line and no file (never
    # libsc's or Open MPI's abort banner); the smallest limits are refused before meshing.
    # AddressSanitizer reserves terabytes of address space for its shadow: no ulimit -v there.
    if "ASAN_OPTIONS" in os.environ:
        print("OK: memory limits (ulimit -v part skipped under AddressSanitizer)")
        return
    refused = 0
    for mib in (80, 100, 120, 200, 300, 400, 600, 1000):
        if os.path.exists(out):
            os.remove(out)
        def limit(mib=mib):
            resource.setrlimit(resource.RLIMIT_AS, (mib << 20, mib << 20))
        result = subprocess.run([EXE, "mesh", image, "-o", out, "--no-measure", "-q"], capture_output=True,
                                text=True, timeout=540, preexec_fn=limit)
        err = result.stderr.strip()
        print(f"ulimit -v {mib} MiB: exit {result.returncode}: {err}")
        assert result.returncode in (0, 1), (mib, result.returncode, result.stderr)
        if result.returncode == 1:
            assert err.startswith("labelmesher:") and "\n" not in err, (mib, result.stderr)
            assert not os.path.exists(out), f"ulimit -v {mib} MiB: a failed run left {out}"
            refused += "ulimit -v" in err
    assert refused > 0, "no run was refused by the ulimit -v check"
    print("OK: memory limits")


def case_no_decimate():
    """The initial mesh: the proven 30 degrees, no decimation in the report."""
    image = write_nrrd("ball.nrrd", ball(12, 4.5).astype(np.uint8), "uchar")
    result = run("mesh", image, "-o", path("mesh.vtu"), "--report", path("report.json"), "--no-decimate")
    assert result.returncode == 0, result.stderr
    assert "Not decimated" in result.stdout, result.stdout
    grid, report = check_mesh_and_report(path("mesh.vtu"), path("report.json"), VTK_TETRA, {1})
    assert report["decimation"] is None
    assert report["quality"]["minimum_angle_degrees"] >= 30.0 - 1e-9
    decimated = run("mesh", image, "-o", path("decimated.vtu"), "--report", path("decimated.json"))
    assert decimated.returncode == 0, decimated.stderr
    with open(path("decimated.json")) as f:
        assert json.load(f)["decimation"]["cells_before"] == grid.GetNumberOfCells()
    print("OK: no decimation")


def case_min_angle():
    """--min-angle is the decimated mesh's bound: larger keeps more cells; above
    the proven 30 degrees (3D) it is refused with one line."""
    image = write_nrrd("ball.nrrd", ball(16, 6.5).astype(np.uint8), "uchar")
    cells = {}
    for angle in ("10", "25"):
        result = run("mesh", image, "-o", path(angle + ".vtu"), "--report", path(angle + ".json"),
                     "--min-angle", angle)
        assert result.returncode == 0, result.stderr
        grid, report = check_mesh_and_report(path(angle + ".vtu"), path(angle + ".json"), VTK_TETRA, {1})
        assert report["decimation"]["minimum_angle_bound_degrees"] == float(angle)
        cells[angle] = grid.GetNumberOfCells()
    assert cells["10"] < cells["25"], cells
    expect_failure(run("mesh", image, "-o", path("40.vtu"), "--min-angle", "40"), "(0, 30", 1)
    assert not os.path.exists(path("40.vtu")), "a failed run leaves no file"
    print("OK: min angle", cells)


def case_no_relocate():
    """--no-relocate keeps the merges alone: no vertex relocated, at least as
    many cells, the same bounds; it cannot go with --no-decimate."""
    image = write_nrrd("ball.nrrd", ball(20, 8.5).astype(np.uint8), "uchar")
    cells, reports = {}, {}
    for name, extra in (("relocated", []), ("merges", ["--no-relocate"])):
        result = run("mesh", image, "-o", path(name + ".vtu"), "--report", path(name + ".json"), *extra)
        assert result.returncode == 0, result.stderr
        assert "interior vertices relocated" in result.stdout, result.stdout
        grid, reports[name] = check_mesh_and_report(path(name + ".vtu"), path(name + ".json"), VTK_TETRA, {1})
        cells[name] = grid.GetNumberOfCells()
        assert reports[name]["quality"]["minimum_angle_degrees"] >= 15.0 - 1e-9
    assert reports["merges"]["decimation"]["vertices_relocated"] == 0, reports["merges"]["decimation"]
    assert reports["relocated"]["decimation"]["vertices_relocated"] > 0, reports["relocated"]["decimation"]
    assert cells["relocated"] < cells["merges"], cells
    expect_failure(run("mesh", image, "-o", path("x.vtu"), "--no-relocate", "--no-decimate"),
                   "cannot go with --no-decimate", 2)
    print("OK: no relocate", cells)


def two_blobs_png(name):
    """A disc of label 2 touching a disc of label 5 (an interface between two
    materials and with the background) on a 48 x 40 image."""
    y, x = np.mgrid[0:40, 0:48]
    labels = np.zeros((40, 48), dtype=np.uint8)
    labels[(x - 16.3) ** 2 + (y - 19.6) ** 2 <= 11.2 ** 2] = 2
    labels[(x - 32.1) ** 2 + (y - 20.4) ** 2 <= 10.4 ** 2] = 5
    return write_png(name, labels)


def case_curve_good_png():
    """curve decimates by default and curves C1 (fitted) or C2: every cell
    proven valid, both bounds kept on the curves, no crossings, the topology;
    the default C1 curves misclassify fewer pixels than the linear mesh."""
    for smoothness in ("1", "2"):
        mesh, report_file = path(f"curved{smoothness}.vtu"), path(f"curve{smoothness}.json")
        result = run("curve", two_blobs_png("blobs.png"), "-o", mesh, "--report", report_file,
                     "--smoothness", smoothness)
        assert result.returncode == 0, result.stderr
        assert "proven valid" in result.stdout, result.stdout
        assert "Pieces shortened" in result.stdout and "Curves: h(I,M)" in result.stdout, result.stdout
        grid = read_mesh(mesh)
        types = vtk_to_numpy(grid.GetCellTypesArray())
        assert np.all(types == VTK_BEZIER_TRIANGLE), set(types)
        assert all(grid.GetCell(c).GetNumberOfPoints() == 10 for c in range(grid.GetNumberOfCells()))
        cell_data = grid.GetCellData()
        assert set(np.unique(vtk_to_numpy(cell_data.GetArray("Material")))) == {2, 5}
        assert np.all(vtk_to_numpy(cell_data.GetArray("Valid")) == 1)
        scaled = vtk_to_numpy(cell_data.GetArray("ScaledJacobian"))
        assert np.all(vtk_to_numpy(cell_data.GetArray("MinimumJacobian")) > 0) or np.all(scaled > 0)
        with open(report_file) as f:
            report = json.load(f)
        assert report["command"] == "curve"
        decimation = report["decimation"]
        assert decimation is not None, "curve decimates by default"
        assert decimation["cells_after"] == report["linear_mesh"]["cells"] < decimation["cells_before"]
        assert report["parameters"]["smoothness"] == int(smoothness)
        assert report["validity"]["valid"] is True and report["validity"]["invalid_cells"] == 0
        # The scaled Jacobian bound (default 0.1): the certified smallest and the written cells.
        assert report["parameters"]["minimum_scaled_jacobian"] == 0.1
        assert report["validity"]["minimum_scaled_jacobian"] >= 0.1, report["validity"]
        assert report["validity"]["scaled_jacobian_bound_holds"] is True
        assert "Scaled Jacobian: every cell at least 0.100" in result.stdout, result.stdout
        curved = report["curved_mesh"]
        assert curved["cells"] == grid.GetNumberOfCells()
        assert curved["control_points"] == grid.GetNumberOfPoints()
        assert curved["image_to_mesh_bound"] == 2.0 and curved["mesh_to_image_bound"] == 2.0
        slack = curved["measure_resolution"] + 1e-9
        assert 0 < curved["measured_image_to_mesh"] <= 2.0 + slack, curved
        assert 0 < curved["measured_mesh_to_image"] <= 2.0 + slack, curved
        assert curved["interface_crossings"] == 0 and curved["topology_matches"] is True, curved
        assert curved["within_bounds"] is True and curved["uncertified_pieces"] == 0, curved
        assert 0 <= curved["straightened_pieces"] <= curved["shortened_pieces"] <= curved["curved_edges"]
        # Ears (cells with two edges on one smooth chain) are split before curving.
        split = curved["split_ears"]
        assert report["linear_mesh"]["cells"] + split <= grid.GetNumberOfCells()
        assert grid.GetNumberOfCells() <= report["linear_mesh"]["cells"] + 2 * split
        histogram = report["validity"]["scaled_jacobian_histogram"]
        assert sum(b["cells"] for b in histogram) == grid.GetNumberOfCells()
        assert histogram[0]["cells"] == 0
        accuracy = report["accuracy"]
        assert accuracy["pixels"] == 48 * 40
        assert {m["material"] for m in accuracy["materials"]} == {2, 5}
        for kind in ("linear", "curved"):
            assert 0 < accuracy["misclassified_" + kind] < 0.05 * 48 * 40, accuracy
        if smoothness == "1":
            assert accuracy["misclassified_curved"] < accuracy["misclassified_linear"], accuracy
        print("OK: C" + smoothness, grid.GetNumberOfCells(), "cells, misclassified",
              accuracy["misclassified_linear"], "->", accuracy["misclassified_curved"])
    result = run("curve", two_blobs_png("blobs.png"), "-o", path("initial.vtu"),
                 "--report", path("initial.json"), "--no-decimate")
    assert result.returncode == 0, result.stderr
    with open(path("initial.json")) as f:
        report = json.load(f)
    assert report["decimation"] is None, "--no-decimate keeps the initial mesh"
    assert report["validity"]["valid"] is True and report["curved_mesh"]["within_bounds"] is True
    result = run("curve", two_blobs_png("blobs.png"), "-o", path("decimated.vtu"),
                 "--report", path("decimated.json"), "--min-angle", "20")
    assert result.returncode == 0, result.stderr
    with open(path("decimated.json")) as f:
        report = json.load(f)
    assert report["decimation"]["minimum_angle_bound_degrees"] == 20.0
    assert report["validity"]["valid"] is True, report["validity"]
    print("OK: --no-decimate and --min-angle")


def case_curve_rejects_3d():
    image = write_nrrd("ball.nrrd", ball(10, 3.5).astype(np.uint8), "uchar")
    expect_failure(run("curve", image, "-o", path("out.vtu")), "needs a 2D image")


def case_curve_bad_options():
    png = two_blobs_png("blobs.png")
    expect_failure(run("curve", png, "-o", path("out.vtu"), "--smoothness", "3"), "1 (C1) or 2", 2)
    expect_failure(run("curve", png, "-o", path("out.vtu"), "--tension", "1.5"), "[0, 1]", 2)
    expect_failure(run("curve", png, "-o", path("out.vtu"), "--min-angle", "50"), "(0, 45] (2D)", 2)
    expect_failure(run("curve", png, "-o", path("out.vtu"), "--min-angle", "20", "--no-decimate"),
                   "--no-decimate", 2)
    expect_failure(run("curve", png, "-o", path("out.vtu"), "--decimate", "--no-decimate"), "contradict", 2)
    expect_failure(run("mesh", png, "-o", path("out.vtu"), "--smoothness", "2"), "'curve' only", 2)
    expect_failure(run("curve", png, "-o", path("out.vtu"), "--min-scaled-jacobian", "1"), "[0, 1)", 2)
    expect_failure(run("curve", png, "-o", path("out.vtu"), "--min-scaled-jacobian", "-0.1"), "[0, 1)", 2)
    expect_failure(run("mesh", png, "-o", path("out.vtu"), "--min-scaled-jacobian", "0.2"), "'curve' only", 2)


if __name__ == "__main__":
    os.makedirs(WORK, exist_ok=True)
    globals()["case_" + CASE]()
