#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Command-line tests of the mesh files and of writing safely (issue 14): every
format read back by independent readers (Testing/Support/export_checks.py),
names from a colour table and from a 3D Slicer segmentation, and every way a
write can fail: a full device, a file-size limit, a folder, a missing folder,
an unknown extension. Each case is one ctest test (label "cli").

usage: export_test.py LABELMESHER WORKDIR CASE
"""
import itertools
import json
import os
import resource
import shutil
import signal
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Support"))
sys.path.insert(0, HERE)
import cli_test as cli  # noqa: E402  (same argv: LABELMESHER WORKDIR CASE)
from export_checks import check_exports, tetra10_jacobians  # noqa: E402
from segmentation_fixture import write_itksnap_labels, write_seg_nrrd, write_slicer_ctbl  # noqa: E402

FORMATS_3D = [".vtu", ".msh", ".inp", ".mesh", ".vtp", ".stl", ".obj"]
FORMATS_2D = [".vtu", ".msh", ".inp", ".mesh", ".vtp", ".obj"]


def nested_balls():
    return (cli.ball(16, 6.5, 1) + cli.ball(16, 3.5, 1)).astype(np.uint8)  # 2 inside 1


def mesh_to(image, stem, formats, *options):
    outputs = {f: cli.path(stem + f) for f in formats}
    args = ["mesh", image, "--report", cli.path(stem + ".json")]
    for f in formats:
        args += ["-o", outputs[f]]
    result = cli.run(*args, *options)
    assert result.returncode == 0, result.stderr
    with open(cli.path(stem + ".json")) as f:
        report = json.load(f)
    assert report["outputs"] == [outputs[f] for f in formats], report["outputs"]
    return outputs, report, result


def assert_exports(outputs, names, dimension, gmsh22=False):
    checked = {(".msh22" if gmsh22 and k == ".msh" else k): v for k, v in outputs.items() if k != ".vtu"}
    failures = check_exports(outputs[".vtu"], checked, names, dimension)
    assert not failures, "\n".join(failures)


def assert_report_names(report, names):
    table = {e["label"]: e["name"] for e in report["material_table"]}
    for label in table:
        assert table[label] == names.get(label, "label_%d" % label), (label, table[label])
    cells = {int(k): v for k, v in report["mesh"]["cells_per_material"].items()}
    assert {e["label"]: e["cells"] for e in report["material_table"]} == cells


def case_export_formats_3d():
    image = cli.write_nrrd("balls.nrrd", nested_balls(), "uchar", spacing=(0.5, 0.5, 0.5))
    labels = cli.path("names.txt")
    names = {1: "outer shell", 2: "Core-2"}
    write_itksnap_labels(labels, [(1, "outer shell", (200, 80, 40)), (2, "Core-2", (20, 200, 20))], clear_label=False)
    outputs, report, result = mesh_to(image, "plain", FORMATS_3D, "--labels", labels)
    assert_report_names(report, names)
    assert "outer shell" in result.stdout and "Core-2" in result.stdout, result.stdout
    colour = {e["label"]: e["color"] for e in report["material_table"]}
    assert np.allclose(colour[1], [200 / 255, 80 / 255, 40 / 255]), colour
    assert_exports(outputs, names, 3)
    # With the background, in MSH 2.2: label 0 is the physical tag largest + 1.
    outputs, report, _ = mesh_to(image, "background", [".vtu", ".msh", ".inp", ".mesh", ".vtp"],
                                 "--labels", labels, "--include-background", "--msh-version", "2.2")
    with open(outputs[".msh"]) as f:
        head = f.read(200)
    assert head.startswith("$MeshFormat\n2.2 0 8\n"), head
    assert 0 in {e["label"] for e in report["material_table"]}
    assert_exports(outputs, names, 3, gmsh22=True)
    print("OK: 3D formats round trip")


def case_export_formats_2d():
    disk = np.zeros((20, 26), dtype=np.uint8)
    y, x = np.mgrid[0:20, 0:26]
    disk[(x - 8.5) ** 2 + (y - 9.5) ** 2 <= 36] = 3
    disk[(x - 18.5) ** 2 + (y - 9.5) ** 2 <= 25] = 7
    png = cli.write_png("disks.png", disk)
    table = cli.path("colours.ctbl")
    write_slicer_ctbl(table, [(3, "left", (255, 0, 0)), (7, "right", (0, 0, 255))])
    outputs, report, _ = mesh_to(png, "disks", FORMATS_2D, "--labels", table)
    names = {3: "left", 7: "right"}
    assert_report_names(report, names)
    assert_exports(outputs, names, 2)
    with open(outputs[".inp"]) as f:
        assert "*ELEMENT, TYPE=CPS3, ELSET=left" in f.read()
    with open(outputs[".mesh"]) as f:
        assert "Dimension 2\n" in f.read()
    # STL holds triangles only: refused before any meshing.
    cli.expect_failure(cli.run("mesh", png, "-o", cli.path("disks.stl")), "segments")
    assert not os.path.exists(cli.path("disks.stl"))
    print("OK: 2D formats round trip")


def bezier_triangle_point(control, u, v, w):
    """The cubic Bezier triangle with VTK's ten control points (corners, two per edge from its
    first corner, centre) at barycentric (u, v, w): Bernstein polynomials, written out here."""
    index = {(3, 0, 0): 0, (0, 3, 0): 1, (0, 0, 3): 2, (2, 1, 0): 3, (1, 2, 0): 4, (0, 2, 1): 5,
             (0, 1, 2): 6, (1, 0, 2): 7, (2, 0, 1): 8, (1, 1, 1): 9}
    fact = [1, 1, 2, 6]
    point = np.zeros(3)
    for (i, j, k), slot in index.items():
        point += 6 / (fact[i] * fact[j] * fact[k]) * u ** i * v ** j * w ** k * control[slot]
    return point


def case_export_curved_msh():
    """`curve` writes Gmsh's 10-node triangles: read back by meshio with every material, accepted
    by gmsh -check, and each node on the .vtu's Bezier cell at its Lagrange position."""
    disk = np.zeros((30, 40), dtype=np.uint8)
    y, x = np.mgrid[0:30, 0:40]
    disk[(x - 12.5) ** 2 + (y - 14.5) ** 2 <= 81] = 3
    disk[(x - 28.5) ** 2 + (y - 14.5) ** 2 <= 49] = 7
    png = cli.write_png("curved.png", disk)
    vtu, msh, report = cli.path("curved.vtu"), cli.path("curved.msh"), cli.path("curved.json")
    result = cli.run("curve", png, "-o", vtu, "-o", msh, "--report", report)
    assert result.returncode == 0, result.stderr
    # The .vtu through VTK (meshio 5 does not read Bezier cells), the .msh through meshio.
    grid = cli.read_mesh(vtu)
    assert set(cli.vtk_to_numpy(grid.GetCellTypesArray()).tolist()) == {cli.VTK_BEZIER_TRIANGLE}
    control = cli.vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 10)
    materials = cli.vtk_to_numpy(grid.GetCellData().GetArray("Material")).astype(np.int64)
    points = cli.vtk_to_numpy(grid.GetPoints().GetData())
    meshio = __import__("meshio")
    mesh = meshio.read(msh)
    blocks = [(i, c) for i, c in enumerate(mesh.cells) if c.type == "triangle10"]
    assert blocks and len(blocks) == len(mesh.cells), [c.type for c in mesh.cells]
    cells = np.concatenate([c.data for _, c in blocks])
    tags = np.concatenate([mesh.cell_data["gmsh:physical"][i] for i, _ in blocks]).astype(np.int64)
    assert len(cells) == len(control), (len(cells), len(control))
    assert sorted(tags.tolist()) == sorted(materials.tolist()), "materials differ"
    assert {int(mesh.field_data[n][0]) for n in ("label_3", "label_7")} == {3, 7}, mesh.field_data
    # Same cells in the same order within a material (both files group by material, stably).
    order = np.argsort(materials, kind="stable")
    nodes = [(3, 0, 0), (0, 3, 0), (0, 0, 3), (2, 1, 0), (1, 2, 0), (0, 2, 1), (0, 1, 2), (1, 0, 2), (2, 0, 1), (1, 1, 1)]
    worst = 0.0
    for written, source in zip(cells, order):
        cp = points[control[source]]
        for slot, (i, j, k) in enumerate(nodes):
            want = bezier_triangle_point(cp, i / 3, j / 3, k / 3)
            worst = max(worst, float(np.linalg.norm(mesh.points[written[slot]] - want)))
    assert worst < 1e-9, "a Lagrange node is %g off its Bezier cell" % worst
    # Conforming: every edge node shared by the two cells of an inner edge.
    edges = {}
    for cell in cells:
        for a, b, p, q in ((0, 1, 3, 4), (1, 2, 5, 6), (2, 0, 7, 8)):
            key = (min(cell[a], cell[b]), max(cell[a], cell[b]))
            mid = (cell[p], cell[q]) if cell[a] < cell[b] else (cell[q], cell[p])
            assert edges.setdefault(key, mid) == mid, "edge %s has two sets of nodes" % (key,)
    assert shutil.which("gmsh"), "gmsh is not installed (python3-meshio and gmsh are test dependencies)"
    check = subprocess.run(["gmsh", msh, "-check"], capture_output=True, text=True)
    assert check.returncode == 0 and "Error" not in check.stdout + check.stderr, (check.stdout + check.stderr)[-500:]
    # Formats without cubic triangles are refused before meshing.
    cli.expect_failure(cli.run("curve", png, "-o", cli.path("curved.mesh")), ".vtu, .pvtu, .vtk or .msh only", 2)
    print("OK: curved mesh as 10-node triangles, %d cells, nodes within %.1e" % (len(cells), worst))


def quadratic_face_key(points, nodes):
    """A 6-node triangle (corners, then the mid-nodes of edges 0-1, 1-2, 2-0) as a key that is the
    same in either orientation, and only when each mid-node belongs to its edge."""
    p = [np.round(points[n], 9).tobytes() for n in nodes]
    return frozenset((frozenset((p[i], p[(i + 1) % 3])), p[3 + i]) for i in range(3))


def assert_quadratic_interfaces(reference, written):
    """The interfaces `written` (a .msh read by meshio) holds as 6-node triangles are exactly the
    faces of `reference`'s tetra10 cells between two materials or of one cell alone (against the
    background, material 0; none between background and background), each in the physical group
    named for its pair; returns those faces (key -> pair) and a reader of another file's faces."""
    cells = reference.cells[0].data
    materials = reference.cell_data["Material"][0].astype(np.int64)
    # Mid-node slot of each edge in VTK's tetra10 order (corners 0-3, then edges 01, 12, 20, 03,
    # 13, 23), and a face's corners in any order: the key does not depend on either.
    slot = {(0, 1): 4, (1, 2): 5, (0, 2): 6, (0, 3): 7, (1, 3): 8, (2, 3): 9}
    uses, counts = {}, {}
    for c, cell in enumerate(cells):
        for face in itertools.combinations(range(4), 3):
            nodes = list(face) + [slot[(face[0], face[1])], slot[(face[1], face[2])], slot[(face[0], face[2])]]
            key = quadratic_face_key(reference.points, cell[nodes])
            uses.setdefault(key, set()).add(int(materials[c]))
            counts[key] = counts.get(key, 0) + 1
    expected = {}
    for key, found in uses.items():
        pair = tuple(sorted(found | ({0} if counts[key] == 1 else set())))
        if len(pair) == 2:
            expected[key] = pair

    def faces_of(mesh, tag_key):
        return {quadratic_face_key(mesh.points, face): int(tag) for i, c in enumerate(mesh.cells)
                if c.type == "triangle6" for face, tag in zip(c.data, mesh.cell_data[tag_key][i])}
    got = faces_of(written, "gmsh:physical")
    assert len(expected) > 0 and set(got) == set(expected), \
        "the .msh interfaces are not the cells' faces with their mid-nodes (%d, %d)" % (len(got), len(expected))
    names = {int(v[0]): k for k, v in written.field_data.items() if v[1] == 2}
    for key, pair in expected.items():
        assert names[got[key]] == "%s|%s" % tuple("label_%d" % m for m in pair), (names[got[key]], pair)
    return expected, faces_of


def case_export_quadratic():
    """`mesh --order 2` writes quadratic tetrahedra: .vtu, .msh (Gmsh's 10-node tetrahedra, its own
    node order), .inp (C3D10) read back by meshio as the same cells on the same nodes with every
    material, .mesh (Medit's TetrahedraP2) read by Gmsh into the same; det J positive and the
    scaled Jacobian at least 0.1 from the written nodes; gmsh -check accepts the .msh; the interfaces
    as 6-node triangles (Gmsh's, Medit's TrianglesP2) on the cells' faces; the report's certified
    figures and fewer misclassified voxels."""
    labels = np.zeros((18, 20, 22), dtype=np.uint8)
    z, y, x = np.mgrid[0:18, 0:20, 0:22]
    labels[(x - 8.5) ** 2 + (y - 9.5) ** 2 + (z - 8.5) ** 2 <= 36] = 2
    labels[(x - 15.0) ** 2 + (y - 10.0) ** 2 + (z - 9.0) ** 2 <= 16] = 5
    image = cli.write_nrrd("quadratic.nrrd", labels, "uchar", spacing=(0.5, 0.5, 0.5))
    vtu, msh, inp, medit, report = (cli.path("quadratic." + e) for e in ("vtu", "msh", "inp", "mesh", "json"))
    result = cli.run("mesh", image, "--order", "2", "-o", vtu, "-o", msh, "-o", inp, "-o", medit, "--report", report)
    assert result.returncode == 0, result.stderr
    meshio = __import__("meshio")
    meshes = {f: meshio.read(f) for f in (vtu, msh, inp)}
    reference = meshes[vtu]
    assert [c.type for c in reference.cells] == ["tetra10"], [c.type for c in reference.cells]
    ref_cells = reference.cells[0].data
    materials = reference.cell_data["Material"][0].astype(np.int64)
    assert set(materials.tolist()) == {2, 5}, set(materials.tolist())
    # Every file: the same cells (as sets of node coordinates, in VTK's node order after meshio's
    # own reordering), so the writers' node orders agree with meshio's readers.
    def keyed(mesh):
        cells = np.concatenate([c.data for c in mesh.cells if c.type == "tetra10"])
        coords = np.round(mesh.points[cells], 9)
        return sorted(map(lambda a: a.tobytes(), coords))
    want = keyed(reference)
    for f in (msh, inp):
        assert keyed(meshes[f]) == want, f + " has other cells or another node order"
    tags = np.concatenate([meshes[msh].cell_data["gmsh:physical"][i] for i, c in enumerate(meshes[msh].cells)
                           if c.type == "tetra10"]).astype(np.int64)
    assert sorted(tags.tolist()) == sorted(materials.tolist()), "materials differ in the .msh"
    nodes = reference.points[ref_cells]
    det = tetra10_jacobians(nodes)
    assert det.min() > 0, "a written cell has det J %g" % det.min()
    ratio = det.min(axis=1) / det.max(axis=1)
    with open(report) as f:
        q = json.load(f)["quadratic"]
    assert q["guarantees_hold"] is True, q
    assert q["certified_minimum_scaled_jacobian"] >= q["scaled_jacobian_bound"] == 0.1, q
    assert ratio.min() >= q["certified_minimum_scaled_jacobian"] - 1e-9, (ratio.min(), q)
    assert q["curved_edges"] > 0 and q["cells"] == len(ref_cells), q
    assert q["misclassified_quadratic"] < q["misclassified_linear"], q
    assert shutil.which("gmsh"), "gmsh is not installed (python3-meshio and gmsh are test dependencies)"
    check = subprocess.run(["gmsh", msh, "-check"], capture_output=True, text=True)
    assert check.returncode == 0 and "Error" not in check.stdout + check.stderr, (check.stdout + check.stderr)[-500:]
    # Medit's TetrahedraP2: Debian's meshio cannot read it, so Gmsh reads it (its reader knows the
    # format's node order, which differs from its own) and writes it as .msh, which meshio reads
    # into VTK's order: the same cells, each with its material as Gmsh's elementary tag.
    converted = cli.path("quadratic_from_medit.msh")
    convert = subprocess.run(["gmsh", medit, "-0", "-o", converted, "-format", "msh22"], capture_output=True, text=True)
    assert convert.returncode == 0 and "Error" not in convert.stdout + convert.stderr, convert.stdout[-500:]
    from_medit = meshio.read(converted)
    assert keyed(from_medit) == want, ".mesh has other cells or another node order"
    elementary = np.concatenate([from_medit.cell_data["gmsh:geometrical"][i] for i, c in enumerate(from_medit.cells)
                                 if c.type == "tetra10"]).astype(np.int64)
    assert sorted(elementary.tolist()) == sorted(materials.tolist()), "materials differ in the .mesh"
    # The interfaces as 6-node triangles: exactly the faces of the written cells between two
    # materials or of one cell alone (against the background), each with the three mid-nodes of
    # its edges; the .msh groups them by pair (named "a|b"), the .mesh as TrianglesP2 (read by
    # Gmsh) into the same faces.
    expected, faces_of = assert_quadratic_interfaces(reference, meshes[msh])
    assert set(faces_of(from_medit, "gmsh:geometrical")) == set(expected), "the .mesh interfaces differ"
    # With the background written: its cells' own faces on the box bound nothing.
    with_background = cli.path("quadratic_background.msh")
    result = cli.run("mesh", image, "--order", "2", "--include-background", "-o", with_background, "-o",
                     cli.path("quadratic_background.vtu"), "--no-measure")
    assert result.returncode == 0, result.stderr
    assert_quadratic_interfaces(meshio.read(cli.path("quadratic_background.vtu")), meshio.read(with_background))
    # Formats without quadratic tetrahedra, and bad requests, are refused before meshing.
    cli.expect_failure(cli.run("mesh", image, "--order", "2", "-o", cli.path("q.stl")), ".inp or .mesh only", 2)
    cli.expect_failure(cli.run("mesh", image, "--order", "2", "-o", cli.path("q.vtp")), ".inp or .mesh only", 2)
    cli.expect_failure(cli.run("mesh", image, "--order", "3", "-o", vtu), "1 (linear) or 2", 2)
    cli.expect_failure(cli.run("mesh", image, "--order", "2", "--no-decimate", "-o", vtu), "--no-decimate", 2)
    cli.expect_failure(cli.run("mesh", image, "--order", "2", "--smoothness", "2", "-o", vtu), "'curve' only", 2)
    png = cli.write_png("flat.png", labels[9].astype(np.uint8))
    cli.expect_failure(cli.run("curve", png, "--order", "2", "-o", vtu), "applies to 'mesh'", 2)
    print("OK: %d quadratic tetrahedra, scaled Jacobian %.3f sampled (%.3f certified), misclassified %d -> %d"
          % (len(ref_cells), ratio.min(), q["certified_minimum_scaled_jacobian"], q["misclassified_linear"],
             q["misclassified_quadratic"]))


def triangle6_jacobians(nodes, n=10):
    """det J of 6-node triangles (corners, then the mid-nodes of edges 0-1, 1-2, 2-0; x, y) at a
    barycentric lattice, from the Lagrange shape functions' derivatives written out here."""
    dets = []
    for i in range(n + 1):
        for j in range(n + 1 - i):
            r, s = i / n, j / n
            t = 1 - r - s
            # d/dr and d/ds of t(2t-1), r(2r-1), s(2s-1), 4rt, 4rs, 4st (corner 0 at r = s = 0)
            dr = np.array([1 - 4 * t, 4 * r - 1, 0, 4 * (t - r), 4 * s, -4 * s])
            ds = np.array([1 - 4 * t, 0, 4 * s - 1, -4 * r, 4 * r, 4 * (t - s)])
            xr = np.einsum("k,ckd->cd", dr, nodes)
            xs = np.einsum("k,ckd->cd", ds, nodes)
            dets.append(xr[:, 0] * xs[:, 1] - xr[:, 1] * xs[:, 0])
    return np.stack(dets, axis=1)


def read_medit_p2(path):
    """A 2D Medit file's Vertices, TrianglesP2 and EdgesP2 (read here: Debian's meshio 5 has no P2
    Medit reader, and Gmsh 4.8's reader takes no Dimension 2 file)."""
    with open(path) as f:
        words = [w for line in f if not line.startswith("#") for w in line.split()]
    sections, k = {}, 0
    sizes = {"Vertices": 3, "TrianglesP2": 7, "EdgesP2": 4}
    while k < len(words):
        if words[k] in sizes:
            count, width = int(words[k + 1]), sizes[words[k]]
            sections[words[k]] = np.array(words[k + 2:k + 2 + count * width], dtype=float).reshape(count, width)
            k += 2 + count * width
        else:
            k += 1
    return sections


def case_export_quadratic_2d():
    """`mesh --order 2` of a 2D image writes quadratic triangles: .vtu, .msh (Gmsh's 6-node
    triangles, interfaces as its 3-node lines), .inp (CPS6) and .mesh (Medit's TrianglesP2 and
    EdgesP2), all the same cells on the same nodes with every material; det J positive and the
    scaled Jacobian at least 0.1 from the written nodes; each interface segment an edge of the
    cells between two materials (or against the background) with that edge's mid-node; the
    report's certified figures and fewer misclassified pixels."""
    disk = np.zeros((30, 40), dtype=np.uint8)
    y, x = np.mgrid[0:30, 0:40]
    disk[(x - 12.5) ** 2 + (y - 14.5) ** 2 <= 81] = 3
    disk[(x - 26.5) ** 2 + (y - 14.5) ** 2 <= 49] = 7
    png = cli.write_png("quadratic2d.png", disk)
    vtu, msh, inp, medit, report = (cli.path("quadratic2d." + e) for e in ("vtu", "msh", "inp", "mesh", "json"))
    result = cli.run("mesh", png, "--order", "2", "-o", vtu, "-o", msh, "-o", inp, "-o", medit, "--report", report)
    assert result.returncode == 0, result.stderr
    assert "quadratic triangles" in result.stdout, result.stdout[-800:]
    meshio = __import__("meshio")
    reference = meshio.read(vtu)
    assert [c.type for c in reference.cells] == ["triangle6"], [c.type for c in reference.cells]
    cells = reference.cells[0].data
    materials = reference.cell_data["Material"][0].astype(np.int64)
    assert set(materials.tolist()) == {3, 7}, set(materials.tolist())

    def keyed(points, cell_blocks):
        coords = np.round(points[np.concatenate(cell_blocks)][:, :, :2], 9)
        return sorted(map(lambda a: a.tobytes(), coords))
    want = keyed(reference.points, [cells])
    # .msh and .inp through meshio; meshio 5 knows Abaqus' 6-node triangle as CPE6 and STRI65, not
    # CPS6 (the same node order): the plane-stress name is read under the plane-strain one.
    gmsh_mesh = meshio.read(msh)
    assert keyed(gmsh_mesh.points, [c.data for c in gmsh_mesh.cells if c.type == "triangle6"]) == want, ".msh cells"
    tags = np.concatenate([gmsh_mesh.cell_data["gmsh:physical"][i] for i, c in enumerate(gmsh_mesh.cells)
                           if c.type == "triangle6"]).astype(np.int64)
    assert sorted(tags.tolist()) == sorted(materials.tolist()), "materials differ in the .msh"
    with open(inp) as f:
        text = f.read()
    assert "TYPE=CPS6" in text and "CPS3" not in text, text[:400]
    plane_strain = cli.path("quadratic2d_cpe6.inp")
    with open(plane_strain, "w") as f:
        f.write(text.replace("TYPE=CPS6", "TYPE=CPE6"))
    abaqus = meshio.read(plane_strain)
    assert keyed(abaqus.points, [c.data for c in abaqus.cells if c.type == "triangle6"]) == want, ".inp cells"
    sections = read_medit_p2(medit)
    medit_points = sections["Vertices"][:, :2]
    medit_cells = sections["TrianglesP2"][:, :6].astype(np.int64) - 1
    assert keyed(np.c_[medit_points, np.zeros(len(medit_points))], [medit_cells]) == want, ".mesh cells"
    assert sorted(sections["TrianglesP2"][:, 6].astype(np.int64).tolist()) == sorted(materials.tolist())
    # Valid, and the scaled Jacobian bound, from the written nodes.
    det = triangle6_jacobians(reference.points[cells][:, :, :2])
    det = det * np.sign(det[0, 0])  # one orientation for every cell: an inverted one fails
    assert det.min() > 0, "a written cell has det J %g" % det.min()
    ratio = (det.min(axis=1) / det.max(axis=1)).min()
    with open(report) as f:
        r = json.load(f)
    assert r["curved_mesh"]["order"] == 2 and r["curved_mesh"]["cell_type"] == "quadratic_triangle", r["curved_mesh"]
    assert r["validity"]["valid"] and r["validity"]["scaled_jacobian_bound_holds"], r["validity"]
    assert ratio >= r["validity"]["minimum_scaled_jacobian"] - 1e-9 and ratio >= 0.1, ratio
    assert r["curved_mesh"]["curved_edges"] > 0 and r["curved_mesh"]["within_bounds"], r["curved_mesh"]
    assert r["accuracy"]["misclassified_curved"] < r["accuracy"]["misclassified_linear"], r["accuracy"]
    # Interfaces: each cell edge between two materials or of one cell alone (material 0 beyond),
    # with its mid-node, in the .msh as 3-node lines grouped by pair and in the .mesh as EdgesP2.
    slot = {(0, 1): 3, (1, 2): 4, (0, 2): 5}
    uses = {}
    for c, cell in enumerate(cells):
        for (a, b), m in slot.items():
            key = (frozenset((cell[a], cell[b])), cell[m])
            uses.setdefault(key, []).append(int(materials[c]))
    def point_key(points, nodes):
        p = [np.round(points[n][:2], 9).tobytes() for n in nodes]
        return (frozenset(p[:2]), p[2])
    expected = {}
    for (ends, mid), found in uses.items():
        pair = tuple(sorted(found + ([0] if len(found) == 1 else [])))
        if pair[0] != pair[1]:
            expected[point_key(reference.points, list(ends) + [mid])] = pair
    lines = {point_key(gmsh_mesh.points, line): int(tag) for i, c in enumerate(gmsh_mesh.cells) if c.type == "line3"
             for line, tag in zip(c.data, gmsh_mesh.cell_data["gmsh:physical"][i])}
    assert expected and set(lines) == set(expected), "the .msh interfaces are not the cells' edges (%d, %d)" % (
        len(lines), len(expected))
    names = {int(v[0]): k for k, v in gmsh_mesh.field_data.items() if v[1] == 1}
    for key, pair in expected.items():
        assert names[lines[key]] == "%s|%s" % tuple("label_%d" % m for m in pair), (names[lines[key]], pair)
    medit_points3 = np.c_[medit_points, np.zeros(len(medit_points))]
    medit_lines = {point_key(medit_points3, e[:3].astype(np.int64) - 1) for e in sections["EdgesP2"]}
    assert medit_lines == set(expected), "the .mesh interfaces differ"
    assert shutil.which("gmsh"), "gmsh is not installed (python3-meshio and gmsh are test dependencies)"
    check = subprocess.run(["gmsh", msh, "-check"], capture_output=True, text=True)
    assert check.returncode == 0 and "Error" not in check.stdout + check.stderr, (check.stdout + check.stderr)[-500:]
    print("OK: %d quadratic triangles, scaled Jacobian %.3f sampled (%.3f certified), misclassified %d -> %d"
          % (len(cells), ratio, r["validity"]["minimum_scaled_jacobian"], r["accuracy"]["misclassified_linear"],
             r["accuracy"]["misclassified_curved"]))


def case_stl_per_interface():
    image = cli.write_nrrd("balls.nrrd", nested_balls(), "uchar")
    result = cli.run("mesh", image, "-o", cli.path("surface.stl"), "--stl-per-interface", "--report", cli.path("r.json"))
    assert result.returncode == 0, result.stderr
    with open(cli.path("r.json")) as f:
        outputs = json.load(f)["outputs"]
    want = [cli.path("surface_label_0_label_1.stl"), cli.path("surface_label_1_label_2.stl")]
    assert outputs == want, outputs
    assert all(os.path.getsize(p) > 84 for p in want)
    assert not os.path.exists(cli.path("surface.stl"))
    cli.expect_failure(cli.run("mesh", image, "-o", cli.path("m.vtu"), "--stl-per-interface"), ".stl", 2)
    print("OK:", outputs)


def segmentation(name, **kwargs):
    shape = (12, 14, 16)
    z, y, x = np.mgrid[0:shape[0], 0:shape[1], 0:shape[2]]
    layer0 = np.zeros(shape, dtype=np.uint8)
    layer0[(x - 5) ** 2 + (y - 6.5) ** 2 + (z - 5.5) ** 2 <= 12] = 1        # liver
    layer0[(x - 11) ** 2 + (y - 6.5) ** 2 + (z - 5.5) ** 2 <= 6] = 2        # left kidney
    layer1 = np.zeros(shape, dtype=np.uint8)
    layer1[1:4, 1:4, 11:15] = 1                                              # tumour, same value in layer 1
    segments = [
        {"name": "Liver", "color": (0.86, 0.51, 0.40), "label": 1, "layer": 0},
        {"name": "left kidney", "color": (0.73, 0.30, 0.20), "label": 2, "layer": 0},
        {"name": "Tumour", "color": (0.9, 0.9, 0.1), "label": 1, "layer": 1},
    ]
    if kwargs.get("overlap"):
        layer1[5, 6, 5] = 1
    path = cli.path(name)
    write_seg_nrrd(path, [layer0, layer1], segments, spacing=(0.8, 0.8, 1.0), origin=(10, -5, 2))
    return path


def case_seg_nrrd_names():
    seg = segmentation("organs.seg.nrrd")
    outputs, report, result = mesh_to(seg, "organs", FORMATS_3D)
    # Label values repeat across the layers, so segments are renumbered 1..3 in file order.
    names = {1: "Liver", 2: "left kidney", 3: "Tumour"}
    assert_report_names(report, names)
    assert {e["label"] for e in report["material_table"]} == {1, 2, 3}, report["material_table"]
    assert any("renumbered" in n for n in report["notes"]), report["notes"]
    assert "renumbered" in result.stdout, result.stdout
    colour = {e["label"]: e["color"] for e in report["material_table"]}
    assert np.allclose(colour[3], [0.9, 0.9, 0.1]), colour
    assert_exports(outputs, names, 3)
    with open(outputs[".msh"]) as f:
        text = f.read()
    assert '3 1 "Liver"' in text and '3 2 "left kidney"' in text and '3 3 "Tumour"' in text
    with open(outputs[".inp"]) as f:
        text = f.read()
    assert "ELSET=Liver" in text and "ELSET=left_kidney" in text and "ELSET=Tumour" in text
    with open(outputs[".mesh"]) as f:
        text = f.read()
    assert "#   1 = Liver\n" in text and "#   2 = left kidney\n" in text and "#   3 = Tumour\n" in text
    with open(outputs[".obj"]) as f:
        groups = {line.split()[1] for line in f if line.startswith("g ")}
    assert "label_0|Liver" in groups and "label_0|left_kidney" in groups, groups
    overlapping = segmentation("overlap.seg.nrrd", overlap=True)
    cli.expect_failure(cli.run("mesh", overlapping, "-o", cli.path("overlap.vtu")), "overlap")
    print("OK: segmentation names reach every format")


def case_write_full_device():
    image = cli.write_nrrd("ball.nrrd", cli.ball(12, 4.5).astype(np.uint8), "uchar")
    full = cli.path("full.vtu")
    if os.path.lexists(full):
        os.remove(full)
    os.symlink("/dev/full", full)
    result = cli.run("mesh", image, "-o", full)
    cli.expect_failure(result, "No space left on device")
    assert full in result.stderr, result.stderr
    assert "Output" not in result.stdout, result.stdout  # no summary of a mesh that was not written
    print("OK: /dev/full")


def limited_run(limit, *args):
    """A run whose files may not grow beyond `limit` bytes (write fails with EFBIG)."""
    def restrict():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    import subprocess
    # OpenMPI's PMIx keeps its data store in files, which the limit would break: use its in-memory store.
    env = dict(os.environ, PMIX_MCA_gds="hash")
    result = subprocess.run([cli.EXE, *args], capture_output=True, text=True, timeout=540, preexec_fn=restrict, env=env)
    # OpenMPI's launcher reports the ignored SIGXFSZ; that line is the test's doing, not labelmesher's.
    result.stderr = "".join(l for l in result.stderr.splitlines(True) if "Forwarding signal" not in l)
    return result


def case_write_no_partial_file():
    image = cli.write_nrrd("ball.nrrd", cli.ball(20, 8.5).astype(np.uint8), "uchar")
    folder = cli.path("out")
    os.makedirs(folder, exist_ok=True)
    for name in os.listdir(folder):
        os.remove(os.path.join(folder, name))
    target = os.path.join(folder, "mesh.msh")
    with open(target, "w") as f:
        f.write("previous file\n")
    result = limited_run(4096, "mesh", image, "-o", target, "--no-decimate")
    cli.expect_failure(result, "File too large")
    with open(target) as f:
        assert f.read() == "previous file\n", "the failed write touched the existing file"
    assert os.listdir(folder) == ["mesh.msh"], os.listdir(folder)  # no temporary left behind
    fresh = os.path.join(folder, "new.inp")
    cli.expect_failure(limited_run(4096, "mesh", image, "-o", fresh, "--no-decimate"), "new.inp")
    assert not os.path.exists(fresh)
    assert os.listdir(folder) == ["mesh.msh"], os.listdir(folder)
    print("OK: no partial file")


def case_bad_output_paths():
    image = cli.write_nrrd("ball.nrrd", cli.ball(12, 4.5).astype(np.uint8), "uchar")
    folder = cli.path("a_folder.vtu")
    os.makedirs(folder, exist_ok=True)
    linked = cli.path("linked.pvtu")  # VTK would read its pieces beside the link, not beside its target
    if os.path.lexists(linked):
        os.remove(linked)
    os.symlink("elsewhere.pvtu", linked)
    for output, fragment in [(folder, "is a folder"),
                             (linked, "symbolic link"),
                             (cli.path("missing/mesh.vtu"), "does not exist"),
                             (os.path.join(image, "mesh.vtu"), "is not a folder"),
                             ("/proc/labelmesher-test.vtu", "cannot write")]:
        result = cli.run("mesh", image, "-o", cli.path("good.vtu"), "-o", output)
        cli.expect_failure(result, fragment)
        # Checked before meshing: no progress, no summary, and the good output not written either.
        assert result.stdout == "", result.stdout
        assert not os.path.exists(cli.path("good.vtu"))
    cli.expect_failure(cli.run("mesh", image, "-o", cli.path("mesh.foo")), "unknown extension", 2)
    cli.expect_failure(cli.run("mesh", image, "-o", cli.path("m.vtu"), "-o", cli.path("m.vtu")), "twice", 2)
    cli.expect_failure(cli.run("mesh", image, "-o", cli.path("m.vtu"), "--report", cli.path("m.vtu")), "overwrite", 2)
    cli.expect_failure(cli.run("mesh", image, "-o", cli.path("m.msh"), "--msh-version", "3"), "4.1 or 2.2", 2)
    cli.expect_failure(cli.run("curve", image, "-o", cli.path("m.inp")), ".vtu, .pvtu, .vtk or .msh only", 2)
    cli.expect_failure(cli.run("mesh", image, "-o", cli.path("m.vtu"), "--report", cli.path("missing/r.json")),
                       "does not exist")
    # Other formats are written through a link: the link stays, its target gets the mesh.
    target, link = cli.path("through_target.msh"), cli.path("through.msh")
    for path in (target, link):
        if os.path.lexists(path):
            os.remove(path)
    os.symlink(os.path.basename(target), link)
    result = cli.run("mesh", image, "-o", link, "-q", "--no-measure")
    assert result.returncode == 0, result.stderr
    assert os.path.islink(link) and os.path.getsize(target) > 0
    # /dev/stdout is a link too, to a pipe here: written directly, not resolved.
    result = cli.run("mesh", image, "-o", cli.path("piped.msh"), "-q", "--no-measure", "--report", "/dev/stdout")
    assert result.returncode == 0, result.stderr
    assert '"mesh"' in result.stdout, result.stdout[:300]
    # ... and when the shell appends stdout to a file, the file keeps what it held.
    log = cli.path("stdout.log")
    with open(log, "w") as f:
        f.write("earlier line\n")
    with open(log, "a") as f:
        done = subprocess.run([cli.EXE, "mesh", image, "-o", cli.path("piped.msh"), "-q", "--no-measure",
                               "--report", "/dev/stdout"], stdout=f, stderr=subprocess.PIPE, text=True, timeout=540)
    assert done.returncode == 0, done.stderr
    with open(log) as f:
        text = f.read()
    assert text.startswith("earlier line\n") and '"mesh"' in text, text[:300]
    print("OK: bad output paths fail first; a link is written through")


def assert_plain(result, fragment):
    cli.expect_failure(result, fragment)
    err = result.stderr
    for noise in ("\x1b[", "vtk", "ERROR:", "0x", "itk::", "Warning"):
        assert noise not in err, f"{noise!r} in {err!r}"


def case_plain_errors():
    broken = cli.path("broken.png")
    with open(broken, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + b"this is not a PNG stream" * 4)
    assert_plain(cli.run("mesh", broken, "-o", cli.path("m.vtu")), "broken.png")
    zero = cli.write_nrrd("zero.nrrd", cli.ball(8, 2.5).astype(np.uint8), "uchar", spacing=(1, 0, 1))
    assert_plain(cli.run("mesh", zero, "-o", cli.path("m.vtu")), "spacing")
    good = cli.write_nrrd("good.nrrd", cli.ball(8, 2.5).astype(np.uint8), "uchar")
    table = cli.path("bad_labels.txt")
    with open(table, "w") as f:
        f.write("1 liver 300 0 0 255\n")
    assert_plain(cli.run("mesh", good, "-o", cli.path("m.vtu"), "--labels", table), "bad_labels.txt")
    assert_plain(cli.run("mesh", good, "-o", cli.path("m.vtu"), "--labels", cli.path("nothing.txt")), "nothing.txt")
    # Found by seeding the fuzzers: NrrdIO's chained complaint and a gzip stream under .nii.
    bad_type = cli.path("bad_type.nrrd")
    with open(bad_type, "wb") as f:
        f.write(b"NRRD0004\ntype: float32\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n" + bytes(32))
    assert_plain(cli.run("mesh", bad_type, "-o", cli.path("m.vtu")), 'not a valid NRRD file (couldn\'t parse type "float32")')
    gz_as_nii = cli.path("gzip_content.nii")
    with open(cli.write_nifti("real.nii.gz", cli.ball(8, 2.5).astype(np.uint8)), "rb") as f, open(gz_as_nii, "wb") as g:
        g.write(f.read())
    assert_plain(cli.run("mesh", gz_as_nii, "-o", cli.path("m.vtu")), "not a valid NIfTI file")
    # Found by fuzzing the VTI reader: a broken zlib header made VTK log a coloured record past the
    # output window (vtkLogger) before the CLI's line.
    pinned = os.path.join(REGRESSIONS, "read_vti/compression_header_log_record.vti")
    assert_plain(cli.run("mesh", pinned, "-o", cli.path("m.vtu")), "cannot read")
    # Found by fuzzing the .seg.nrrd reader: a malformed field line of ~1,200 characters overran
    # NrrdIO's error buffer (the CLI aborted); refused before NrrdIO parses it, in .nrrd too.
    long_line = os.path.join(REGRESSIONS, "read_segmentation/long_field_line.seg.nrrd")
    assert_plain(cli.run("mesh", long_line, "-o", cli.path("m.vtu")), "is a field of")
    long_nrrd = cli.path("long_field.nrrd")
    with open(long_nrrd, "wb") as f:
        f.write(b"NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\n" + b"x" * 1200 +
                b"\nencoding: raw\n\n" + bytes(8))
    assert_plain(cli.run("mesh", long_nrrd, "-o", cli.path("m.vtu")), "header line 5 is a field of 1200 characters")
    # Found by fuzzing the NIfTI reader: a NaN in the sform made ITK's VNL abort the CLI; refused
    # before ITK reads the header, plain or gzip-compressed.
    nan_sform = os.path.join(REGRESSIONS, "read_nifti/nan_sform.nii")
    assert_plain(cli.run("mesh", nan_sform, "-o", cli.path("m.vtu")), "srow_y[2] is not finite")
    import gzip
    with open(nan_sform, "rb") as f, gzip.open(cli.path("nan_sform.nii.gz"), "wb") as g:
        g.write(f.read())
    assert_plain(cli.run("mesh", cli.path("nan_sform.nii.gz"), "-o", cli.path("m.vtu")), "srow_y[2] is not finite")
    # Found by fuzzing too, two readers that never returned: a sform entry of -1.7e38 (ITK's float
    # SVD of it loops) and an NDims of 3e25 (MetaIO reads that many values per axis field).
    assert_plain(cli.run("mesh", os.path.join(REGRESSIONS, "read_nifti/huge_sform.nii"), "-o", cli.path("m.vtu")),
                 "beyond +-1e9")
    assert_plain(cli.run("mesh", os.path.join(REGRESSIONS, "read_metaimage/huge_ndims.mha"), "-o", cli.path("m.vtu")),
                 "NDims must be 1 to 8")
    # One more from the MetaImage reader: compressed voxels whose zlib header asks for a preset
    # dictionary (MetaIO's inflate loop never ends).
    assert_plain(cli.run("mesh", os.path.join(REGRESSIONS, "read_metaimage/preset_dictionary.mha"), "-o",
                         cli.path("m.vtu")), "asks for a preset zlib dictionary")
    # And six more, each aborting ITK in the sanitizer build or never returning. The fuzzed bytes
    # are garbled in more than one way, and most are now refused at their first line without '='
    # (MetaIO takes the value of such a line from the next '=' on, lines further: it took a later
    # line's value for one and so read compressed voxels of unknown size). Clean copies of what each
    # tripped over follow below, so that each check has an input that reaches it.
    for name, fragment in (("text_voxels_1d.mha", "header line 3 is not 'Name = Value'"),
                           ("data_file_pattern.mha", "header line 3 is not 'Name = Value'"),
                           ("pattern_and_nul_in_ndims.mha", "header line 3 is not 'Name = Value'"),
                           ("binary_data_file_name.mha", "header line 3 is not 'Name = Value'"),
                           ("empty_data_file_name.mha", "header line 2 is not 'Name = Value'"),
                           ("line_without_separator.mha", "header line 6 is not 'Name = Value'")):
        assert_plain(cli.run("mesh", os.path.join(REGRESSIONS, "read_metaimage", name), "-o", cli.path("m.vtu")),
                     fragment)
    # MetaImage fields as MetaIO reads them: a name ending at a NUL or a ':', a boolean that is 1.
    # And MetaIO's own lines on std::cerr ("Incomplete file record definition", ...) stay unprinted.
    header = "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\n"
    voxels = "ElementDataFile = LOCAL\n" + "\1" * 8
    for name, text, fragment in (
            ("nul_ndims.mha", header.replace("NDims = 3", "NDims\0\x80 = -3") + voxels, "NDims must be 1 to 8"),
            ("colon_ndims.mha", header.replace("NDims = 3", "NDims: 300000000000") + voxels, "NDims must be 1 to 8"),
            ("compressed_one.mha", header + "CompressedData = 1\nCompressedDataSize = 8\n" + voxels,
             "not a zlib stream"),
            ("incomplete.mha", header + "ElementSpacing =", "cannot read"),
            # MetaIO would read the NDims of this line from the next line's value, unchecked.
            ("ndims_value_below.mha", header.replace("NDims = 3", "NDims\nModality = 3e25") + voxels,
             "header line 2 is not 'Name = Value'"),
            # The clean copies: text voxels in 1D (ITK frees memory it does not own), a data file
            # pattern (MetaIO parses its numbers unchecked), a name of control characters, no name.
            ("text_1d.mha", "ObjectType = Image\nNDims = 1\nBinaryData = False\nDimSize = 4\n"
             "ElementType = MET_UCHAR\nElementDataFile = LOCAL\n1 2 3 4\n", "stores its voxels as text"),
            ("pattern.mha", header + "ElementDataFile = slice%03d.raw 1 2 1\n", "several data files"),
            ("control_name.mha", header + "ElementDataFile = \x01\x02\n", "data file name holds control characters"),
            ("no_name.mha", header + "ElementDataFile =\n", "ElementDataFile names no file")):
        with open(cli.path(name), "wb") as f:
            f.write(text.encode("latin-1"))
        assert_plain(cli.run("mesh", cli.path(name), "-o", cli.path("m.vtu")), fragment)
    # And a NIfTI-1 header whose sizeof_hdr is damaged (1116): niftilib reads it by its magic, so it
    # escaped the geometry check and its sform of -1.7e38 hung ITK.
    assert_plain(cli.run("mesh", os.path.join(REGRESSIONS, "read_nifti/damaged_sizeof_hdr.nii"), "-o",
                         cli.path("m.vtu")), "sizeof_hdr is 1116, expected 348")
    # The same with the magic "n+6" (found by fuzzing in CI): niftilib took it for a later NIfTI
    # version, read the geometry from other offsets and ITK aborted on its non-finite SVD.
    assert_plain(cli.run("mesh", os.path.join(REGRESSIONS, "read_nifti/version6_magic.nii"), "-o",
                         cli.path("m.vtu")), "sizeof_hdr is 134218076, expected 348")
    # Found by fuzzing the VTI reader: point data without a Scalars attribute reached the filter.
    # The only point array is the labels; two unmarked arrays, several components or fractional
    # floats are refused by the reader in one line.
    only_array = os.path.join(REGRESSIONS, "read_vti/no_scalars_attribute.vti")
    result = cli.run("mesh", only_array, "-o", cli.path("only_array.vtu"))
    assert result.returncode == 0, result.stderr
    ball = cli.ball(6, 2.2).astype(np.uint8).ravel(order="F").tolist()
    two = write_vti("two_arrays.vti", (6, 6, 6), [("a", "UInt8", 1, ball), ("b", "UInt8", 1, ball)])
    assert_plain(cli.run("mesh", two, "-o", cli.path("m.vtu")), "2 point data arrays and none marked as Scalars")
    pairs = write_vti("pairs.vti", (6, 6, 6), [("Labels", "UInt8", 2, ball + ball)], scalars="Labels")
    assert_plain(cli.run("mesh", pairs, "-o", cli.path("m.vtu")), "2 components per voxel")
    halves = write_vti("halves.vti", (6, 6, 6), [("Labels", "Float32", 1, [v + 0.5 for v in ball])], scalars="Labels")
    assert_plain(cli.run("mesh", halves, "-o", cli.path("m.vtu")), "non-integer value 0.5")
    floats = write_vti("floats.vti", (6, 6, 6), [("Labels", "Float32", 1, [float(v) for v in ball])], scalars="Labels")
    result = cli.run("mesh", floats, "-o", cli.path("floats.vtu"))
    assert result.returncode == 0, result.stderr
    print("OK: plain one-line errors")


REGRESSIONS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../Fuzz/Regressions")


def write_vti(name, dims, arrays, scalars=None):
    """An ASCII VTI of `dims` points; arrays: (name, VTK type, components, flat values)."""
    extent = " ".join(f"0 {d - 1}" for d in dims)
    body = "".join(f'<DataArray type="{t}" Name="{n}" NumberOfComponents="{c}" format="ascii">'
                   f'{" ".join(str(v) for v in values)}</DataArray>' for n, t, c, values in arrays)
    marked = f' Scalars="{scalars}"' if scalars else ""
    path = cli.path(name)
    with open(path, "w") as f:
        f.write(f'<?xml version="1.0"?><VTKFile type="ImageData" version="1.0" byte_order="LittleEndian">'
                f'<ImageData WholeExtent="{extent}" Origin="0 0 0" Spacing="1 1 1"><Piece Extent="{extent}">'
                f'<PointData{marked}>{body}</PointData></Piece></ImageData></VTKFile>')
    return path


def case_png_mutations():
    """Damaged PNGs (random bytes changed, half of them with the chunk CRCs made
    right again so the damage reaches the header and the image data): never a
    crash, always one plain line or a mesh."""
    import random
    import zlib
    disk = np.zeros((20, 24), dtype=np.uint8)
    y, x = np.mgrid[0:20, 0:24]
    disk[(x - 11.5) ** 2 + (y - 9.5) ** 2 <= 49] = 3
    with open(cli.write_png("good.png", disk), "rb") as f:
        good = f.read()

    def fix_crcs(data):
        out, at = bytearray(data[:8]), 8
        while at + 12 <= len(data):
            length = int.from_bytes(data[at:at + 4], "big")
            if at + 12 + length > len(data):
                out += data[at:]
                break
            body = data[at + 4:at + 8 + length]
            out += data[at:at + 8 + length] + zlib.crc32(body).to_bytes(4, "big")
            at += 12 + length
        return bytes(out)

    rng = random.Random(14)
    outcomes = {0: 0, 1: 0}
    for trial in range(60):
        data = bytearray(good)
        for _ in range(rng.randint(1, 4)):
            data[rng.randrange(8, len(data))] = rng.randrange(256)
        if trial % 3 == 2:
            data = data[:rng.randrange(8, len(data))]
        if trial % 2:
            data = bytearray(fix_crcs(bytes(data)))
        name = cli.path("mutated.png")
        with open(name, "wb") as f:
            f.write(bytes(data))
        result = cli.run("mesh", name, "-o", cli.path("mutated.vtu"), "-q")
        assert result.returncode in (0, 1), f"trial {trial}: status {result.returncode}: {result.stderr!r}"
        if result.returncode == 1:
            err = result.stderr.strip()
            assert err.startswith("labelmesher: error:") and "\n" not in err and "libpng" not in err, err
        outcomes[result.returncode] += 1
    print("OK: 60 damaged PNGs:", outcomes[0], "meshed,", outcomes[1], "refused in one line")


def case_vti_compression_headers():
    """Compressed VTI arrays ([#blocks][block size][last block size][compressed sizes], then the
    blocks): VTK 9.1 allocates what the header announces, so a 652-byte fuzzed file took 7 GB.
    Inline and appended, UInt32 and UInt64 headers, several blocks: read; a header announcing
    more blocks than the file can list, or other bytes than the extent holds: one plain line."""
    import base64
    import struct
    import zlib
    labels = cli.ball(12, 4.5).astype(np.uint8).ravel(order="F").tobytes()  # 1,728 bytes

    def compressed(data, block, word, last=None, blocks=None):
        pieces = [zlib.compress(data[i:i + block]) for i in range(0, len(data), block)]
        fmt = "<" + ("I" if word == 4 else "Q")
        numbers = [len(pieces) if blocks is None else blocks, block,
                   len(data) % block if last is None else last] + [len(p) for p in pieces]
        return b"".join(struct.pack(fmt, n) for n in numbers), b"".join(pieces)

    def write(name, header, data, word, appended, tail=True):
        kind = "UInt32" if word == 4 else "UInt64"
        extent = "0 11 0 11 0 11"
        start = (f'<?xml version="1.0"?><VTKFile type="ImageData" version="1.0" byte_order="LittleEndian" '
                 f'header_type="{kind}" compressor="vtkZLibDataCompressor"><ImageData WholeExtent="{extent}" '
                 f'Origin="0 0 0" Spacing="1 1 1"><Piece Extent="{extent}"><PointData Scalars="Labels">'
                 f'<DataArray type="UInt8" Name="Labels" format="{"appended" if appended else "binary"}"')
        if appended:
            text = (start + ' offset="0"/></PointData></Piece></ImageData><AppendedData encoding="raw">\n_').encode()
            text += header + data + (b"\n</AppendedData></VTKFile>\n" if tail else b"")
        else:
            text = (start + ">\n" + base64.b64encode(header).decode() + base64.b64encode(data).decode() +
                    "\n</DataArray></PointData></Piece></ImageData></VTKFile>\n").encode()
        with open(cli.path(name), "wb") as f:
            f.write(text)
        return cli.path(name)

    for word in (4, 8):
        for appended in (False, True):
            name = f"good_{word}_{appended}.vti"
            path = write(name, *compressed(labels, 500, word), word, appended)  # 4 blocks, the last of 228
            result = cli.run("mesh", path, "-o", cli.path("good.vtu"), "-q")
            assert result.returncode == 0, (name, result.stderr)
    for name, fragment in (("huge_block_count.vti", "announces 1771701761 blocks, more than the file of 652 bytes"),
                           ("huge_block_count_base64_offset.vti", "announces 3488824527 blocks")):
        assert_plain(cli.run("mesh", os.path.join(REGRESSIONS, "read_vti", name), "-o", cli.path("m.vtu")), fragment)
    # One block announced as 2 GB (VTK would allocate it), a block count one short, and a header
    # cut off by the end of the file.
    for name, (header, data), fragment in (
            ("huge_block.vti", compressed(labels, 1728, 4, last=1 << 31), "announces 2.14748e+09 bytes in 1 blocks"),
            ("one_short.vti", compressed(labels, 500, 8, blocks=3), "announces 1228 bytes in 3 blocks; its 1728 tuples"),
            ("cut.vti", (compressed(labels, 500, 8)[0][:20], b""), "ends before its compression header")):
        path = write(name, header, data, 4 if "huge" in name else 8, True, tail=name != "cut.vti")
        assert_plain(cli.run("mesh", path, "-o", cli.path("m.vtu")), fragment)
    print("OK: compressed VTI headers checked")


if __name__ == "__main__":
    os.makedirs(cli.WORK, exist_ok=True)
    globals()["case_" + cli.CASE]()
