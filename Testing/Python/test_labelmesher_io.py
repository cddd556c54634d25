# SPDX-License-Identifier: GPL-2.0-or-later
"""`import labelmesher` as a Python user meets it: the checked reader (vtkLabelImageReader), the
one-filter pipeline (vtkLabelMesher) and the writer of every mesh format (vtkLabelMeshWriter).
Each written file is read back by independent readers (Debian's meshio, `gmsh -check`; the
checks of Testing/Support/export_checks.py that the CLI's export tests use) and compared with
the .vtu of the same mesh: points, cells, materials and their names, interface faces. Also the
shared gzip NRRD (which VTK's own NRRD reader misreads) read voxel for voxel as numpy decodes it,
a 3D Slicer segmentation's names reaching every file, and failed reads and writes: one line, an
empty output, Write() returning 0 and no file left behind. The report (vtkLabelMeshReport) is the
CLI's: the same JSON as `labelmesher mesh|curve --report` on the same image.

Run with PYTHONPATH=<build>/lib/python3/dist-packages (ctest sets it)."""

import json
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import labelmesher
from test_vtkMeshDecimator import record_errors

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Support"))
sys.path.insert(0, os.path.join(HERE, "..", "CLI"))
from export_checks import check_exports  # noqa: E402
from label_nrrd import read_label_nrrd  # noqa: E402
from segmentation_fixture import write_seg_nrrd  # noqa: E402

SHARED = os.path.join(HERE, "..", "..", "..", "shared", "data")
RAT_HEAD = os.path.join(SHARED, "3d", "iso2mesh_rat_head.nrrd")
FORMATS = [".vtu", ".vtk", ".msh", ".inp", ".mesh", ".vtp", ".stl", ".obj"]


def read(path, table=None):
    reader = labelmesher.vtkLabelImageReader()
    errors = record_errors(reader)
    reader.SetFileName(path)
    if table:
        reader.SetLabelTableFileName(table)
    reader.Update()
    return reader, errors


def write(mesher, path, **settings):
    writer = labelmesher.vtkLabelMeshWriter()
    errors = record_errors(writer)
    writer.SetInputConnection(mesher.GetOutputPort(0))
    writer.SetInterfacesConnection(mesher.GetOutputPort(1))
    writer.SetFileName(path)
    for name, value in settings.items():
        getattr(writer, "Set" + name)(value)
    return writer.Write(), writer, errors


def organs(path):
    """Two segments in one layer and a third in a second layer with the same value: the reader
    renumbers them 1..3 in file order."""
    shape = (12, 14, 16)
    z, y, x = np.mgrid[0:shape[0], 0:shape[1], 0:shape[2]]
    layer0 = np.zeros(shape, dtype=np.uint8)
    layer0[(x - 5) ** 2 + (y - 6.5) ** 2 + (z - 5.5) ** 2 <= 12] = 1
    layer0[(x - 11) ** 2 + (y - 6.5) ** 2 + (z - 5.5) ** 2 <= 6] = 2
    layer1 = np.zeros(shape, dtype=np.uint8)
    layer1[1:4, 1:4, 11:15] = 1
    segments = [
        {"name": "Liver", "color": (0.86, 0.51, 0.40), "label": 1, "layer": 0},
        {"name": "left kidney", "color": (0.73, 0.30, 0.20), "label": 2, "layer": 0},
        {"name": "Tumour", "color": (0.9, 0.9, 0.1), "label": 1, "layer": 1},
    ]
    write_seg_nrrd(path, [layer0, layer1], segments, spacing=(0.8, 0.8, 1.0), origin=(10, -5, 2))


def table_of(data):
    fd = data.GetFieldData()
    labels = fd.GetArray("MaterialLabel")
    names = fd.GetAbstractArray("MaterialName")
    if labels is None or names is None:
        return {}
    return {int(labels.GetValue(i)): names.GetValue(i) for i in range(labels.GetNumberOfTuples())}


class ReaderTest(unittest.TestCase):
    def test_gzip_nrrd_voxel_for_voxel(self):
        reader, errors = read(RAT_HEAD)
        self.assertEqual(errors, [])
        image = reader.GetOutput()
        want, spacing = read_label_nrrd(RAT_HEAD)
        self.assertEqual(image.GetDimensions(), tuple(want.shape[::-1]))
        self.assertTrue(np.allclose(image.GetSpacing(), spacing))
        labels = image.GetPointData().GetScalars()
        self.assertEqual(labels.GetName(), "Labels")
        self.assertTrue(np.array_equal(vtk_to_numpy(labels).reshape(want.shape), want))
        self.assertTrue(labelmesher.vtkLabelImageReader.CanReadFile(RAT_HEAD))
        self.assertFalse(labelmesher.vtkLabelImageReader.CanReadFile("mesh.vtu"))

    def test_segmentation_names_colours_and_note(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "organs.seg.nrrd")
            organs(path)
            reader, errors = read(path)
        self.assertEqual(errors, [])
        image = reader.GetOutput()
        self.assertEqual(table_of(image), {1: "Liver", 2: "left kidney", 3: "Tumour"})
        colours = vtk_to_numpy(image.GetFieldData().GetArray("MaterialColor"))
        self.assertTrue(np.allclose(colours[2], [0.9, 0.9, 0.1]))
        self.assertTrue(np.allclose(image.GetSpacing(), (0.8, 0.8, 1.0)))
        self.assertTrue(np.allclose(image.GetOrigin(), (10, -5, 2)))
        self.assertEqual(reader.GetNumberOfNotes(), 1)
        self.assertIn("renumbered", reader.GetNote(0))

    def test_colour_table_names_labels(self):
        with tempfile.TemporaryDirectory() as folder:
            table = os.path.join(folder, "names.ctbl")
            with open(table, "w") as f:
                f.write("# Slicer colour table\n1 skull 255 255 255 255\n")
            reader, errors = read(RAT_HEAD, table)
        self.assertEqual(errors, [])
        self.assertEqual(table_of(reader.GetOutput()), {1: "skull"})

    def test_bad_inputs_one_line_and_empty_output(self):
        with tempfile.TemporaryDirectory() as folder:
            rgb = os.path.join(folder, "rgb.nrrd")
            with open(rgb, "w") as f:
                f.write("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 3 2 2\nkinds: RGB-color domain domain\n"
                        "encoding: raw\n\n" + "x" * 12)
            cases = [(os.path.join(folder, "missing.nrrd"), "no such file"),
                     (folder, "not a regular file"),
                     (rgb, "components")]
            for path, fragment in cases:
                reader, errors = read(path)
                self.assertEqual(len(errors), 1, (path, errors))
                self.assertIn(fragment, reader.GetErrorText())
                self.assertNotIn("\n", reader.GetErrorText())
                self.assertIn(reader.GetErrorText(), errors[0])
                self.assertEqual(reader.GetOutput().GetNumberOfPoints(), 0)


class WriterTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.TemporaryDirectory()
        cls.seg = os.path.join(cls.folder.name, "organs.seg.nrrd")
        organs(cls.seg)
        cls.reader, _ = read(cls.seg)
        cls.mesher = labelmesher.vtkLabelMesher()
        cls.mesher.SetInputConnection(cls.reader.GetOutputPort())
        cls.mesher.Update()

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def path(self, name):
        return os.path.join(self.folder.name, name)

    def test_every_format_read_back_with_the_segments_names(self):
        names = {1: "Liver", 2: "left kidney", 3: "Tumour"}
        self.assertEqual(table_of(self.mesher.GetOutput()), names)
        outputs = {}
        for extension in FORMATS:
            outputs[extension] = self.path("organs" + extension)
            ok, writer, errors = write(self.mesher, outputs[extension])
            self.assertEqual((ok, errors), (1, []), extension)
            self.assertEqual(writer.GetErrorText(), "")
        outputs[".msh22"] = self.path("organs22.msh")
        ok, _, errors = write(self.mesher, outputs[".msh22"], GmshVersion22=True)
        self.assertEqual((ok, errors), (1, []))
        with open(outputs[".msh22"]) as f:
            self.assertTrue(f.read(100).startswith("$MeshFormat\n2.2 0 8\n"))
        checked = {k: v for k, v in outputs.items() if k not in (".vtu", ".vtk")}
        failures = check_exports(outputs[".vtu"], checked, names, 3)
        self.assertEqual(failures, [])
        with open(outputs[".inp"]) as f:
            self.assertIn("ELSET=left_kidney", f.read())

    def test_five_lines_of_the_readme(self):
        reader = labelmesher.vtkLabelImageReader()
        reader.SetFileName(RAT_HEAD)
        mesher = labelmesher.vtkLabelMesher()
        mesher.SetInputConnection(reader.GetOutputPort())
        writer = labelmesher.vtkLabelMeshWriter()
        writer.SetInputConnection(mesher.GetOutputPort())
        writer.SetFileName(self.path("rat_head.msh"))
        self.assertEqual(writer.Write(), 1)
        failures = check_exports(self.vtu_of(mesher), {".msh": self.path("rat_head.msh")}, {}, 3)
        self.assertEqual(failures, [])

    def vtu_of(self, mesher):
        path = self.path("reference.vtu")
        ok, _, errors = write(mesher, path)
        self.assertEqual((ok, errors), (1, []))
        return path

    def test_failed_writes_leave_nothing(self):
        missing = self.path(os.path.join("no such folder", "m.msh"))
        folder = self.path("a folder.msh")
        os.makedirs(folder, exist_ok=True)
        full = self.path("full.inp")
        if not os.path.lexists(full):
            os.symlink("/dev/full", full)
        for path, fragment in [(missing, "no such folder"), (folder, "folder"),
                               (full, "No space left on device"), (self.path("m.xyz"), "unknown extension")]:
            before = sorted(os.listdir(self.folder.name))
            ok, writer, errors = write(self.mesher, path)
            self.assertEqual(ok, 0, path)
            self.assertEqual(len(errors), 1, (path, errors))
            self.assertIn(fragment, writer.GetErrorText())
            self.assertNotIn("\n", writer.GetErrorText())
            self.assertIn(writer.GetErrorText(), errors[0])
            self.assertEqual(sorted(os.listdir(self.folder.name)), before, path)

    def test_surface_formats_need_the_interfaces(self):
        writer = labelmesher.vtkLabelMeshWriter()
        errors = record_errors(writer)
        writer.SetInputConnection(self.mesher.GetOutputPort(0))
        writer.SetFileName(self.path("surface.stl"))
        self.assertEqual(writer.Write(), 0)
        self.assertEqual(len(errors), 1)
        self.assertIn("interface", errors[0])
        self.assertFalse(os.path.exists(self.path("surface.stl")))


class ReportTest(unittest.TestCase):
    """vtkLabelMeshReport from Python and the CLI's --report: one report, the same figures."""

    # What only the CLI knows (file names, the reader's notes, its own timings and memory).
    CALLER_KEYS = {"input", "output", "outputs", "notes", "timings", "total_seconds", "memory"}

    def report_of_cli(self, command, image, *options):
        cli = os.environ.get("LABELMESHER_CLI")
        self.assertTrue(cli, "LABELMESHER_CLI: the labelmesher program to compare with (ctest sets it)")
        with tempfile.TemporaryDirectory() as folder:
            report = os.path.join(folder, "report.json")
            subprocess.run([cli, command, image, "-o", os.path.join(folder, "mesh.vtu"), "--report", report, "-q",
                            *options], check=True)
            with open(report) as f:
                return json.load(f)

    def report_of_python(self, image, **settings):
        reader, errors = read(image)
        self.assertEqual(errors, [])
        mesher = labelmesher.vtkLabelMesher()
        mesher.SetInputConnection(reader.GetOutputPort())
        for name, value in settings.items():
            getattr(mesher, "Set" + name)(value)
        mesher.Update()
        builder = labelmesher.vtkLabelMeshReport()
        builder.SetImage(reader.GetOutput())
        builder.SetMesh(mesher.GetOutput())
        if mesher.GetCurve():
            builder.SetCurvedMesh(mesher.GetCurvedOutput())
        self.assertTrue(builder.GetGuaranteesHold())
        return json.loads(builder.GetJSON()), builder.GetSummary()

    def without_caller_keys(self, report):
        return {k: v for k, v in report.items() if k not in self.CALLER_KEYS}

    def test_mesh_report_is_the_clis(self):
        ours, summary = self.report_of_python(RAT_HEAD, MinimumAngle=20.0)
        cli = self.report_of_cli("mesh", RAT_HEAD, "--min-angle", "20")
        self.assertEqual(self.without_caller_keys(ours), self.without_caller_keys(cli))
        # The filters' stages, timed alike (the CLI adds its reading and writing around them).
        self.assertEqual([t["stage"] for t in ours["timings"]],
                         [t["stage"] for t in cli["timings"] if t["stage"] not in ("read", "write")])
        self.assertEqual(ours["quality"]["angle_bound_degrees"], 20.0)
        self.assertIn("Both bounds certified", summary)

    def test_a_failed_untangling_keeps_the_linear_mesh_and_the_marked_curves(self):
        # One load step and one round cannot untangle every cell of this slice (as
        # RealData.curve_digimouse_sagittal's --check-failure finds through the CLI).
        reader, _ = read(os.path.join(SHARED, "2d", "digimouse_sagittal.nrrd"))
        mesher = labelmesher.vtkLabelMesher()
        errors = record_errors(mesher)
        mesher.SetInputConnection(reader.GetOutputPort())
        mesher.SetCurve(True)
        mesher.SetMaximumUntanglingSteps(1)
        mesher.SetMaximumShorteningRounds(1)
        mesher.Update()
        self.assertEqual(len(errors), 1, errors)
        self.assertIn("could not be proven valid", errors[0])
        self.assertGreater(mesher.GetOutput().GetNumberOfCells(), 0)
        self.assertGreater(mesher.GetInterfacesOutput().GetNumberOfCells(), 0)
        curved = mesher.GetCurvedOutput()
        valid = vtk_to_numpy(curved.GetCellData().GetArray("Valid"))
        self.assertEqual(valid.size, curved.GetNumberOfCells())
        self.assertTrue(0 < np.count_nonzero(valid == 0) < valid.size)
        builder = labelmesher.vtkLabelMeshReport()
        builder.SetImage(reader.GetOutput())
        builder.SetMesh(mesher.GetOutput())
        builder.SetCurvedMesh(curved)
        report = json.loads(builder.GetJSON())
        self.assertFalse(report["validity"]["valid"])
        self.assertEqual(report["validity"]["invalid_cells"], int(np.count_nonzero(valid == 0)))
        self.assertFalse(builder.GetGuaranteesHold())

    def test_curve_report_is_the_clis(self):
        image = os.path.join(SHARED, "2d", "digimouse_sagittal.nrrd")
        ours, summary = self.report_of_python(image, Curve=True, Smoothness=2)
        cli = self.report_of_cli("curve", image, "--smoothness", "2")
        self.assertEqual(self.without_caller_keys(ours), self.without_caller_keys(cli))
        self.assertEqual(ours["command"], "curve")
        self.assertTrue(ours["validity"]["valid"])
        self.assertIn("every cell proven valid", summary)


if __name__ == "__main__":
    unittest.main()
