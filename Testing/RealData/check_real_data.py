#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Mesh one real label image with the labelmesher CLI at h = 2, 2 -- decimated at
the default 15 degrees, or with --no-decimate the initial mesh -- and assert every
guarantee from the JSON report (which the measuring component fills in):

- minimum dihedral (planar) angle >= the bound: 15 deg decimated, or the one
  our enumeration proves for the initial mesh (TestAngleBoundEnumeration:
  30 deg in 3D, 45 deg in 2D); no inverted cell;
- decimated: fewer cells than the initial mesh (at most half);
- conformity with the background included (the mesh fills the octree's cube):
  no face shared by more than two cells, no hanging vertex, a watertight
  boundary;
- both measured one-sided Hausdorff distances within their bounds;
- per material, components and Euler characteristic of mesh and voxels equal;
- decimated: the mesh also written as .msh, .inp, .mesh, .vtp, .obj (and .stl
  in 3D) in the same run, each read back by meshio / gmsh / VTK and compared
  with the .vtu (Testing/Support/export_checks.py).

- with --block-cells N: decimated block by block in blocks of N initial cells,
  which must cut the image into more than one block (the guarantees above hold
  across the block borders).

usage: check_real_data.py LABELMESHER INPUT WORKDIR [--no-decimate | --block-cells N]
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from export_checks import check_exports  # noqa: E402

PROVEN_DIHEDRAL = 30.0
PROVEN_PLANAR = 45.0
DECIMATION_ANGLE = 15.0  # the CLI's default --min-angle
BOUND = 2.0


def main():
    labelmesher, image, workdir = sys.argv[1:4]
    decimate = "--no-decimate" not in sys.argv[4:]
    blocks = sys.argv[sys.argv.index("--block-cells") + 1] if "--block-cells" in sys.argv else None
    os.makedirs(workdir, exist_ok=True)
    name = os.path.splitext(os.path.basename(image))[0] + ("" if decimate else "_initial") + \
        ("_blocks" + blocks if blocks else "")
    mesh = os.path.join(workdir, name + ".vtu")
    report_path = os.path.join(workdir, name + ".json")
    exports = {}
    if decimate:
        formats = [".msh", ".inp", ".mesh", ".vtp", ".obj"] + ([] if image.endswith(".png") else [".stl"])
        exports = {f: os.path.join(workdir, name + f) for f in formats}
    command = [labelmesher, "mesh", image, "-o", mesh, "--report", report_path,
               "--hausdorff", str(BOUND), "--include-background"] + ([] if decimate else ["--no-decimate"]) + \
        (["--block-cells", blocks] if blocks else [])
    for path in exports.values():
        command += ["-o", path]
    run = subprocess.run(command, capture_output=True, text=True)
    print(run.stdout)
    if run.returncode != 0:
        print(run.stderr, file=sys.stderr)
        sys.exit("labelmesher failed with status %d" % run.returncode)
    with open(report_path) as f:
        report = json.load(f)
    failures = []
    if exports:
        failures += check_exports(mesh, exports, {}, report["mesh"]["dimension"])
    for path in [mesh] + list(exports.values()):
        os.remove(path)  # large; the report holds what is checked

    quality = report["quality"]
    bound = PROVEN_DIHEDRAL if report["mesh"]["dimension"] == 3 else PROVEN_PLANAR
    if decimate:
        bound = DECIMATION_ANGLE
        decimation = report["decimation"]
        if decimation is None:
            failures.append("the report says the mesh was not decimated")
        elif decimation["cells_after"] * 2 > decimation["cells_before"]:
            failures.append("decimated only from %d to %d cells" % (decimation["cells_before"], decimation["cells_after"]))
        if blocks and not (decimation and decimation["blocks"] > 1):
            failures.append("--block-cells %s left the image in one block: no border was crossed" % blocks)
    elif report["decimation"] is not None:
        failures.append("--no-decimate, yet the report describes a decimation")
    if abs(quality["angle_bound_degrees"] - bound) > 1e-9:
        failures.append("the report's angle bound %.4f is not %.4f" % (quality["angle_bound_degrees"], bound))
    if not report["measured"]:
        failures.append("the report holds no measurements")
    if quality["minimum_angle_degrees"] < bound - 1e-9:
        failures.append("minimum angle %.6f < %.6f" % (quality["minimum_angle_degrees"], bound))
    if quality["inverted_cells"] != 0:
        failures.append("%d inverted cells" % quality["inverted_cells"])
    for key, value in report["conformity"].items():
        if value != 0:
            failures.append("conformity: %s = %s" % (key, value))
    fidelity = report["fidelity"]
    if fidelity["bounds_certified"] is not True:
        failures.append("the checks' exact test does not certify both distance bounds")
    for side in ("image_to_mesh", "mesh_to_image"):
        if fidelity[side] > fidelity[side + "_bound"]:
            failures.append("h %s = %.4f > %.4f" % (side, fidelity[side], fidelity[side + "_bound"]))
    for entry in report["topology"]["materials"]:
        if not entry["matches"]:
            failures.append("topology of material %d: image (%d, %d) vs mesh (%d, %d)" % (
                entry["material"], entry["image_components"], entry["image_euler_characteristic"],
                entry["mesh_components"], entry["mesh_euler_characteristic"]))
    labels_in_mesh = {int(k) for k in report["mesh"]["cells_per_material"]} - {0}
    labels_checked = {e["material"] for e in report["topology"]["materials"]}
    if labels_in_mesh != labels_checked:
        failures.append("materials in the mesh %s differ from those compared %s" % (
            sorted(labels_in_mesh), sorted(labels_checked)))
    if failures:
        sys.exit("\n".join(failures))
    print("%s: all guarantees hold (%d cells, minimum angle %.4f deg >= %.2f, h(I,M) %.3f, h(M,I) %.3f)" % (
        name, report["mesh"]["cells"], quality["minimum_angle_degrees"], bound,
        fidelity["image_to_mesh"], fidelity["mesh_to_image"]))


if __name__ == "__main__":
    main()
