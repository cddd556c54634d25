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
