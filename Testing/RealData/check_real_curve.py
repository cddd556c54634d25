#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Curve one real 2D label image with `labelmesher curve` (C1 and C2, h = 2), and make it
quadratic triangles with `labelmesher mesh --order 2`, and assert what the curver promises,
from its JSON report and from the written mesh:

- every cell proven valid (report), no cell marked invalid (cell data);
- det J of every cell, evaluated here from the written control points with
  numpy (VTK's Bézier triangle order, finite differences; independent of the
  C++ proof), has one sign at every sample;
- cubic Bézier triangles only (quadratic triangles with --order 2, whose sampled
  min det J / max det J is also at least the bound of 0.1);
- the scaled-Jacobian histogram accounts for every cell;
- decimated by default; both distance bounds kept on the curves (the report's
  measured figures, which may exceed the true distances by its resolution),
  no crossing interfaces, the image's topology;
- pixel accuracy of the linear and the curved mesh reported, and the default
  C1 curves misclassify at least a fifth fewer pixels than the linear mesh;
- with --check-failure: a run allowed one load step and one round, which cannot untangle
  every cell, exits 1 with one line on stderr and writes the mesh with exactly
  the cells it could not prove valid marked Valid = 0.

usage: check_real_curve.py LABELMESHER INPUT WORKDIR [--check-failure]
"""
import json
import os
import subprocess
import sys

import numpy as np
from vtkmodules.vtkCommonDataModel import VTK_BEZIER_TRIANGLE, VTK_QUADRATIC_TRIANGLE
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy

# VTK_BEZIER_TRIANGLE degree 3: multi-index (i, j, k) of each point, weights of corners 0, 1, 2.
ORDER = [(3, 0, 0), (0, 3, 0), (0, 0, 3), (2, 1, 0), (1, 2, 0), (0, 2, 1), (0, 1, 2),
         (1, 0, 2), (2, 0, 1), (1, 1, 1)]
FACTORIAL = [1, 1, 2, 6]


def evaluate(points, r, s):
    """Cubic Bézier triangles (n, 10, 2) at parametric (r, s): u = 1 - r - s."""
    u, v, w = 1.0 - r - s, r, s
    result = np.zeros((points.shape[0], 2))
    for p, (i, j, k) in enumerate(ORDER):
        b = 6.0 / (FACTORIAL[i] * FACTORIAL[j] * FACTORIAL[k]) * u ** i * v ** j * w ** k
        result += b * points[:, p, :]
    return result


def evaluate_quadratic(points, r, s):
    """6-node (Lagrange) triangles (n, 6, 2), corners then the mid-nodes of edges 0-1, 1-2, 2-0."""
    u = 1.0 - r - s
    weights = (u * (2 * u - 1), r * (2 * r - 1), s * (2 * s - 1), 4 * u * r, 4 * r * s, 4 * s * u)
    return sum(w * points[:, p, :] for p, w in enumerate(weights))


def sampled_jacobians(points, n=8, h=1e-6):
    values = []
    for a in range(n + 1):
        for b in range(n + 1 - a):
            # Stay h inside the triangle so that central differences are defined.
            r = min(max(a / n, 2 * h), 1 - 4 * h)
            s = min(max(b / n, 2 * h), 1 - r - 2 * h)
            at = evaluate_quadratic if points.shape[1] == 6 else evaluate
            dr = (at(points, r + h, s) - at(points, r - h, s)) / (2 * h)
            ds = (at(points, r, s + h) - at(points, r, s - h)) / (2 * h)
            values.append(dr[:, 0] * ds[:, 1] - dr[:, 1] * ds[:, 0])
    return np.array(values)


def check(labelmesher, image, workdir, smoothness):
    """smoothness "1" or "2": `curve` with C1 or C2; "order2": `mesh --order 2` (C1 fitted)."""
    quadratic = smoothness == "order2"
    name = os.path.splitext(os.path.basename(image))[0] + "_c" + smoothness
    mesh = os.path.join(workdir, name + ".vtu")
    report_path = os.path.join(workdir, name + ".json")
    command = ["mesh", image, "--order", "2"] if quadratic else ["curve", image, "--smoothness", smoothness]
    run = subprocess.run([labelmesher] + command + ["-o", mesh, "--report", report_path, "--hausdorff", "2"],
                         capture_output=True, text=True)
    print(run.stdout)
    failures = []
    if run.returncode != 0:
        failures.append("labelmesher curve failed (%d): %s" % (run.returncode, run.stderr.strip()))
        return failures
    with open(report_path) as f:
        report = json.load(f)
    validity = report["validity"]
    if not validity["valid"] or validity["invalid_cells"] != 0:
        failures.append("report: %d invalid cells" % validity["invalid_cells"])
    cells = report["curved_mesh"]["cells"]
    if sum(b["cells"] for b in validity["scaled_jacobian_histogram"]) != cells:
        failures.append("histogram does not account for every cell")
    if report["accuracy"] is None:
        failures.append("no pixel accuracy in the report")
        return failures
    if report["decimation"] is None:
        failures.append("curve did not decimate by default")
    curved = report["curved_mesh"]
    slack = curved["measure_resolution"] + 1e-9
    for side, bound in (("image_to_mesh", 2.0), ("mesh_to_image", 2.0)):
        if curved[side + "_bound"] != bound or not (0 < curved["measured_" + side] <= bound + slack):
            failures.append("curves: %s %s (bound %s)" % (side, curved["measured_" + side], curved[side + "_bound"]))
    if curved["interface_crossings"] != 0 or curved["topology_matches"] is not True or not curved["within_bounds"]:
        failures.append("curves: %d crossings, topology matches %s" % (curved["interface_crossings"],
                                                                     curved["topology_matches"]))
    accuracy = report["accuracy"]
    if smoothness != "2" and not 5 * accuracy["misclassified_curved"] <= 4 * accuracy["misclassified_linear"]:
        failures.append("fitted curves not a fifth more accurate than linear: %d -> %d" %
                        (accuracy["misclassified_linear"], accuracy["misclassified_curved"]))

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(mesh)
    reader.Update()
    grid = reader.GetOutput()
    os.remove(mesh)
    if grid.GetNumberOfCells() != cells:
        failures.append("mesh has %d cells, report %d" % (grid.GetNumberOfCells(), cells))
    cell_type, nodes = (VTK_QUADRATIC_TRIANGLE, 6) if quadratic else (VTK_BEZIER_TRIANGLE, 10)
    if not np.all(vtk_to_numpy(grid.GetCellTypesArray()) == cell_type):
        failures.append("cells other than type %d" % cell_type)
        return failures
    if not np.all(vtk_to_numpy(grid.GetCellData().GetArray("Valid")) == 1):
        failures.append("cells marked Valid = 0")
    connectivity = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, nodes)
    points = vtk_to_numpy(grid.GetPoints().GetData())[:, :2][connectivity]
    jacobians = sampled_jacobians(points)
    lowest, highest = jacobians.min(), jacobians.max()
    if not (lowest > 0 or highest < 0):
        failures.append("sampled det J changes sign: [%g, %g]" % (lowest, highest))
    ratio = float(np.min(np.abs(jacobians).min(axis=0) / np.abs(jacobians).max(axis=0)))
    if quadratic and not ratio >= 0.1:
        failures.append("sampled min det J / max det J %g below 0.1" % ratio)
    print("%s: %d cells, sampled det J in [%g, %g] (ratio %.3f), misclassified pixels %d -> %d, curves h(I,M) %.4f "
          "h(M,I) %.4f (linear %.4f %.4f), %d of %d pieces shortened"
          % ("order 2" if quadratic else "C" + smoothness, cells, lowest, highest, ratio, accuracy["misclassified_linear"], accuracy["misclassified_curved"],
             curved["measured_image_to_mesh"], curved["measured_mesh_to_image"],
             report["linear_mesh"]["measured_image_to_mesh"], report["linear_mesh"]["measured_mesh_to_image"],
             curved["shortened_pieces"], curved["curved_edges"]))
    return failures


def check_loud_failure(labelmesher, image, workdir):
    """With a single load step and no shortening some cells stay invalid: the run must fail with
    one line on stderr, yet write the mesh with exactly those cells marked."""
    name = os.path.splitext(os.path.basename(image))[0] + "_one_step"
    mesh = os.path.join(workdir, name + ".vtu")
    report_path = os.path.join(workdir, name + ".json")
    run = subprocess.run([labelmesher, "curve", image, "-o", mesh, "--report", report_path,
                          "--max-untangling-steps", "1", "--max-shortening-rounds", "1", "--quiet"],
                         capture_output=True, text=True)
    failures = []
    if run.returncode != 1:
        return ["one-step run: exit status %d, expected 1 (if one step now suffices, pick a "
                "harder case)" % run.returncode]
    if run.stderr.count("\n") != 1 or "could not be proven valid" not in run.stderr:
        failures.append("one-step run: stderr %r" % run.stderr)
    with open(report_path) as f:
        validity = json.load(f)["validity"]
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(mesh)
    reader.Update()
    marked = int(np.count_nonzero(vtk_to_numpy(reader.GetOutput().GetCellData().GetArray("Valid")) == 0))
    os.remove(mesh)
    if validity["valid"] or validity["invalid_cells"] != marked or marked == 0:
        failures.append("one-step run: report %s, %d cells marked" % (validity, marked))
    if validity["scaled_jacobian_histogram"][0]["cells"] != marked:
        failures.append("one-step run: histogram's first bin is not the marked cells")
    print("one step: %d cells marked invalid, exit status 1: %s" % (marked, run.stderr.strip()))
    return failures


def main():
    labelmesher, image, workdir = sys.argv[1:4]
    os.makedirs(workdir, exist_ok=True)
    failures = []
    for smoothness in ("1", "2", "order2"):
        label = "order 2" if smoothness == "order2" else "C" + smoothness
        failures += ["%s: %s" % (label, f) for f in check(labelmesher, image, workdir, smoothness)]
    if "--check-failure" in sys.argv[4:]:
        failures += check_loud_failure(labelmesher, image, workdir)
    if failures:
        sys.exit("FAILED:\n  " + "\n  ".join(failures))
    print("OK: every guarantee of the curver holds")


if __name__ == "__main__":
    main()
