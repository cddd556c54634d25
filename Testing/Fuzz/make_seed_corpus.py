#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Writes the fuzzers' seed corpus (Testing/Fuzz/Corpus/<target>/) from the project's fixture
Resources/Data/rat_head.nrrd: a 6 x 5 x 4 crop of it (and a 2D slice) in every format the CLI
reads, in the encodings the readers take, plus a 3D Slicer segmentation written by
Testing/CLI/segmentation_fixture.py. A few KiB in all; re-run after changing a reader.

  /usr/bin/python3 Testing/Fuzz/make_seed_corpus.py
"""
import gzip
import os
import shutil
import struct
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(root, "Testing", "Support"))
sys.path.insert(0, os.path.join(root, "Testing", "CLI"))
from label_nrrd import read_label_nrrd  # noqa: E402
from segmentation_fixture import write_seg_nrrd  # noqa: E402

corpus = os.path.join(here, "Corpus")


def target(name):
    path = os.path.join(corpus, name)
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


def nrrd(labels, encoding="raw", dtype="uint8", spacing=(1.0, 0.8, 1.3), data_file=None):
    """An attached NRRD, or with data_file a detached header naming it followed by the data file's
    bytes (the .nhdr target's layout: the header ends at its blank line)."""
    array = labels.astype(dtype)
    nz, ny, nx = array.shape
    body = array.tobytes()
    if encoding == "gzip":
        body = gzip.compress(body, mtime=0)  # the same bytes on every run
    nrrd_type = {"float32": "float", "float64": "double"}.get(dtype, dtype)  # NRRD's names for them
    header = (f"NRRD0004\ntype: {nrrd_type}\ndimension: 3\nspace: left-posterior-superior\nsizes: {nx} {ny} {nz}\n"
              f"space directions: ({spacing[0]},0,0) (0,{spacing[1]},0) (0,0,{spacing[2]})\n"
              f"kinds: domain domain domain\nendian: little\nencoding: {encoding}\nspace origin: (0,0,0)\n"
              + (f"data file: {data_file}\n" if data_file else "") + "\n")
    return header.encode() + body


def nifti(labels, datatype=2, dtype="uint8", gz=False):
    array = labels.astype(dtype)
    nz, ny, nx = array.shape
    header = bytearray(352)
    struct.pack_into("<i", header, 0, 348)
    struct.pack_into("<8h", header, 40, 3, nx, ny, nz, 1, 1, 1, 1)
    struct.pack_into("<hh", header, 70, datatype, array.dtype.itemsize * 8)
    struct.pack_into("<8f", header, 76, 1.0, 1.0, 0.8, 1.3, 1.0, 1.0, 1.0, 1.0)
    struct.pack_into("<f", header, 108, 352.0)  # vox_offset
    struct.pack_into("<f", header, 112, 1.0)    # scl_slope
    struct.pack_into("<h", header, 254, 1)      # sform_code
    for row, values in enumerate(((1.0, 0, 0, 0), (0, 0.8, 0, 0), (0, 0, 1.3, 0))):
        struct.pack_into("<4f", header, 280 + 16 * row, *values)
    header[344:348] = b"n+1\0"
    data = bytes(header) + array.tobytes()
    return gzip.compress(data, mtime=0) if gz else data


def metaimage(labels, element="MET_UCHAR", dtype="uint8", compressed=False):
    array = labels.astype(dtype)
    nz, ny, nx = array.shape
    body = array.tobytes()
    if compressed:
        import zlib
        body = zlib.compress(body)
    header = (f"ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
              f"CompressedData = {'True' if compressed else 'False'}\n"
              + (f"CompressedDataSize = {len(body)}\n" if compressed else "")
              + f"TransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = 0 0 0\nElementSpacing = 1 0.8 1.3\n"
              f"DimSize = {nx} {ny} {nz}\nElementType = {element}\nElementDataFile = LOCAL\n")
    return header.encode() + body


def vtk_writes(labels, path_of, kinds):
    """VTI and PNG through Debian's VTK (the CLI reads them with VTK)."""
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk
    out = []
    for kind in kinds:
        array = labels if kind != "png16" else labels.astype(np.uint16) * 300
        if kind.startswith("png"):
            array = array[:1]
        image = vtk.vtkImageData()
        nz, ny, nx = array.shape
        image.SetDimensions(nx, ny, nz)
        image.SetSpacing(1.0, 0.8, 1.3)
        scalars = numpy_to_vtk(np.ascontiguousarray(array).ravel(), deep=True)
        scalars.SetName("Labels")
        image.GetPointData().SetScalars(scalars)
        path = path_of(kind)
        if kind.startswith("vti"):
            writer = vtk.vtkXMLImageDataWriter()
            writer.SetDataModeToAscii() if kind == "vti_ascii" else writer.SetDataModeToAppended()
            if kind == "vti_raw":
                writer.EncodeAppendedDataOff()
            writer.SetCompressorTypeToZLib() if kind == "vti_zlib" else writer.SetCompressorTypeToNone()
        else:
            writer = vtk.vtkPNGWriter()
        writer.SetFileName(path)
        writer.SetInputData(image)
        writer.Write()
        out.append(path)
    return out


def main():
    labels, _ = read_label_nrrd(os.path.join(root, "Resources", "Data", "rat_head.nrrd"))
    crop = labels[20:24, 24:29, 22:28].copy()          # [k, j, i]: 6 x 5 x 4, background and head
    crop[0, 0, :3] = 2                                  # a second label
    flat = crop[:1]

    d = target("nrrd")
    for name, data in {"raw.nrrd": nrrd(crop), "gzip.nrrd": nrrd(crop, "gzip"),
                       "short.nrrd": nrrd(crop, dtype="int16"), "uint.nrrd": nrrd(crop, dtype="uint32"),
                       "slice.nrrd": nrrd(flat), "float.nrrd": nrrd(crop, dtype="float32")}.items():
        open(os.path.join(d, name), "wb").write(data)
    d = target("nhdr")
    for name, data in {"raw.nhdr": nrrd(crop, data_file="input.raw"),
                       "gzip.nhdr": nrrd(crop, "gzip", data_file="input.raw"),
                       "short.nhdr": nrrd(crop, dtype="int16", data_file="input.raw"),
                       "slice.nhdr": nrrd(flat, data_file="input.raw")}.items():
        open(os.path.join(d, name), "wb").write(data)
    d = target("nifti")
    for name, data in {"uchar.nii": nifti(crop), "short.nii": nifti(crop, 4, "int16"),
                       "int.nii": nifti(crop, 8, "int32"), "float.nii": nifti(crop, 16, "float32"),
                       "gzip.nii": nifti(crop, gz=True)}.items():
        open(os.path.join(d, name), "wb").write(data)
    d = target("metaimage")
    for name, data in {"uchar.mha": metaimage(crop), "short.mha": metaimage(crop, "MET_SHORT", "int16"),
                       "zlib.mha": metaimage(crop, compressed=True),
                       "float.mha": metaimage(crop, "MET_FLOAT", "float32")}.items():
        open(os.path.join(d, name), "wb").write(data)
    d = target("vti")
    vtk_writes(crop, lambda k: os.path.join(d, k + ".vti"), ["vti_ascii", "vti_appended", "vti_raw", "vti_zlib"])
    d = target("png")
    vtk_writes(crop, lambda k: os.path.join(d, k + ".png"), ["png8", "png16"])
    d = target("segmentation")
    segments = [{"name": "head", "color": (0.9, 0.7, 0.6), "label": 1, "layer": 0},
                {"name": "marker", "color": (0.2, 0.4, 0.8), "label": 2, "layer": 0}]
    write_seg_nrrd(os.path.join(d, "one_layer.seg.nrrd"), [crop], segments, encoding="raw")
    write_seg_nrrd(os.path.join(d, "gzip.seg.nrrd"), [crop], segments)
    layers = [(crop == 1).astype(np.uint8), (crop == 2).astype(np.uint8)]
    write_seg_nrrd(os.path.join(d, "two_layers.seg.nrrd"), layers,
                   [dict(segments[0], label=1, layer=0), dict(segments[1], label=1, layer=1)], encoding="raw")
    # The validation and mesher targets decode their own byte layouts (see their sources): seeds
    # are the crop's labels behind a small header.
    d = target("label_validation")
    for scalar_type, dtype in ((3, "uint8"), (4, "int16"), (6, "int32"), (10, "float32")):
        body = struct.pack("<BBBBB", scalar_type, 6, 5, 4, 1) + struct.pack("<3d", 1.0, 0.8, 1.3)
        open(os.path.join(d, f"type{scalar_type}.bin"), "wb").write(body + crop.astype(dtype).tobytes())
    d = target("mesher")
    for dimension, data in ((3, crop), (2, labels[22, 20:36, 18:34])):
        shape = data.shape[::-1] + ((1,) if dimension == 2 else ())
        for bounds in (0x22, 0x41, 0x06):
            header = struct.pack("<BBBBBB", dimension, shape[0], shape[1], shape[2], bounds, 0x80)
            open(os.path.join(d, f"{dimension}d_{bounds:02x}.bin"), "wb").write(
                header + np.clip(data, 0, 3).astype(np.uint8).tobytes())
    print("seed corpus written to", corpus)


if __name__ == "__main__":
    main()
