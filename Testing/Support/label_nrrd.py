# SPDX-License-Identifier: GPL-2.0-or-later
"""Reads the shared label volumes (../shared/data: gzip or raw NRRD, uchar,
axis-aligned) with numpy only: VTK 9.1's NRRD reader misreads gzip NRRD, and
the tests that need them run in interpreters without ITK."""
import gzip

import numpy as np


def read_label_nrrd(path):
    """(labels indexed [k, j, i], spacing (3,) in mm)."""
    with open(path, "rb") as f:
        raw = f.read()
    head, _, body = raw.partition(b"\n\n")
    fields = dict(line.split(": ", 1) for line in head.decode().splitlines()[1:] if ": " in line)
    sizes = [int(s) for s in fields["sizes"].split()]
    data = gzip.decompress(body) if fields["encoding"] == "gzip" else body
    assert fields["type"] in ("uchar", "unsigned char", "uint8"), fields["type"]
    spacing = [float(v.strip("()").split(",")[i]) for i, v in enumerate(fields["space directions"].split())]
    labels = np.frombuffer(data, dtype=np.uint8).reshape(sizes[::-1]).copy()
    return labels, np.asarray(spacing + [1.0] * (3 - len(spacing)))


def three_labels(n=36):
    """Two balls and a slab: enough interface for many small blocks."""
    z, y, x = np.mgrid[0:n, 0:n, 0:n]
    labels = np.zeros((n, n, n), np.uint8)
    labels[(x - 12) ** 2 + (y - 13) ** 2 + (z - 14) ** 2 < 81] = 1
    labels[(x - 23) ** 2 + (y - 22) ** 2 + (z - 21) ** 2 < 64] = 2
    labels[(z > 27) & (x > 5)] = 3
    return labels


def write_float_image(filename, values):
    """`values` ([k, j, i]) as little-endian 32-bit floats at `filename`: .mha (raw MetaImage),
    .nrrd.gz (gzip NRRD, written without the .gz) or .nrrd (raw). Returns the name written."""
    data = values.astype("<f4").tobytes()
    sizes = " ".join(str(n) for n in values.shape[::-1])
    if filename.endswith(".mha"):
        header = ("ObjectType = Image\nNDims = 3\nDimSize = {}\nElementType = MET_FLOAT\nElementSpacing = 1 1 1\n"
                  "ElementByteOrderMSB = False\nElementDataFile = LOCAL\n").format(sizes)
    else:
        gzipped = filename.endswith(".gz")
        filename = filename[:-3] if gzipped else filename
        header = "NRRD0004\ntype: float\ndimension: 3\nsizes: {}\nspacings: 1 1 1\nendian: little\n" \
                 "encoding: {}\n\n".format(sizes, "gzip" if gzipped else "raw")
        data = gzip.compress(data) if gzipped else data
    with open(filename, "wb") as f:
        f.write(header.encode() + data)
    return filename
