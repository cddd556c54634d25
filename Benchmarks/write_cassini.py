# SPDX-License-Identifier: GPL-2.0-or-later
"""Writes the Cassini volume of the benchmarks (Testing/Cxx/Support/SyntheticShapes.cxx,
MakeCassiniVolume with its defaults: ratio 1.02, margin 4, lobes labelled 1 and 2) as a raw
uchar NRRD, for runs of the command-line tool (e.g. under mpirun):

    python3 Benchmarks/write_cassini.py N OUT.nrrd
"""
import sys

import numpy as np


def cassini(n, ratio=1.02, margin=4.0):
    length = n - 2.0 * margin
    a = 0.5 * length / np.sqrt(1.0 + ratio * ratio)
    b = ratio * a
    a2, b4 = a * a, b ** 4
    c = 0.5 * (n - 1)
    labels = np.zeros((n, n, n), np.uint8)  # z, y, x
    x = np.arange(n) - c
    for k in range(n):
        z = k - c
        y = (np.arange(n) - c)[:, None]
        yz = y * y + z * z
        s = x[None, :] * x[None, :] + yz + a2
        inside = (s * s - 4.0 * a2 * x[None, :] * x[None, :] <= b4) & (yz <= b * b)
        labels[k][inside] = np.where(x[None, :] >= 0, 2, 1).repeat(n, 0)[inside]
    return labels


if __name__ == "__main__":
    n, out = int(sys.argv[1]), sys.argv[2]
    labels = cassini(n)
    with open(out, "wb") as f:
        f.write(f"NRRD0004\ntype: uchar\ndimension: 3\nsizes: {n} {n} {n}\nspacings: 1 1 1\nencoding: raw\n\n".encode())
        f.write(labels.tobytes())
